#pragma once
// Reflected light (docs/indirect.md): the public face of calc/indirect.
//
//   decide_indirect(scene)                 -> run it or not, and why (decision.h; make_plan calls
//   it) compute_indirect(scene, surfaces, opt) -> E_indirect per point of every surface + a summary
//   = gather_indirect(*solve_indirect(scene, opt), scene, surfaces): the rooms solved once, then
//   gathered at any set of points (the plan's estimate gathers at its probe points only)
//
// Method (docs/indirect.md): rooms are meshed into patches (patches.h); the first bounce
// integrates every luminaire's intensity over each patch's solid angle and makes each lit patch a
// virtual point light of flux rho x incident lumens (first_bounce.h, [Gadia2024]); the light is
// then carried between patches with exact polygon form factors and solved to convergence, or for
// exactly N reflections (radiosity.h); finally each grid point gathers from the patches with
// Lambert's exact polygon form factor near a patch, the point kernel on its quarters extrapolated
// (Richardson) at intermediate distances and the seed's point kernel far from it (gather.h);
// a patch seen from closer than a patch diameter is gathered cell by cell, each cell with the
// exitance its own direct and reflected light give it (subcells.h).
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "calc/indirect/decision.h"
#include "calc/indirect/form_factor.h"
#include "calc/indirect/indirect_notes.h"
#include "calc/indirect/limits.h"
#include "calc/indirect/patches.h"
#include "calc/scene.h"
#include "calc/scene_visibility.h"
#include "geometry/surface_grid.h"
#include "geometry/visibility.h"

