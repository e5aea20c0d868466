// Marching squares against a field whose contours are known, and the report's building blocks.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>

#include "photometry/builtin.h"
#include "report/colour_scale.h"
#include "report/html_report.h"
#include "report/isolux.h"
#include "report/polar_diagram.h"
#include "report/raster_text.h"
#include "util/error.h"

namespace luxgrid::report {
namespace {

TEST(Isolux, LinearFieldGivesAStraightLineAtTheRightPlace) {
  // E = 100 * i on a 5 x 4 grid: the 250 lx contour is the vertical line x = 2.5.
  const int nu = 5, nv = 4;
  std::vector<double> E;
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) E.push_back(100.0 * i);
  const auto s = isolux_segments(E, nu, nv, 250.0);
  ASSERT_EQ(s.size(), 3u);  // one per row of squares
  for (const auto& g : s) {
    EXPECT_DOUBLE_EQ(g.x0, 2.5);
    EXPECT_DOUBLE_EQ(g.x1, 2.5);
    EXPECT_DOUBLE_EQ(std::abs(g.y1 - g.y0), 1.0);
  }
}

TEST(Isolux, CircleRadiusIsRecovered) {
  // E = r (distance from the centre): every segment end lies on the circle r = 5 to within the
  // linear interpolation error of a chord (< 0.05 grid units at r = 5).
  const int n = 21;
  std::vector<double> E;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) E.push_back(std::hypot(i - 10.0, j - 10.0));
  const auto s = isolux_segments(E, n, n, 5.0);
  ASSERT_GT(s.size(), 20u);
  for (const auto& g : s) {
    EXPECT_NEAR(std::hypot(g.x0 - 10, g.y0 - 10), 5.0, 0.05);
    EXPECT_NEAR(std::hypot(g.x1 - 10, g.y1 - 10), 5.0, 0.05);
  }
}

TEST(Isolux, InactivePointsAndFlatFieldsGiveNothing) {
  std::vector<double> E(16, 300.0);
  EXPECT_TRUE(isolux_segments(E, 4, 4, 250.0).empty());
  E[0] = 100.0;
  std::vector<bool> active(16, true);
  active[0] = false;
  EXPECT_TRUE(isolux_segments(E, 4, 4, 250.0, active).empty());
  EXPECT_FALSE(isolux_segments(E, 4, 4, 250.0).empty());
}

TEST(Isolux, ManyLevelsAtOnceAreEachLevelsOwnSegments) {
  // The plots ask for all their levels in one pass, which visits only the levels between a
  // square's lowest and highest corner. Each level must get exactly its own segments, in the
  // same order: levels in any order, repeated, equal to corner values (a corner exactly at a
  // level counts as above it), NaN and infinite; NaN corners and inactive points in the field.
  std::mt19937 rng(9);
  std::uniform_int_distribution<int> step(0, 12);
  const int nu = 23, nv = 17;
  std::vector<double> E;
  for (int k = 0; k < nu * nv; ++k) E.push_back(25.0 * step(rng));  // many exact ties
  E[40] = NAN, E[41] = NAN, E[200] = INFINITY;
  std::vector<bool> active(E.size(), true);
  for (size_t k = 3; k < active.size(); k += 11) active[k] = false;
  const std::vector<double> levels = {150, 25,        300,      150,   0,  12.5,
                                      NAN, -INFINITY, INFINITY, 299.9, 1e9};
  const auto all = isolux_segments(E, nu, nv, levels, active);
  ASSERT_EQ(all.size(), levels.size());
  size_t total = 0;
  for (size_t k = 0; k < levels.size(); ++k) {
    const auto one = isolux_segments(E, nu, nv, levels[k], active);
    // Independently: a square gives one segment when its corners are on both sides of the level
    // (at or above it, or not: NaN is not), two for a saddle.
    size_t expected = 0;
    for (int j = 0; j + 1 < nv; ++j)
      for (int i = 0; i + 1 < nu; ++i) {
        const size_t c[4] = {static_cast<size_t>(j) * nu + i, static_cast<size_t>(j) * nu + i + 1,
                             static_cast<size_t>(j + 1) * nu + i + 1,
                             static_cast<size_t>(j + 1) * nu + i};
        int code = 0, on = 0;
        for (int q = 0; q < 4; ++q) code |= (E[c[q]] >= levels[k]) << q, on += active[c[q]];
        if (on == 4 && code != 0 && code != 15) expected += code == 5 || code == 10 ? 2 : 1;
      }
    ASSERT_EQ(one.size(), expected) << "level " << levels[k];
    ASSERT_EQ(all[k].size(), one.size()) << "level " << levels[k];
    // The same doubles, bit for bit (a NaN or infinite corner gives NaN ends).
    for (size_t n = 0; n < one.size(); ++n)
      EXPECT_EQ(std::memcmp(&all[k][n], &one[n], sizeof(IsoSegment)), 0) << levels[k] << " " << n;
    total += one.size();
  }
  EXPECT_GT(total, 500u);
  EXPECT_TRUE(all[6].empty()) << "NaN level";
}

