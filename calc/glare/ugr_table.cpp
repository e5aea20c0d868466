#include "calc/glare/ugr_table.h"

#include <cmath>

#include "calc/glare/flux_transfer.h"
#include "calc/glare/ugr.h"
#include "calc/scaled_distribution.h"
#include "calc/scene.h"
#include "photometry/opening.h"
#include "util/error.h"

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
struct FluxCell {
  double flux_lm, dx_m, dy_m;
};
constexpr int kNadirSteps = 360, kAzimuthSteps = 360;

struct Fluxes {
  double down_lm = 0.0, up_lm = 0.0;
  std::vector<FluxCell> down;
};

Fluxes flux_cells(const photometry::IntensityDistribution& d, const glm::dmat3& rotation,
                  double H) {
  Fluxes f;
  f.down.reserve(static_cast<size_t>(kNadirSteps) * kAzimuthSteps);
  const double dt = kPi / (2 * kNadirSteps), dp = 2.0 * kPi / kAzimuthSteps;
  for (int hemisphere = 0; hemisphere < 2; ++hemisphere) {
    for (int i = 0; i < kNadirSteps; ++i) {
      const double t = (i + 0.5) * dt;  // from nadir (down) or from zenith (up)
      const double dw = std::sin(t) * dt * dp;
      for (int k = 0; k < kAzimuthSteps; ++k) {
        const double p = (k + 0.5) * dp;
        const double z = hemisphere == 0 ? -std::cos(t) : std::cos(t);
        const Vec3 world(std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), z);
        const double flux = d.intensity(world * rotation) * dw;
        if (hemisphere == 1) {
          f.up_lm += flux;
          continue;
        }
        f.down_lm += flux;
        const double reach = H * std::tan(t);
        f.down.push_back({flux, reach * std::cos(p), reach * std::sin(p)});
      }
    }
  }
  return f;
}

// Luminaire centres along one side: n = L / S of them, S/2 from each end.
std::vector<double> grid_line(double from, double length, double S) {
  const int n = static_cast<int>(std::lround(length / S));
  std::vector<double> v;
  for (int i = 0; i < n; ++i) v.push_back(from + S * (i + 0.5));
  return v;
}

size_t count_inside(const std::vector<double>& centres, double offset, double lo, double hi) {
  size_t n = 0;
  for (double c : centres) n += (c + offset >= lo && c + offset <= hi) ? 1 : 0;
  return n;
}

std::optional<double> room_ugr(const photometry::IntensityDistribution& d,
                               const photometry::LuminousOpening& o, const TableRoom& room,
                               const TableReflectances& refl, Viewing viewing,
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
      if (const auto t = glare_term(d, o, pose, eye, view)) sum += t->value();
    }
  if (!(sum > 0.0)) return std::nullopt;
  // Direct flux of all luminaires onto the floor (the plane at eye level), walls and ceiling.
  const double n = static_cast<double>(xs.size() * ys.size());
  double floor_lm = 0.0;
  for (const auto& c : fluxes.down) {
    floor_lm += c.flux_lm * static_cast<double>(count_inside(xs, c.dx_m, -0.5 * X, 0.5 * X) *
                                                count_inside(ys, c.dy_m, 0.0, Y));
  }
  const ThreeSurfaces direct{floor_lm, n * fluxes.down_lm - floor_lm, n * fluxes.up_lm};
  const ThreeSurfaces in = indirect_flux(X, Y, H, {refl.floor, refl.walls, refl.ceiling}, direct);
  const double E_wid_lx = in.walls / (2.0 * H * (X + Y));
  const double Lb = E_wid_lx / kPi;
  if (!(Lb > 0.0)) return std::nullopt;
  return unified_glare_rating(sum, Lb);
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
  const Fluxes f = flux_cells(d, table_rotation(viewing), kTableH_m);
  return room_ugr(d, o, room, refl, viewing, f);
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
  for (const Viewing v : {Viewing::crosswise, Viewing::endwise}) {
    const Fluxes f = flux_cells(d, table_rotation(v), kTableH_m);
    auto& rows = v == Viewing::crosswise ? t.crosswise : t.endwise;
    for (const auto& room : kTableRooms) {
      std::array<std::optional<double>, 5> row;
      for (size_t r = 0; r < kTableReflectances.size(); ++r)
        row[r] = room_ugr(d, o, room, kTableReflectances[r], v, f);
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
