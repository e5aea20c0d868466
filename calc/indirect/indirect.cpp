#include "calc/indirect/indirect.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <memory>
#include <stdexcept>

#include <tbb/parallel_for.h>

#include "calc/direct.h"
#include "calc/indirect/first_bounce.h"
#include "calc/indirect/prism_visibility.h"
#include "calc/indirect/radiosity.h"
#include "calc/scaled_distribution.h"
#include "calc/visibility.h"
#include "util/error.h"

namespace luxgrid::calc::indirect {

namespace {

// A receiver point closer than this to a patch's plane (or behind it) gets nothing from that
// patch: it lies on the same face (coplanar, F = 0) or sees it edge-on. Also keeps grid points
// lying exactly on a wall, at a floor-wall edge or in a corner finite.
constexpr double kGatherPlaneDistance_m = 1e-7;
// Points at most this far outside a room's outline still gather from it (surfaces on a wall).
constexpr double kRoomTolerance_m = 1e-3;
// Receiver points on a room face (a grid on the floor, at a floor-wall edge, in a corner) are
// moved this far into the room before gathering. On the face itself the adjacent faces are seen
// exactly edge-on and drop out, so the value there would be the limit from one side only (half a
// corner's light missing); 1 mm inside, the field is continuous and differs from the limit by far
// less than any tolerance (the analogue of the Luksch horizon shift).
constexpr double kReceiverInset_m = 1e-3;
// Auto-mode estimate of the direct light: at most this many far-field points per surface.
constexpr size_t kDecisionSamplesPerSurface = 256;

double quality_patch_size(Quality q) {
  switch (q) {
    case Quality::draft: return 1.0;
    case Quality::standard: return 0.5;
    case Quality::high: return 0.25;
    case Quality::reference: return 0.2;
  }
  return 0.5;
}
double quality_far_ratio(Quality q) {
  switch (q) {
    case Quality::draft: return 3.0;
    case Quality::standard: return 5.0;
    case Quality::high: return 8.0;
    case Quality::reference: return std::numeric_limits<double>::infinity();
  }
  return 5.0;
}
double quality_tolerance(Quality q) {
  switch (q) {
    case Quality::draft: return 1e-2;
    case Quality::standard: return 1e-3;
    case Quality::high: return 1e-4;
    case Quality::reference: return 1e-6;
  }
  return 1e-3;
}

std::string fmt(const char* f, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

double mean_reflectance(const Room& room) {
  double perimeter = 0.0;
  for (size_t k = 0; k < room.outline.size(); ++k)
    perimeter += glm::length(room.outline[(k + 1) % room.outline.size()] - room.outline[k]);
  const double a_floor = std::abs(signed_area2(room.outline)) / 2.0;
  const double a_walls = perimeter * room.height;
  const double a = 2.0 * a_floor + a_walls;
  if (!(a > 0.0)) return 0.0;
  return (a_floor * (room.reflectance.floor + room.reflectance.ceiling) +
          a_walls * room.reflectance.walls) / a;
}

// Rooms' patch mesh at the requested size, coarsened to fit the budget when the size was not
// given explicitly.
PatchMesh mesh_within_budget(const Scene& scene, const IndirectOptions& o, double size,
                             std::vector<std::string>& notes) {
  for (int attempt = 0;; ++attempt) {
    PatchMesh mesh = build_patch_mesh(scene, size);
    size_t worst = 0;
    int worst_room = 0;
    for (size_t r = 0; r + 1 < mesh.room_begin.size(); ++r) {
      const size_t c = mesh.room_begin[r + 1] - mesh.room_begin[r];
      if (c > worst) worst = c, worst_room = static_cast<int>(r);
    }
    if (worst <= o.max_patches_per_room) return mesh;
    if (o.patch_size_m > 0.0 || attempt > 20)
      throw InputError(
          "room '" + scene.rooms[worst_room].name + "': " + std::to_string(worst) +
          " patches at a patch size of " + fmt("%.3g", size) + " m exceed the budget of " +
          std::to_string(o.max_patches_per_room) + " patches per room");
    const double grow = std::sqrt(static_cast<double>(worst) / o.max_patches_per_room) * 1.05;
    notes.push_back("room '" + scene.rooms[worst_room].name + "': patch size raised from " +
                    fmt("%.3g", size) + " m to " + fmt("%.3g", size * grow) +
                    " m to stay within " + std::to_string(o.max_patches_per_room) + " patches");
    size *= grow;
  }
}

// Axis-aligned bounding box of an obstacle, grown by kBoxMargin_m.
struct Box3 {
  Vec3 lo, hi;
};
// Obstacle boxes are grown by this much so that a segment ending on an obstacle face, or grazing
// one, always goes to the exact test (the tree's end allowance is 1 um).
constexpr double kBoxMargin_m = 1e-5;

std::vector<Box3> obstacle_boxes(const Scene& scene) {
  std::vector<Box3> boxes;
  for (const auto& room : scene.rooms)
    for (const auto& o : room.obstacles) {
      Box3 b{Vec3(o.footprint[0].x, o.footprint[0].y, o.z0), Vec3(o.footprint[0].x, o.footprint[0].y, o.z1)};
      for (const auto& v : o.footprint) {
        b.lo = glm::min(b.lo, Vec3(v.x, v.y, o.z0));
        b.hi = glm::max(b.hi, Vec3(v.x, v.y, o.z1));
      }
      b.lo -= Vec3(kBoxMargin_m);
      b.hi += Vec3(kBoxMargin_m);
      boxes.push_back(b);
    }
  return boxes;
}

// True when the closed segment ab meets the box (slab test).
bool segment_meets_box(const Vec3& a, const Vec3& b, const Box3& box) {
  double t0 = 0.0, t1 = 1.0;
  const Vec3 d = b - a;
  for (int k = 0; k < 3; ++k) {
    if (d[k] == 0.0) {
      if (a[k] < box.lo[k] || a[k] > box.hi[k]) return false;
      continue;
    }
    double ta = (box.lo[k] - a[k]) / d[k], tb = (box.hi[k] - a[k]) / d[k];
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
    if (t0 > t1) return false;
  }
  return true;
}

// `x` moved to at least kReceiverInset_m inside every face of `room` that it lies on or near.
Vec3 inset_into_room(const Room& room, Vec3 x) {
  x.z = std::clamp(x.z, room.floor_z + kReceiverInset_m, room.floor_z + room.height - kReceiverInset_m);
  const auto& o = room.outline;
  for (size_t k = 0; k < o.size(); ++k) {
    const Vec2 a = o[k], b = o[(k + 1) % o.size()];
    const double len = glm::length(b - a);
    if (!(len > 0.0)) continue;
    const Vec2 t = (b - a) / len, inward(-t.y, t.x);
    const Vec2 q(x.x, x.y);
    const double along = glm::dot(q - a, t);
    const double d = glm::dot(q - a, inward);
    if (along < -kReceiverInset_m || along > len + kReceiverInset_m) continue;
    if (d > -kReceiverInset_m && d < kReceiverInset_m) {
      x.x += (kReceiverInset_m - d) * inward.x;
      x.y += (kReceiverInset_m - d) * inward.y;
    }
  }
  return x;
}

}  // namespace

IndirectOptions indirect_options(const Settings& settings) {
  IndirectOptions o;
  o.quality = settings.quality;
  o.bounces = settings.bounces;
  return o;
}

IndirectDecision decide_indirect(const Scene& scene) {
  IndirectDecision d;
  if (scene.settings.indirect == IndirectMode::off) {
    d.reason = "skipped: indirect is off in the settings";
    return d;
  }
  bool any = false;
  for (const auto& r : scene.rooms)
  {
    any = any || r.reflectance.floor > 0.0 || r.reflectance.walls > 0.0 ||
          r.reflectance.ceiling > 0.0;
    for (const auto& o : r.obstacles) any = any || o.reflectance > 0.0;
  }
  if (!any) {
    d.reason = "skipped: all reflectances are 0";
    return d;
  }
  if (scene.luminaires.empty()) {
    d.reason = "skipped: no luminaires";
    return d;
  }
  // Integrating-sphere estimate per room: rho Phi / (A (1 - rho)), rho area-weighted.
  // luminous_flux integrates the whole distribution: once per distinct one.
  std::map<const photometry::IntensityDistribution*, double> flux_of;
  for (size_t r = 0; r < scene.rooms.size(); ++r) {
    const Room& room = scene.rooms[r];
    double flux = 0.0;
    for (const auto& lum : scene.luminaires)
      if (room_containing(scene, lum.pose.position, 0.0) == static_cast<int>(r)) {
        auto [it, fresh] = flux_of.try_emplace(lum.distribution.get(), 0.0);
        if (fresh) it->second = luminous_flux(*lum.distribution);
        flux += it->second;
      }
    const double rho = mean_reflectance(room);
    const double area = room_surface_area(room);
    const double e = rho < 1.0 && area > 0.0 ? rho * flux / (area * (1.0 - rho))
                                             : std::numeric_limits<double>::infinity();
    d.estimate_lx = std::max(d.estimate_lx, e);
  }
  if (scene.settings.indirect == IndirectMode::on) {
    d.run = true;
    d.reason = "on (forced by the settings); integrating-sphere estimate " +
               fmt("%.4g", d.estimate_lx) + " lx";
    return d;
  }
  // Mean direct light on the calculation surfaces, far field, on a sample of points.
  double sum = 0.0;
  size_t count = 0;
  for (const auto& s : scene.surfaces) {
    const size_t step = std::max<size_t>(1, s.points.size() / kDecisionSamplesPerSurface);
    for (size_t i = 0; i < s.points.size(); i += step) {
      if (!s.active.empty() && !s.active[i]) continue;
      double e = 0.0;
      for (const auto& lum : scene.luminaires) e += far_field_illuminance(lum, s.points[i], s.normals[i]);
      sum += e;
      ++count;
    }
  }
  d.mean_direct_lx = count ? sum / count : 0.0;
  if (count > 0 && d.estimate_lx < kAutoSkipFraction * d.mean_direct_lx) {
    d.reason = "skipped: integrating-sphere estimate " + fmt("%.4g", d.estimate_lx) +
               " lx is below 1 % of the mean direct illuminance " + fmt("%.4g", d.mean_direct_lx) +
               " lx";
    return d;
  }
  d.run = true;
  d.reason = "on: integrating-sphere estimate " + fmt("%.4g", d.estimate_lx) + " lx" +
             (count ? " against a mean direct illuminance of " + fmt("%.4g", d.mean_direct_lx) + " lx"
                    : std::string());
  return d;
}

double gather_point(const PatchMesh& mesh, size_t begin, size_t end,
                    const std::vector<double>& exitant_flux_lm, const Vec3& x, const Vec3& n,
                    double far_ratio, const OcclusionFn& occluded) {
  double e = 0.0;
  for (size_t j = begin; j < end; ++j) {
    const double flux = exitant_flux_lm[j];
    if (!(flux > 0.0)) continue;
    const Patch& p = mesh.patches[j];
    if (!(glm::dot(p.normal, x - p.centroid) > kGatherPlaneDistance_m)) continue;
    const double d = glm::length(x - p.centroid);
    double f = d > far_ratio * p.diameter_m
                   ? point_kernel_form_factor(x, n, p.centroid, p.normal, p.area_m2)
                   : point_polygon_form_factor(x, n, p.polygon);
    if (f > 0.0 && occluded) {
      // Fraction of the patch visible from x (centroid and four inner points).
      int seen = 0;
      const Vec3 from = x + n * 1e-6;
      seen += occluded(from, p.centroid + p.normal * 1e-6) ? 0 : 1;
      for (const auto& v : p.polygon) seen += occluded(from, 0.5 * (v + p.centroid) + p.normal * 1e-6) ? 0 : 1;
      f *= static_cast<double>(seen) / static_cast<double>(p.polygon.size() + 1);
    }
    e += flux / p.area_m2 * f;  // exitance M = flux / area; E = M F
  }
  return e;
}

IndirectResult compute_indirect(const Scene& scene,
                                const std::vector<geometry::SurfaceGrid>& surfaces,
                                const IndirectOptions& options) {
  const auto t0 = std::chrono::steady_clock::now();
  IndirectResult res;
  const double size = options.patch_size_m > 0.0 ? options.patch_size_m
                                                 : quality_patch_size(options.quality);
  const double far_ratio = options.far_ratio > 0.0 ? options.far_ratio
                                                   : quality_far_ratio(options.quality);
  const double tol = options.tolerance > 0.0 ? options.tolerance
                                             : quality_tolerance(options.quality);
  const int bounces = options.bounces > 0 ? options.bounces
                      : options.quality == Quality::draft ? 1 : 0;

  const PatchMesh mesh = mesh_within_budget(scene, options, size, res.notes);
  res.patches = mesh.patches.size();
  res.patch_size_m = mesh.patch_size_m;

  // Visibility: the caller's callback (the pipeline passes the scene's AABB tree); else, with
  // obstacles, our own tree over scene_faces (rooms and obstacles); else the prism test for
  // non-convex rooms, and nothing for convex ones.
  size_t obstacle_count = 0;
  for (const auto& room : scene.rooms) obstacle_count += room.obstacles.size();
  std::shared_ptr<const Visibility> own_tree;
  OcclusionFn tree_occlusion;
  if (!options.occluded && obstacle_count > 0) {
    own_tree = std::make_shared<const Visibility>(scene_faces(scene));
    tree_occlusion = [own_tree](const Vec3& a, const Vec3& b) { return !own_tree->visible(a, b); };
  }
  std::vector<OcclusionFn> occlusion(scene.rooms.size());
  bool prism = false;
  const auto boxes = std::make_shared<const std::vector<Box3>>(obstacle_boxes(scene));
  for (size_t r = 0; r < scene.rooms.size(); ++r) {
    const OcclusionFn& general = options.occluded ? options.occluded : tree_occlusion;
    if (general && outline_is_convex(scene.rooms[r])) {
      // In a convex room only obstacles can block a segment between two of its points: skip
      // the tree for segments that miss every obstacle's box (most of them), an exact filter.
      occlusion[r] = [boxes, general](const Vec3& a, const Vec3& b) {
        for (const auto& box : *boxes)
          if (segment_meets_box(a, b, box)) return general(a, b);
        return false;
      };
    } else if (general) {
      occlusion[r] = general;
    } else if (!outline_is_convex(scene.rooms[r])) {
      occlusion[r] = prism_occlusion(scene.rooms[r]), prism = true;
    }
  }

  const FirstBounce fb = first_bounce(scene, mesh, occlusion);
  for (const auto& n : fb.notes) res.notes.push_back(n);
  res.vpls = fb.vpl_count;
  res.emitted_flux_lm = fb.emitted_flux_lm;
  res.received_flux_lm = fb.received_flux_lm;
  for (double f : fb.vpl_flux_lm) res.vpl_flux_lm += f;

  // Exitant flux per patch, room by room (rooms are closed: no light passes between them).
  std::vector<double> exitant(mesh.patches.size(), 0.0);
  for (size_t r = 0; r < scene.rooms.size(); ++r) {
    const size_t begin = mesh.room_begin[r], end = mesh.room_begin[r + 1];
    std::vector<double> rho(end - begin), incident(end - begin);
    double room_vpl = 0.0;
    for (size_t i = begin; i < end; ++i) {
      rho[i - begin] = mesh.patches[i].reflectance;
      incident[i - begin] = fb.incident_flux_lm[i];
      room_vpl += fb.vpl_flux_lm[i];
    }
    if (!(room_vpl > 0.0)) continue;
    RadiosityResult sol;
    if (bounces == 1) {
      // The seed's one-bounce model needs no form factors between patches.
      FormFactorMatrix none;
      none.n = end - begin;
      sol = solve_radiosity(none, rho, incident, 1, tol);
    } else {
      const FormFactorMatrix F = form_factors(mesh, static_cast<int>(r), occlusion[r], far_ratio);
      res.max_row_correction = std::max(res.max_row_correction, F.max_row_correction);
      sol = solve_radiosity(F, rho, incident, bounces, tol);
    }
    res.bounces_run = std::max(res.bounces_run, sol.bounces_run);
    res.tail_added = res.tail_added || sol.tail_added;
    res.residual = std::max(res.residual, sol.residual);
    for (size_t i = begin; i < end; ++i) exitant[i] = sol.exitant_flux_lm[i - begin];
  }

  // Final gather.
  res.E_indirect_per_surface.resize(surfaces.size());
  for (size_t s = 0; s < surfaces.size(); ++s) {
    const auto& grid = surfaces[s];
    auto& out = res.E_indirect_per_surface[s];
    out.assign(grid.points.size(), 0.0);
    tbb::parallel_for(size_t(0), grid.points.size(), [&](size_t i) {
      if (!grid.active.empty() && !grid.active[i]) return;
      const int r = room_containing(scene, grid.points[i], kRoomTolerance_m);
      if (r < 0) return;
      const size_t begin = mesh.room_begin[r], end = mesh.room_begin[r + 1];
      const Vec3 x = inset_into_room(scene.rooms[r], grid.points[i]);
      out[i] = gather_point(mesh, begin, end, exitant, x, grid.normals[i],
                            far_ratio, occlusion[r]);
    });
  }
  res.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  std::string what = bounces == 1 ? "one bounce (RSM-style)"
                     : bounces > 1 ? std::to_string(bounces) + " bounces"
                                   : "converged interreflection (" + std::to_string(res.bounces_run) +
                                         " bounces" + (res.tail_added ? " + geometric tail" : "") + ")";
  res.summary = what + ": " + std::to_string(res.patches) + " patches of " +
                fmt("%.3g", res.patch_size_m) + " m, " + std::to_string(res.vpls) +
                " virtual point lights, residual " + fmt("%.2g", res.residual) + "; direct flux on room faces " +
                fmt("%.6g", res.received_flux_lm) + " lm of " + fmt("%.6g", res.emitted_flux_lm) +
                " lm emitted" + (prism ? "; visibility: walls of non-convex rooms" : "") +
                (options.occluded ? "; visibility: occlusion callback" : "") +
                (own_tree ? "; visibility: AABB tree of room and obstacle faces" : "") +
                (obstacle_count ? "; " + std::to_string(obstacle_count) + " obstacle" +
                                      (obstacle_count == 1 ? "" : "s") + " reflect and shade"
                                : std::string());
  return res;
}

}  // namespace luxgrid::calc::indirect
