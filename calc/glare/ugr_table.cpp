#include "calc/glare/ugr_table.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "calc/glare/flux_transfer.h"
#include "calc/glare/ugr.h"
#include "calc/scaled_distribution.h"
#include "calc/scene.h"
#include "photometry/opening.h"
#include "photometry/tabular_distribution.h"
#include "util/error.h"
#include "util/large_buffer.h"

namespace luxgrid::calc::glare {

namespace {

// Luminaire frame -> room frame (x across the line of sight, y along it, z up). Crosswise: the
// C0 half-plane faces the observer (-y), so a luminaire straight ahead is seen at C = 0 (CIE 117:
// C = arctan(T / R)); endwise: the C90 half-plane faces the observer (C = 90 - arctan(T / R)).
glm::dmat3 table_rotation(Viewing v) {
  if (v == Viewing::crosswise) return glm::dmat3(Vec3(0, -1, 0), Vec3(1, 0, 0), Vec3(0, 0, 1));
  return glm::dmat3(Vec3(-1, 0, 0), Vec3(0, -1, 0), Vec3(0, 0, 1));
}

// Quadrature of the luminaire's flux over the lower hemisphere (midpoint rule in the angle from
// nadir and in azimuth, in the room frame): per cell its flux and where its ray, leaving a
// luminaire at height H, lands on the floor relative to the luminaire. 0.25 x 1 degree cells:
// the floor's share of a luminaire's flux then converges to ~1e-4 (docs/glare.md).
constexpr int kNadirSteps = 360, kAzimuthSteps = 360;
constexpr double kNadirStep_rad = kPi / (2 * kNadirSteps),
                 kAzimuthStep_rad = 2.0 * kPi / kAzimuthSteps;

// Where each lower cell's central ray lands (H = kTableH_m), nadir step by azimuth step: the
// same for every distribution and viewing, so made once.
struct Landing {
  double dx_m, dy_m;
};
// The quadrature's arrays (2 MB, 1 MB) in huge pages where the system gives them: fresh 4 kB
// pages cost more than the quadrature on a virtual machine (util/large_buffer.h).
const LargeBuffer<Landing>& landings() {
  static const LargeBuffer<Landing> made = [] {
    auto l = LargeBuffer<Landing>::uninitialised(static_cast<size_t>(kNadirSteps) * kAzimuthSteps);
    size_t cell = 0;
    std::array<double, kAzimuthSteps> cos_p, sin_p;  // once per azimuth, not per cell
    for (int k = 0; k < kAzimuthSteps; ++k) {
      const double p = (k + 0.5) * kAzimuthStep_rad;
      cos_p[k] = std::cos(p), sin_p[k] = std::sin(p);
    }
    for (int i = 0; i < kNadirSteps; ++i) {
      const double reach = kTableH_m * std::tan((i + 0.5) * kNadirStep_rad);
      for (int k = 0; k < kAzimuthSteps; ++k) l[cell++] = {reach * cos_p[k], reach * sin_p[k]};
    }
    return l;
  }();
  return made;
}

struct Fluxes {
  double down_lm = 0.0, up_lm = 0.0;
  LargeBuffer<double> down_cell_lm;  // per lower cell, in the order of landings()
};

// `intensity_cd(hemisphere, i, k, world)`: the intensity of cell i (angle from nadir, or from
// zenith in the upper hemisphere 1) and k (azimuth) towards `world`, the cell centre's direction
// in the room frame.
template <class IntensityOfCell>
Fluxes flux_cells(const IntensityOfCell& intensity_cd) {
  Fluxes f;
  // Every lower cell is written below (hemisphere 0).
  f.down_cell_lm =
      LargeBuffer<double>::uninitialised(static_cast<size_t>(kNadirSteps) * kAzimuthSteps);
  std::array<double, kAzimuthSteps> cos_p, sin_p;
  for (int k = 0; k < kAzimuthSteps; ++k) {
    const double p = (k + 0.5) * kAzimuthStep_rad;
    cos_p[k] = std::cos(p), sin_p[k] = std::sin(p);
  }
  for (int hemisphere = 0; hemisphere < 2; ++hemisphere) {
    for (int i = 0; i < kNadirSteps; ++i) {
      const double t = (i + 0.5) * kNadirStep_rad;  // from nadir (down) or from zenith (up)
      const double sin_t = std::sin(t), cos_t = std::cos(t);
      const double dw = sin_t * kNadirStep_rad * kAzimuthStep_rad;
      const double z = hemisphere == 0 ? -cos_t : cos_t;
      double* down = &f.down_cell_lm[static_cast<size_t>(i) * kAzimuthSteps];
      for (int k = 0; k < kAzimuthSteps; ++k) {
        const Vec3 world(sin_t * cos_p[k], sin_t * sin_p[k], z);
        const double flux = intensity_cd(hemisphere, i, k, world) * dw;
        if (hemisphere == 1) {
          f.up_lm += flux;
          continue;
        }
        f.down_lm += flux;
        down[k] = flux;
      }
    }
  }
  return f;
}

// The two viewings turn the luminaire about the vertical by a quarter turn (crosswise: room
// azimuth p is the luminaire's C = p + 90 degrees) or a half turn (endwise: C = p + 180 degrees),
// so a cell of the room's quadrature is a cell of the same ring in the luminaire frame, 90 or 180
// azimuth steps on. A type C table is therefore read once, at the cells' own angles (gamma = the
// angle from nadir, C = the azimuth; no trigonometry per lookup), for both viewings; any other
// distribution is asked per direction.
int azimuth_offset(Viewing v) {
  return v == Viewing::crosswise ? kAzimuthSteps / 4 : kAzimuthSteps / 2;
}

class CellIntensities {
 public:
  explicit CellIntensities(const photometry::IntensityDistribution& d) : d_(d) {
    const photometry::TableView view = d.table_view();
    if (!view.table) return;
    std::vector<photometry::TabularDistribution::CPosition> c(kAzimuthSteps);
    for (int k = 0; k < kAzimuthSteps; ++k)
      c[k] = view.table->c_position((k + 0.5) * kAzimuthStep_rad);
    cd_ = LargeBuffer<double>::filled(static_cast<size_t>(2) * kNadirSteps * kAzimuthSteps, 0.0);
    for (int hemisphere = 0; hemisphere < 2; ++hemisphere)
      for (int i = 0; i < kNadirSteps; ++i) {
        const double t = (i + 0.5) * kNadirStep_rad;
        std::size_t j = 0;
        double tg = 0.0;
        if (!view.table->gamma_cell(hemisphere == 0 ? t : kPi - t, j, tg)) continue;
        double* row = &cd_[(static_cast<size_t>(hemisphere) * kNadirSteps + i) * kAzimuthSteps];
        for (int k = 0; k < kAzimuthSteps; ++k)
          row[k] = view.scale * view.table->intensity_at(c[k], j, tg);
      }
  }

