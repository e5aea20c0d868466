#include "calc/indirect/indirect.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>

#include <tbb/parallel_for.h>

#include "calc/direct.h"
#include "calc/indirect/emitter_cells.h"
#include "calc/indirect/first_bounce.h"
#include "calc/indirect/radiosity.h"
#include "calc/scaled_distribution.h"
#include "calc/visibility.h"
#include "geometry/box3.h"
#include "util/error.h"
#include "util/format.h"

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
// The plan line gives the flux of the whole openings beside the flux entering the rooms when
// they differ by more than this (rounding of the clip planes, emitter_cells.h).
constexpr double kOutsideFluxFraction = 1e-6;

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

// The patch size at which the rooms' patch counts are estimated (surface area / size^2, the
// count of a box room) to fit the per-room budget and kMaxTotalPatches: checked before the mesh
// is built, so that a huge room is never meshed at a fine size first (1 km^2 at 0.5 m would be
// 8 million patches, gigabytes, before the budget is checked). With an explicit size an excess
// is an error naming the room or the total.
double size_within_limits(const Scene& scene, const IndirectOptions& o, double size,
                          std::vector<std::string>& notes) {
  double total_area = 0.0, worst_area = 0.0;
  int worst_room = 0;
  for (size_t r = 0; r < scene.rooms.size(); ++r) {
    const double a = room_surface_area(scene.rooms[r]);
    total_area += a;
    if (a > worst_area) worst_area = a, worst_room = static_cast<int>(r);
  }
  const double worst = worst_area / (size * size), total = total_area / (size * size);
  const double budget = static_cast<double>(o.max_patches_per_room);
  const double limit = static_cast<double>(kMaxTotalPatches);
  if (!(worst > budget) && !(total > limit)) return size;
  if (o.patch_size_m > 0.0) {
    if (worst > budget)
      throw InputError("room '" + scene.rooms[worst_room].name + "': " +
                       std::to_string(std::llround(worst)) + " patches at a patch size of " +
                       format_double("%.3g", size) + " m exceed the budget of " +
                       std::to_string(o.max_patches_per_room) + " patches per room");
    throw InputError(std::to_string(std::llround(total)) + " patches in " +
                     std::to_string(scene.rooms.size()) + " rooms at a patch size of " +
                     format_double("%.3g", size) + " m exceed the limit of " +
                     std::to_string(kMaxTotalPatches) + " patches in all rooms");
  }
  const double grow = std::sqrt(std::max(worst / budget, total / limit));
  notes.push_back(
      (worst / budget >= total / limit
           ? "room '" + scene.rooms[worst_room].name + "': patch size raised from "
           : "all " + std::to_string(scene.rooms.size()) + " rooms: patch size raised from ") +
      format_double("%.3g", size) + " m to " + format_double("%.3g", size * grow) +
      " m to stay within " +
      (worst / budget >= total / limit
           ? std::to_string(o.max_patches_per_room) + " patches per room"
           : std::to_string(kMaxTotalPatches) + " patches in all rooms"));
  return size * grow;
}

