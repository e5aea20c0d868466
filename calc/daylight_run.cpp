#include "calc/daylight_run.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>

#include <tbb/parallel_for.h>

#include "calc/daylight/aperture_integral.h"
#include "calc/daylight/clear_glass.h"
#include "calc/daylight/sky_normalisation.h"
#include "calc/opening_placement.h"
#include "calc/plan_estimates.h"
#include "calc/statistics.h"
#include "geometry/polygon.h"

namespace luxgrid::calc {
namespace {

using daylight::Triangle3;

// Most triangles one part (sky or ground) of one opening is cut into at one point: the adaptive
// integration stops there even above its tolerance (the plan's error estimate says by how much).
constexpr int kMaxTrianglesPerOpening = 16384;
// The absolute floor of the tolerance, as a fraction of E_h: 1e-5 is a daylight factor of
// 0.001 %, below anything a design reads.
constexpr double kAbsoluteToleranceOfEh = 1e-5;
// The widest edge a triangle starts with, seen from the point (aperture_integral.h): 0.15 rad
// (8.6 degrees), under half the scale on which a general sky's indicatrix changes
// near the sun, so its nodes cannot all miss the sun's brightening.
constexpr double kMaxStartEdge_rad = 0.15;

struct PreparedOpening {
  std::size_t room = 0;
  std::vector<Triangle3> triangles;  // the polygon, triangulated in its face
  Vec3 inward_normal{0, 0, 1};
  std::optional<daylight::ClearGlass> glass;
  double factor = 1.0;  // frame x maintenance
};

std::vector<PreparedOpening> prepare_openings(const Scene& scene) {
  std::vector<PreparedOpening> out;
  for (const DaylightOpening& o : scene.openings) {
    PreparedOpening p;
    p.room = o.room;
    p.inward_normal = o.inward_normal;
    p.factor = o.frame_factor * o.maintenance_factor;
    if (o.glazing_transmittance) p.glass.emplace(*o.glazing_transmittance);
    // Triangulated in the face's 2D coordinates (the polygon may be non-convex), the corners
    // taken from the 3D polygon by index.
    std::vector<Vec2> flat = face_coordinates(scene.rooms[o.room], o.face, o.polygon);
    std::vector<Vec3> corners = o.polygon;
    if (geometry::signed_area(flat) < 0.0) {
      std::reverse(flat.begin(), flat.end());
      std::reverse(corners.begin(), corners.end());
    }
    for (const auto& t : geometry::triangulate(flat))
      p.triangles.push_back({corners[t[0]], corners[t[1]], corners[t[2]]});
    out.push_back(std::move(p));
  }
  return out;
}

struct PointParts {
  double sky = 0.0, ground = 0.0;              // int w cos d omega (sky: relative luminance)
  double sky_error = 0.0, ground_error = 0.0;  // their estimates
  std::size_t evaluations = 0;
};

}  // namespace

double daylight_tolerance(Quality q) {
  switch (q) {
    case Quality::draft: return 0.05;
    case Quality::standard:
    case Quality::high: return promised_error(q);
    case Quality::reference: return 1e-4;
  }
  return 0.01;
}

Results run_daylight_scene(const Scene& scene, const Progress& progress) {
  (void)progress;
  const auto t0 = std::chrono::steady_clock::now();
  const DaylightInputs& inputs = *scene.daylight;
  Results results;
  results.project = scene.name;
  results.scene = LightingScene::daylight;
  results.quality = scene.settings.quality;
  results.maintenance_factor = 1.0;  // openings carry their own maintenance factors
  for (const auto& g : scene.surfaces) {
    if (g.kind == geometry::SurfaceGrid::Kind::observers)
      throw InputError(
          SourceLocation(),
          "surface '" + g.name + "': the daylight scene calculates no glare (observers surfaces)");
    if (g.quantity == geometry::Quantity::cylindrical ||
        g.quantity == geometry::Quantity::semi_cylindrical)
      throw InputError(SourceLocation(), "surface '" + g.name +
                                             "': the daylight scene calculates planar, "
                                             "horizontal and vertical illuminance only (not built "
                                             "for " +
                                             geometry::to_string(g.quantity) + ")");
  }

  // The scene's occlusion test (obstacles, non-convex rooms), without the luminaires: the
  // daylight scene lights nothing electric.
  Scene geometry_only = scene;
  geometry_only.luminaires.clear();
  Plan plan;
  plan.quality = scene.settings.quality;
  plan.visibility_test = make_visibility(geometry_only, plan.visibility);
  const geometry::Visibility* visibility = plan.visibility_test.get();

  DaylightPlan dp;
  dp.sky = inputs.sky.name();
  dp.diffuse_horizontal_lx = inputs.diffuse_horizontal_lx;
  dp.ground_reflectance = inputs.ground_reflectance;
  if (inputs.sun) {
    dp.has_sun = true;
    dp.sun_altitude_deg = inputs.sun->altitude_deg, dp.sun_azimuth_deg = inputs.sun->azimuth_deg;
  }
  dp.sun_from_site = inputs.sun_from_site;
  const daylight::QuadratureResult norm =
      daylight::horizontal_illuminance_per_zenith_luminance(inputs.sky);
  dp.sky_integral_sr = norm.value, dp.sky_integral_error_sr = norm.error_estimate;
  dp.openings = scene.openings.size();
  for (const auto& o : scene.openings) dp.glazed_openings += o.glazing_transmittance.has_value();
  dp.relative_tolerance = daylight_tolerance(scene.settings.quality);
  dp.ground_exact = dp.glazed_openings == 0 && !visibility;
  dp.sky_exact = dp.ground_exact && inputs.sky.kind == daylight::SkyKind::uniform;
  dp.luminaires_left_out = scene.luminaires.size();
  for (const Room& room : scene.rooms) {
    const Reflectances& rho = room.reflectance;
    dp.reflecting_surfaces =
        dp.reflecting_surfaces || rho.floor > 0.0 || rho.walls > 0.0 || rho.ceiling > 0.0;
    for (const auto& o : room.obstacles)
      dp.reflecting_surfaces = dp.reflecting_surfaces || o.reflectance > 0.0;
  }

  const std::vector<PreparedOpening> openings = prepare_openings(scene);
  const double tolerance = dp.relative_tolerance;
  const double sky_floor = kAbsoluteToleranceOfEh * norm.value;
  const double ground_floor = kAbsoluteToleranceOfEh * kPi;

  const auto point_parts = [&](const Vec3& point, const Vec3& normal) {
    PointParts parts;
    for (const PreparedOpening& o : openings) {
      if (!inside_room(scene.rooms[o.room], point)) continue;
      // A point in the opening's own plane (a grid point of its face, in the hole or beside it)
      // sees the opening edge-on: nothing through it.
      if (std::abs(glm::dot(point - o.triangles.front()[0], o.inward_normal)) <
          kOpeningPlaneTolerance_m)
        continue;
      const auto transmitted = [&](const Vec3& node, const Vec3& dir) {
        double t = o.factor;
        if (o.glass) t *= o.glass->transmittance(glm::dot(dir, o.inward_normal));
        if (t > 0.0 && geometry::blocked(visibility, point, node)) return 0.0;
        return t;
      };
      const std::vector<Triangle3> sky_part =
          daylight::clip_to_receiver(o.triangles, point, normal, true);
      const std::vector<Triangle3> ground_part =
          daylight::clip_to_receiver(o.triangles, point, normal, false);
      if (dp.sky_exact) {
        parts.sky += o.factor * daylight::aperture_projected_solid_angle(sky_part, point, normal);
      } else if (!sky_part.empty()) {
        const auto r = daylight::integrate_aperture(
            sky_part, point, normal,
            [&](const Vec3& node, const Vec3& dir) {
              return daylight::relative_luminance(inputs.sky, dir) * transmitted(node, dir);
            },
            0.5 * tolerance, sky_floor, kMaxTrianglesPerOpening, kMaxStartEdge_rad);
        parts.sky += r.value, parts.sky_error += r.error_estimate,
            parts.evaluations += r.evaluations;
      }
      if (dp.ground_exact) {
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
    return parts;
  };

  const double to_sky_percent = 100.0 / norm.value;
  const double to_ground_percent = 100.0 * inputs.ground_reflectance / kPi;
  std::atomic<std::size_t> evaluations{0}, outside{0};
  for (const auto& g : scene.surfaces) {
    SurfaceResult r;
    r.grid = g;
    const std::size_t n = g.points.size();
    r.SC.assign(n, 0.0), r.ERC.assign(n, 0.0), r.IRC.assign(n, 0.0), r.DF.assign(n, 0.0);
    std::vector<double> sky_error(n, 0.0), ground_error(n, 0.0);
    tbb::parallel_for(std::size_t{0}, n, [&](std::size_t i) {
      if (!g.active.empty() && !g.active[i]) return;
      bool in_a_room = false;
      for (const Room& room : scene.rooms) in_a_room = in_a_room || inside_room(room, g.points[i]);
      if (!in_a_room) {
        outside.fetch_add(1, std::memory_order_relaxed);
        return;
      }
      const PointParts p = point_parts(g.points[i], g.normals[i]);
      r.SC[i] = p.sky * to_sky_percent;
      r.ERC[i] = p.ground * to_ground_percent;
      sky_error[i] = p.sky_error * to_sky_percent;
      ground_error[i] = p.ground_error * to_ground_percent;
      evaluations.fetch_add(p.evaluations, std::memory_order_relaxed);
    });
    for (std::size_t i = 0; i < n; ++i) {
      dp.sky_error_percent = std::max(dp.sky_error_percent, sky_error[i]);
      dp.ground_error_percent = std::max(dp.ground_error_percent, ground_error[i]);
    }
    // E under the given sky: DF x E_h / 100, all of it arriving straight through the openings
    // (E_direct) until the internally reflected component is built (E_indirect).
    r.E_direct.resize(n), r.E_indirect.assign(n, 0.0), r.E.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      r.DF[i] = r.SC[i] + r.ERC[i] + r.IRC[i];
      r.E_direct[i] = (r.SC[i] + r.ERC[i]) * inputs.diffuse_horizontal_lx / 100.0;
      r.E_indirect[i] = r.IRC[i] * inputs.diffuse_horizontal_lx / 100.0;
      r.E[i] = r.E_direct[i] + r.E_indirect[i];
    }
    r.stats = compute_statistics(r.E, g.active);
    results.surfaces.push_back(std::move(r));
  }
  dp.evaluations = evaluations.load();
  dp.points_outside_rooms = outside.load();
  plan.daylight = dp;
  plan.promise = promised_error(scene.settings.quality);
  results.plan = std::move(plan);
  results.timing_s.emplace_back(
      "daylight", std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  return results;
}

}  // namespace luxgrid::calc