TEST(Isolux, LevelsAreTicksInsideTheData) {
  const auto scale = fixed_scale(0, 1000);  // ticks every 200
  EXPECT_EQ(isolux_levels(scale, 150, 700), (std::vector<double>{200, 400, 600}));
}

TEST(Scale, ParsesAndRejects) {
  const auto s = parse_scale("0:1000");
  EXPECT_EQ(s.min, 0.0);
  EXPECT_EQ(s.max, 1000.0);
  EXPECT_EQ(s.ticks.back(), 1000.0);
  try {
    parse_scale("500:100");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "--scale 500:100: MIN must be less than MAX");
  }
  EXPECT_THROW(parse_scale("100:100"), InputError);
  EXPECT_THROW(parse_scale("100"), InputError);
  EXPECT_THROW(parse_scale("a:100"), InputError);
  EXPECT_THROW(parse_scale("-5:100"), InputError);
}

TEST(Html, Base64MatchesRfc4648Vectors) {
  EXPECT_EQ(base64(""), "");
  EXPECT_EQ(base64("f"), "Zg==");
  EXPECT_EQ(base64("fo"), "Zm8=");
  EXPECT_EQ(base64("foo"), "Zm9v");
  EXPECT_EQ(base64("foobar"), "Zm9vYmFy");
  EXPECT_EQ(html_escape("<a&\"b\">"), "&lt;a&amp;&quot;b&quot;&gt;");
}

// The page's images are encoded a few kilobytes at a time (base64_to, 12 288 bytes a piece):
// pieces that end inside an image and a last group of one or two bytes must give the same text
// as encoding it whole.
// The reference is RFC 4648's definition, six bits at a time from a bit stream.
TEST(Html, Base64InPiecesMatchesTheBitStreamDefinition) {
  static constexpr char kAlphabet[] =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  for (const std::size_t size : {std::size_t{12287}, std::size_t{12288}, std::size_t{12289},
                                 std::size_t{50000}, std::size_t{50001}}) {
    std::string bytes(size, '\0');
    std::uint32_t state = 12345;
    for (char& c : bytes) c = static_cast<char>((state = state * 1103515245u + 12345u) >> 24);
    std::string expected;
    std::uint32_t bits = 0;
    int count = 0;
    for (const char c : bytes) {
      bits = (bits << 8) | static_cast<unsigned char>(c), count += 8;
      for (; count >= 6; count -= 6) expected += kAlphabet[(bits >> (count - 6)) & 63];
    }
    if (count > 0) expected += kAlphabet[(bits << (6 - count)) & 63];
    while (expected.size() % 4) expected += '=';
    std::string streamed;
    int pieces = 0;
    base64_to(bytes, [&](std::string_view piece) { streamed += piece, ++pieces; });
    EXPECT_EQ(streamed, expected) << size << " bytes";
    EXPECT_EQ(base64(bytes), expected) << size << " bytes";
    if (size > 12288) {
      EXPECT_GT(pieces, 1) << size << " bytes: encoded in one piece";
    }
  }
}