// Rooms' patch mesh at the requested size, coarsened to fit the budget when the size was not
// given explicitly.
PatchMesh mesh_within_budget(const Scene& scene, IndirectOptions o, double size,
                             std::vector<std::string>& notes) {
  if (o.max_patches_per_room > kMaxPatchesPerRoom) {
    notes.push_back("indirect: the budget of " + std::to_string(o.max_patches_per_room) +
                    " patches per room is above the limit of " +
                    std::to_string(kMaxPatchesPerRoom) + " (a form-factor matrix of " +
                    std::to_string(kMaxFormFactorMatrixBytes / kBytesPerMegabyte) + " MB); " +
                    std::to_string(kMaxPatchesPerRoom) + " used");
    o.max_patches_per_room = kMaxPatchesPerRoom;
  }
  size = size_within_limits(scene, o, size, notes);
  size_t previous_worst = 0;
  for (int attempt = 0;; ++attempt) {
    PatchMesh mesh = build_patch_mesh(scene, size);
    size_t worst = 0;
    int worst_room = 0;
    for (size_t r = 0; r + 1 < mesh.room_begin.size(); ++r) {
      const size_t c = mesh.room_begin[r + 1] - mesh.room_begin[r];
      if (c > worst) worst = c, worst_room = static_cast<int>(r);
    }
    const size_t total = mesh.patches.size();
    if (worst <= o.max_patches_per_room && total <= kMaxTotalPatches) return mesh;
    // Every face is at least one patch: once larger patches no longer lower the count, the
    // room's faces alone exceed the budget (thousands of small obstacles).
    if (attempt > 0 && worst > o.max_patches_per_room && worst >= previous_worst) {
      const Room& room = scene.rooms[worst_room];
      throw InputError("room \"" + room.name + "\": its walls and " +
                       std::to_string(room.obstacles.size()) + " obstacles have " +
                       std::to_string(worst) +
                       " faces, each at least one patch, more than the budget of " +
                       std::to_string(o.max_patches_per_room) +
                       " patches per room; use fewer obstacles, or \"indirect\": \"off\"");
    }
    previous_worst = worst;
    if (worst <= o.max_patches_per_room) {
      // Obstacles and clipped boundary cells beyond the estimate of size_within_limits.
      if (o.patch_size_m > 0.0 || attempt > 20)
        throw InputError(std::to_string(total) + " patches in " +
                         std::to_string(scene.rooms.size()) + " rooms at a patch size of " +
                         format_double("%.3g", size) + " m exceed the limit of " +
                         std::to_string(kMaxTotalPatches) + " patches in all rooms");
      const double grow = std::sqrt(static_cast<double>(total) / kMaxTotalPatches) * 1.05;
      notes.push_back("all rooms: patch size raised from " + format_double("%.3g", size) +
                      " m to " + format_double("%.3g", size * grow) + " m to stay within " +
                      std::to_string(kMaxTotalPatches) + " patches in all rooms");
      size *= grow;
      continue;
    }
    if (o.patch_size_m > 0.0 || attempt > 20)
      throw InputError("room '" + scene.rooms[worst_room].name + "': " + std::to_string(worst) +
                       " patches at a patch size of " + format_double("%.3g", size) +
                       " m exceed the budget of " + std::to_string(o.max_patches_per_room) +
                       " patches per room");
    const double grow = std::sqrt(static_cast<double>(worst) / o.max_patches_per_room) * 1.05;
    notes.push_back("room '" + scene.rooms[worst_room].name + "': patch size raised from " +
                    format_double("%.3g", size) + " m to " + format_double("%.3g", size * grow) +
                    " m to stay within " + std::to_string(o.max_patches_per_room) + " patches");
    size *= grow;
  }
}

// The gather's visibility segments start this far in front of the receiver and end this far in
// front of the patch (patches.h visible_fraction), so neither end's own face hides the other.
constexpr double kGatherLift_m = 1e-6;

using geometry::Box3;
using geometry::box_distance2;
using geometry::box_max_height;
using geometry::box_min_height;

// Axis-aligned bounding boxes of the obstacles, grown by kBoxMargin_m.
// Obstacle boxes are grown by this much so that a segment ending on an obstacle face, or grazing
// one, always goes to the exact test (the tree's end allowance is 1 um).
constexpr double kBoxMargin_m = 1e-5;

