#pragma once
// The emitter as every near-field model sees it: the luminous opening turned into a world-space
// convex polygon, with what the radiance substitution L_e = I / (A cos) (Luksch et al. 2020,
// Eq. 2) needs: its area, its emitting normal, the rotation that takes world directions back into
// the luminaire frame for the intensity lookup, and the distribution.
#include <vector>

#include <glm/mat3x3.hpp>

#include "calc/nearfield/table_cells.h"
#include "geometry/polygon3.h"
#include "photometry/intensity_distribution.h"
#include "photometry/photometry.h"
#include "util/robust_math.h"

namespace luxgrid::photometry {
class DistributionTexture;  // photometry/distribution_texture.h
}

namespace luxgrid::nearfield {

struct FarFieldBound;  // far_field_bound.h

// Capacity of the fixed-size polygons on the hot path (no heap allocation per receiver point):
// a disk of at most kMaxDiskSegments sides plus the one vertex a horizon clip can add.
inline constexpr int kMaxDiskSegments = 128;
inline constexpr int kMaxPolygonVertices = kMaxDiskSegments + 2;
inline constexpr int kDefaultDiskSegments = 32;

// The opening (or its part above a receiver's horizon) on the hot path, relative to a receiver.
using OpeningPolygon = geometry::FixedPolygon3<kMaxPolygonVertices>;

struct Emitter {
  // Convex, counter-clockwise seen from the emitting side (looking against `normal`). A point
  // opening has one vertex and zero area; every model then falls back to the far-field point.
  std::vector<Vec3> vertices;        // m, world
  Vec3 centroid{0.0};                // m, world
  double area_m2 = 0.0;              // area of the polygon (a disk's N-gon keeps the disk's area)
  Vec3 normal{0.0, 0.0, -1.0};       // emitting normal, world: R * (0, 0, -1)
  glm::dmat3 rotation{1.0};          // luminaire frame -> world frame
  glm::dmat3 world_to_local{1.0};    // R^T, cached for the lookups on the hot path
  double largest_dimension_m = 0.0;  // largest distance between two vertices (five-times rule)
  photometry::DistributionPtr distribution;
  // The table rung's gamma cells when `distribution` has a table view (table_cells.h).
  std::shared_ptr<const TableGammaCells> table_cells;
  // Where the far-field point model is within the quality's promise (far_field_bound.h), shared
  // by every copy of the luminaire; null: the five-times rule (studies, unit tests).
  std::shared_ptr<const FarFieldBound> far_bound;
  // The fixed rule's nodes (m, world) and their area shares (fixed_rule.h): what distant
  // near-field pairs use where the error bound allows it. Empty for a point opening.
  std::vector<Vec3> rule_nodes;
  std::vector<double> rule_weights;
  // What the far-field point model looks intensities up in (calc/intensity_lookup.h): the light
  // distribution texture where its measured deviation from the table is within the quality's
  // share, times the luminaire's factor; null: `distribution`. `far_texture` is that texture
  // (kept alive by far_distribution) for loops that call its lookup directly, times
  // `far_texture_factor`; null when the far field looks the table up.
  photometry::DistributionPtr far_distribution;
  const photometry::DistributionTexture* far_texture = nullptr;
  double far_texture_factor = 1.0;

  const photometry::IntensityDistribution& far_lookup() const {
    return far_distribution ? *far_distribution : *distribution;
  }
  bool is_point() const { return vertices.size() < 3 || area_m2 <= 0.0; }
  // Intensity (cd) sent along the world direction `dir_world` (unit, pointing away from the
  // emitter): the lookup turns it into the luminaire frame with R^T (R is a rotation).
  double intensity_towards(const Vec3& dir_world) const {
    return distribution->intensity(world_to_local * dir_world);
  }
};

// Builds the emitter of a luminaire whose opening centre sits at `position` and whose frame is
// turned by `rotation` (world = position + rotation * local). A disk becomes a regular
// `disk_segments`-gon (3..kMaxDiskSegments) scaled so its area equals the disk's, so the flux
// and the far field are unchanged. A box/cylinder `height` is ignored: the flat opening emits.
// `table_cells`: the distribution's table cells when the caller already has them (they depend
// on the table alone, and a scene's luminaires share a few tables: building them once per
// table, not once per luminaire, spares 0.1 ms a luminaire); null: built here.
// Throws InputError for negative sizes, a null distribution or a bad segment count.
Emitter make_emitter(const photometry::LuminousOpening& opening, const Vec3& position,
                     const glm::dmat3& rotation, photometry::DistributionPtr distribution,
                     int disk_segments = kDefaultDiskSegments,
                     std::shared_ptr<const TableGammaCells> table_cells = nullptr);

// Builds an emitter from an explicit convex world polygon (tests, hard cases). The emitting
// normal is `rotation * (0, 0, -1)`; the polygon must lie in the plane through its centroid with
// that normal (checked to 1e-9 of its size).
Emitter make_polygon_emitter(std::vector<Vec3> vertices, const glm::dmat3& rotation,
                             photometry::DistributionPtr distribution,
                             std::shared_ptr<const TableGammaCells> table_cells = nullptr);

}  // namespace luxgrid::nearfield
