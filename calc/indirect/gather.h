#pragma once
// The final gather of calc/indirect: E_indirect at a receiver point from the exitance of every
// patch of its room (indirect.h). Near a patch (closer than far_ratio x its diameter) Lambert's
// exact polygon formula or the point kernel on its quarters, far from it the seed's point kernel;
// a patch refined into cells (subcells.h) is gathered cell by cell by a receiver closer than
// kSubcellReach diameters.
#include <atomic>
#include <limits>
#include <vector>

#include "calc/indirect/patches.h"
#include "calc/indirect/subcells.h"
#include "geometry/visibility.h"

namespace luxgrid::calc::indirect {

// A receiver point closer than this to a patch's plane (or behind it) gets nothing from that
// patch: it lies on the same face (coplanar, F = 0) or sees it edge-on. Also keeps grid points
// lying exactly on a wall, at a floor-wall edge or in a corner finite.
inline constexpr double kGatherPlaneDistance_m = 1e-7;
// The gather's visibility segments start this far in front of the receiver and end this far in
// front of the patch (patches.h visible_fraction), so neither end's own face hides the other.
inline constexpr double kGatherLift_m = 1e-6;

// Two patches of one normal lie in one plane when their centroids' offsets along it differ by at
// most this: rounding of a face's centroids is some 1e-13 m at 1 km, and faces closer than this
// are one plane to kGatherPlaneDistance_m's test.
inline constexpr double kGatherCoplanar_m = 1e-9;

// The emitting patches of one room (exitant flux > 0) laid out for the final gather: in groups
// of consecutive patches in one plane (the same normal, offsets within kGatherCoplanar_m: a face,
// or part of one; two faces of one plane may share a group), each cut into chunks of
// nearby patches (tiles of kChunkTile x the largest diameter). A receiver skips a whole group
// when it lies behind the group's plane (the floor, for a workplane point), and a whole chunk
// when the chunk lies wholly behind the receiver's tangent plane (its own wall): exactly the
// patches whose form factor is 0. A chunk wholly in front of the receiver and farther than every
// one of its patches' near distances takes the far kernel for all its patches in one loop without
// branches. Thirteen thousand points times a few thousand patches is the largest loop of
// calc/indirect.
inline constexpr double kChunkTile = 4.0;
inline constexpr double kBlockChunks = 4.0;
struct GatherSet {
  // Entries (patches with flux), structure of arrays, ordered by group and chunk.
  std::vector<double> cx, cy, cz, flux_lm;
  std::vector<double>
      near_d2;                // (far_ratio x diameter)^2: closer, the quarters or the exact formula
  std::vector<size_t> patch;  // index into the mesh
  // Per entry: the index of its first cell in `cell_exitance_lm_m2` (subcells.h), or -1 when
  // the patch has no cells (no receiver comes close to it, or it is not a parallelogram).
  std::vector<long> first_cell;
  std::vector<double> cell_exitance_lm_m2;
  struct Chunk {
    size_t begin = 0, end = 0;  // entries
    Vec3 lo{0.0}, hi{0.0};      // bounding box of the patches' vertices
    Vec3 clo{0.0}, chi{0.0};    // bounding box of the centroids
    double max_near_d2 = 0.0;
    double max_diameter_m = 0.0;
    // The chunk as one source (clustered rooms, cluster_opening > 0): its flux at its
    // flux-weighted centroid, taken when the chunk's diagonal is below cluster_opening x its
    // distance from the receiver. The flux-weighted centroid makes the first-order term of the
    // kernel's expansion vanish, so the error is of second order, as for one far patch.
    double flux_lm = 0.0;
    Vec3 flux_centroid{0.0};
    double diagonal2_m2 = 0.0;  // squared diagonal of the vertex box
  };
  struct Group {
    size_t begin = 0, end = 0;  // chunks
    Vec3 normal{0.0};
    double max_offset = 0.0;                // largest normal . centroid over the group
    size_t block_begin = 0, block_end = 0;  // blocks (clustered rooms; none otherwise)
  };
  std::vector<Chunk> chunks;
  // Clustered rooms: the chunks of a group in blocks of kBlockChunks x kBlockChunks tiles (a
  // Chunk whose begin, end are chunks), each with its aggregate, a second level of far sources.
  std::vector<Chunk> blocks;
  std::vector<Group> groups;
  double cluster_opening = 0.0;  // 0: every patch is gathered by itself
};

// The patches [begin, end) of one room with exitant flux > 0; `cells` (may be null) gives the
// cells of refined patches. `cluster_opening` > 0 (rooms with the clustered transfer,
// clustered.h): a far chunk seen under less than this ratio is gathered as one source.
GatherSet make_gather_set(const PatchMesh& mesh, size_t begin, size_t end,
                          const std::vector<double>& exitant_flux_lm, double far_ratio,
                          const SubcellExitance* cells = nullptr, double cluster_opening = 0.0);

// The patches a gather takes: those whose centroids lie at a distance in [inner_m, outer_m) from
// the receiver (all by default).
struct GatherBand {
  double inner_m = 0.0;
  double outer_m = std::numeric_limits<double>::infinity();
};

// E_indirect (lx) at the receiver (x, n) from the patches of `set` in `band`; `visibility` may be
// null (nothing blocks).
double gather_set_point(const PatchMesh& mesh, const GatherSet& set, const Vec3& x, const Vec3& n,
                        double far_ratio, const geometry::Visibility* visibility,
                        const GatherBand& band = {});

// Sets near[j] for every patch j of `set` that the receiver (x, n) sees from closer than
// kSubcellReach of its diameters: the patches whose cells the gather would use. Atomic, so that
// receivers are marked in parallel.
void mark_near_patches(const PatchMesh& mesh, const GatherSet& set, const Vec3& x, const Vec3& n,
                       std::vector<std::atomic<char>>& near);

}  // namespace luxgrid::calc::indirect
