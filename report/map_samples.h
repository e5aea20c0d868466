#pragma once
// What each pixel of a grid's false-colour map shows, and its colour (report/false_colour.h draws
// the rest of the plot around it). A pixel shows white outside the room, light grey inside the
// room but off the surface, mid grey on an obstacle or where no active point is near, else the
// viridis colour of the grid's illuminance interpolated bilinearly at the pixel's centre.
//
// What a pixel shows depends on the grid, the scene and the map's size, not on the values, so
// it is worked out once (MapSamples) for the total and the direct and reflected plots of a grid.
// A map has about 10^5 pixels: where the grid's u runs along the map's columns and v along its
// rows (the plans and walls of rooms whose edges follow the axes), the interpolation's points
// and fractions are worked out once per column and once per row, and each pixel keeps one byte;
// elsewhere (a grid turned against the map) each pixel keeps its own. Both give every pixel the
// same doubles (make_map_samples' per_pixel mode is the check).
#include <cstdint>
#include <vector>

#include "calc/results.h"
#include "calc/scene.h"
#include "geometry/polygon.h"
#include "report/colour_scale.h"
#include "report/map_frame.h"
#include "report/raster.h"

namespace luxgrid::report {

// Which grid points a sample of the map is interpolated from, and how, or what else the pixel
// shows.
struct Stencil {
  enum class Kind : std::uint8_t { outside_room, not_calculated, obstacle, sampled };
  double tx = 0.0, ty = 0.0;  // bilinear weights' fractions along i and j
  std::uint32_t k0 = 0;       // index of point (i0, j0)
  Kind kind = Kind::sampled;
  std::uint8_t used = 0;  // bit 2 dj + di: point (i0 + di, j0 + dj) has weight and a value
  static double weight(double tx, double ty, int di, int dj) {
    return (di ? tx : 1 - tx) * (dj ? ty : 1 - ty);
  }
};

// Where a sample lies along one of the grid's axes, at fractional index coordinate f (point i
// at f = i): the first of its two points, its fraction towards the second and its nearest point.
struct AxisStencil {
  int first = 0, nearest = 0;
  double t = 0.0;
};

// The grid's value at fractional index coordinates (fi, fj) (point (i, j) at fi = i, fj = j):
// bilinear between the four surrounding points, over the active ones only; NaN where none of
// them is active or (by default) the nearest is not. In two steps: which points with which
// weights (the Stencil, the same for every plot of one grid), then the value from the
// illuminances.
class Field {
 public:
  // Whether each point counts is looked up once here, not at each of a plot's 10^5 samples.
  explicit Field(const calc::SurfaceResult& r);

  int nu() const { return nu_; }
  int nv() const { return nv_; }
  // Point (i, j) has a value and is active.
  bool on(int i, int j) const { return on_[static_cast<std::size_t>(j) * nu_ + i]; }
  // Which of the points (i, j), (i + 1, j), (i, j + 1), (i + 1, j + 1) are on, as the bits of
  // Stencil::used (those beyond the grid's edge off).
  std::uint8_t cell_on(int i, int j) const {
    auto bit = [&](int di, int dj) {
      return i + di < nu_ && j + dj < nv_ && on(i + di, j + dj) ? 1u << (2 * dj + di) : 0u;
    };
    return static_cast<std::uint8_t>(bit(0, 0) | bit(1, 0) | bit(0, 1) | bit(1, 1));
  }

  // The sample's place along the u (n = nu()) or v (n = nv()) axis.
  static AxisStencil axis(double f, int n);
  // `nearest_must_be_on`: NaN where the nearest point is left out (the left-out cell is drawn
  // grey); false when the caller draws the obstacles' real footprints instead.
  Stencil stencil(const AxisStencil& along_u, const AxisStencil& along_v,
                  bool nearest_must_be_on = true) const {
    Stencil st;
    st.tx = along_u.t, st.ty = along_v.t;
    st.k0 =
        static_cast<std::uint32_t>(static_cast<std::size_t>(along_v.first) * nu_ + along_u.first);
    st.used = used(along_u, along_v, nearest_must_be_on);
    return st;
  }
  Stencil stencil(double fi, double fj, bool nearest_must_be_on = true) const {
    return stencil(axis(fi, nu_), axis(fj, nv_), nearest_must_be_on);
  }
  // The stencil's points that have weight and a value (Stencil::used); none where the nearest
  // must be on and is not. The four points (i0, j0), (i0 + 1, j0), (i0, j0 + 1), (i0 + 1,
  // j0 + 1): on a grid one point wide (or high) t is 0 along that axis, so the second point's
  // weight is 0 and it is never looked at. Inline: once a pixel.
  std::uint8_t used(const AxisStencil& along_u, const AxisStencil& along_v,
                    bool nearest_must_be_on) const {
    const std::size_t nu = static_cast<std::size_t>(nu_);
    if (nearest_must_be_on &&
        !on_[static_cast<std::size_t>(along_v.nearest) * nu + along_u.nearest])
      return 0;
    const std::size_t k0 = static_cast<std::size_t>(along_v.first) * nu + along_u.first;
    const double tx = along_u.t, ty = along_v.t;
    return static_cast<std::uint8_t>((Stencil::weight(tx, ty, 0, 0) > 0.0 && on_[k0]) |
                                     (Stencil::weight(tx, ty, 1, 0) > 0.0 && on_[k0 + 1]) << 1 |
                                     (Stencil::weight(tx, ty, 0, 1) > 0.0 && on_[k0 + nu]) << 2 |
                                     (Stencil::weight(tx, ty, 1, 1) > 0.0 && on_[k0 + nu + 1])
                                         << 3);
  }