namespace luxgrid::calc::indirect {

struct CellMesh;  // subcells.h

// A ball around a point: the patches that reach into it are cut finer (IndirectOptions::
// refine_near).
struct Neighbourhood {
  Vec3 point{0.0};
  double radius_m = 0.0;
};
// Whether `p` may reach into one of `near`: its centroid within the radius plus the patch's
// diameter (every point of a patch lies within its diameter of its centroid, which lies in it), so
// no patch that reaches in is missed; one that only comes close may be taken too.
bool near_any(const Patch& p, const std::vector<Neighbourhood>& near);

struct IndirectOptions {
  Quality quality = Quality::standard;
  int bounces = 0;            // 0: auto (converged; draft: 1); N >= 1: exactly N reflections
  double patch_size_m = 0.0;  // 0: the quality's (draft 1.0, standard 0.5, high 0.25, ref 0.2 m)
  // Budget: the patch size grows to fit, unless set above. At most kMaxPatchesPerRoom (the
  // form-factor matrix's memory; a larger value is lowered to it, with a note); all rooms
  // together at most kMaxTotalPatches (limits.h).
  size_t max_patches_per_room = kDefaultPatchesPerRoom;
  double far_ratio = 0.0;  // 0: the quality's (draft 3, standard 5, high 8, reference: never)
  // The links of one clustered room at most (clustered.h); a larger value only for finer
  // references than a project can ask for (bench/hall_reference.cpp: a smaller opening ratio).
  size_t max_clustered_link_bytes = kMaxClusteredLinkBytes;
  double tolerance = 0.0;  // 0: the quality's (draft 1e-2, standard 1e-3, high 1e-4, ref 1e-6)
  // Patches a receiver comes close to gathered cell by cell (subcells.h); draft does not.
  bool refine_near_patches = true;
  // In rooms where something blocks light (a reflex corner, obstacles), at every quality but
  // `draft`: the patches whose exitance jumps against a neighbour's cut into quarters
  // and the room solved again (split_mask.h).
  bool split_patches = true;
  // Where the mesh is cut finer than patch_size_m (the plan's local step, calc/pipeline.cpp):
  // every parallelogram patch (Patch::has_quarters) near_any of these is cut into quarters before
  // the rooms are solved, and then split where its light jumps as any other.
  std::vector<Neighbourhood> refine_near;
  // A mesh to solve on instead of meshing the rooms (the second solve of split_patches).
  std::shared_ptr<const PatchMesh> mesh;
  // What blocks light between two points of the scene: the plan's visibility test (its AABB tree
  // of room and obstacle faces, calc/scene_visibility.h). Null: nothing blocks (make_visibility's
  // verdict for a convex room without obstacles).
  std::shared_ptr<const geometry::Visibility> visibility;
  // Luminous flux per distribution already integrated (decide_indirect's), so the first bounce
  // does not integrate the same distributions again; missing ones are computed.
  std::map<const photometry::IntensityDistribution*, double> luminous_flux_lm;
  // What the first bounce looks each luminaire's intensity up in (calc/intensity_lookup.h: the
  // texture where the quality allows it); a distribution missing here is looked up itself.
  std::map<const photometry::IntensityDistribution*, photometry::DistributionPtr> intensity_lookup;
  // Per room, whether it is solved with the clustered transfer (clustered.h). Empty: decided at
  // the requested patch size (use_clustered_transfer). The plan's estimate meshes the rooms again
  // at twice the size and must compare like with like: it passes the main run's decisions
  // (IndirectResult::clustered), and a room clustered there keeps the clustered budget.
  std::vector<char> clustered;
  // Light that enters through openings (the daylight scene, calc/daylight_light.h): the flux
  // straight from the sky and the ground landing on each patch of a mesh, lm. When set it
  // replaces the luminaires' first bounce, for the patches and for the cells of subcells.h.
  std::function<std::vector<double>(const PatchMesh&)> incident_flux_lm;
  // With incident_flux_lm, the same for the cells of subcells.h (mesh: the patches they cut),
  // when the light's source has a cheaper way to them than integrating each cell (the daylight
  // scene interpolates within the cell's patch). Unset: incident_flux_lm on the cells' mesh.
  std::function<std::vector<double>(const PatchMesh& mesh, const CellMesh& cells)>
      cell_incident_flux_lm;
};

// Options from the project's settings (quality, bounces).
IndirectOptions indirect_options(const Settings& settings);

struct IndirectResult {
  std::vector<std::vector<double>>
      E_indirect_per_surface;  // lx, same order as the surfaces' points
  std::vector<IndirectNote> notes;
  std::vector<IndirectNote> warnings;  // for the plan's warnings: what may break the promise
  size_t patches = 0;
  size_t vpls = 0;
  int bounces_asked = 0;  // as IndirectSolution::bounces: 1 one bounce, 0 converged
  int bounces_run = 0;    // largest over rooms
  bool tail_added = false;
  double residual = 0.0;  // largest over rooms, relative
  double patch_size_m = 0.0;
  size_t refined_patches = 0;          // patches gathered cell by cell (subcells.h)
  size_t locally_refined_patches = 0;  // cut into quarters near IndirectOptions::refine_near
  size_t split_patches = 0;        // patches cut into quarters where the light jumps (split_mask.h)
  double emitted_flux_lm = 0.0;    // entering the rooms (the parts of the openings inside them)
  double luminaire_flux_lm = 0.0;  // of the luminaires that reach a room, whole
  bool part_outside = false;       // a share of it (beyond rounding) falls outside every room
  double received_flux_lm = 0.0;   // direct lumens landing on patches
  double vpl_flux_lm = 0.0;        // sum over VPLs (= sum rho x received)
  double max_row_correction = 0.0;
  // Reflected light leaving through the openings: each patch's exitant flux times its escape
  // fraction (patches.h), summed; 0 without openings.
  double escaped_flux_lm = 0.0;
  // Rooms solved with the clustered transfer (clustered.h), their links in all and the largest
  // one's memory (nodes and links).
  size_t clustered_rooms = 0, clustered_links = 0, clustered_bytes = 0;
  std::vector<char> clustered;  // per room: solved with the clustered transfer
  bool visibility = false;      // rooms and obstacles block light (an AABB tree of their faces)
  size_t obstacles = 0;         // that reflect and shade
  double seconds = 0.0;
};

// The rooms solved: the mesh and every patch's exitant flux, all the gather needs. Not copied or
// moved: room_visibility may point into obstacles_only.
struct IndirectSolution {
  IndirectOptions options;  // as solved (its visibility kept alive here)
  PatchMesh mesh;
  std::vector<double> exitant_flux_lm;  // per patch of the mesh
  std::vector<double> room_far;         // the far ratio each room is gathered with
  std::vector<const geometry::Visibility*> room_visibility;  // per room; null: nothing blocks
  std::optional<geometry::BoxFilteredVisibility> obstacles_only;
  int bounces = 0;  // as asked (0: converged)
  size_t obstacle_count = 0;
  // What the solve found (patches, bounces, residual, fluxes, notes, warnings, clustered
  // rooms); gather_indirect adds the values, the refined patches and the summary.
  IndirectResult result;
  IndirectSolution() = default;
  IndirectSolution(const IndirectSolution&) = delete;
  IndirectSolution& operator=(const IndirectSolution&) = delete;
};

// Meshes and solves every room (throws as compute_indirect).
std::unique_ptr<const IndirectSolution> solve_indirect(const Scene& scene,
                                                       const IndirectOptions& options);
// E_indirect at every point of `surfaces` from a solution. A point's value does not depend on
// which other points are gathered with it (a patch is refined into cells for the receivers that
// come close to it, and only those receivers gather its cells), so the values at a subset of a
// grid's points are those of the whole grid at the same points, to the bit.
IndirectResult gather_indirect(const IndirectSolution& solution, const Scene& scene,
                               const std::vector<geometry::SurfaceGrid>& surfaces);

// E_indirect at every point of every surface (inactive points get 0). Throws
// InputError naming the room for a bad room or a patch budget the scene exceeds (with an
// explicit patch size; else the patches grow), or a budget above the limits of limits.h.
IndirectResult compute_indirect(const Scene& scene,
                                const std::vector<geometry::SurfaceGrid>& surfaces,
                                const IndirectOptions& options);

}  // namespace luxgrid::calc::indirect
