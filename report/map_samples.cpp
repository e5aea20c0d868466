#include "report/map_samples.h"

#include <algorithm>
#include <cmath>

#include "geometry/row_locate.h"
#include "report/viridis.h"
#include "util/error.h"

namespace luxgrid::report {

namespace {

const Rgb kOutsideRoom{1, 1, 1};
const Rgb kNotCalculated{0.93f, 0.93f, 0.93f};  // inside the room, outside the surface
const Rgb kObstacle{0.72f, 0.72f, 0.72f};       // points left out inside the surface

// std::lround of a coordinate >= 0 (halves away from zero) without the call into libm: x - k is
// exact for k = trunc(x), so the comparison decides as lround does (NaN: 0, as lround's result
// cast to int was).
int round_index(double x) {
  if (!(x >= 0.0)) return 0;
  const int k = static_cast<int>(x);
  return x - k >= 0.5 ? k + 1 : k;
}

std::uint8_t code_of(const Stencil& st) {
  return static_cast<std::uint8_t>(static_cast<unsigned>(st.kind) | (st.used << 2));
}

}  // namespace

Field::Field(const calc::SurfaceResult& r)
    : E_(r.E), nu_(std::max(1, r.grid.nu)), nv_(std::max(1, r.grid.nv)) {
  on_.resize(static_cast<size_t>(nu_) * nv_);
  for (size_t k = 0; k < on_.size(); ++k)
    on_[k] = k < E_.size() && (k >= r.grid.active.size() || r.grid.active[k]);
}

AxisStencil Field::axis(double f, int n) {
  f = std::clamp(f, 0.0, n - 1.0);
  AxisStencil a;
  a.nearest = round_index(f);
  a.first = std::min(static_cast<int>(f), std::max(n - 2, 0));
  a.t = n > 1 ? f - a.first : 0.0;
  return a;
}

MapLayout map_layout(const geometry::SurfaceGrid& g, const calc::Scene* scene, double max_w_px,
                     double max_h_px) {
  MapLayout l;
  l.frame = map_frame(g, scene);
  l.horizontal = l.frame.view == MapFrame::View::plan || l.frame.view == MapFrame::View::ceiling;
  l.ppm = std::min(max_w_px / l.frame.width_m, max_h_px / l.frame.height_m);
  l.map_w = std::max(1, static_cast<int>(std::lround(l.frame.width_m * l.ppm)));
  l.map_h = std::max(1, static_cast<int>(std::lround(l.frame.height_m * l.ppm)));
  return l;
}

std::vector<const geometry::Polygon2*> cut_obstacles(const MapLayout& l) {
  std::vector<const geometry::Polygon2*> cut;
  if (l.horizontal && l.frame.room)
    for (const auto& o : l.frame.room->obstacles)
      if (o.z0 <= l.frame.origin.z && l.frame.origin.z <= o.z1) cut.push_back(&o.footprint);
  return cut;
}

Stencil MapSamples::at(int px, int py, int nu) const {
  const std::size_t k = static_cast<std::size_t>(py) * map_w + px;
  Stencil st;
  st.kind = static_cast<Stencil::Kind>(code[k] & 3u);
  st.used = static_cast<std::uint8_t>(code[k] >> 2);
  if (st.used == 0) return st;  // no point: the fractions do not matter
  if (separable) {
    const AxisStencil &c = columns[px], &r = rows[py];
    st.tx = c.t, st.ty = r.t;
    st.k0 = static_cast<std::uint32_t>(static_cast<std::size_t>(r.first) * nu + c.first);
  } else {
    st.tx = pixels[k].tx, st.ty = pixels[k].ty, st.k0 = pixels[k].k0;
  }
  return st;
}

MapSamples make_map_samples(const calc::SurfaceResult& r, const calc::Scene* scene,
                            const MapLayout& layout,
                            const std::vector<const geometry::Polygon2*>& cut_obstacles,
                            const Field& field, bool per_pixel) {
  const auto& g = r.grid;
  const MapFrame& frame = layout.frame;
  const double ppm = layout.ppm;
  const int map_w = layout.map_w, map_h = layout.map_h;
  MapSamples ms;
  ms.scene = scene, ms.map_w = map_w, ms.map_h = map_h;
  ms.points = r.E.size(), ms.active = g.active;
  ms.code.resize(static_cast<size_t>(map_w) * map_h);
  const double su = g.nu > 0 ? g.size_u / g.nu : 1.0,
               sv = g.nv > 0 ? g.size_v / g.nv : 1.0;  // cell size, m
  const bool nearest_must_be_on = cut_obstacles.empty();
  // Each polygon's point location is prepared once per row (geometry/row_locate.h), the same
  // answers as geometry::locate for a fraction of the cost.
  const bool room_shown = layout.horizontal && frame.room;
  std::vector<geometry::RowLocator> room, region, obstacles;
  if (room_shown) room.emplace_back(frame.room->outline, 0.0);
  for (const auto& poly : g.region) region.emplace_back(poly, 0.0);
  for (const auto* fp : cut_obstacles) obstacles.emplace_back(*fp, 0.0);
  // A pixel's world point, frame_point(frame, a, b) = (origin + right a) + up b: its first sum
  // depends on the column only and its last term on the row only, so each is made once, the
  // same doubles.
  std::vector<Vec3> along_row(static_cast<size_t>(map_w));
  for (int px = 0; px < map_w; ++px)
    along_row[px] = frame.origin + frame.right * ((px + 0.5) / ppm);
  auto up_of_row = [&](int py) { return frame.up * ((map_h - py - 0.5) / ppm); };
  auto grid_uv = [&](const Vec3& w, double& u, double& v) {
    const Vec3 rel = w - g.origin;
    u = glm::dot(rel, g.u_dir), v = glm::dot(rel, g.v_dir);
  };
  // u = dot(w - origin, u_dir) does not depend on the row when every component that u_dir
  // weighs is one the map's up leaves alone (up's part of w is then exactly 0 there, and the
  // other components' products are zeros), and v not on the column in the same way: then
  // pixel (px, 0)'s u holds for its whole column and pixel (0, py)'s v for its whole row (up to
  // the sign of a zero, which u >= 0 and u / su - 0.5 do not see).
  bool separable = !per_pixel;
  for (int c = 0; c < 3; ++c)
    separable = separable && (g.u_dir[c] == 0.0 || frame.up[c] == 0.0) &&
                (g.v_dir[c] == 0.0 || frame.right[c] == 0.0);
  std::vector<unsigned char> u_inside, v_inside;  // separable: 0 <= u <= size_u, per column
  // Separable: which of a pixel's weights (Stencil::weight(tx, ty, di, dj), bit 2 dj + di) are
  // positive, from which of its factors are, per column (1 - tx, tx) and per row (1 - ty, ty).
  // The factors are >= 0, and rounded multiplication is monotone: when the smallest positive
  // factors along u and v have a positive product, so has every pair of positive factors, and a
  // weight is positive exactly when both its factors are. Else (an underflow, which the map's
  // fractions of 2^-54 and more never reach) the pixels are worked out one by one.
  std::vector<std::uint8_t> column_mask, row_mask;
  if (separable) {
    ms.columns.resize(static_cast<size_t>(map_w)), ms.rows.resize(static_cast<size_t>(map_h));
    u_inside.resize(ms.columns.size()), v_inside.resize(ms.rows.size());
    column_mask.resize(ms.columns.size()), row_mask.resize(ms.rows.size());
    double smallest_u = INFINITY, smallest_v = INFINITY;
    auto factor_mask = [](double t, std::uint8_t first, std::uint8_t second, double& smallest) {
      for (double f : {1 - t, t})
        if (f > 0.0) smallest = std::min(smallest, f);
      return static_cast<std::uint8_t>((1 - t > 0.0 ? first : 0) | (t > 0.0 ? second : 0));
    };
    for (int px = 0; px < map_w; ++px) {
      double u, v;
      grid_uv(along_row[px] + up_of_row(0), u, v);
      u_inside[px] = u >= 0 && u <= g.size_u;
      ms.columns[px] = Field::axis(u / su - 0.5, field.nu());
      column_mask[px] = factor_mask(ms.columns[px].t, 0b0101, 0b1010, smallest_u);
    }
    for (int py = 0; py < map_h; ++py) {
      double u, v;
      grid_uv(along_row[0] + up_of_row(py), u, v);
      v_inside[py] = v >= 0 && v <= g.size_v;
      ms.rows[py] = Field::axis(v / sv - 0.5, field.nv());
      row_mask[py] = factor_mask(ms.rows[py].t, 0b0011, 0b1100, smallest_v);
    }
    if (!(smallest_u * smallest_v > 0.0)) separable = false, ms.columns.clear(), ms.rows.clear();
  }
  ms.separable = separable;
  if (!separable) ms.pixels.resize(ms.code.size());

  // Per row: each pixel's world x (the locators' answers for the row at once when every pixel
  // lies on the row's y, as on plans), then which polygons it lies in (the bits below), then what
  // it shows.
  constexpr unsigned kInRegion = 1, kInRoom = 2, kInObstacle = 4;
  std::vector<double> xs(static_cast<size_t>(map_w));
  std::vector<geometry::Location> where(xs.size());
  std::vector<std::uint8_t> in(xs.size());
  // Separable: per row, each grid column's points (as Stencil::used's bits) and its point
  // nearest to the row that are on.
  std::vector<std::uint8_t> cell_on(static_cast<size_t>(field.nu())),
      nearest_on(static_cast<size_t>(field.nu()));
  // Separable: the map's columns in runs that take the same from their column (in u's range,
  // first and nearest point along u, positive factors), so that within a run and a row a pixel's
  // code depends only on the polygons it lies in.
  std::vector<int> run_end;
  for (int px = 1; separable && px <= map_w; ++px) {
    const AxisStencil &a = ms.columns[px - 1], &b = ms.columns[std::min(px, map_w - 1)];
    if (px == map_w || u_inside[px] != u_inside[px - 1] || a.first != b.first ||
        a.nearest != b.nearest || column_mask[px] != column_mask[px - 1])
      run_end.push_back(px);
  }
  for (int py = 0; py < map_h; ++py) {
    const Vec3 up_row = up_of_row(py);
    const double row_y = frame_point(frame, 0.5 / ppm, (map_h - py - 0.5) / ppm).y;
    std::fill(in.begin(), in.end(), region.empty() ? kInRegion : 0u);
    if (room_shown || !region.empty() || !obstacles.empty()) {
      bool on_row = true;
      for (int px = 0; px < map_w; ++px) {
        const Vec3 w = along_row[px] + up_row;
        xs[px] = w.x, on_row = on_row && w.y == row_y;
      }
      // Whether each pixel lies in any of the polygons (boundary included).
      auto mark = [&](std::vector<geometry::RowLocator>& set, unsigned bit) {
        for (auto& l : set) {
          l.set_row(row_y);
          if (on_row) {
            l.locate_row(xs, where);
          } else {
            for (int px = 0; px < map_w; ++px) where[px] = l.locate(Vec2(along_row[px] + up_row));
          }
          for (int px = 0; px < map_w; ++px)
            if (where[px] != geometry::Location::outside) in[px] |= bit;
        }
      };
      mark(region, kInRegion), mark(room, kInRoom), mark(obstacles, kInObstacle);
    }
    // Inside the surface: its colour, or obstacle grey; outside it: the room's light grey or
    // white.
    auto kind_of = [&](unsigned polygons, bool in_rect) {
      if (!(in_rect && (polygons & kInRegion)))
        return room_shown && (polygons & kInRoom) ? Stencil::Kind::not_calculated
                                                  : Stencil::Kind::outside_room;
      return polygons & kInObstacle ? Stencil::Kind::obstacle : Stencil::Kind::sampled;
    };
    std::uint8_t* code = ms.code.data() + static_cast<size_t>(py) * map_w;
    if (separable) {
      for (int i = 0; i < field.nu(); ++i) {
        cell_on[i] = field.cell_on(i, ms.rows[py].first);
        nearest_on[i] = field.on(i, ms.rows[py].nearest);
      }
      auto code_at = [&](int px, unsigned polygons) {
        Stencil st;
        st.kind = kind_of(polygons, u_inside[px] && v_inside[py]);
        if (st.kind == Stencil::Kind::sampled &&
            (!nearest_must_be_on || nearest_on[ms.columns[px].nearest]))
          st.used = cell_on[ms.columns[px].first] & column_mask[px] & row_mask[py];
        return code_of(st);
      };
      // Each run's codes by the polygons a pixel lies in, worked out at the first such pixel
      // (0xFF: not yet; a code is below 64).
      int px = 0;
      for (int end : run_end) {
        std::uint8_t by_polygons[8] = {0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF};
        for (; px < end; ++px) {
          std::uint8_t& c = by_polygons[in[px]];
          if (c == 0xFF) c = code_at(px, in[px]);
          code[px] = c;
        }
      }
    } else {
      for (int px = 0; px < map_w; ++px) {
        double u, v;
        grid_uv(along_row[px] + up_row, u, v);
        Stencil st;
        st.kind = kind_of(in[px], u >= 0 && u <= g.size_u && v >= 0 && v <= g.size_v);
        if (st.kind == Stencil::Kind::sampled)
          st = field.stencil(u / su - 0.5, v / sv - 0.5, nearest_must_be_on);
        code[px] = code_of(st);
        ms.pixels[static_cast<size_t>(py) * map_w + px] = st;
      }
    }
  }
  return ms;
}

namespace {

// The map's pixels, [px0, px1) of rows [py0, py1), each as its code says; a sampled pixel's
// value is `values.row(py)`'s (px, used).
template <class Values>
void paint_rows(const MapSamples& ms, const ColourScale& scale, Raster& canvas, int x0, int y0,
                int px0, int px1, int py0, int py1, const Values& values) {
  const Rgb8 fixed[3] = {Raster::to_bytes(kOutsideRoom), Raster::to_bytes(kNotCalculated),
                         Raster::to_bytes(kObstacle)};
  const double span = scale.max - scale.min;
  const ViridisBytes& viridis_bytes = ViridisBytes::get();
  for (int py = py0; py < py1; ++py) {
    std::uint8_t* out = canvas.row(y0 + py) + static_cast<std::size_t>(x0 + px0) * 3;
    const std::uint8_t* code = ms.code.data() + static_cast<std::size_t>(py) * ms.map_w;
    const auto value = values.row(py);
    for (int px = px0; px < px1; ++px, out += 3) {
      const unsigned kind = code[px] & 3u;
      Rgb8 c;
      if (kind != static_cast<unsigned>(Stencil::Kind::sampled)) {
        c = fixed[kind];
      } else {
        const double e = value(px, code[px] >> 2);
        c = std::isnan(e) ? fixed[static_cast<int>(Stencil::Kind::obstacle)]
                          : viridis_bytes(std::clamp((e - scale.min) / span, 0.0, 1.0));
      }
      out[0] = c.r, out[1] = c.g, out[2] = c.b;
    }
  }
}

// Separable samples: the weights' factors (1 - tx, tx) and first points per column, made once.
struct SeparableValues {
  const MapSamples& ms;
  const Field& field;
  const std::vector<double>& E;
  std::vector<double> u0, u1;
  std::vector<std::size_t> first;