  // The value at a stencil: NaN where it uses no point. Inline: once a pixel.
  double value(const Stencil& st, const std::vector<double>& E) const {
    return value(1 - st.tx, st.tx, 1 - st.ty, st.ty, st.k0, st.used, E);
  }
  // The same from the weights' factors: (1 - tx, tx) along u, (1 - ty, ty) along v; the sums in
  // the order of `used`'s bits.
  double value(double u0, double u1, double v0, double v1, std::size_t k0, unsigned used,
               const std::vector<double>& E) const {
    const std::size_t nu = static_cast<std::size_t>(nu_);
    if (used == 15u) {  // all four, as below without the branches (nearly every pixel)
      const double w0 = u0 * v0, w1 = u1 * v0, w2 = u0 * v1, w3 = u1 * v1;
      const double* e = E.data() + k0;
      return ((((0.0 + w0 * e[0]) + w1 * e[1]) + w2 * e[nu]) + w3 * e[nu + 1]) /
             ((((0.0 + w0) + w1) + w2) + w3);
    }
    double sum = 0.0, weight = 0.0;
    if (used & 1u) sum += u0 * v0 * E[k0], weight += u0 * v0;
    if (used & 2u) sum += u1 * v0 * E[k0 + 1], weight += u1 * v0;
    if (used & 4u) sum += u0 * v1 * E[k0 + nu], weight += u0 * v1;
    if (used & 8u) sum += u1 * v1 * E[k0 + nu + 1], weight += u1 * v1;
    return weight > 0.0 ? sum / weight : NAN;
  }

  double sample(double fi, double fj, bool nearest_must_be_on = true) const {
    return value(stencil(fi, fj, nearest_must_be_on), E_);
  }

 private:
  const std::vector<double>& E_;
  int nu_, nv_;
  std::vector<unsigned char> on_;  // point (i, j) has a value and is active: on_[j nu + i]
};

// The map's place and scale: the frame it is drawn in, map_w x map_h pixels at ppm pixels a
// metre, the top row first.
struct MapLayout {
  MapFrame frame;
  bool horizontal = true;
  double ppm = 1.0;  // pixels per metre
  int map_w = 1, map_h = 1;
};

// The map of `g` drawn to scale, at most max_w_px wide and max_h_px tall, whichever binds first.
MapLayout map_layout(const geometry::SurfaceGrid& g, const calc::Scene* scene, double max_w_px,
                     double max_h_px);

// On plans, the footprints of the obstacles the surface's height cuts: drawn as they are (a
// rotated cabinet as a rotated rectangle), not as the staircase of the points they remove.
std::vector<const geometry::Polygon2*> cut_obstacles(const MapLayout& layout);

struct MapSamples {
  const calc::Scene* scene = nullptr;
  int map_w = 0, map_h = 0;
  std::size_t points = 0;    // E.size() of the grid it was made for
  std::vector<bool> active;  // and its active points
  // Per pixel, row by row from the top: its Stencil::Kind in bits 0-1, Stencil::used in 2-5.
  std::vector<std::uint8_t> code;
  // Separable: the stencils' u part per column and v part per row; else per pixel.
  bool separable = false;
  std::vector<AxisStencil> columns, rows;
  std::vector<Stencil> pixels;

  // The pixel's stencil (its kind and, when sampled, its points and fractions).
  Stencil at(int px, int py, int nu) const;
};

// `per_pixel`: every pixel's stencil worked out alone even where columns and rows would do (the
// reference the separable samples are tested against).
MapSamples make_map_samples(const calc::SurfaceResult& r, const calc::Scene* scene,
                            const MapLayout& layout,
                            const std::vector<const geometry::Polygon2*>& cut_obstacles,
                            const Field& field, bool per_pixel = false);

// Paints the map of values E (on the grid `field` was made for) at (x0, y0) of `canvas`, each
// pixel as the samples say, on `scale`.
void paint_map(const MapSamples& samples, const Field& field, const std::vector<double>& E,
               const ColourScale& scale, Raster& canvas, int x0, int y0);

}  // namespace luxgrid::report