  Fluxes fluxes(Viewing v) const {
    if (cd_.empty()) {
      const glm::dmat3 rotation = table_rotation(v);
      return flux_cells(
          [&](int, int, int, const Vec3& world) { return d_.intensity(world * rotation); });
    }
    const int offset = azimuth_offset(v);
    return flux_cells([&](int hemisphere, int i, int k, const Vec3&) {
      return cd_[(static_cast<size_t>(hemisphere) * kNadirSteps + i) * kAzimuthSteps +
                 (k + offset) % kAzimuthSteps];
    });
  }

 private:
  const photometry::IntensityDistribution& d_;
  LargeBuffer<double>
      cd_;  // [hemisphere][nadir step][azimuth step], luminaire frame; empty: ask d_
};

// Luminaire centres along one side: n = L / S of them, S/2 from each end.
std::vector<double> grid_line(double from, double length, double S) {
  const int n = static_cast<int>(std::lround(length / S));
  std::vector<double> v;
  for (int i = 0; i < n; ++i) v.push_back(from + S * (i + 0.5));
  return v;
}

// Luminaire centres along one side (grid_line), for counting how many of them, shifted by an
// offset, lie in [lo, hi]: c + offset rounds monotonically in c, so those at or above lo are a
// suffix and those at or below hi a prefix. Each end is guessed from the spacing and then moved
// to where the comparison itself changes, so the count is that of a comparison per centre, the
// same one, in a few comparisons (it runs once per quadrature cell, 129 600 a table room).
class ShiftedCount {
 public:
  explicit ShiftedCount(const std::vector<double>& centres)
      : c_(centres), n_(static_cast<std::ptrdiff_t>(centres.size())) {
    if (n_ > 1) inv_spacing_ = static_cast<double>(n_ - 1) / (c_[n_ - 1] - c_[0]);
  }
  std::size_t count(double offset, double lo, double hi) const {
    // Most rays that land beside the room lie beyond every centre on one side (and a NaN
    // offset compares false, as it did centre by centre).
    if (n_ == 0 || !(c_[0] + offset <= hi) || !(c_[n_ - 1] + offset >= lo)) return 0;
    // The first index at or above lo, and the first above hi.
    std::ptrdiff_t from = guess(lo - offset), to = guess(hi - offset);
    while (from > 0 && c_[from - 1] + offset >= lo) --from;
    while (from < n_ && !(c_[from] + offset >= lo)) ++from;
    while (to > 0 && !(c_[to - 1] + offset <= hi)) --to;
    while (to < n_ && c_[to] + offset <= hi) ++to;
    return to > from ? static_cast<std::size_t>(to - from) : 0;
  }