std::vector<Box3> obstacle_boxes(const Scene& scene) {
  std::vector<Box3> boxes;
  for (const auto& room : scene.rooms)
    for (const auto& o : room.obstacles) {
      Box3 b{Vec3(o.footprint[0].x, o.footprint[0].y, o.z0),
             Vec3(o.footprint[0].x, o.footprint[0].y, o.z1)};
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

// A receiver on a face of `room` (within kReceiverInset_m) whose normal points out through that
// face lies on the face's outer side: the opaque face hides the whole room from it, so it gathers
// nothing from the room. Without this test the inset below would move it inside, where it would
// face its own face from 1 mm and receive that face's whole exitance (a wall grid facing out of
// the room would read the wall's exitance). The cosine limit keeps a receiver whose normal lies
// in the face's plane (a floor grid at a wall) gathering: only a normal pointing out counts.
constexpr double kFacingOutCosine = 1e-9;
bool faces_out_of_room(const Room& room, const Vec3& x, const Vec3& n) {
  if (std::abs(x.z - room.floor_z) < kReceiverInset_m && n.z < -kFacingOutCosine) return true;
  if (std::abs(x.z - room.floor_z - room.height) < kReceiverInset_m && n.z > kFacingOutCosine)
    return true;
  for (size_t k = 0; k < room.outline.size(); ++k) {
    const geometry::EdgeCoordinates e = geometry::edge_coordinates(room.outline, k, Vec2(x.x, x.y));
    if (!(e.length_m > 0.0)) continue;
    if (e.along_m < -kReceiverInset_m || e.along_m > e.length_m + kReceiverInset_m) continue;
    if (std::abs(e.inside_m) < kReceiverInset_m &&
        glm::dot(Vec2(n.x, n.y), e.inward) < -kFacingOutCosine)
      return true;
  }
  return false;
}

// `x` moved to at least kReceiverInset_m inside every face of `room` that it lies on or near.
Vec3 inset_into_room(const Room& room, Vec3 x) {
  x.z = std::clamp(x.z, room.floor_z + kReceiverInset_m,
                   room.floor_z + room.height - kReceiverInset_m);
  for (size_t k = 0; k < room.outline.size(); ++k) {
    const geometry::EdgeCoordinates e = geometry::edge_coordinates(room.outline, k, Vec2(x.x, x.y));
    if (!(e.length_m > 0.0)) continue;
    if (e.along_m < -kReceiverInset_m || e.along_m > e.length_m + kReceiverInset_m) continue;
    const double d = e.inside_m;
    if (d > -kReceiverInset_m && d < kReceiverInset_m) {
      x.x += (kReceiverInset_m - d) * e.inward.x;
      x.y += (kReceiverInset_m - d) * e.inward.y;
    }
  }
  return x;
}

// The emitting patches of one room (exitant flux > 0) laid out for the final gather: in groups
// of consecutive patches with the same normal (a face, or part of one), each cut into chunks of
// nearby patches (tiles of kChunkTile x the largest diameter). A receiver skips a whole group
// when it lies behind the group's plane (the floor, for a workplane point), and a whole chunk
// when the chunk lies wholly behind the receiver's tangent plane (its own wall): exactly the
// patches whose form factor is 0. A chunk wholly in front of the receiver and farther than every
// one of its patches' near distances takes the far kernel for all its patches in one loop without
// branches. Thirteen thousand points times a few thousand patches is the largest loop of
// calc/indirect.
constexpr double kChunkTile = 4.0;
struct GatherSet {
  // Entries (patches with flux), structure of arrays, ordered by group and chunk.
  std::vector<double> cx, cy, cz, flux_lm;
  std::vector<double>
      near_d2;                // (far_ratio x diameter)^2: closer, the quarters or the exact formula
  std::vector<size_t> patch;  // index into the mesh
  struct Chunk {
    size_t begin = 0, end = 0;  // entries
    Vec3 lo{0.0}, hi{0.0};      // bounding box of the patches' vertices
    Vec3 clo{0.0}, chi{0.0};    // bounding box of the centroids
    double max_near_d2 = 0.0;
  };
  struct Group {
    size_t begin = 0, end = 0;  // chunks
    Vec3 normal{0.0};
    double max_offset = 0.0;  // largest normal . centroid over the group
  };
  std::vector<Chunk> chunks;
  std::vector<Group> groups;
};

GatherSet make_gather_set(const PatchMesh& mesh, size_t begin, size_t end,
                          const std::vector<double>& exitant_flux_lm, double far_ratio) {
  GatherSet set;
  // Runs of emitting patches with the same normal.
  std::vector<std::pair<size_t, size_t>> runs;  // [first, last) into `emitting`
  std::vector<size_t> emitting;
  for (size_t j = begin; j < end; ++j) {
    if (!(exitant_flux_lm[j] > 0.0)) continue;
    if (emitting.empty() || mesh.patches[emitting.back()].normal != mesh.patches[j].normal)
      runs.push_back({emitting.size(), emitting.size()});
    emitting.push_back(j);
    runs.back().second = emitting.size();
  }
  for (const auto& [first, last] : runs) {
    GatherSet::Group g;
    g.normal = mesh.patches[emitting[first]].normal;
    g.max_offset = -std::numeric_limits<double>::infinity();
    g.begin = set.chunks.size();
    Vec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
    double dmax = 0.0;
    for (size_t k = first; k < last; ++k) {
      const Patch& p = mesh.patches[emitting[k]];
      lo = glm::min(lo, p.centroid), hi = glm::max(hi, p.centroid);
      dmax = std::max(dmax, p.diameter_m);
      g.max_offset = std::max(g.max_offset, glm::dot(p.normal, p.centroid));
    }
    // Tiles of kChunkTile x the largest diameter: sort the run by tile (stable, so the order
    // within a tile is the mesh's).
    const double tile = std::max(kChunkTile * dmax, 1e-9);
    auto key = [&](size_t j) {
      const Vec3 t = glm::floor((mesh.patches[j].centroid - lo) / tile);
      return std::array<double, 3>{t.x, t.y, t.z};
    };
    std::vector<size_t> order(emitting.begin() + first, emitting.begin() + last);
    std::stable_sort(order.begin(), order.end(),
                     [&](size_t a, size_t b) { return key(a) < key(b); });
    for (size_t k = 0; k < order.size(); ++k) {
      if (k == 0 || key(order[k]) != key(order[k - 1])) {
        GatherSet::Chunk c;
        c.begin = c.end = set.patch.size();
        c.lo = c.clo = Vec3(std::numeric_limits<double>::infinity());
        c.hi = c.chi = Vec3(-std::numeric_limits<double>::infinity());
        set.chunks.push_back(c);
      }
      const size_t j = order[k];
      const Patch& p = mesh.patches[j];
      GatherSet::Chunk& c = set.chunks.back();
      const double limit = far_ratio * p.diameter_m;
      set.cx.push_back(p.centroid.x);
      set.cy.push_back(p.centroid.y);
      set.cz.push_back(p.centroid.z);
      set.flux_lm.push_back(exitant_flux_lm[j]);
      set.near_d2.push_back(limit * limit);
      set.patch.push_back(j);
      c.end = set.patch.size();
      c.clo = glm::min(c.clo, p.centroid), c.chi = glm::max(c.chi, p.centroid);
      for (const auto& v : p.polygon) c.lo = glm::min(c.lo, v), c.hi = glm::max(c.hi, v);
      c.max_near_d2 = std::max(c.max_near_d2, limit * limit);
    }
    g.end = set.chunks.size();
    set.groups.push_back(g);
  }
  return set;
}

// Form factor from the point (x, n) to patch p in the final gather: the point kernel when the
// patch is far (`far`: beyond far_ratio x its diameter), the kernel on its quarters between
// far_ratio x D / 2 and far_ratio x D, Lambert's exact polygon formula closer (and whenever the
// quarter rule declines: non-parallelogram patches, patches crossing the horizon).
double gather_form_factor(const Vec3& x, const Vec3& n, const Patch& p, double far_ratio,
                          bool far) {
  if (far) return point_kernel_form_factor(x, n, p.centroid, p.normal, p.area_m2);
  const double half = 0.5 * far_ratio * p.diameter_m;
  const double f = p.has_quarters
                       ? quarter_kernel_form_factor(x, n, p.polygon, p.centroid, p.quarter_centroid,
                                                    p.normal, p.area_m2, p.diameter_m, half * half)
                       : -1.0;
  return f < 0.0 ? point_polygon_form_factor(x, n, p.polygon) : f;
}

double gather_set_point(const PatchMesh& mesh, const GatherSet& set, const Vec3& x, const Vec3& n,
                        double far_ratio, const geometry::Visibility* visibility) {
  double near = 0.0, far = 0.0;
  const double* cx = set.cx.data();
  const double* cy = set.cy.data();
  const double* cz = set.cz.data();
  const double* flux = set.flux_lm.data();
  for (const auto& g : set.groups) {
    // x behind (or on) the plane of every patch of the group: each term is skipped below.
    if (!(glm::dot(g.normal, x) - g.max_offset > kGatherPlaneDistance_m)) continue;
    const Vec3 m = g.normal;
    for (size_t c = g.begin; c < g.end; ++c) {
      const GatherSet::Chunk& ch = set.chunks[c];
      // Every vertex behind the receiver's tangent plane: so are the centroids and quarter
      // centroids, and the kernel and the horizon-clipped polygon give 0.
      if (box_max_height(n, x, ch.lo, ch.hi) < 0.0) continue;
      if (!visibility && box_min_height(n, x, ch.clo, ch.chi) > 0.0 &&
          box_distance2(x, ch.clo, ch.chi) > ch.max_near_d2) {
        // Far kernel for the whole chunk: every centroid in front of the receiver (n . dx < 0),
        // the receiver in front of every patch (group test), farther than its near distance.
        double sum = 0.0;
        for (size_t k = ch.begin; k < ch.end; ++k) {
          const double dx = x.x - cx[k], dy = x.y - cy[k], dz = x.z - cz[k];
          const double hm = m.x * dx + m.y * dy + m.z * dz;
          const double hn = -(n.x * dx + n.y * dy + n.z * dz);
          const double d2 = dx * dx + dy * dy + dz * dz;
          sum += flux[k] * point_kernel_pi_per_m2(hm, hn, d2);
        }
        far += sum;
        continue;
      }
      for (size_t k = ch.begin; k < ch.end; ++k) {
        const Vec3 dx = x - Vec3(cx[k], cy[k], cz[k]);
        const double hm = glm::dot(m, dx);
        if (!(hm > kGatherPlaneDistance_m)) continue;
        const double d2 = glm::dot(dx, dx);
        if (d2 > set.near_d2[k] && !visibility) {
          // point_kernel_form_factor x exitance: flux x the kernel / pi (the pi once, below)
          const double hn = -glm::dot(n, dx);
          if (hn > 0.0) far += flux[k] * point_kernel_pi_per_m2(hm, hn, d2);
          continue;
        }
        const Patch& p = mesh.patches[set.patch[k]];
        double f = gather_form_factor(x, n, p, far_ratio, d2 > set.near_d2[k]);
        if (f > 0.0 && visibility)
          f *= visible_fraction(visibility, x + n * kGatherLift_m, p, kGatherLift_m);
        near += flux[k] / p.area_m2 * f;
      }
    }
  }
  return near + far / kPi;
}

}  // namespace

IndirectOptions indirect_options(const Settings& settings) {
  IndirectOptions o;
  o.quality = settings.quality;
  o.bounces = settings.bounces;
  return o;
}

IndirectResult compute_indirect(const Scene& scene,
                                const std::vector<geometry::SurfaceGrid>& surfaces,
                                const IndirectOptions& options) {
  const auto t0 = std::chrono::steady_clock::now();
  IndirectResult res;
  const double size =
      options.patch_size_m > 0.0 ? options.patch_size_m : quality_patch_size(options.quality);
  const double far_ratio =
      options.far_ratio > 0.0 ? options.far_ratio : quality_far_ratio(options.quality);
  const double tol =
      options.tolerance > 0.0 ? options.tolerance : quality_tolerance(options.quality);
  const int bounces = options.bounces > 0                 ? options.bounces
                      : options.quality == Quality::draft ? 1
                                                          : 0;

  const PatchMesh mesh = mesh_within_budget(scene, options, size, res.notes);
  res.patches = mesh.patches.size();
  res.patch_size_m = mesh.patch_size_m;

  // Visibility: the plan's (the scene's AABB tree, calc/visibility), or nothing blocks.
  size_t obstacle_count = 0;
  for (const auto& room : scene.rooms) obstacle_count += room.obstacles.size();
  std::vector<const geometry::Visibility*> room_visibility(scene.rooms.size(), nullptr);
  std::optional<geometry::BoxFilteredVisibility> obstacles_only;
  if (const geometry::Visibility* vis = options.visibility.get()) {
    // In a convex room only obstacles can block a segment between two of its points: skip the
    // tree for segments that miss every obstacle's box (most of them), an exact filter.
    obstacles_only.emplace(*vis, obstacle_boxes(scene));
    for (size_t r = 0; r < scene.rooms.size(); ++r)
      room_visibility[r] = outline_is_convex(scene.rooms[r]) ? &*obstacles_only : vis;
  }

  const FirstBounce fb = first_bounce(scene, mesh, room_visibility, 0.08, &options.luminous_flux_lm,
                                      &options.intensity_lookup);
  for (const auto& n : fb.notes) res.notes.push_back(n);
  res.vpls = fb.vpl_count;
  res.emitted_flux_lm = fb.emitted_flux_lm;
  res.luminaire_flux_lm = fb.luminaire_flux_lm;
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
      const FormFactorMatrix F =
          form_factors(mesh, static_cast<int>(r), room_visibility[r], far_ratio);
      res.max_row_correction = std::max(res.max_row_correction, F.max_row_correction);
      sol = solve_radiosity(F, rho, incident, bounces, tol);
    }
    res.bounces_run = std::max(res.bounces_run, sol.bounces_run);
    res.tail_added = res.tail_added || sol.tail_added;
    res.residual = std::max(res.residual, sol.residual);
    for (size_t i = begin; i < end; ++i) exitant[i] = sol.exitant_flux_lm[i - begin];
  }

  // Final gather.
  std::vector<GatherSet> gather_sets;
  for (size_t r = 0; r < scene.rooms.size(); ++r)
    gather_sets.push_back(
        make_gather_set(mesh, mesh.room_begin[r], mesh.room_begin[r + 1], exitant, far_ratio));
  res.E_indirect_per_surface.resize(surfaces.size());
  for (size_t s = 0; s < surfaces.size(); ++s) {
    const auto& grid = surfaces[s];
    auto& out = res.E_indirect_per_surface[s];
    out.assign(grid.points.size(), 0.0);
    tbb::parallel_for(size_t(0), grid.points.size(), [&](size_t i) {
      if (!grid.active.empty() && !grid.active[i]) return;
      const int r = room_containing(scene, grid.points[i], kRoomTolerance_m);
      if (r < 0 || faces_out_of_room(scene.rooms[r], grid.points[i], grid.normals[i])) return;
      const Vec3 x = inset_into_room(scene.rooms[r], grid.points[i]);
      out[i] =
          gather_set_point(mesh, gather_sets[r], x, grid.normals[i], far_ratio, room_visibility[r]);
    });
  }
  res.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  std::string what = bounces == 1 ? "one bounce (RSM-style)"
                     : bounces > 1
                         ? std::to_string(bounces) + " bounces"
                         : "converged interreflection (" + std::to_string(res.bounces_run) +
                               " bounces" + (res.tail_added ? " + geometric tail" : "") + ")";
  res.summary =
      what + ": " + std::to_string(res.patches) + " patches of " +
      format_double("%.3g", res.patch_size_m) + " m, " + std::to_string(res.vpls) +
      " virtual point lights, residual " + format_double("%.2g", res.residual) +
      "; direct flux on room faces " + format_double("%.6g", res.received_flux_lm) + " lm of " +
      format_double("%.6g", res.emitted_flux_lm) + " lm emitted into the rooms" +
      (res.emitted_flux_lm < res.luminaire_flux_lm * (1.0 - kOutsideFluxFraction)
           ? " (of " + format_double("%.6g", res.luminaire_flux_lm) + " lm from the whole openings)"
           : std::string()) +
      (options.visibility ? "; visibility: AABB tree of room and obstacle faces" : "") +
      (obstacle_count ? "; " + std::to_string(obstacle_count) + " obstacle" +
                            (obstacle_count == 1 ? "" : "s") + " reflect and shade"
                      : std::string());
  return res;
}

}  // namespace luxgrid::calc::indirect