  SeparableValues(const MapSamples& samples, const Field& f, const std::vector<double>& values)
      : ms(samples), field(f), E(values) {
    for (const AxisStencil& c : ms.columns)
      u0.push_back(1 - c.t), u1.push_back(c.t), first.push_back(static_cast<std::size_t>(c.first));
  }
  auto row(int py) const {
    const AxisStencil& r = ms.rows[py];
    const double v0 = 1 - r.t, v1 = r.t;
    const std::size_t base = static_cast<std::size_t>(r.first) * field.nu();
    return [this, v0, v1, base](int px, unsigned used) {
      return field.value(u0[px], u1[px], v0, v1, base + first[px], used, E);
    };
  }
};

struct PerPixelValues {
  const MapSamples& ms;
  const Field& field;
  const std::vector<double>& E;
  auto row(int py) const {
    const Stencil* pixels = ms.pixels.data() + static_cast<std::size_t>(py) * ms.map_w;
    return [this, pixels](int px, unsigned) { return field.value(pixels[px], E); };
  }
};

}  // namespace

void paint_map(const MapSamples& ms, const Field& field, const std::vector<double>& E,
               const ColourScale& scale, Raster& canvas, int x0, int y0) {
  // Clipped to the canvas (the plots make it large enough for the map).
  const int px0 = std::max(0, -x0), px1 = std::min(ms.map_w, canvas.width() - x0);
  const int py0 = std::max(0, -y0), py1 = std::min(ms.map_h, canvas.height() - y0);
  if (px0 >= px1 || py0 >= py1) return;
  if (ms.separable)
    paint_rows(ms, scale, canvas, x0, y0, px0, px1, py0, py1, SeparableValues(ms, field, E));
  else
    paint_rows(ms, scale, canvas, x0, y0, px0, px1, py0, py1, PerPixelValues{ms, field, E});
}

}  // namespace luxgrid::report
