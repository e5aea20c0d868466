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
#include <fstream>
#include <iterator>
#include <random>
#include <string>
#include <vector>

#include "calc/statistics.h"
#include "geometry/surface_grid.h"
#include "geometry/workplane.h"
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
  std::uint8_t at(int x, int y, int c) const {
    return rgb[(static_cast<std::size_t>(y) * width + x) * 3 + c];
  }
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
  if (!png_image_finish_read(&image, nullptr, d.rgb.data(), 0, nullptr))
    ADD_FAILURE() << image.message;
  return d;
}

fs::path scratch() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const fs::path dir =
      fs::path(::testing::TempDir()) /
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

TEST(Png, NoiseSinglePixelsAndExtremeShapesDecodeExactly) {
  // The writer lays out the chunks itself: every byte must come back through libpng's reader
  // (which checks each chunk's CRC and the stream's Adler-32) for pictures that compress to
  // nothing, not at all (noise: stored blocks), a single pixel, a single row or column, and in
  // an order that makes each thread's kept buffers shrink and grow again.
  std::mt19937 rng(3);
  auto picture = [&](int w, int h, bool noise) {
    Raster r(w, h, {0.2f, 0.4f, 0.6f});
    if (noise)
      for (int y = 0; y < h; ++y)
        for (int k = 0; k < w * 3; ++k) r.row(y)[k] = static_cast<std::uint8_t>(rng());
    return r;
  };
  const fs::path dir = scratch();
  const std::pair<int, int> sizes[] = {{700, 500}, {1, 1},   {4000, 1},
                                       {1, 3000},  {37, 23}, {700, 500}};
  for (bool noise : {true, false}) {
    for (const auto& [w, h] : sizes) {
      const Raster r = picture(w, h, noise);
      write_png(r, dir / "p.png");
      const Decoded d = decode(dir / "p.png");
      ASSERT_EQ(d.width, w);
      ASSERT_EQ(d.height, h);
      ASSERT_EQ(d.rgb, r.pixels()) << w << " x " << h << (noise ? " noise" : "");
      // encode_png gives the file's bytes.
      std::ifstream in(dir / "p.png", std::ios::binary);
      const std::string file((std::istreambuf_iterator<char>(in)),
                             std::istreambuf_iterator<char>());
      ASSERT_EQ(encode_png(r), file);
    }
  }
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
  EXPECT_EQ(b.at(3, 3).r, 1.f);        // outline only
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

// Rec. 709 luma of a decoded pixel, 0..255: viridis rises monotonically in it.
double luma(const Decoded& d, int x, int y) {
  return 0.2126 * d.at(x, y, 0) + 0.7152 * d.at(x, y, 1) + 0.0722 * d.at(x, y, 2);
}

// A surface whose illuminance rises linearly towards one world corner (the bright corner), with
// the statistics the plot prints.
calc::SurfaceResult rising_towards(const geometry::SurfaceGrid& g, const Vec3& bright_corner) {
  calc::SurfaceResult s;
  s.grid = g;
  double far = 0.0;
  for (const Vec3& p : g.points) far = std::max(far, glm::length(p - bright_corner));
  for (const Vec3& p : g.points)
    s.E.push_back(100.0 + 400.0 * (1.0 - glm::length(p - bright_corner) / far));
  s.E_direct = s.E;
  s.E_indirect.assign(s.E.size(), 0.0);
  s.stats = calc::compute_statistics(s.E, s.grid.active);
  return s;
}

// Which quarter of the map is brightest: the mean luma over each quarter's inner part.
std::string brightest_quarter(const Decoded& d, const MapPixels& m) {
  double best = -1.0;
  std::string name;
  for (int qy = 0; qy < 2; ++qy) {
    for (int qx = 0; qx < 2; ++qx) {
      double sum = 0.0;
      int n = 0;
      for (int y = m.y0 + qy * m.height / 2 + m.height / 8;
           y < m.y0 + (qy + 1) * m.height / 2 - m.height / 8; ++y)
        for (int x = m.x0 + qx * m.width / 2 + m.width / 8;
             x < m.x0 + (qx + 1) * m.width / 2 - m.width / 8; ++x)
          sum += luma(d, x, y), ++n;
      if (n && sum / n > best)
        best = sum / n, name = std::string(qy ? "bottom" : "top") + (qx ? " right" : " left");
    }
  }
  return name;
}

calc::Scene office_scene() {
  calc::Scene scene;
  calc::Room room;
  room.name = "r";
  room.outline = {{0, 0}, {6, 0}, {6, 4}, {0, 4}};
  room.height = 3.0;
  scene.rooms.push_back(room);
  return scene;
}

TEST(FalseColour, FloorCeilingAndWallAreOrientedAsDocumented) {
  // The same world corner made bright on the floor, the ceiling and a wall. Floor and ceiling
  // are drawn as the plan (the ceiling as a reflected ceiling plan), so the bright corner
  // (6, 4) is top right on both, although the ceiling grid runs v = -y. Wall 0 (y = 0, from
  // (0,0) to (6,0)) is seen from inside the room: looking towards -y, +x is on the left, so its
  // bright corner (0, 0, 3) is top right.
  const calc::Scene scene = office_scene();
  geometry::RoomShape shape;
  shape.outline = scene.rooms[0].outline;
  shape.height = 3.0;
  const auto grids = geometry::make_room_surface_grids("r", shape, 0.5, {});
  ASSERT_EQ(grids[1].name, "r ceiling");
  ASSERT_LT(grids[1].v_dir.y, 0.0) << "the ceiling grid runs v = -y: the case this test is for";
  const struct {
    const geometry::SurfaceGrid& grid;
    Vec3 bright;
  } cases[] = {{grids[0], {6, 4, 0}}, {grids[1], {6, 4, 3}}, {grids[2], {0, 0, 3}}};
  const fs::path dir = scratch();
  for (const auto& c : cases) {
    const calc::SurfaceResult s = rising_towards(c.grid, c.bright);
    PlotOverlay overlay;
    overlay.scene = &scene;
    overlay.isolux = false;
    MapPixels m;
    write_false_colour_png(s, fit_scale(s.stats.Emin, s.stats.Emax), dir / "map.png", overlay, &m);
    const Decoded d = decode(dir / "map.png");
    EXPECT_EQ(brightest_quarter(d, m), "top right") << c.grid.name;
    // Drawn to scale: 6 m across, 4 m (floor, ceiling) or 3 m (wall) high, to the pixel.
    EXPECT_NEAR(m.width, 6.0 * m.px_per_m, 1.0) << c.grid.name;
    EXPECT_NEAR(m.height, (c.grid.name == "r wall 0" ? 3.0 : 4.0) * m.px_per_m, 1.0) << c.grid.name;
  }
  fs::remove_all(dir);
}

TEST(FalseColour, SmoothBetweenGridPointsNotBlocks) {
  // A 2 x 1 grid, 0 lx and 400 lx: bilinear interpolation makes the colour change across the
  // middle of the map in many steps; blocks would give exactly two colours.
  calc::SurfaceResult s;
  s.grid = geometry::make_plane_grid("wp", {0, 0, 0.8}, {1, 0, 0}, {0, 1, 0}, 4.0, 2.0, 2.0);
  ASSERT_EQ(s.grid.nu, 2);
  s.E = {0.0, 400.0};
  s.E_direct = s.E;
  s.E_indirect = {0, 0};
  s.stats = calc::compute_statistics(s.E, s.grid.active);
  PlotOverlay overlay;
  overlay.isolux = false;
  MapPixels m;
  const fs::path dir = scratch();
  write_false_colour_png(s, fixed_scale(0, 400), dir / "wp.png", overlay, &m);
  const Decoded d = decode(dir / "wp.png");
  const int y = m.y0 + m.height / 2;
  int distinct = 0;
  double previous = -1.0;
  for (int x = m.x0 + 1; x < m.x0 + m.width - 1; ++x) {
    const double l = luma(d, x, y);
    EXPECT_GE(l, previous - 1.0) << "rises monotonically left to right (1 of 255 for rounding), x "
                                 << x;
    distinct += std::abs(l - previous) > 0.0;
    previous = l;
  }
  EXPECT_GT(distinct, 50) << "a gradient, not two blocks";
  // Between the point centres (x = 1 m and 3 m) the value is linear: at 2 m it is 200 lx.
  const int xm = m.x0 + static_cast<int>(2.0 * m.px_per_m);
  const Rgb want = viridis(0.5);
  EXPECT_NEAR(d.at(xm, y, 0), byte(want.r), 3);  // 3 of 255: half a pixel of a 100 lx/m gradient
  EXPECT_NEAR(d.at(xm, y, 1), byte(want.g), 3);
  EXPECT_NEAR(d.at(xm, y, 2), byte(want.b), 3);
  fs::remove_all(dir);
}

TEST(FalseColour, LShapedWorkplaneKeepsItsShapeInsideTheRoomOutline) {
  // An L-shaped room and a workplane inset 0.5 m: the missing quarter stays white (outside the
  // room), the strip between workplane and walls light grey, the room's edge black.
  calc::Scene scene;
  calc::Room room;
  room.name = "L";
  room.outline = {{0, 0}, {8, 0}, {8, 4}, {4, 4}, {4, 8}, {0, 8}};
  room.height = 3.0;
  scene.rooms.push_back(room);
  const auto region = geometry::inset_outline(room.outline, 0.5);
  calc::SurfaceResult s;
  s.grid = geometry::make_region_grid("wp", region, 0.8, 0.25, {});
  ASSERT_FALSE(s.grid.region.empty());
  s.E.assign(s.grid.points.size(), 300.0);
  for (size_t k = 0; k < s.E.size(); ++k) s.E[k] += 10.0 * s.grid.points[k].x;
  s.E_direct = s.E;
  s.E_indirect.assign(s.E.size(), 0.0);
  s.stats = calc::compute_statistics(s.E, s.grid.active);
  PlotOverlay overlay;
  overlay.scene = &scene;
  MapPixels m;
  const fs::path dir = scratch();
  write_false_colour_png(s, fit_scale(s.stats.Emin, s.stats.Emax), dir / "wp.png", overlay, &m);
  const Decoded d = decode(dir / "wp.png");
  auto px = [&](double x, double y, int& ix, int& iy) {
    ix = m.x0 + static_cast<int>(x * m.px_per_m),
    iy = m.y0 + m.height - 1 - static_cast<int>(y * m.px_per_m);
  };
  int x, y;
  px(6.0, 6.0, x, y);  // the missing quarter
  EXPECT_EQ(d.at(x, y, 0), 255);
  EXPECT_EQ(d.at(x, y, 1), 255);
  EXPECT_EQ(d.at(x, y, 2), 255);
  px(0.25, 4.0, x, y);  // between the west wall and the workplane
  EXPECT_EQ(d.at(x, y, 0), d.at(x, y, 2)) << "grey";
  EXPECT_GT(d.at(x, y, 0), 200);
  EXPECT_LT(d.at(x, y, 0), 255);
  px(1.5, 2.0, x,
     y);  // on the workplane, off the isolux lines (300, 320, ... lx at x = 0, 2, ... m): viridis
  EXPECT_NE(d.at(x, y, 0), d.at(x, y, 2));
  px(2.0, 0.0, x, y);  // the south wall
  int dark = 0;
  for (int dy = -2; dy <= 2; ++dy) dark += d.at(x, y + dy, 0) < 40 && d.at(x, y + dy, 1) < 40;
  EXPECT_GE(dark, 2) << "the room outline is drawn 3 px wide in black";
  px(6.0, 4.0, x, y);  // the inner edge of the L
  dark = 0;
  for (int dy = -2; dy <= 2; ++dy) dark += d.at(x, y + dy, 0) < 40 && d.at(x, y + dy, 1) < 40;
  EXPECT_GE(dark, 2) << "the L's inner edge";
  fs::remove_all(dir);
}

TEST(FalseColour, SharedSamplesDrawTheSamePictureAsSamplesOfItsOwn) {
  // A surface's total, direct and reflected plots share one map_samples: each must be the file
  // the plot writes on its own. An L-shaped room with a cabinet cutting the workplane, so the
  // samples hold every kind of pixel: outside the room, off the surface, obstacle, interpolated.
  calc::Scene scene;
  calc::Room room;
  room.name = "L";
  room.outline = {{0, 0}, {8, 0}, {8, 4}, {4, 4}, {4, 8}, {0, 8}};
  room.height = 3.0;
  geometry::Obstacle cabinet;
  cabinet.name = "cabinet";
  cabinet.footprint = {{1.0, 1.0}, {2.3, 1.75}, {1.8, 2.6}, {0.5, 1.87}};
  cabinet.z0 = 0.0, cabinet.z1 = 1.8;
  room.obstacles.push_back(cabinet);
  scene.rooms.push_back(room);
  calc::SurfaceResult s;
  s.grid = geometry::make_region_grid("wp", geometry::inset_outline(room.outline, 0.5), 0.8, 0.25,
                                      {cabinet});
  s.E_direct.resize(s.grid.points.size()), s.E_indirect.resize(s.grid.points.size());
  for (size_t k = 0; k < s.grid.points.size(); ++k) {
    s.E_direct[k] = 300.0 + 40.0 * std::sin(s.grid.points[k].x) * s.grid.points[k].y;
    s.E_indirect[k] = 50.0 + 3.0 * s.grid.points[k].x;
    s.E.push_back(s.E_direct[k] + s.E_indirect[k]);
  }
  s.stats = calc::compute_statistics(s.E, s.grid.active);
  size_t active = 0;
  for (bool a : s.grid.active) active += a;
  ASSERT_LT(active, s.grid.points.size()) << "the cabinet and the L leave points out";
  PlotOverlay overlay;
  overlay.scene = &scene;
  const auto samples = map_samples(s, &scene);
  const fs::path dir = scratch();
  for (const std::vector<double>* E : {&s.E, &s.E_direct, &s.E_indirect}) {
    calc::SurfaceResult part = s;
    part.E = *E;
    part.stats = calc::compute_statistics(part.E, s.grid.active);
    const ColourScale scale = fit_scale(part.stats.Emin, part.stats.Emax);
    write_false_colour_png(part, scale, dir / "own.png", overlay);
    write_false_colour_png(part, scale, dir / "shared.png", overlay, nullptr, samples.get());
    const Decoded own = decode(dir / "own.png"), shared = decode(dir / "shared.png");
    EXPECT_EQ(own.rgb, shared.rgb);
  }
  // Samples made for other active points are not used: that picture is still its own.
  calc::SurfaceResult fewer = s;
  fewer.grid.active.assign(fewer.grid.active.size(), true);
  write_false_colour_png(fewer, fit_scale(s.stats.Emin, s.stats.Emax), dir / "own.png", overlay);
  write_false_colour_png(fewer, fit_scale(s.stats.Emin, s.stats.Emax), dir / "shared.png", overlay,
                         nullptr, samples.get());
  EXPECT_EQ(decode(dir / "own.png").rgb, decode(dir / "shared.png").rgb);
  fs::remove_all(dir);
}

TEST(FalseColour, TheRequiredValueGetsItsIsoluxLine) {
  // E rises from 400 to 600 lx across x; on a 0..1000 scale no tick lies strictly inside the
  // data, so the only line is the requirement's: 500 lx at the middle of the map, white (the dark
  // half of the scale). Without the requirement that column has no white.
  calc::SurfaceResult s;
  s.grid = geometry::make_plane_grid("wp", {0, 0, 0.8}, {1, 0, 0}, {0, 1, 0}, 4.0, 4.0, 0.5);
  for (const Vec3& p : s.grid.points) s.E.push_back(400.0 + 200.0 * (p.x - 0.25) / 3.5);
  s.E_direct = s.E;
  s.E_indirect.assign(s.E.size(), 0.0);
  s.stats = calc::compute_statistics(s.E, s.grid.active);
  const fs::path dir = scratch();
  auto white_rows_near_middle = [&](const std::vector<double>& required) {
    PlotOverlay overlay;
    overlay.required_lx = required;
    MapPixels m;
    write_false_colour_png(s, fixed_scale(0, 1000), dir / "wp.png", overlay, &m);
    const Decoded d = decode(dir / "wp.png");
    const int xc = m.x0 + m.width / 2;
    int rows = 0;
    for (int y = m.y0 + 2; y < m.y0 + m.height - 2; ++y) {
      bool white = false;
      for (int x = xc - 3; x <= xc + 3; ++x)
        white = white || (d.at(x, y, 0) == 255 && d.at(x, y, 1) == 255 && d.at(x, y, 2) == 255);
      rows += white;
    }
    return std::pair<int, int>(rows, m.height - 4);
  };
  const auto [with, total] = white_rows_near_middle({500.0});
  EXPECT_GT(with, total * 9 / 10) << "the 500 lx line runs the full height (a label may sit on it)";
  EXPECT_EQ(white_rows_near_middle({}).first, 0);
  fs::remove_all(dir);
}

TEST(ColourScale, FittedToTheDataWithRoundLimits) {
  // The example from the office's ceiling: 534-622 lx gets 525-625, not 0-1000.
  const ColourScale s = fit_scale(534.0, 622.0);
  EXPECT_DOUBLE_EQ(s.min, 525.0);
  EXPECT_DOUBLE_EQ(s.max, 625.0);
  ASSERT_FALSE(s.ticks.empty());
  EXPECT_DOUBLE_EQ(s.ticks.front(), 525.0);
  EXPECT_DOUBLE_EQ(s.ticks.back(), 625.0);
  // Properties over many ranges: the data inside, 3 to 8 round steps, at most twice the data's
  // range plus one step (so the colours use most of the scale).
  for (double lo : {0.0, 0.3, 12.0, 95.0, 480.0, 1234.0}) {
    for (double width : {0.5, 7.0, 60.0, 333.0, 2500.0}) {
      const ColourScale f = fit_scale(lo, lo + width);
      EXPECT_LE(f.min, lo);
      EXPECT_GE(f.max, lo + width);
      ASSERT_GE(f.ticks.size(), 4u) << lo << " " << width;
      const double step = f.ticks[1] - f.ticks[0];
      EXPECT_NEAR(nice_ceil(step), step, 1e-9 * step) << "a round step";
      EXPECT_LE(f.max - f.min, 2.0 * width + step + 1e-9) << lo << " " << width;
    }
  }
  EXPECT_DOUBLE_EQ(fit_scale(0.0, 0.0).max, 1.0);  // all dark
  const ColourScale flat = fit_scale(500.0, 500.0);
  EXPECT_LT(flat.min, 500.0);
  EXPECT_GT(flat.max, 500.0);
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
  const std::size_t header_len =
      static_cast<unsigned char>(f[8]) | (static_cast<unsigned char>(f[9]) << 8);
  EXPECT_EQ((10 + header_len) % 64, 0u) << "data aligned to 64 bytes";
  const std::string dict = f.substr(10, header_len);
  EXPECT_EQ(dict.back(), '\n');
  EXPECT_EQ(dict.rfind("{'descr': '<f8', 'fortran_order': False, 'shape': (2, 6), }", 0), 0u)
      << dict;
  ASSERT_EQ(f.size(), 10 + header_len + 2 * 6 * 8);
  auto value = [&](std::size_t index) {
    std::uint64_t bits = 0;
    for (int k = 0; k < 8; ++k)
      bits |= std::uint64_t(static_cast<unsigned char>(f[10 + header_len + index * 8 + k]))
              << (8 * k);
    return std::bit_cast<double>(bits);
  };
  const double want[2][6] = {{0.25, 0.25, 1.2, 80.0, 100.0, 1.0 / 3.0},
                             {0.75, 0.25, 1.2, -0.0, 50.25, 0.0}};
  for (int row = 0; row < 2; ++row)
    for (int col = 0; col < 6; ++col)
      EXPECT_EQ(value(row * 6 + col), want[row][col]) << row << "," << col;  // bit-exact
  EXPECT_TRUE(std::signbit(value(9)));
}

TEST(Npy, OneDimensionalShapeHasTheTrailingComma) {
  const std::string h = npy_float64_header({7});
  EXPECT_NE(h.find("'shape': (7,), }"), std::string::npos) << h;
  EXPECT_EQ(h.size() % 64, 0u);
}

}  // namespace
}  // namespace luxgrid::report
