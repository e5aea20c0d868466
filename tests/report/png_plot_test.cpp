// The plots as files: what write_png writes decodes (with libpng's reader, independent of the
// writer's code path) to exactly the pixels drawn, the false-colour map puts each grid point's
// viridis colour in its cell, and the .npy arrays read back to the values written.
#include <gtest/gtest.h>
#include <png.h>
#include <unistd.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "geometry/surface_grid.h"
#include "report/colour_scale.h"
#include "report/false_colour.h"
#include "report/npy.h"
#include "report/png_file.h"
#include "report/raster.h"
#include "report/raster_text.h"
#include "report/surface_npy.h"
#include "report/viridis.h"
#include "util/error.h"

namespace luxgrid::report {
namespace {

namespace fs = std::filesystem;

struct Decoded {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;
  std::uint8_t at(int x, int y, int c) const { return rgb[(static_cast<std::size_t>(y) * width + x) * 3 + c]; }
};

Decoded decode(const fs::path& file) {
  png_image image;
  std::memset(&image, 0, sizeof image);
  image.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&image, file.c_str())) ADD_FAILURE() << image.message;
  Decoded d;
  EXPECT_EQ(image.format & PNG_FORMAT_FLAG_ALPHA, 0u) << "written as RGB, without alpha";
  image.format = PNG_FORMAT_RGB;
  d.width = static_cast<int>(image.width);
  d.height = static_cast<int>(image.height);
  d.rgb.resize(PNG_IMAGE_SIZE(image));
  if (!png_image_finish_read(&image, nullptr, d.rgb.data(), 0, nullptr)) ADD_FAILURE() << image.message;
  return d;
}

