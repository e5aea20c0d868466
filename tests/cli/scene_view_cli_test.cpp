// The 3D view as a person sees it: report.html and `luxgrid view` rendered by headless Chromium
// with WebGL on SwiftShader, the screenshot read back: the legend's colours and coloured surfaces
// in the report's view, three rotated luminaires' photometric solids where their rotations aim,
// seen from above, and a click's value.
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

// Three 4 x 4 m rooms, 6 m high, side by side along x (from x = 0, 6 and 12 m), each with one
// Lambertian luminaire at its centre, 3 m up: turned -90 degrees about y (nadir to +x, east),
// turned 90 degrees about x (nadir to +y, north), not turned (straight down). A Lambertian solid
// is a sphere from the luminaire along its aim, 2 m across (a third of the rooms' height). Seen
// from above with north up, its pixels' centroid lies 1 m from the luminaire on the aim's side.
TEST(SceneViewChromium, ARotatedLuminairesSolidPointsWhereItsRotationAims) {
  REQUIRE_CHROMIUM();
  const fs::path dir = scratch("scene_view_aim");
  std::string rooms, luminaires;
  const char* rotation[3] = {"[0, -90, 0]", "[90, 0, 0]", "[0, 0, 0]"};
  for (int k = 0; k < 3; ++k) {
    const int x0 = 6 * k;
    const std::string n = std::to_string(k);
    rooms += std::string(k ? ", " : "") + "{ \"name\": \"r" + n + "\", \"outline\": [[" +
             std::to_string(x0) + ",0],[" + std::to_string(x0 + 4) + ",0],[" +
             std::to_string(x0 + 4) + ",4],[" + std::to_string(x0) + ",4]], \"height\": 6 }";
    luminaires += std::string(k ? ", " : "") + "{ \"photometry\": \"lb\", \"position\": [" +
                  std::to_string(x0 + 2) + ", 2, 3], \"rotation\": " + rotation[k] + " }";
  }
  luxgrid::test::write_file(dir / "p.json", R"({ "format": "luxgrid-project/1", "name": "aim",
  "photometry": { "lb": { "builtin": "lambertian", "intensity_cd": 1000 } },
  "rooms": [ )" + rooms + R"( ], "luminaires": [ )" +
                                                luminaires + R"( ],
  "surfaces": [ { "name": "floor", "workplane": { "room": "r0", "height": 0 }, "spacing": 1 } ] })");
  const auto view =
      luxgrid::test::luxgrid("view " + quote(dir / "p.json") + " -o " + quote(dir / "view.html"));
  ASSERT_EQ(view.code, 0) << view.output;
  const fs::path png = dir / "aim.png";
  screenshot("file://" + (dir / "view.html").string() + "#view=top&show=solids", png, 1000, 700);
  const Image img = read_png(png);
  ASSERT_EQ(img.width, 1000);
  // The camera (report/scene_view.js): above the centre of the rooms' box, (8, 2, 3), at 1.25
  // times the box's diagonal (16 x 4 x 6 m), north up, a 40 degree vertical field over the
  // canvas, which is the window's height less 2em (32 px). A point (x, y, z) is seen at
  // (500 + (x - 8) f / d, h / 2 - (y - 2) f / d), d its depth below the camera, f the focal length.
  const double canvas_h = 700.0 - 32.0;
  const double camera_z = 3.0 + 1.25 * std::sqrt(16.0 * 16.0 + 4.0 * 4.0 + 6.0 * 6.0);
  const double f = canvas_h / (2.0 * std::tan(20.0 * 3.14159265358979 / 180.0));
  // Each sphere's centre: 1 m from its luminaire along the aim.
  const double centre[3][3] = {{3, 2, 3}, {8, 3, 3}, {14, 2, 2}};
  struct Seen {
    double x = 0.0, y = 0.0;  // px
    long pixels = 0;
  } seen[3];
  for (int y = 0; y < static_cast<int>(canvas_h); ++y)
    for (int x = 0; x < img.width; ++x) {
      const auto c = img.at(x, y);
      if (!(c[0] > 200 && c[0] - c[2] > 60)) continue;  // the solid's translucent amber
      const int k = x < 375 ? 0 : x < 625 ? 1 : 2;      // the rooms' thirds of the picture
      seen[k].x += x + 0.5;
      seen[k].y += y + 0.5;
      ++seen[k].pixels;
    }
  // Within 6 px (about 0.15 m) of where the sphere's centre is seen: a wrong turn puts the
  // sphere a metre (about 40 px) or more away.
  for (int k = 0; k < 3; ++k) {
    ASSERT_GT(seen[k].pixels, 1500) << k;
    const double d = camera_z - centre[k][2];
    EXPECT_NEAR(seen[k].x / seen[k].pixels, 500.0 + (centre[k][0] - 8.0) * f / d, 6.0) << k;
    EXPECT_NEAR(seen[k].y / seen[k].pixels, canvas_h / 2.0 - (centre[k][1] - 2.0) * f / d, 6.0)
        << k;
  }
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
