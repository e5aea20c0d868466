#include "calc/daylight_light.h"

#include <algorithm>
#include <array>
#include <cmath>

#include <tbb/parallel_for.h>

#include "calc/daylight/aperture_split.h"
#include "calc/daylight/plane_illuminance.h"
#include "calc/daylight/sky_normalisation.h"
#include "calc/opening_placement.h"
#include "calc/plan_estimates.h"
#include "calc/scene_visibility.h"
#include "geometry/polygon.h"
#include "geometry/polygon3.h"

namespace luxgrid::calc {
namespace {

using daylight::Triangle3;

// Most triangles one part (sky or ground) of one opening is cut into at one point: the adaptive
// integration stops there even above its tolerance (the plan's error estimate says by how much).
constexpr int kMaxTrianglesPerOpening = 16384;
// The absolute floor of the tolerance, as a fraction of E_h, at `standard` (and `draft`): 1e-5 is
// a daylight factor of 0.001 %, 1 % of a point of DF 0.1 %. Finer qualities scale it with their
// tolerance (absolute_floor_of_eh), so a point of DF 0.1 % keeps their promise too: a floor fixed
// at 1e-5 left floor points beside a glazed window wall (DF 0.1 %, the glass seen at grazing
// angles) 0.33 % off at `high`.
constexpr double kAbsoluteToleranceOfEh = 1e-5;
// The widest edge a triangle starts with under a general sky, seen from the point
// (aperture_integral.h): 0.15 rad (8.6 degrees), under half the scale on which its indicatrix
// changes near the sun, so its nodes cannot all miss the sun's brightening.
constexpr double kMaxStartEdge_rad = 0.15;
// The same for the traditional overcast and the uniform sky, which have no such peak: what the
// start is for there is the glazing's fall towards grazing incidence, which three nodes of a
// wider triangle miss. 0.5 rad keeps CIE 171's unglazed cases under the traditional overcast
// sky within 0.13 % of their references at `standard` (0.015 % with 0.15 rad, 0.72 % with no
// start subdivision) at a fifth of the evaluations of 0.15 rad (2.9 million to 0.6 million over
// a windowed 6 x 4 m office's points).
constexpr double kSlowSkyStartEdge_rad = 0.5;
// A patch whose centroid lies within this many of its diameters of an opening (its bounding
// sphere) is integrated at its four quarters, else at its centroid: the midpoint rule's error,
// about (diameter / distance)^2 / 24 of the patch's flux, is then below 0.3 %.
constexpr double kQuartersWithin = 4.0;
// Points per side of a cut patch at which its cells' light is sampled (daylight_light.h,
// cell_flux_lm); the cells' centres are interpolated between them.
constexpr int kCellSamplesPerSide = 2;

}  // namespace

DaylightLight::DaylightLight(const Scene& scene, const geometry::Visibility* visibility,
                             double relative_tolerance)
    : scene_(scene),
      visibility_(visibility),
      relative_tolerance_(relative_tolerance),
      absolute_floor_of_eh_(kAbsoluteToleranceOfEh *
                            std::min(1.0, relative_tolerance / promised_error(Quality::standard))) {
  const DaylightInputs& inputs = *scene.daylight;
  ground_reflectance_ = inputs.ground_reflectance;
  diffuse_horizontal_lx_ = inputs.diffuse_horizontal_lx;
  sky_integral_ = daylight::horizontal_illuminance_per_zenith_luminance(inputs.sky);
  std::size_t glazed = 0;
  for (const DaylightOpening& o : scene.openings) {
    PreparedOpening p;
    p.room = o.room;
    p.inward_normal = o.inward_normal;
    p.factor = o.frame_factor * o.maintenance_factor;
    if (o.glazing_transmittance) p.glass.emplace(*o.glazing_transmittance), ++glazed;
    // Triangulated in the face's 2D coordinates (the polygon may be non-convex), the corners
    // taken from the 3D polygon by index.
    std::vector<Vec2> flat = face_coordinates(scene.rooms[o.room], o.face, o.polygon);
    std::vector<Vec3> corners = o.polygon;
    if (geometry::signed_area(flat) < 0.0) {
      std::reverse(flat.begin(), flat.end());
      std::reverse(corners.begin(), corners.end());
    }
    p.area_m2 = std::abs(geometry::signed_area(flat));
    for (const Vec3& v : o.polygon) p.centre += v / static_cast<double>(o.polygon.size());
    for (const Vec3& v : o.polygon) p.radius_m = std::max(p.radius_m, glm::length(v - p.centre));
    for (const auto& t : geometry::triangulate(flat))
      p.triangles.push_back({corners[t[0]], corners[t[1]], corners[t[2]]});
    openings_.push_back(std::move(p));
  }
  // A general sky's start subdivision is finer: its brightening about the sun is narrow.
  max_start_edge_rad_ =
      inputs.sky.kind == daylight::SkyKind::cie_general ? kMaxStartEdge_rad : kSlowSkyStartEdge_rad;
  // An exterior obstruction makes the integrand vary over the opening: no exact shortcut.
  ground_exact_ = glazed == 0 && !visibility && inputs.obstructions.empty();
  sky_exact_ = ground_exact_ && inputs.sky.kind == daylight::SkyKind::uniform;
  for (const ExteriorObstruction& b : inputs.obstructions) {
    std::array<double, kBoxFaces> luminance{};
    for (int face = 0; face < kBoxFaces; ++face)
      luminance[face] = b.reflectance / kPi *
                        daylight::plane_illuminance_lx(
                            inputs.sky, 1.0 / sky_integral_.value, ground_reflectance_ / kPi,
                            box_face_normal(face), [](double) { return 1.0; });
    face_luminance_per_eh_.push_back(luminance);
  }
}

OpeningLightParts DaylightLight::at(const Vec3& point, const Vec3& normal) const {
  OpeningLightParts parts;
  for (const PreparedOpening& o : openings_) add_through(o, point, normal, parts);
  return parts;
}

void DaylightLight::add_through(const PreparedOpening& o, const Vec3& point, const Vec3& normal,
                                OpeningLightParts& parts) const {
  const DaylightInputs& inputs = *scene_.daylight;
  const double tolerance = relative_tolerance_;
  const double sky_floor = absolute_floor_of_eh_ * sky_integral_.value;
  const double ground_floor = absolute_floor_of_eh_ * kPi;
  {
    if (!inside_room(scene_.rooms[o.room], point)) return;
    // A point in the opening's own plane (a grid point of its face, in the hole or beside it)
    // sees the opening edge-on: nothing through it.
    if (std::abs(glm::dot(point - o.triangles.front()[0], o.inward_normal)) <
        kOpeningPlaneTolerance_m)
      return;
    const auto transmitted = [&](const Vec3& node, const Vec3& dir) {
      double t = o.factor;
      if (o.glass) t *= o.glass->transmittance(glm::dot(dir, o.inward_normal));
      if (t > 0.0 && geometry::blocked(visibility_, point, node)) return 0.0;
      return t;
    };
    if (!face_luminance_per_eh_.empty())
      return add_obstructed(o, point, normal, transmitted, parts);
    const std::vector<Triangle3> sky_part =
        daylight::clip_to_receiver(o.triangles, point, normal, true);
    const std::vector<Triangle3> ground_part =
        daylight::clip_to_receiver(o.triangles, point, normal, false);
    if (sky_exact_) {
      parts.sky += o.factor * daylight::aperture_projected_solid_angle(sky_part, point, normal);
    } else if (!sky_part.empty()) {
      const auto r = daylight::integrate_aperture(
          sky_part, point, normal,
          [&](const Vec3& node, const Vec3& dir) {
            return daylight::relative_luminance(inputs.sky, dir) * transmitted(node, dir);
          },
          0.5 * tolerance, sky_floor, kMaxTrianglesPerOpening, max_start_edge_rad_);
      parts.sky += r.value, parts.sky_error += r.error_estimate, parts.evaluations += r.evaluations;
    }
    if (ground_exact_) {
      parts.ground +=
          o.factor * daylight::aperture_projected_solid_angle(ground_part, point, normal);
    } else if (!ground_part.empty()) {
      const auto r =
          daylight::integrate_aperture(ground_part, point, normal, transmitted, 0.5 * tolerance,
                                       ground_floor, kMaxTrianglesPerOpening);
      parts.ground += r.value, parts.ground_error += r.error_estimate;
      parts.evaluations += r.evaluations;
    }
  }
}

void DaylightLight::add_obstructed(const PreparedOpening& o, const Vec3& point, const Vec3& normal,
                                   const Transmitted& transmitted, OpeningLightParts& parts) const {
  const DaylightInputs& inputs = *scene_.daylight;
  std::vector<std::array<Vec3, 2>> edges;
  for (const ExteriorObstruction& b : inputs.obstructions)
    for (const auto& e : edges_facing(b, point)) edges.push_back(e);
  const Vec3 on_plane = o.triangles.front()[0];
  const double tolerance = 0.5 * relative_tolerance_;
  for (const bool above : {true, false}) {
    const std::vector<Triangle3> pieces =
        daylight::split_along_edges(daylight::clip_to_receiver(o.triangles, point, normal, above),
                                    point, edges, on_plane, -o.inward_normal);
    // Each piece sees one thing throughout: what its centroid's ray meets beyond the opening.
    std::vector<Triangle3> open;
    std::vector<std::pair<std::size_t, std::vector<Triangle3>>> faces;  // key obstruction x 6
    for (const Triangle3& t : pieces) {
      const Vec3 c = (t[0] + t[1] + t[2]) / 3.0;
      const double length = glm::length(c - point);
      const auto hit =
          length > 0.0 ? first_exterior_obstruction(inputs.obstructions, c, (c - point) / length)
                       : std::nullopt;
      if (!hit) {
        open.push_back(t);
        continue;
      }
      const std::size_t key = hit->obstruction * kBoxFaces + hit->face;
      auto it =
          std::find_if(faces.begin(), faces.end(), [&](const auto& f) { return f.first == key; });
      if (it == faces.end()) it = faces.insert(faces.end(), {key, {}});
      it->second.push_back(t);
    }
    if (!open.empty()) {
      const auto r =
          above
              ? daylight::integrate_aperture(
                    open, point, normal,
                    [&](const Vec3& node, const Vec3& dir) {
                      return daylight::relative_luminance(inputs.sky, dir) * transmitted(node, dir);
                    },
                    tolerance, absolute_floor_of_eh_ * sky_integral_.value, kMaxTrianglesPerOpening,
                    max_start_edge_rad_)
              : daylight::integrate_aperture(open, point, normal, transmitted, tolerance,
                                             absolute_floor_of_eh_ * kPi, kMaxTrianglesPerOpening);
      (above ? parts.sky : parts.ground) += r.value;
      (above ? parts.sky_error : parts.ground_error) += r.error_estimate;
      parts.evaluations += r.evaluations;
    }
    for (const auto& [key, triangles] : faces) {
      const double luminance = face_luminance_per_eh_[key / kBoxFaces][key % kBoxFaces];
      if (!(luminance > 0.0)) continue;
      // A face's luminance is uniform: what varies over it is the glazing and the visibility.
      const auto r = daylight::integrate_aperture(triangles, point, normal, transmitted, tolerance,
                                                  absolute_floor_of_eh_ / luminance,
                                                  kMaxTrianglesPerOpening, max_start_edge_rad_);
      parts.obstruction += luminance * r.value;
      parts.obstruction_error += luminance * r.error_estimate;
      parts.evaluations += r.evaluations;
    }
  }
}

double DaylightLight::illuminance_lx(const OpeningLightParts& parts) const {
  return (sky_percent(parts.sky) + external_percent(parts)) * diffuse_horizontal_lx_ / 100.0;
}

std::vector<double> DaylightLight::patch_flux_lm(const indirect::PatchMesh& mesh) const {
  std::vector<double> flux(mesh.patches.size(), 0.0);
  if (openings_.empty()) return flux;

  tbb::parallel_for(std::size_t{0}, mesh.patches.size(), [&](std::size_t i) {
    const indirect::Patch& p = mesh.patches[i];
    const Vec3 lift = p.normal * kPatchLift_m;
    const auto E = [&](const Vec3& x) { return illuminance_lx(at(x + lift, p.normal)); };
    // Far from every opening the illuminance varies little over the patch: its centroid alone
    // (the midpoint rule's error falls as (diameter / distance)^2).
    bool near = false;
    for (const PreparedOpening& o : openings_)
      near = near ||
             (o.room == static_cast<std::size_t>(p.room) &&
              glm::length(p.centroid - o.centre) - o.radius_m < kQuartersWithin * p.diameter_m);
    double sum = 0.0;
    if (!near) {
      sum = p.area_m2 * E(p.centroid);
    } else if (p.has_quarters) {
      for (const Vec3& q : p.quarter_centroid) sum += 0.25 * p.area_m2 * E(q);
    } else {
      for (std::size_t k = 1; k + 1 < p.polygon.size(); ++k) {
        const Vec3 a = p.polygon[0], b = p.polygon[k], c = p.polygon[k + 1];
        const double area = 0.5 * glm::length(glm::cross(b - a, c - a));
        if (area > 0.0) sum += area * E((a + b + c) / 3.0);
      }
    }
    flux[i] = sum;
  });
  return flux;
}

std::vector<double> DaylightLight::cell_flux_lm(const indirect::PatchMesh& mesh,
                                                const indirect::CellMesh& cells) const {
  constexpr int kPerSide = indirect::kSubcellsPerSide, kCells = kPerSide * kPerSide;
  constexpr int kSamples = kCellSamplesPerSide;
  std::vector<double> flux(cells.mesh.patches.size(), 0.0);
  if (openings_.empty()) return flux;
  // Lagrange weights of the samples, at (k + 1/2) / kSamples along an edge, for the cells'
  // centres, at (a + 1/2) / kPerSide.
  std::array<std::array<double, kSamples>, kPerSide> weight{};
  for (int a = 0; a < kPerSide; ++a) {
    const double x = (a + 0.5) / kPerSide;
    for (int k = 0; k < kSamples; ++k) {
      double w = 1.0;
      for (int j = 0; j < kSamples; ++j)
        if (j != k) w *= (x - (j + 0.5) / kSamples) / ((k - j) / static_cast<double>(kSamples));
      weight[a][k] = w;
    }
  }
  // Cells come kCells at a time, patch by patch (subcells.h, cell_mesh).
  tbb::parallel_for(std::size_t{0}, cells.patch.size() / kCells, [&](std::size_t k) {
    const std::size_t c0 = k * kCells;
    const indirect::Patch& p = mesh.patches[cells.patch[c0]];
    const Vec3 o = p.polygon[0], e1 = p.polygon[1] - o, e2 = p.polygon[3] - o;
    const Vec3 lift = p.normal * kPatchLift_m;
    std::array<std::array<double, kSamples>, kSamples> E{};
    for (int i = 0; i < kSamples; ++i)
      for (int j = 0; j < kSamples; ++j) {
        const Vec3 x = o + ((i + 0.5) / kSamples) * e1 + ((j + 0.5) / kSamples) * e2;
        E[i][j] = illuminance_lx(at(x + lift, p.normal));
      }
    for (int a = 0; a < kPerSide; ++a)
      for (int b = 0; b < kPerSide; ++b) {
        double e = 0.0;
        for (int i = 0; i < kSamples; ++i)
          for (int j = 0; j < kSamples; ++j) e += weight[a][i] * weight[b][j] * E[i][j];
        const std::size_t c = c0 + static_cast<std::size_t>(a * kPerSide + b);
        flux[c] = std::max(0.0, e) * cells.mesh.patches[c].area_m2;
      }
  });
  return flux;
}

double DaylightLight::entering_flux_lm(std::size_t k) const {
  const PreparedOpening& o = openings_.at(k);
  const DaylightInputs& inputs = *scene_.daylight;
  const double transmitted_lx = daylight::plane_illuminance_lx(
      inputs.sky, diffuse_horizontal_lx_ / sky_integral_.value,
      ground_reflectance_ * diffuse_horizontal_lx_ / kPi, -o.inward_normal,
      [&o](double c) { return o.factor * (o.glass ? o.glass->transmittance(c) : 1.0); });
  return o.area_m2 * transmitted_lx;
}

}  // namespace luxgrid::calc