fs::path scratch() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const fs::path dir = fs::path(::testing::TempDir()) /
                       ("luxgrid_png_" + std::string(info->name()) + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::uint8_t byte(float v) { return static_cast<std::uint8_t>(std::lround(v * 255.f)); }

TEST(Png, DecodesToExactlyThePixelsDrawn) {
  // Lossless format: every byte must come back; a pattern with lines, boxes and a blend, so a
  // row-order, channel-order or stride mistake shows.
  Raster r(37, 23, {1, 1, 1});
  r.fill(2, 10, 3, 9, {1, 0, 0});
  r.line(0, 22, 36, 0, {0, 0.5f, 1});
  r.box(20, 5, 30, 15, {0, 0, 0}, false);
  r.blend(25, 10, {0, 0, 0}, 0.5f);
  const fs::path dir = scratch();
  write_png(r, dir / "p.png");
  const Decoded d = decode(dir / "p.png");
  ASSERT_EQ(d.width, 37);
  ASSERT_EQ(d.height, 23);
  EXPECT_EQ(d.rgb, r.pixels());
  EXPECT_EQ(d.at(5, 5, 0), 255);  // red square
  EXPECT_EQ(d.at(5, 5, 1), 0);
  EXPECT_EQ(d.at(25, 10, 0), 128);  // half black over white: 127.5 rounds to 128
  fs::remove_all(dir);
}

TEST(Png, UnwritablePathIsACalculationErrorNamingIt) {
  Raster r(4, 4, {0, 0, 0});
  const fs::path dir = scratch();
  const fs::path bad = dir / "missing-folder" / "p.png";
  try {
    write_png(r, bad);
    FAIL() << "no error";
  } catch (const CalculationError& e) {
    EXPECT_NE(std::string(e.what()).find(bad.string()), std::string::npos) << e.what();
  }
  fs::remove_all(dir);
}

TEST(Raster, LinesIncludeBothEndsAndBoxesTheirCorners) {
  Raster r(10, 10, {1, 1, 1});
  r.line(1, 1, 8, 4, {0, 0, 0});
  EXPECT_EQ(r.at(1, 1).r, 0.f);
  EXPECT_EQ(r.at(8, 4).r, 0.f);
  int dark = 0;
  for (int x = 0; x < 10; ++x)
    for (int y = 0; y < 10; ++y) dark += r.at(x, y).r == 0.f;
  EXPECT_EQ(dark, 8);  // an x-major Bresenham line has one pixel per column from 1 to 8
  Raster b(10, 10, {1, 1, 1});
  b.box(2, 2, 5, 6, {0, 0, 0}, false);
  EXPECT_EQ(b.at(2, 2).r, 0.f);
  EXPECT_EQ(b.at(5, 6).r, 0.f);
  EXPECT_EQ(b.at(3, 3).r, 1.f);  // outline only
  b.fill(-5, 100, 9, 100, {0, 0, 0});  // clipped, no crash
  EXPECT_EQ(b.at(0, 9).r, 0.f);
}

TEST(Viridis, EndsMatchMatplotlibAndLightnessRises) {
  // matplotlib's viridis table, first and last entries (6 decimals as published, hence 1e-5).
  const Rgb lo = viridis(0.0), hi = viridis(1.0);
  EXPECT_NEAR(lo.r, 0.267004, 1e-5);
  EXPECT_NEAR(lo.g, 0.004874, 1e-5);
  EXPECT_NEAR(lo.b, 0.329415, 1e-5);
  EXPECT_NEAR(hi.r, 0.993248, 1e-5);
  EXPECT_NEAR(hi.g, 0.906157, 1e-5);
  EXPECT_NEAR(hi.b, 0.143936, 1e-5);
  // Monotonic in lightness (Rec. 709 luma of the sRGB values) is why the plots use it.
  double previous = -1.0;
  for (int k = 0; k <= 256; ++k) {
    const Rgb c = viridis(k / 256.0);
    const double luma = 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b;
    EXPECT_GT(luma, previous) << k;
    previous = luma;
  }
}

TEST(FalseColour, EachCellHasItsPointsColourAndLeftOutPointsAreGrey) {
  calc::SurfaceResult s;
  s.grid = geometry::make_plane_grid("wp", {0, 0, 0.8}, {1, 0, 0}, {0, 1, 0}, 4.0, 2.0, 1.0);
  ASSERT_EQ(s.grid.nu, 4);
  ASSERT_EQ(s.grid.nv, 2);
  s.E = {0, 100, 200, 300, 400, 500, 600, 700};
  s.E_direct = s.E;
  s.E_indirect.assign(8, 0.0);
  s.grid.active[5] = false;
  s.stats.Emin = 0, s.stats.Emax = 700, s.stats.Eavg = 350;
  const ColourScale scale = fixed_scale(0, 700);
  PlotOverlay overlay;
  overlay.isolux = false;  // no lines across the cells' centres
  const fs::path dir = scratch();
  const std::string warning = write_false_colour_png(s, scale, dir / "wp.png", overlay);
  const Decoded d = decode(dir / "wp.png");
  // Layout of report/false_colour.cpp: 480 px for the longer side, so 120 px cells; margin 16,
  // title band 56, legend 150 wide; v up, so grid row 0 is the lower row of cells.
  constexpr int kCell = 120, kMargin = 16, kTitle = 56;
  ASSERT_EQ(d.width, kMargin + 4 * kCell + kMargin + 150);
  ASSERT_EQ(d.height, kTitle + 2 * kCell + kMargin);
  for (int j = 0; j < 2; ++j) {
    for (int i = 0; i < 4; ++i) {
      const int k = j * 4 + i;
      const int x = kMargin + i * kCell + kCell / 2, y = kTitle + (1 - j) * kCell + kCell / 2;
      const Rgb want = k == 5 ? Rgb{0.5f, 0.5f, 0.5f} : viridis(s.E[k] / 700.0);
      EXPECT_EQ(d.at(x, y, 0), byte(want.r)) << "cell " << k;
      EXPECT_EQ(d.at(x, y, 1), byte(want.g)) << "cell " << k;
      EXPECT_EQ(d.at(x, y, 2), byte(want.b)) << "cell " << k;
    }
  }
  EXPECT_EQ(d.at(2, 2, 0), 255);  // white frame
  // The title is drawn when the font is there (and a warning names the file otherwise).
  if (fs::exists(kPlotFont)) {
    EXPECT_EQ(warning, "");
    int dark = 0;
    for (int y = 0; y < 28; ++y)
      for (int x = kMargin; x < kMargin + 30; ++x) dark += d.at(x, y, 0) < 128;
    EXPECT_GT(dark, 10) << "the name 'wp' in 18 px type has more than 10 dark pixels";
  } else {
    EXPECT_NE(warning.find("wp.png"), std::string::npos);
  }
  fs::remove_all(dir);
}

TEST(Text, MissingFontDrawsNothingAndSaysSo) {
  Raster r(50, 20, {1, 1, 1});
  const std::vector<std::uint8_t> before = r.pixels();
  EXPECT_FALSE(draw_text(r, 2, 15, "abc", 14, "/nonexistent/font.ttf", {0, 0, 0}));
  EXPECT_EQ(r.pixels(), before);
}

// Reads a .npy v1.0 file the way numpy.load does: magic, version, header length, the dict.
TEST(Npy, HeaderAndValuesReadBack) {
  calc::SurfaceResult s;
  s.grid = geometry::make_plane_grid("seats", {0, 0, 1.2}, {1, 0, 0}, {0, 1, 0}, 1.0, 0.5, 0.5);
  s.E_direct = {100.0, 50.25};
  s.E_indirect = {1.0 / 3.0, 0.0};
  s.E = {80.0, -0.0};
  const std::string f = surface_npy(s);
  ASSERT_GT(f.size(), 10u);
  EXPECT_EQ(f.substr(0, 6), "\x93NUMPY");
  EXPECT_EQ(f[6], 1);
  EXPECT_EQ(f[7], 0);
  const std::size_t header_len = static_cast<unsigned char>(f[8]) | (static_cast<unsigned char>(f[9]) << 8);
  EXPECT_EQ((10 + header_len) % 64, 0u) << "data aligned to 64 bytes";
  const std::string dict = f.substr(10, header_len);
  EXPECT_EQ(dict.back(), '\n');
  EXPECT_EQ(dict.rfind("{'descr': '<f8', 'fortran_order': False, 'shape': (2, 6), }", 0), 0u) << dict;
  ASSERT_EQ(f.size(), 10 + header_len + 2 * 6 * 8);
  auto value = [&](std::size_t index) {
    std::uint64_t bits = 0;
    for (int k = 0; k < 8; ++k) bits |= std::uint64_t(static_cast<unsigned char>(f[10 + header_len + index * 8 + k])) << (8 * k);
    return std::bit_cast<double>(bits);
  };
  const double want[2][6] = {{0.25, 0.25, 1.2, 80.0, 100.0, 1.0 / 3.0}, {0.75, 0.25, 1.2, -0.0, 50.25, 0.0}};
  for (int row = 0; row < 2; ++row)
    for (int col = 0; col < 6; ++col) EXPECT_EQ(value(row * 6 + col), want[row][col]) << row << "," << col;  // bit-exact
  EXPECT_TRUE(std::signbit(value(9)));
}

TEST(Npy, OneDimensionalShapeHasTheTrailingComma) {
  const std::string h = npy_float64_header({7});
  EXPECT_NE(h.find("'shape': (7,), }"), std::string::npos) << h;
  EXPECT_EQ(h.size() % 64, 0u);
}

}  // namespace
}  // namespace luxgrid::report