TEST(Html, ReportIsSelfContainedAndPrintsTheStatistics) {
  calc::Results r;
  r.project = "demo <1>";
  r.plan.near_switch = nearfield::NearFieldSwitch::never;
  calc::SurfaceResult s;
  s.grid = geometry::make_plane_grid("wp", {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 2.0, 1.0, 1.0);
  s.E = {400.0, 600.0};
  s.stats = calc::compute_statistics(s.E);
  r.surfaces.push_back(s);
  ReportInput in;
  in.results = &r;
  in.version = "0.1.0";
  in.png["wp"] = "PNGDATA";
  const std::string h = html_report(in);
  // The page handed out in pieces is the same page.
  std::string pieces;
  write_html_report(in, [&](std::string_view piece) { pieces += piece; });
  EXPECT_EQ(pieces, h);
  EXPECT_NE(h.find("demo &lt;1&gt;"), std::string::npos);
  EXPECT_NE(h.find("data-stat=\"Eavg\">500.0 lx<"), std::string::npos);
  EXPECT_NE(h.find("data-stat=\"U0\">0.800<"), std::string::npos);
  EXPECT_NE(h.find("src=\"data:image/png;base64," + base64("PNGDATA") + "\""), std::string::npos);
  EXPECT_EQ(h.find("<script"), std::string::npos);
  EXPECT_EQ(h.find("http://"), h.find("http://www.w3.org/2000/svg"));  // no external resource
  EXPECT_NE(h.find("@page { size: A4"), std::string::npos);
  EXPECT_NE(h.find("<td>400</td><td>600</td>"), std::string::npos);  // the value table
}

TEST(Polar, OneRendererWithTheReportsColoursAndRingValues) {
  // A Lambertian 800 cd luminaire: I = 800 cos(gamma) in both planes, so the C0 curve (blue,
  // solid) and the C90 curve (red, dashed, drawn over it) both reach 0.8 of the outer ring
  // (1000 cd) straight down and nothing upwards.
  EXPECT_DOUBLE_EQ(polar_outer_ring_cd(800.0), 1000.0);
  EXPECT_DOUBLE_EQ(polar_outer_ring_cd(1000.0), 1000.0);
  const photometry::LambertianDistribution d(800.0);
  bool font_ok = false;
  const Raster img = polar_diagram(d, "test", 640, &font_ok);
  ASSERT_EQ(img.width(), 640);
  ASSERT_EQ(img.height(), 640);
  auto is = [](Rgb c, Rgb want) {
    return std::abs(c.r - want.r) < 0.02f && std::abs(c.g - want.g) < 0.02f &&
           std::abs(c.b - want.b) < 0.02f;
  };
  const Rgb blue{0.12f, 0.25f, 0.56f}, red{0.75f, 0.22f, 0.17f};
  int blue_px = 0, red_px = 0, lowest_blue = 0, highest_curve = 640;
  for (int y = 0; y < 640; ++y)
    for (int x = 0; x < 640; ++x) {
      const Rgb c = img.at(x, y);
      const bool b = is(c, blue), r = is(c, red);
      blue_px += b, red_px += r;
      if (b && x > 200 && x < 440) lowest_blue = std::max(lowest_blue, y);
      if ((b || r) && x > 200 && x < 440 && y > 60 && y < 600)
        highest_curve = std::min(highest_curve, y);
    }
  EXPECT_GT(blue_px, 500) << "the C0-C180 curve in the report's blue";
  EXPECT_GT(red_px, 300) << "the C90-C270 curve in the report's red";
  // Nadir is at the bottom: the curve lies below the centre, nothing of it above (the legend's
  // blue sample sits in the bottom band, outside 200 < x < 440 where it could matter).
  EXPECT_GT(lowest_blue, 360);
  EXPECT_GT(highest_curve, 300) << "a downlight's curves stay in the lower half";
  if (std::filesystem::exists(kPlotFont)) {
    EXPECT_TRUE(font_ok);
  }
}

}  // namespace
}  // namespace luxgrid::report
