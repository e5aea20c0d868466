// The map's samples and colours must be the plots' own to the last byte, however they are found:
// per column and row (separable grids), per pixel, or as the plots found them before both, each
// pixel located with geometry::locate in every polygon and its stencil worked out alone. Checked
// on the grids where the three could part: region grids with obstacles (points left out, the
// footprints drawn), grids turned against the map, walls along and across the axes, a ceiling
// (v = -y), tilted planes, grids one point wide or high, a single point, and maps whose pixels
// fall far outside the grid or are only a pixel across.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "calc/statistics.h"
#include "geometry/surface_grid.h"
#include "geometry/workplane.h"
#include "report/colour_scale.h"
#include "report/map_frame.h"
#include "report/map_samples.h"
#include "report/raster.h"
#include "report/viridis.h"

namespace luxgrid::report {
namespace {

struct Case {
  std::string what;
  calc::SurfaceResult result;
  const calc::Scene* scene = nullptr;
  bool separable = true;
  double max_w_px = 560.0, max_h_px = 400.0;  // the map's largest size (the plots')
};

MapLayout layout_of(const Case& c) {
  return map_layout(c.result.grid, c.scene, c.max_w_px, c.max_h_px);
}

// Pixel (px, py) as the plots worked it out before the samples were made per row and column: its
// world point, its place on the grid, geometry::locate in each polygon, its own stencil.
Stencil reference(const Case& c, const MapLayout& l, const Field& field, int px, int py) {
  const auto& g = c.result.grid;
  const auto cut = cut_obstacles(l);
  const Vec3 w = (l.frame.origin + l.frame.right * ((px + 0.5) / l.ppm)) +
                 l.frame.up * ((l.map_h - py - 0.5) / l.ppm);
  const Vec3 rel = w - g.origin;
  const double u = glm::dot(rel, g.u_dir), v = glm::dot(rel, g.v_dir);
  auto inside = [&](const geometry::Polygon2& poly) {
    return geometry::locate(Vec2(w), poly, 0.0) != geometry::Location::outside;
  };
  bool in_region = u >= 0 && u <= g.size_u && v >= 0 && v <= g.size_v;
  if (in_region && !g.region.empty()) {
    in_region = false;
    for (const auto& poly : g.region) in_region = in_region || inside(poly);
  }
  Stencil st;
  if (!in_region) {
    st.kind = l.horizontal && l.frame.room && inside(l.frame.room->outline)
                  ? Stencil::Kind::not_calculated
                  : Stencil::Kind::outside_room;
    return st;
  }
  for (const auto* fp : cut)
    if (inside(*fp)) return st.kind = Stencil::Kind::obstacle, st;
  const double su = g.size_u / g.nu, sv = g.size_v / g.nv;
  st = field.stencil(u / su - 0.5, v / sv - 0.5, cut.empty());
  if (st.used == 0) st = Stencil{};  // no point: the fractions do not matter
  return st;
}

Rgb8 reference_colour(const Stencil& st, const Field& field, const std::vector<double>& E,
                      const ColourScale& scale) {
  switch (st.kind) {
    case Stencil::Kind::outside_room: return Raster::to_bytes({1, 1, 1});
    case Stencil::Kind::not_calculated: return Raster::to_bytes({0.93f, 0.93f, 0.93f});
    case Stencil::Kind::obstacle: break;
    case Stencil::Kind::sampled: {
      const double e = field.value(st, E);
      if (!std::isnan(e))
        return Raster::to_bytes(
            viridis(std::clamp((e - scale.min) / (scale.max - scale.min), 0.0, 1.0)));
    }
  }
  return Raster::to_bytes({0.72f, 0.72f, 0.72f});
}

calc::SurfaceResult with_values(const geometry::SurfaceGrid& g) {
  calc::SurfaceResult s;
  s.grid = g;
  for (size_t k = 0; k < g.points.size(); ++k) {
    const Vec3& p = g.points[k];
    s.E.push_back(200.0 + 150.0 * std::sin(1.3 * p.x + 0.7 * p.z) * std::cos(0.9 * p.y) +
                  static_cast<double>(k % 7));
  }
  s.E_direct = s.E;
  s.E_indirect.assign(s.E.size(), 0.0);
  s.stats = calc::compute_statistics(s.E, g.active);
  return s;
}

calc::Scene l_room_scene() {
  calc::Scene scene;
  calc::Room room;
  room.name = "L";
  room.outline = {{0, 0}, {8, 0}, {8, 4}, {4, 4}, {4, 8}, {0, 8}};
  room.height = 3.0;
  geometry::Obstacle cabinet;  // turned, and cutting the workplane
  cabinet.name = "cabinet";
  cabinet.footprint = {{1.0, 1.0}, {2.3, 1.75}, {1.8, 2.6}, {0.5, 1.87}};
  cabinet.z0 = 0.0, cabinet.z1 = 1.8;
  geometry::Obstacle table;  // below the workplane: its points stay
  table.name = "table";
  table.footprint = {{5.0, 1.0}, {7.0, 1.0}, {7.0, 2.5}, {5.0, 2.5}};
  table.z0 = 0.0, table.z1 = 0.7;
  room.obstacles = {cabinet, table};
  scene.rooms.push_back(room);
  return scene;
}

calc::Scene slanted_room_scene() {
  calc::Scene scene;
  calc::Room room;
  room.name = "S";
  room.outline = {{0, 0}, {6, 0}, {7.5, 3.3}, {0, 4}};  // walls 1 and 2 run across the axes
  room.height = 2.7;
  scene.rooms.push_back(room);
  return scene;
}

std::vector<Case> cases(const calc::Scene& l_room, const calc::Scene& slanted) {
  std::vector<Case> out;
  const auto& L = l_room.rooms[0];
  const auto region = geometry::inset_outline(L.outline, 0.5);
  // The L-shaped workplane: the cabinet's points left out, its footprint drawn.
  out.push_back({"L workplane",
                 with_values(geometry::make_region_grid("wp", region, 0.8, 0.25, L.obstacles)),
                 &l_room});
  // The same without the scene (no room, no footprints: left-out points drawn grey by the
  // nearest point), at a scale whose pixels are coarser than the grid.
  out.push_back({"L workplane without scene",
                 with_values(geometry::make_region_grid("wp", region, 0.8, 0.25, L.obstacles)),
                 nullptr, true, 26.0, 26.0});
  // A region of two polygons, every third point switched off by hand.
  {
    Case c{"two polygons, points off",
           with_values(geometry::make_region_grid(
               "two", {{{0.5, 0.5}, {3, 0.5}, {3, 3}, {0.5, 3}}, {{4, 4}, {7.5, 4.2}, {5, 7.5}}},
               0.8, 0.3, {})),
           &l_room};
    for (size_t k = 0; k < c.result.grid.active.size(); k += 3) c.result.grid.active[k] = false;
    out.push_back(c);
  }
  // The room's floor, ceiling (v = -y) and walls.
  geometry::RoomShape shape;
  shape.outline = L.outline, shape.height = L.height;
  for (const auto& g : geometry::make_room_surface_grids("L", shape, 0.4, L.obstacles))
    out.push_back({g.name, with_values(g), &l_room});
  // Walls across the axes: still separable (a wall's u is horizontal, the map's up vertical).
  geometry::RoomShape slanted_shape;
  slanted_shape.outline = slanted.rooms[0].outline, slanted_shape.height = 2.7;
  for (const auto& g : geometry::make_room_surface_grids("S", slanted_shape, 0.35, {}))
    out.push_back({g.name, with_values(g), &slanted});
  // A rectangle on the L room's plan: pixels off it but in the room, on either side of its edges.
  out.push_back({"desk in the L room",
                 with_values(geometry::make_plane_grid("desk", {1, 5, 0.75}, {1, 0, 0}, {0, 1, 0},
                                                       2.0, 1.2, 0.2)),
                 &l_room});
  // A workplane turned 30 degrees against the plan, in the L room: located per pixel.
  const double c30 = std::cos(0.5235987755982988), s30 = std::sin(0.5235987755982988);
  out.push_back({"turned plane",
                 with_values(geometry::make_plane_grid("turned", {2, 0.5, 0.8}, {c30, s30, 0},
                                                       {-s30, c30, 0}, 3.0, 2.0, 0.3)),
                 &l_room, false});
  // The same without a scene, at a scale finer than the plots'.
  out.push_back({"turned plane without scene",
                 with_values(geometry::make_plane_grid("turned", {2, 0.5, 0.8}, {c30, s30, 0},
                                                       {-s30, c30, 0}, 3.0, 2.0, 0.3)),
                 nullptr, false, 900.0, 900.0});
  // Tilted planes, drawn along their own u and v: one whose u runs along x (separable), one whose
  // u runs across the plan (u's and the map's up share components: per pixel).
  out.push_back({"tilted",
                 with_values(geometry::make_plane_grid("tilted", {0, 0, 1}, {1, 0, 0},
                                                       {0, 0.6, 0.8}, 2.0, 1.5, 0.2)),
                 nullptr});
  out.push_back(
      {"tilted and turned",
       with_values(geometry::make_plane_grid("tilted2", {0, 0, 1}, {c30, s30, 0},
                                             {-0.6 * s30, 0.6 * c30, 0.8}, 2.0, 1.5, 0.2)),
       nullptr, false});
  // Grids one point wide, one point high, and a single point; a map one pixel wide.
  out.push_back({"one point wide",
                 with_values(geometry::make_plane_grid("w1", {0, 0, 0.8}, {1, 0, 0}, {0, 1, 0}, 0.2,
                                                       3.0, 0.25)),
                 nullptr});
  out.push_back({"one point high",
                 with_values(geometry::make_plane_grid("h1", {0, 0, 0.8}, {1, 0, 0}, {0, 1, 0}, 3.0,
                                                       0.2, 0.25)),
                 nullptr});
  out.push_back({"one point",
                 with_values(geometry::make_plane_grid("p1", {1, 1, 0.8}, {1, 0, 0}, {0, 1, 0}, 0.2,
                                                       0.2, 0.25)),
                 nullptr});
  out.push_back({"one pixel",
                 with_values(geometry::make_plane_grid("px1", {0, 0, 0.8}, {1, 0, 0}, {0, 1, 0},
                                                       2.0, 1.0, 0.25)),
                 nullptr, true, 0.6, 0.3});
  return out;
}

TEST(MapSamples, EveryPixelAsThePlotsWorkedItOutBefore) {
  const calc::Scene l_room = l_room_scene(), slanted = slanted_room_scene();
  int separable = 0, per_pixel = 0;
  long sampled = 0, grey = 0, partial = 0;
  for (const Case& c : cases(l_room, slanted)) {
    SCOPED_TRACE(c.what);
    ASSERT_EQ(c.result.grid.kind, geometry::SurfaceGrid::Kind::grid);
    const MapLayout l = layout_of(c);
    const Field field(c.result);
    const auto cut = cut_obstacles(l);
    const MapSamples fast = make_map_samples(c.result, c.scene, l, cut, field);
    const MapSamples slow = make_map_samples(c.result, c.scene, l, cut, field, true);
    EXPECT_EQ(fast.separable, c.separable);
    EXPECT_FALSE(slow.separable);
    (fast.separable ? separable : per_pixel)++;
    const ColourScale scale = fit_scale(c.result.stats.Emin, c.result.stats.Emax);
    // Painted with a margin, as the plots do, and clipped at the far edges.
    Raster fast_map(l.map_w + 3, l.map_h + 2, {0, 0, 1}),
        slow_map(l.map_w + 3, l.map_h + 2, {0, 0, 1});
    paint_map(fast, field, c.result.E, scale, fast_map, 2, 1);
    paint_map(slow, field, c.result.E, scale, slow_map, 2, 1);
    for (int py = 0; py < l.map_h; ++py) {
      for (int px = 0; px < l.map_w; ++px) {
        const Stencil want = reference(c, l, field, px, py);
        for (const MapSamples* ms : {&fast, &slow}) {
          const Stencil got = ms->at(px, py, field.nu());
          ASSERT_EQ(got.kind, want.kind) << px << " " << py;
          ASSERT_EQ(got.used, want.used) << px << " " << py;
          ASSERT_EQ(got.k0, want.k0) << px << " " << py;
          ASSERT_EQ(got.tx, want.tx) << px << " " << py;
          ASSERT_EQ(got.ty, want.ty) << px << " " << py;
        }
        const Rgb8 colour = reference_colour(want, field, c.result.E, scale);
        for (const Raster* r : {&fast_map, &slow_map}) {
          const std::uint8_t* p = r->row(py + 1) + static_cast<size_t>(px + 2) * 3;
          ASSERT_EQ((Rgb8{p[0], p[1], p[2]}), colour) << px << " " << py;
        }
        sampled += want.kind == Stencil::Kind::sampled && want.used != 0;
        grey += want.kind != Stencil::Kind::sampled || want.used == 0;
        partial += want.kind == Stencil::Kind::sampled && want.used != 0 && want.used != 15;
      }
    }
    // The margin is the canvas's own.
    for (int px = 0; px < fast_map.width(); ++px)
      ASSERT_EQ(fast_map.pixels()[static_cast<size_t>(px) * 3 + 2], 255) << "top margin";
  }
  // The cases reached both kinds of samples and every kind of pixel.
  EXPECT_GE(separable, 10);
  EXPECT_GE(per_pixel, 3);
  EXPECT_GT(sampled, 100000);
  EXPECT_GT(grey, 10000);
  EXPECT_GT(partial, 1000) << "pixels interpolated from fewer than four points";
}

}  // namespace
}  // namespace luxgrid::report
