#include "calc/indirect/indirect.h"

#include <algorithm>
#include <array>
#include <atomic>
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
#include "calc/indirect/clustered.h"
#include "calc/indirect/emitter_cells.h"
#include "calc/indirect/first_bounce.h"
#include "calc/indirect/gather.h"
#include "calc/indirect/radiosity.h"
#include "calc/indirect/split_mask.h"
#include "calc/indirect/subcells.h"
#include "calc/scaled_distribution.h"
#include "calc/scene_visibility.h"
#include "geometry/box3.h"
#include "util/error.h"
#include "util/format.h"

namespace luxgrid::calc::indirect {

namespace {

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
// The relative jump of exitance between neighbouring patches above which a patch is cut
// (split_mask.h): 0 where the quality does not cut (`draft`, which promises nothing).
double quality_split_jump(Quality q) { return q == Quality::draft ? 0.0 : kSplitJump; }

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

// Per room: whether it is solved with the clustered transfer (clustered.h), decided once at the
// requested size, and its patch budget.
struct RoomBudgets {
  std::vector<char> clustered;
  std::vector<size_t> budget;
};
RoomBudgets room_budgets(const Scene& scene, const IndirectOptions& o, double size) {
  RoomBudgets b;
  for (size_t r = 0; r < scene.rooms.size(); ++r) {
    const bool c =
        o.clustered.empty() ? use_clustered_transfer(scene.rooms[r], size) : o.clustered.at(r) != 0;
    b.clustered.push_back(c);
    b.budget.push_back(c ? kMaxClusteredPatchesPerRoom : o.max_patches_per_room);
  }
  return b;
}

// The room farthest over its budget and the totals of the dense and the clustered rooms against
// their limits (kMaxTotalPatches, kMaxClusteredTotalPatches), from per-room patch counts.
struct BudgetUse {
  double worst_ratio = 0.0, worst = 0.0;  // count / budget, count of the worst room
  int worst_room = 0;
  double total_ratio = 0.0, total = 0.0;  // the class of rooms farther over its limit
  size_t limit = kMaxTotalPatches;
};
BudgetUse budget_use(const RoomBudgets& b, const std::vector<double>& count) {
  BudgetUse u;
  double dense = 0.0, clustered = 0.0;
  for (size_t r = 0; r < count.size(); ++r) {
    const double ratio = count[r] / static_cast<double>(b.budget[r]);
    if (ratio > u.worst_ratio) u.worst_ratio = ratio, u.worst = count[r], u.worst_room = int(r);
    (b.clustered[r] ? clustered : dense) += count[r];
  }
  const double dense_ratio = dense / static_cast<double>(kMaxTotalPatches);
  const double clustered_ratio = clustered / static_cast<double>(kMaxClusteredTotalPatches);
  if (clustered_ratio > dense_ratio) {
    u.total_ratio = clustered_ratio, u.total = clustered, u.limit = kMaxClusteredTotalPatches;
  } else {
    u.total_ratio = dense_ratio, u.total = dense, u.limit = kMaxTotalPatches;
  }
  return u;
}
std::string total_limit_text(size_t limit) {
  return std::to_string(limit) + " patches in all " +
         (limit == kMaxTotalPatches ? "rooms" : "clustered rooms");
}
IndirectNote raised(IndirectNote::Kind kind, double from_m, double to_m) {
  IndirectNote n;
  n.kind = kind;
  n.from_m = from_m;
  n.to_m = to_m;
  return n;
}

// The patch size at which the rooms' patch counts are estimated (surface area / size^2, the
// count of a box room) to fit the per-room budget and kMaxTotalPatches: checked before the mesh
// is built, so that a huge room is never meshed at a fine size first (1 km^2 at 0.5 m would be
// 8 million patches, gigabytes, before the budget is checked). With an explicit size an excess
// is an error naming the room or the total.
double size_within_limits(const Scene& scene, const IndirectOptions& o, const RoomBudgets& b,
                          double size, std::vector<IndirectNote>& notes) {
  std::vector<double> count;
  for (const auto& room : scene.rooms) count.push_back(room_surface_area(room) / (size * size));
  const BudgetUse u = budget_use(b, count);
  if (!(u.worst_ratio > 1.0) && !(u.total_ratio > 1.0)) return size;
  const size_t budget = b.budget[u.worst_room];
  if (o.patch_size_m > 0.0) {
    if (u.worst_ratio > 1.0)
      throw InputError("room '" + scene.rooms[u.worst_room].name +
                       "': " + std::to_string(std::llround(u.worst)) +
                       " patches at a patch size of " + format_double("%.3g", size) +
                       " m exceed the budget of " + std::to_string(budget) + " patches per room");
    throw InputError(std::to_string(std::llround(u.total)) + " patches in " +
                     std::to_string(scene.rooms.size()) + " rooms at a patch size of " +
                     format_double("%.3g", size) + " m exceed the limit of " +
                     total_limit_text(u.limit));
  }
  const double grow = std::sqrt(std::max(u.worst_ratio, u.total_ratio));
  IndirectNote n = raised(u.worst_ratio >= u.total_ratio ? IndirectNote::Kind::room_raised
                                                         : IndirectNote::Kind::rooms_raised,
                          size, size * grow);
  n.room = scene.rooms[u.worst_room].name;
  n.rooms = scene.rooms.size();
  n.budget = budget;
  n.limit = u.limit;
  n.clustered_limit = u.limit != kMaxTotalPatches;
  notes.push_back(std::move(n));
  return size * grow;
}

// Rooms' patch mesh at the requested size, coarsened to fit the budget when the size was not
// given explicitly.
PatchMesh mesh_within_budget(const Scene& scene, IndirectOptions o, const RoomBudgets& budgets_in,
                             double size, std::vector<IndirectNote>& notes) {
  if (o.max_patches_per_room > kMaxPatchesPerRoom) {
    IndirectNote n;
    n.kind = IndirectNote::Kind::budget_above_limit;
    n.asked = o.max_patches_per_room;
    n.limit = kMaxPatchesPerRoom;
    n.matrix_mb = kMaxFormFactorMatrixBytes / kBytesPerMegabyte;
    notes.push_back(std::move(n));
    o.max_patches_per_room = kMaxPatchesPerRoom;
  }
  RoomBudgets b = budgets_in;
  for (size_t r = 0; r < b.budget.size(); ++r)
    if (!b.clustered[r]) b.budget[r] = o.max_patches_per_room;
  size = size_within_limits(scene, o, b, size, notes);
  double previous_worst = 0;
  for (int attempt = 0;; ++attempt) {
    PatchMesh mesh = build_patch_mesh(scene, size);
    std::vector<double> count;
    for (size_t r = 0; r + 1 < mesh.room_begin.size(); ++r)
      count.push_back(static_cast<double>(mesh.room_begin[r + 1] - mesh.room_begin[r]));
    const BudgetUse u = budget_use(b, count);
    const size_t worst = static_cast<size_t>(u.worst);
    const int worst_room = u.worst_room;
    const size_t budget = b.budget[worst_room];
    if (!(u.worst_ratio > 1.0) && !(u.total_ratio > 1.0)) return mesh;
    // Every face is at least one patch: once larger patches no longer lower the count, the
    // room's faces alone exceed the budget (thousands of small obstacles).
    if (attempt > 0 && u.worst_ratio > 1.0 && u.worst >= previous_worst) {
      const Room& room = scene.rooms[worst_room];
      throw InputError(
          "room \"" + room.name + "\": its walls and " + std::to_string(room.obstacles.size()) +
          " obstacles have " + std::to_string(worst) +
          " faces, each at least one patch, more than the budget of " + std::to_string(budget) +
          " patches per room; use fewer obstacles, or \"indirect\": \"off\"");
    }
    previous_worst = u.worst;
    if (!(u.worst_ratio > 1.0)) {
      // Obstacles and clipped boundary cells beyond the estimate of size_within_limits.
      const size_t total = static_cast<size_t>(u.total);
      if (o.patch_size_m > 0.0 || attempt > 20)
        throw InputError(std::to_string(total) + " patches in " +
                         std::to_string(scene.rooms.size()) + " rooms at a patch size of " +
                         format_double("%.3g", size) + " m exceed the limit of " +
                         total_limit_text(u.limit));
      const double grow = std::sqrt(u.total_ratio) * 1.05;
      IndirectNote n = raised(IndirectNote::Kind::rooms_raised_meshed, size, size * grow);
      n.limit = u.limit;
      n.clustered_limit = u.limit != kMaxTotalPatches;
      notes.push_back(std::move(n));
      size *= grow;
      continue;
    }
    if (o.patch_size_m > 0.0 || attempt > 20)
      throw InputError("room '" + scene.rooms[worst_room].name + "': " + std::to_string(worst) +
                       " patches at a patch size of " + format_double("%.3g", size) +
                       " m exceed the budget of " + std::to_string(budget) + " patches per room");
    const double grow = std::sqrt(u.worst_ratio) * 1.05;
    IndirectNote n = raised(IndirectNote::Kind::room_raised_meshed, size, size * grow);
    n.room = scene.rooms[worst_room].name;
    n.budget = budget;
    notes.push_back(std::move(n));
    size *= grow;
  }
}

using geometry::Box3;

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

// The light each patch of `mesh` receives straight from its source: the luminaires' first
// bounce, or the light entering through openings when the options give it.
FirstBounce incident_light(const Scene& scene, const PatchMesh& mesh, const IndirectOptions& o,
                           const std::vector<const geometry::Visibility*>& room_visibility,
                           const std::vector<char>& clustered) {
  if (!o.incident_flux_lm)
    return first_bounce(scene, mesh, room_visibility, 0.08, &o.luminous_flux_lm,
                        &o.intensity_lookup, &clustered);
  FirstBounce fb;
  fb.incident_flux_lm = o.incident_flux_lm(mesh);
  add_reflected_flux(mesh, fb);
  fb.emitted_flux_lm = fb.luminaire_flux_lm = fb.received_flux_lm;
  return fb;
}

}  // namespace

IndirectOptions indirect_options(const Settings& settings) {
  IndirectOptions o;
  o.quality = settings.quality;
  o.bounces = settings.bounces;
  // `reference` is the yardstick: as many patches as a dense matrix may hold, so that a room of
  // ordinary size is meshed at its 0.2 m (docs/indirect.md, "Limits").
  if (settings.quality == Quality::reference) o.max_patches_per_room = kMaxPatchesPerRoom;
  return o;
}

bool near_any(const Patch& p, const std::vector<Neighbourhood>& near) {
  for (const Neighbourhood& n : near) {
    const double reach_m = n.radius_m + p.diameter_m;
    const Vec3 d = p.centroid - n.point;
    if (glm::dot(d, d) <= reach_m * reach_m) return true;
  }
  return false;
}

namespace {

// solve_indirect, returning the solution it may still change (the split's second solve).
// `clustered_split`: whether the rooms with the clustered transfer and visibility may still choose
// their split before solving (false once they have, on the split mesh).
std::unique_ptr<IndirectSolution> solve_rooms(const Scene& scene, const IndirectOptions& options_in,
                                              bool clustered_split = true) {
  const auto t0 = std::chrono::steady_clock::now();
  auto solution = std::make_unique<IndirectSolution>();
  IndirectSolution& sol_out = *solution;
  sol_out.options = options_in;
  const IndirectOptions& options = sol_out.options;
  IndirectResult& res = sol_out.result;
  const double size =
      options.patch_size_m > 0.0 ? options.patch_size_m : quality_patch_size(options.quality);
  const double far_ratio =
      options.far_ratio > 0.0 ? options.far_ratio : quality_far_ratio(options.quality);
  const double tol =
      options.tolerance > 0.0 ? options.tolerance : quality_tolerance(options.quality);
  const int bounces = options.bounces > 0                 ? options.bounces
                      : options.quality == Quality::draft ? 1
                                                          : 0;

  const RoomBudgets budgets = room_budgets(scene, options, size);
  sol_out.mesh =
      options.mesh ? *options.mesh : mesh_within_budget(scene, options, budgets, size, res.notes);
  if (!options.mesh && !options.refine_near.empty()) {
    std::vector<char> near(sol_out.mesh.patches.size(), 0);
    for (size_t i = 0; i < near.size(); ++i) {
      const Patch& p = sol_out.mesh.patches[i];
      near[i] = p.has_quarters && near_any(p, options.refine_near) ? 1 : 0;
      res.locally_refined_patches += near[i];
    }
    sol_out.mesh = split_patches(scene, sol_out.mesh, near);
  }
  const size_t mesh_notes = res.notes.size();
  const PatchMesh& mesh = sol_out.mesh;
  res.clustered = budgets.clustered;
  res.patches = mesh.patches.size();
  res.patch_size_m = mesh.patch_size_m;

  // Visibility: the plan's (the scene's AABB tree, calc/scene_visibility), or nothing blocks.
  size_t obstacle_count = 0;
  for (const auto& room : scene.rooms) obstacle_count += room.obstacles.size();
  sol_out.obstacle_count = obstacle_count;
  auto& room_visibility = sol_out.room_visibility;
  room_visibility.assign(scene.rooms.size(), nullptr);
  auto& obstacles_only = sol_out.obstacles_only;
  if (const geometry::Visibility* vis = options.visibility.get()) {
    // In a convex room only obstacles can block a segment between two of its points: skip the
    // tree for segments that miss every obstacle's box (most of them), an exact filter.
    obstacles_only.emplace(*vis, obstacle_boxes(scene));
    for (size_t r = 0; r < scene.rooms.size(); ++r)
      room_visibility[r] = outline_is_convex(scene.rooms[r]) ? &*obstacles_only : vis;
  }
  // A clustered room's far ratio is the quality's, or kClusteredReferenceFarRatio where that is
  // infinite (reference): an always-exact gather or transfer over 10^4 patches and more is what
  // clustering avoids. In a convex one without obstacles nothing blocks light.
  auto& room_far = sol_out.room_far;
  room_far.assign(scene.rooms.size(), far_ratio);
  for (size_t r = 0; r < scene.rooms.size(); ++r)
    if (budgets.clustered[r]) {
      const Room& room = scene.rooms[r];
      if (outline_is_convex(room) && room.obstacles.empty()) room_visibility[r] = nullptr;
      if (!std::isfinite(far_ratio)) room_far[r] = kClusteredReferenceFarRatio;
    }

  const FirstBounce fb = incident_light(scene, mesh, options, room_visibility, budgets.clustered);
  for (const auto& n : fb.notes) res.notes.push_back(n);
  res.vpls = fb.vpl_count;
  res.emitted_flux_lm = fb.emitted_flux_lm;
  res.luminaire_flux_lm = fb.luminaire_flux_lm;
  res.received_flux_lm = fb.received_flux_lm;
  for (double f : fb.vpl_flux_lm) res.vpl_flux_lm += f;

  // A room where something blocks light is split where its light jumps (split_mask.h, below). A
  // dense room chooses the patches from its solution, and is solved again; a room with the
  // clustered transfer chooses them before solving, from its first bounce and the ambient term
  // (ambient_exitance), since a solve of the unsplit mesh costs about as much as the split one.
  const double jump = quality_split_jump(options.quality);
  const bool splits = options.split_patches && jump > 0.0 && bounces != 1;
  const auto needs_split = [&](size_t r) {
    const Room& room = scene.rooms[r];
    return room_visibility[r] && !(outline_is_convex(room) && room.obstacles.empty());
  };
  if (splits && clustered_split) {
    std::vector<char> split(mesh.patches.size(), 0);
    size_t cut = 0;
    for (size_t r = 0; r < scene.rooms.size(); ++r) {
      if (!budgets.clustered[r] || !needs_split(r)) continue;
      const size_t begin = mesh.room_begin[r], end = mesh.room_begin[r + 1];
      const std::vector<char> room_split = patches_to_split(
          mesh, begin, end, ambient_exitance(mesh, begin, end, fb.incident_flux_lm), jump,
          kMaxClusteredPatchesPerRoom - std::min(kMaxClusteredPatchesPerRoom, end - begin));
      for (size_t i = begin; i < end; ++i)
        if (room_split[i]) split[i] = 1, ++cut;
    }
    if (cut > 0) {
      // The time until now, before the finer solve (which times itself).
      const double first_s =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      IndirectOptions again = options;
      again.mesh = std::make_shared<const PatchMesh>(split_patches(scene, mesh, split));
      std::unique_ptr<IndirectSolution> finer = solve_rooms(scene, again, false);
      IndirectResult& fr = finer->result;
      fr.notes.insert(fr.notes.begin(), res.notes.begin(), res.notes.begin() + mesh_notes);
      fr.split_patches += cut;
      fr.locally_refined_patches = res.locally_refined_patches;
      fr.seconds += first_s;
      finer->options.mesh.reset();
      return finer;
    }
  }

  // Exitant flux per patch, room by room (rooms are closed: no light passes between them).
  auto& exitant = sol_out.exitant_flux_lm;
  exitant.assign(mesh.patches.size(), 0.0);
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
    } else if (budgets.clustered[r]) {
      const ClusteredTransfer T =
          clustered_transfer(mesh, static_cast<int>(r), room_far[r], true,
                             options.max_clustered_link_bytes, room_visibility[r]);
      res.max_row_correction = std::max(res.max_row_correction, T.max_row_correction);
      // A wider ratio than the quality's is not what the quality's accuracy was measured with
      // (docs/indirect.md, "Large rooms"): a warning, not a note.
      if (T.opening > cluster_opening(room_far[r])) {
        IndirectNote n;
        n.kind = IndirectNote::Kind::clustered_wider;
        n.room = scene.rooms[r].name;
        n.opening = T.opening;
        n.quality_opening = cluster_opening(room_far[r]);
        n.patches = T.n;
        n.limit_mb = options.max_clustered_link_bytes / kBytesPerMegabyte;
        res.warnings.push_back(std::move(n));
      }
      res.clustered_rooms += 1;
      res.clustered_links += T.links();
      res.clustered_bytes = std::max(res.clustered_bytes, T.bytes());
      sol = solve_radiosity(T, rho, incident, bounces, tol);
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
  if (!mesh.escape_fraction.empty())
    for (size_t i = 0; i < exitant.size(); ++i)
      res.escaped_flux_lm += exitant[i] * mesh.escape_fraction[i];

  sol_out.bounces = bounces;
  res.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  // Patches where the light jumps, cut into quarters, and the dense rooms solved again on that
  // mesh (split_mask.h): only rooms where something blocks light, with bounces.
  if (splits) {
    std::vector<char> split(mesh.patches.size(), 0);
    size_t cut = 0;
    for (size_t r = 0; r < scene.rooms.size(); ++r) {
      // Only where something inside the room blocks light (a reflex corner, obstacles): in a
      // convex room without obstacles the exitance changes smoothly and the mesh stays as it is.
      if (budgets.clustered[r] || !needs_split(r)) continue;
      const size_t begin = mesh.room_begin[r], end = mesh.room_begin[r + 1];
      const size_t budget = std::max(options.max_patches_per_room, end - begin);
      const std::vector<char> room_split =
          patches_to_split(mesh, begin, end, exitant, jump, budget - (end - begin));
      for (size_t i = begin; i < end; ++i)
        if (room_split[i]) split[i] = 1, ++cut;
    }
    if (cut > 0) {
      IndirectOptions again = options;
      again.split_patches = false;
      again.mesh = std::make_shared<const PatchMesh>(split_patches(scene, mesh, split));
      std::unique_ptr<IndirectSolution> finer = solve_rooms(scene, again, false);
      IndirectResult& fr = finer->result;
      // The notes of meshing the rooms (the budget) are the first solve's.
      fr.notes.insert(fr.notes.begin(), res.notes.begin(), res.notes.begin() + mesh_notes);
      fr.split_patches += cut;
      fr.locally_refined_patches = res.locally_refined_patches;
      fr.seconds += res.seconds;
      finer->options.mesh.reset();
      finer->options.split_patches = options.split_patches;
      return finer;
    }
  }
  return solution;
}

}  // namespace

std::unique_ptr<const IndirectSolution> solve_indirect(const Scene& scene,
                                                       const IndirectOptions& options) {
  return solve_rooms(scene, options);
}

IndirectResult gather_indirect(const IndirectSolution& solution, const Scene& scene,
                               const std::vector<geometry::SurfaceGrid>& surfaces) {
  const auto t0 = std::chrono::steady_clock::now();
  IndirectResult res = solution.result;
  const IndirectOptions& options = solution.options;
  const PatchMesh& mesh = solution.mesh;
  const std::vector<double>& exitant = solution.exitant_flux_lm;
  const std::vector<double>& room_far = solution.room_far;
  const auto& room_visibility = solution.room_visibility;
  const std::vector<char>& clustered = solution.result.clustered;
  const int bounces = solution.bounces;
  const size_t obstacle_count = solution.obstacle_count;
  // Receivers: each active point's room and its position moved off the room's faces.
  struct Receiver {
    int room = -1;
    Vec3 x{0.0};
  };
  std::vector<std::vector<Receiver>> receivers(surfaces.size());
  for (size_t s = 0; s < surfaces.size(); ++s) {
    const auto& grid = surfaces[s];
    receivers[s].resize(grid.points.size());
    tbb::parallel_for(size_t(0), grid.points.size(), [&](size_t i) {
      if (!grid.active.empty() && !grid.active[i]) return;
      // A point on a wall (floor, ceiling) two rooms share lies in both: it gathers from the
      // first room its normal does not face out of (the room it looks into).
      for (const int r : rooms_containing(scene, grid.points[i], kRoomTolerance_m)) {
        if (faces_out_of_room(scene.rooms[r], grid.points[i], grid.normals[i])) continue;
        receivers[s][i] = {r, inset_into_room(scene.rooms[r], grid.points[i])};
        return;
      }
    });
  }
  std::vector<GatherSet> gather_sets;
  for (size_t r = 0; r < scene.rooms.size(); ++r)
    gather_sets.push_back(make_gather_set(mesh, mesh.room_begin[r], mesh.room_begin[r + 1], exitant,
                                          room_far[r], nullptr,
                                          clustered[r] ? cluster_opening(room_far[r]) : 0.0));

  // Patches a receiver comes close to, refined into cells (subcells.h); not at draft, which
  // promises no accuracy.
  if (options.refine_near_patches && options.quality != Quality::draft) {
    std::vector<std::atomic<char>> near(mesh.patches.size());
    for (size_t s = 0; s < surfaces.size(); ++s)
      tbb::parallel_for(size_t(0), receivers[s].size(), [&](size_t i) {
        if (receivers[s][i].room >= 0)
          mark_near_patches(mesh, gather_sets[receivers[s][i].room], receivers[s][i].x,
                            surfaces[s].normals[i], near);
      });
    std::vector<char> refine(near.size());
    for (size_t j = 0; j < near.size(); ++j) refine[j] = near[j].load(std::memory_order_relaxed);
    const CellMesh cells = cell_mesh(mesh, refine);
    if (!cells.mesh.patches.empty()) {
      const std::vector<double> cell_incident_lm =
          options.incident_flux_lm && options.cell_incident_flux_lm
              ? options.cell_incident_flux_lm(mesh, cells)
              : incident_light(scene, cells.mesh, options, room_visibility, clustered)
                    .incident_flux_lm;
      std::vector<double> cell_indirect(cells.mesh.patches.size(), 0.0);
      // Near patches cell by cell; the far ones, whose light varies smoothly over a patch, at
      // the patch's corners, each distinct corner once, interpolated bilinearly to the cells
      // (subcells.h).
      const GatherBand near_band{0.0, kCellNearGather * mesh.patch_size_m};
      const GatherBand far_band{near_band.outer_m};
      const FarCorners far = far_corners(mesh, cells);
      std::vector<double> far_lx(far.corners.size());
      tbb::parallel_for(size_t(0), far.corners.size(), [&](size_t k) {
        const FarCorners::Corner& c = far.corners[k];
        far_lx[k] = gather_set_point(mesh, gather_sets[c.room], c.x + c.normal * kReceiverInset_m,
                                     c.normal, room_far[c.room], room_visibility[c.room], far_band);
      });
      constexpr int kPerSide = kSubcellsPerSide, kCells = kPerSide * kPerSide;
      tbb::parallel_for(size_t(0), far.of_patch.size(), [&](size_t patch) {
        const size_t c0 = patch * kCells;
        for (int a = 0; a < kPerSide; ++a)
          for (int b = 0; b < kPerSide; ++b) {
            const size_t c = c0 + static_cast<size_t>(a * kPerSide + b);
            const Patch& q = cells.mesh.patches[c];
            double lx = gather_set_point(mesh, gather_sets[q.room],
                                         q.centroid + q.normal * kReceiverInset_m, q.normal,
                                         room_far[q.room], room_visibility[q.room], near_band);
            for (int k = 0; k < 4; ++k)
              lx += far_corner_weight(a, b, k) * far_lx[far.of_patch[patch][k]];
            cell_indirect[c] = lx;
          }
      });
      const SubcellExitance sub =
          cell_exitance(mesh, cells, exitant, cell_incident_lm, cell_indirect);
      res.refined_patches = sub.refined_patches;
      for (size_t r = 0; r < scene.rooms.size(); ++r)
        gather_sets[r] =
            make_gather_set(mesh, mesh.room_begin[r], mesh.room_begin[r + 1], exitant, room_far[r],
                            &sub, clustered[r] ? cluster_opening(room_far[r]) : 0.0);
    }
  }

  // Final gather.
  res.E_indirect_per_surface.resize(surfaces.size());
  for (size_t s = 0; s < surfaces.size(); ++s) {
    auto& out = res.E_indirect_per_surface[s];
    out.assign(surfaces[s].points.size(), 0.0);
    tbb::parallel_for(size_t(0), out.size(), [&](size_t i) {
      const Receiver& rc = receivers[s][i];
      if (rc.room < 0) return;
      out[i] = gather_set_point(mesh, gather_sets[rc.room], rc.x, surfaces[s].normals[i],
                                room_far[rc.room], room_visibility[rc.room]);
    });
  }
  res.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  res.bounces_asked = bounces;
  res.part_outside = res.emitted_flux_lm < res.luminaire_flux_lm * (1.0 - kOutsideFluxFraction);
  res.visibility = options.visibility != nullptr;
  res.obstacles = obstacle_count;
  return res;
}

IndirectResult compute_indirect(const Scene& scene,
                                const std::vector<geometry::SurfaceGrid>& surfaces,
                                const IndirectOptions& options) {
  return gather_indirect(*solve_indirect(scene, options), scene, surfaces);
}

}  // namespace luxgrid::calc::indirect