 private:
  // The index where the centres reach `target`, clamped to [0, n]; the count's ends are found
  // from there by the comparisons themselves, so the guess may be off.
  std::ptrdiff_t guess(double target) const {
    const double g = std::ceil((target - c_[0]) * inv_spacing_);
    if (!(g > 0.0)) return 0;  // also NaN
    return g >= static_cast<double>(n_) ? n_ : static_cast<std::ptrdiff_t>(g);
  }
  const std::vector<double>& c_;
  std::ptrdiff_t n_;
  double inv_spacing_ = 0.0;
};

// What a table room gives whatever its reflectances: the glare sum over its luminaires and the
// direct flux on its floor (at eye level), walls and ceiling. A table row's five reflectance
// columns share it (room_ugr).
struct RoomDirect {
  double glare_sum = 0.0;
  ThreeSurfaces direct{0.0, 0.0, 0.0};
  double X = 0.0, Y = 0.0, H = 0.0;
};

RoomDirect room_direct(const photometry::IntensityDistribution& d,
                       const photometry::LuminousOpening& o, const TableRoom& room, Viewing viewing,
                       const Fluxes& fluxes) {
  const double H = kTableH_m, S = kTableSpacingOverH * H;
  const double X = room.x_H * H, Y = room.y_H * H;
  const auto xs = grid_line(-0.5 * X, X, S), ys = grid_line(0.0, Y, S);
  Pose pose;
  pose.rotation = table_rotation(viewing);
  const Vec3 eye(0.0);
  const ViewFrame view = ViewFrame::looking(Vec3(0, 1, 0));
  double sum = 0.0;
  for (double y : ys)
    for (double x : xs) {
      pose.position = Vec3(x, y, H);
      // CIE 190's tabular method takes A_p / d^2 for every luminaire, as the makers' tables do.
      if (const auto t = glare_term(d, o, pose, eye, view, SolidAngleRule::cie117_formula))
        sum += t->value();
    }
  RoomDirect r;
  r.glare_sum = sum, r.X = X, r.Y = Y, r.H = H;
  if (!(sum > 0.0)) return r;
  // Direct flux of all luminaires onto the floor (the plane at eye level), walls and ceiling.
  const double n = static_cast<double>(xs.size() * ys.size());
  double floor_lm = 0.0;
  const LargeBuffer<Landing>& land = landings();
  const ShiftedCount across_x(xs), along_y(ys);
  for (size_t c = 0; c < land.size(); ++c) {
    const double flux = fluxes.down_cell_lm[c];
    const size_t across = across_x.count(land[c].dx_m, -0.5 * X, 0.5 * X);
    // A ray that lands beside the room for every column adds a finite flux times 0, which leaves
    // the sum as it is: the rows need not be counted.
    if (across == 0 && std::isfinite(flux)) continue;
    floor_lm += flux * static_cast<double>(across * along_y.count(land[c].dy_m, 0.0, Y));
  }
  r.direct = ThreeSurfaces{floor_lm, n * fluxes.down_lm - floor_lm, n * fluxes.up_lm};
  return r;
}

std::optional<double> room_ugr(const RoomDirect& r, const TableReflectances& refl) {
  if (!(r.glare_sum > 0.0)) return std::nullopt;
  const ThreeSurfaces in =
      indirect_flux(r.X, r.Y, r.H, {refl.floor, refl.walls, refl.ceiling}, r.direct);
  const double E_wid_lx = in.walls / (2.0 * r.H * (r.X + r.Y));
  const double Lb = E_wid_lx / kPi;
  if (!(Lb > 0.0)) return std::nullopt;
  return unified_glare_rating(r.glare_sum, Lb);
}

void require_area(const photometry::LuminousOpening& o) {
  if (o.shape == photometry::LuminousOpening::Shape::point) {
    throw InputError(
        "UGR table: the file gives no luminous area (a point emitter); UGR's luminance is the "
        "intensity over the luminous area");
  }
}

}  // namespace

std::optional<double> table_ugr(const photometry::IntensityDistribution& d,
                                const photometry::LuminousOpening& o, const TableRoom& room,
                                const TableReflectances& refl, Viewing viewing) {
  require_area(o);
  return room_ugr(room_direct(d, o, room, viewing, CellIntensities(d).fluxes(viewing)), refl);
}

TableUgrs table_ugrs(const photometry::IntensityDistribution& d,
                     const photometry::LuminousOpening& o, const TableRoom& room,
                     const TableReflectances& refl) {
  require_area(o);
  const CellIntensities cells(d);
  return {
      room_ugr(room_direct(d, o, room, Viewing::crosswise, cells.fluxes(Viewing::crosswise)), refl),
      room_ugr(room_direct(d, o, room, Viewing::endwise, cells.fluxes(Viewing::endwise)), refl)};
}

UgrTable ugr_table(const photometry::DistributionPtr& distribution,
                   const photometry::LuminousOpening& o, double lamp_flux_lm) {
  require_area(o);
  if (!(lamp_flux_lm > 0.0) || !std::isfinite(lamp_flux_lm)) {
    throw InputError("UGR table: the lamp flux must be positive, got " +
                     std::to_string(lamp_flux_lm) + " lm");
  }
  UgrTable t;
  t.lamp_flux_lm = lamp_flux_lm;
  t.correction = 8.0 * std::log10(lamp_flux_lm / kTableFluxLm);
  const ScaledDistribution d(distribution, kTableFluxLm / lamp_flux_lm);
  const CellIntensities cells(d);
  for (const Viewing v : {Viewing::crosswise, Viewing::endwise}) {
    const Fluxes f = cells.fluxes(v);
    auto& rows = v == Viewing::crosswise ? t.crosswise : t.endwise;
    for (const auto& room : kTableRooms) {
      const RoomDirect direct = room_direct(d, o, room, v, f);
      std::array<std::optional<double>, 5> row;
      for (size_t r = 0; r < kTableReflectances.size(); ++r)
        row[r] = room_ugr(direct, kTableReflectances[r]);
      rows.push_back(row);
    }
  }
  return t;
}

double table_lamp_flux_lm(const photometry::Photometry& p,
                          const photometry::IntensityDistribution& distribution) {
  if (p.lamp_flux_lm && *p.lamp_flux_lm > 0.0) return *p.lamp_flux_lm;
  return luminous_flux(distribution);
}

}  // namespace luxgrid::calc::glare
