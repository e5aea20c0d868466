// The 3D view as a person sees it: report.html and `luxgrid view` rendered by headless Chromium
// with WebGL on SwiftShader, the screenshot read back: the legend's colours and coloured surfaces
// in the report's view, and a rotated luminaire's photometric solid on the side its rotation
// aims at, seen from above.
#include <gtest/gtest.h>

#include <png.h>

#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>

#include <nlohmann/json.hpp>

#include "tests/cli/cli_support.h"
#include "util/format.h"

namespace scene_view_test {
namespace {

namespace fs = std::filesystem;
using luxgrid::test::quote;
using luxgrid::test::scratch;
using luxgrid::test::shell;

bool have_chromium() { return shell("command -v chromium").code == 0; }

// A screenshot of `url` at width x height, WebGL drawn by SwiftShader; returns Chromium's log.
std::string screenshot(const std::string& url, const fs::path& png, int width, int height) {
  const fs::path profile = png.string() + ".profile";
  const auto r = shell(
      "chromium --headless --no-sandbox --use-angle=swiftshader --enable-unsafe-swiftshader "
      "--no-first-run --disable-background-networking --disable-component-update --disable-sync "
      "--virtual-time-budget=20000 --user-data-dir=" +
      quote(profile) + " --window-size=" + std::to_string(width) + "," + std::to_string(height) +
      " --screenshot=" + quote(png) + " " + quote(url));
  fs::remove_all(profile);
  return r.output;
}
// The page's DOM after its scripts ran.
std::string dump_dom(const std::string& url, const fs::path& profile) {
  const auto r = shell(
      "chromium --headless --no-sandbox --use-angle=swiftshader --enable-unsafe-swiftshader "
      "--no-first-run --disable-background-networking --disable-component-update --disable-sync "
      "--virtual-time-budget=20000 --window-size=800,600 --user-data-dir=" +
      quote(profile) + " --dump-dom " + quote(url) + " 2>/dev/null");
  fs::remove_all(profile);
  return r.output;
}

struct Image {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;
  std::array<int, 3> at(int x, int y) const {
    const std::size_t i = 3 * (static_cast<std::size_t>(y) * width + x);
    return {rgb[i], rgb[i + 1], rgb[i + 2]};
  }
};
Image read_png(const fs::path& file) {
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  Image out;
  if (!png_image_begin_read_from_file(&image, file.c_str())) return out;
  image.format = PNG_FORMAT_RGB;
  out.width = static_cast<int>(image.width);
  out.height = static_cast<int>(image.height);
  out.rgb.resize(PNG_IMAGE_SIZE(image));
  if (!png_image_finish_read(&image, nullptr, out.rgb.data(), 0, nullptr)) out.width = 0;
  return out;
}

// The colour map's knots as the legend draws them (matplotlib's viridis at k / 16, in bytes,
// report/viridis.h).
constexpr std::array<std::array<int, 3>, 17> kViridis = {{
    {68, 1, 84},
    {72, 24, 106},
    {71, 45, 123},
    {66, 64, 134},
    {59, 82, 139},
    {51, 99, 141},
    {44, 114, 142},
    {38, 130, 142},
    {33, 145, 140},
    {31, 160, 136},
    {40, 174, 128},
    {63, 188, 115},
    {94, 201, 98},
    {132, 212, 75},
    {173, 220, 48},
    {216, 226, 25},
    {253, 231, 37},
}};
bool near(const std::array<int, 3>& a, const std::array<int, 3>& b, int tol) {
  return std::abs(a[0] - b[0]) <= tol && std::abs(a[1] - b[1]) <= tol &&
         std::abs(a[2] - b[2]) <= tol;
}

#define REQUIRE_CHROMIUM()                                                                    \
  if (!have_chromium()) {                                                                     \
    if (std::getenv("CI")) FAIL() << "chromium is required in CI (apt-get install chromium)"; \
    GTEST_SKIP() << "chromium not installed (apt-get install chromium)";                      \
  }

TEST(SceneViewChromium, TheReportsViewShowsTheLegendAndColouredSurfaces) {
  REQUIRE_CHROMIUM();
  const fs::path dir = scratch("scene_view_report");
  const auto calc = luxgrid::test::luxgrid(std::string("calc ") + LUXGRID_SOURCE_DIR +
                                           "/examples/office/project.json -o " +
                                           quote(dir / "office") + " --quality draft");
  ASSERT_EQ(calc.code, 0) << calc.output;
  const std::string url = "file://" + (dir / "office" / "report.html").string();
  // The view alone (#view=...), 1000 x 700: the canvas, the legend at the right edge.
  const fs::path png = dir / "office_view.png";
  const std::string log = screenshot(url + "#view=home", png, 1000, 700);
  const Image img = read_png(png);
  // The legend is drawn by the view's script: the script ran, three.js loaded.
  ASSERT_EQ(img.width, 1000) << log;
  // Every knot of the colour map is on the legend's bar (one byte of rounding per channel).
  int knots = 0;
  for (const auto& k : kViridis) {
    bool found = false;
    for (int y = 0; y < img.height && !found; ++y)
      for (int x = img.width * 85 / 100; x < img.width && !found; ++x)
        found = near(img.at(x, y), k, 2);
    knots += found;
  }
  EXPECT_GE(knots, 16) << "legend colours found: " << knots << " of 17";
  // The surfaces, left of the legend: a large part of the picture in the map's colours.
  long coloured = 0, all = 0;
  for (int y = 0; y < img.height; y += 2)
    for (int x = 0; x < img.width * 85 / 100; x += 2, ++all) {
      const auto c = img.at(x, y);
      // viridis has blue >= red at its dark end and green well above blue at its bright end; the
      // greys of the room and background have all three equal.
      const bool grey = std::abs(c[0] - c[1]) < 12 && std::abs(c[1] - c[2]) < 12;
      coloured += !grey && c[1] > c[0] - 40 && (c[2] > c[0] || c[1] > c[2] + 40);
    }
  EXPECT_GT(coloured, all / 5) << coloured << " of " << all << " pixels coloured";
}

// A 4 x 4 m room, 6 m high, one Lambertian luminaire at its centre (2, 2, 3) turned by
// `rotation`: its solid is a sphere of 2 m (a third of the height) from the luminaire along its
// aim. Seen from above (north up), the solid's pixels lie to the aim's side of the centre.
struct SolidCentroid {
  double dx = 0.0, dy = 0.0;  // px from the view's centre, +x right, +y up
  long pixels = 0;
};
SolidCentroid solid_seen_from_above(const std::string& rotation, const std::string& name) {
  const fs::path dir = scratch("scene_view_" + name);
  luxgrid::test::write_file(dir / "p.json", R"({
  "format": "luxgrid-project/1", "name": "aim",
  "photometry": { "lb": { "builtin": "lambertian", "intensity_cd": 1000 } },
  "rooms": [ { "name": "r", "outline": [[0,0],[4,0],[4,4],[0,4]], "height": 6 } ],
  "luminaires": [ { "photometry": "lb", "position": [2, 2, 3], "rotation": )" +
                                                rotation + R"( } ],
  "surfaces": [ { "name": "floor", "workplane": { "room": "r", "height": 0 }, "spacing": 1 } ] })");
  SolidCentroid out;
  const auto view =
      luxgrid::test::luxgrid("view " + quote(dir / "p.json") + " -o " + quote(dir / "view.html"));
  EXPECT_EQ(view.code, 0) << view.output;
  const fs::path png = dir / (name + ".png");
  // 800 x 600; the canvas takes the window less the 2em line below it.
  screenshot("file://" + (dir / "view.html").string() + "#view=top&show=solids", png, 800, 600);
  const Image img = read_png(png);
  EXPECT_EQ(img.width, 800);
  if (img.width != 800) return out;
  const double cx = 400.0, cy = (600.0 - 32.0) / 2.0;
  double sx = 0.0, sy = 0.0;
  for (int y = 0; y < 560; ++y)
    for (int x = 0; x < 800; ++x) {
      const auto c = img.at(x, y);
      if (c[0] > 200 && c[0] - c[2] > 60) {  // the solid's translucent amber
        sx += x - cx;
        sy += cy - y;
        ++out.pixels;
      }
    }
  if (out.pixels) out.dx = sx / out.pixels, out.dy = sy / out.pixels;
  return out;
}

TEST(SceneViewChromium, ARotatedLuminairesSolidPointsWhereItsRotationAims) {
  REQUIRE_CHROMIUM();
  // Turned -90 degrees about y, nadir (-z) goes to +x: east, to the right of the centre. About
  // 76 px a metre at this size: the centroid of the solid's pixels is about 1 m from the centre.
  const SolidCentroid east = solid_seen_from_above("[0, -90, 0]", "east");
  EXPECT_GT(east.pixels, 2000);
  EXPECT_GT(east.dx, 40.0);
  EXPECT_LT(std::abs(east.dy), 15.0);
  // Turned 90 degrees about x, nadir goes to +y: north, up in the picture.
  const SolidCentroid north = solid_seen_from_above("[90, 0, 0]", "north");
  EXPECT_GT(north.pixels, 2000);
  EXPECT_GT(north.dy, 40.0);
  EXPECT_LT(std::abs(north.dx), 15.0);
  // Not turned: straight down, seen from above a disc about the centre.
  const SolidCentroid down = solid_seen_from_above("[0, 0, 0]", "down");
  EXPECT_GT(down.pixels, 2000);
  EXPECT_LT(std::abs(down.dx), 15.0);
  EXPECT_LT(std::abs(down.dy), 15.0);
}

TEST(SceneViewChromium, AClickOnASurfaceGivesItsValue) {
  REQUIRE_CHROMIUM();
  // The Lambertian downlight of above over the floor grid of the 4 x 4 m room (points at 0.5,
  // 1.5, 2.5, 3.5 m): the centre of the view from above is the room's centre (2, 2), between four
  // points whose values are equal by symmetry, so the value there is theirs.
  const fs::path dir = scratch("scene_view_click");
  luxgrid::test::write_file(dir / "p.json", R"({
  "format": "luxgrid-project/1", "name": "click",
  "photometry": { "lb": { "builtin": "lambertian", "intensity_cd": 1000 } },
  "rooms": [ { "name": "r", "outline": [[0,0],[4,0],[4,4],[0,4]], "height": 6 } ],
  "luminaires": [ { "photometry": "lb", "position": [2, 2, 3] } ],
  "surfaces": [ { "name": "floor", "workplane": { "room": "r", "height": 0, "border": 0 },
                  "spacing": 1 } ] })");
  const auto calc = luxgrid::test::luxgrid("calc " + quote(dir / "p.json") + " -o " +
                                           quote(dir / "out") + " --quality draft");
  ASSERT_EQ(calc.code, 0) << calc.output;
  const auto results =
      nlohmann::json::parse(luxgrid::test::read_file(dir / "out" / "results.json"));
  const auto& floor = results["surfaces"][0];
  const auto& points = floor["points"];
  double e = -1.0;
  for (std::size_t i = 0; i < points.size(); ++i)
    if (points[i][0] == 1.5 && points[i][1] == 1.5) e = floor["E"][i];
  ASSERT_GT(e, 0.0);
  const std::string page = dump_dom(
      "file://" + (dir / "out" / "report.html").string() + "#view=top&show=surfaces&pick=0.5,0.5",
      dir / "profile");
  const std::string want = "floor: " + luxgrid::format_double("%.1f", e) + " lx at x 2.00, y 2.00";
  EXPECT_NE(page.find(want), std::string::npos)
      << want << "\n"
      << page.substr(0, std::min<std::size_t>(page.size(), 400));
}

}  // namespace
}  // namespace scene_view_test
