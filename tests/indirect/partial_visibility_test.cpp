// A patch partly hidden from a receiver (calc/indirect/partial_visibility.h): its cells, each with
// its own visible fraction, against the exact form factor of the visible part (Lambert's polygon
// formula on the part the occluder leaves), and against the five-sample fraction it replaces.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "calc/indirect/form_factor.h"
#include "calc/indirect/partial_visibility.h"
#include "calc/indirect/patches.h"
#include "calc/indirect/subcells.h"
#include "geometry/occlusion.h"

namespace luxgrid::calc::indirect {
namespace {

// A thin occluder in the plane z = 0.5 covering x > edge: it blocks a segment from the origin
// to the patch at z = 1 when the segment crosses that plane beyond the edge.
class HalfPlaneOccluder final : public geometry::Visibility {
 public:
  explicit HalfPlaneOccluder(double edge_m) : edge_m_(edge_m) {}
  bool visible(const Vec3& from, const Vec3& to) const override {
    if ((from.z - 0.5) * (to.z - 0.5) > 0.0) return true;
    const double t = (0.5 - from.z) / (to.z - from.z);
    return !(from.x + t * (to.x - from.x) > edge_m_);
  }

 private:
  double edge_m_;
};

// The 1 m square at z = 1 facing down (-z), corners counter-clockwise seen from below, with its
// quarters as patches.cpp makes them.
Patch ceiling_square() {
  Patch p;
  p.polygon = {Vec3(-0.5, -0.5, 1.0), Vec3(-0.5, 0.5, 1.0), Vec3(0.5, 0.5, 1.0),
               Vec3(0.5, -0.5, 1.0)};
  p.centroid = Vec3(0.0, 0.0, 1.0);
  p.normal = Vec3(0.0, 0.0, -1.0);
  p.area_m2 = 1.0;
  p.diameter_m = std::sqrt(2.0);
  p.has_quarters = true;
  for (int q = 0; q < 4; ++q) p.quarter_centroid[q] = 0.5 * (p.polygon[q] + p.centroid);
  return p;
}

// The patch's part with x <= x_max: Lambert's exact form factor from the origin (normal +z).
double visible_part_form_factor(double x_max) {
  const Polygon3 part = {Vec3(-0.5, -0.5, 1.0), Vec3(-0.5, 0.5, 1.0), Vec3(x_max, 0.5, 1.0),
                         Vec3(x_max, -0.5, 1.0)};
  return point_polygon_form_factor(Vec3(0.0), Vec3(0.0, 0.0, 1.0), part);
}

TEST(PartialVisibility, CellsResolveAShadowEdgeToACell) {
  const Patch p = ceiling_square();
  const Vec3 x(0.0), n(0.0, 0.0, 1.0);
  const Vec3 from = x + n * 1e-6;
  // Edges at several places across the patch (the shadow on the patch is at twice the edge's x).
  for (double edge : {-0.2, -0.07, 0.03, 0.1, 0.17}) {
    const HalfPlaneOccluder occluder(edge);
    const double exact = visible_part_form_factor(2.0 * edge);
    const double five =
        point_polygon_form_factor(x, n, p.polygon) * visible_fraction(&occluder, from, p, 1e-6);
    const double cells = partial_cells_integral(x, n, from, p, nullptr, 1.0, 5.0, occluder, 1e-6);
    // A cell is a quarter of the patch wide, its samples an eighth apart: the edge is placed to
    // within half a cell, so the error is at most the form factor of a strip of half a cell's
    // width at the edge (the strip's factor is at most its area's share at normal incidence,
    // bounded here by the factor of the strip directly overhead).
    const double half_cell = 0.5 / kSubcellsPerSide;
    const double strip = visible_part_form_factor(half_cell) - visible_part_form_factor(0.0);
    EXPECT_NEAR(cells, exact, strip) << "edge " << edge;
    // And better than the five samples it replaces, where those are off by more than a strip.
    if (std::abs(five - exact) > strip) {
      EXPECT_LT(std::abs(cells - exact), 0.5 * std::abs(five - exact)) << "edge " << edge;
    }
  }
}

TEST(PartialVisibility, WhollyVisibleCellsSumToThePatchFactor) {
  // Nothing blocks: the cells' factors add up to the patch's (Lambert's formula is additive over
  // a tiling), to 1e-12, and a per-cell weight scales each cell.
  const Patch p = ceiling_square();
  const Vec3 x(0.1, -0.2, 0.0), n(0.0, 0.0, 1.0);
  const Vec3 from = x + n * 1e-6;
  const HalfPlaneOccluder none(10.0);
  const double whole = point_polygon_form_factor(x, n, p.polygon);
  EXPECT_NEAR(partial_cells_integral(x, n, from, p, nullptr, 1.0, 1e9, none, 1e-6), whole, 1e-12);
  std::vector<double> weight(kSubcellsPerSide * kSubcellsPerSide, 3.0);
  EXPECT_NEAR(partial_cells_integral(x, n, from, p, weight.data(), 0.0, 1e9, none, 1e-6),
              3.0 * whole, 3e-12);
}

// The scene's visibility test (geometry/occlusion.h) over one thin occluder in the plane z = 0.5
// covering edge_m <= x <= edge_m + 2, |y| <= 2: from the origin its shadow on the patch at z = 1
// is x >= 2 edge_m.
geometry::OcclusionTree sheet_occluder(double edge_m) {
  geometry::Face f;
  f.kind = geometry::Face::Kind::obstacle;
  f.label = "sheet";
  f.corners = {Vec3(edge_m, -2.0, 0.5), Vec3(edge_m + 2.0, -2.0, 0.5), Vec3(edge_m + 2.0, 2.0, 0.5),
               Vec3(edge_m, 2.0, 0.5)};
  f.normal = Vec3(0.0, 0.0, 1.0);
  return geometry::OcclusionTree({f});
}

// The same sheet cut to y >= y_min: from the origin its shadow on the patch is x >= 2 edge_m,
// y >= 2 y_min.
geometry::OcclusionTree corner_sheet_occluder(double edge_m, double y_min) {
  geometry::Face f;
  f.kind = geometry::Face::Kind::obstacle;
  f.label = "corner sheet";
  f.corners = {Vec3(edge_m, y_min, 0.5), Vec3(edge_m + 2.0, y_min, 0.5),
               Vec3(edge_m + 2.0, 2.0, 0.5), Vec3(edge_m, 2.0, 0.5)};
  f.normal = Vec3(0.0, 0.0, 1.0);
  return geometry::OcclusionTree({f});
}

TEST(PartialVisibility, AShadowInOneQuarterIsFoundThere) {
  // The shadow 0.4 <= x <= 0.5, 0.3 <= y <= 0.5 lies in one corner cell, between every sample
  // and every cell centre. The patch's verdict is partial and every centre agrees, so the
  // patch's quarters are classified first: three are proven visible, and the fourth goes cell by
  // cell. The answer is Lambert's factor of the patch less that of the shadow, to within the
  // strip bound of the tests above; the patch's five samples miss the shadow altogether.
  const Patch p = ceiling_square();
  const Vec3 x(0.0), n(0.0, 0.0, 1.0);
  const Vec3 from = x + n * 1e-6;
  const double whole = point_polygon_form_factor(x, n, p.polygon);
  const geometry::OcclusionTree occluder = corner_sheet_occluder(0.2, 0.15);
  const Polygon3 shadow = {Vec3(0.4, 0.3, 1.0), Vec3(0.4, 0.5, 1.0), Vec3(0.5, 0.5, 1.0),
                           Vec3(0.5, 0.3, 1.0)};
  const double exact = whole - point_polygon_form_factor(x, n, shadow);
  EXPECT_EQ(whole * visible_fraction(&occluder, from, p, 1e-6), whole);
  const double resolved = undecided_patch_integral(x, n, from, p, nullptr, 1.0, whole, 5.0,
                                                   occluder, 1e-6, geometry::ShaftFaces{});
  const double half_cell = 0.5 / kSubcellsPerSide;
  const double strip = visible_part_form_factor(half_cell) - visible_part_form_factor(0.0);
  EXPECT_LT(resolved, whole);
  EXPECT_NEAR(resolved, exact, 0.2 * strip);
  // The cell's five samples place the shadow's corner to within a fifth of the cell: less than
  // half the error of calling it wholly seen.
  EXPECT_LT(std::abs(resolved - exact), 0.5 * (whole - exact));
}

TEST(PartialVisibility, AnEdgeBetweenEverySampleIsFoundByTheShaftVerdicts) {
  // A shadow covering the patch's strip 0.4 <= x <= 0.5: the five samples (x = 0, +-0.25) and the
  // sixteen cell centres (x = +-0.125, +-0.375) all see the light, so both sampled rules call
  // the patch wholly seen. The patch's own shaft verdict is partial, and each cell's verdict
  // within the faces it left finds the edge in the outer column of cells, whose five samples
  // (x = 0.3125, 0.375, 0.4375) place it to within the strip bound of the test above. The
  // five-sample answer is off by the whole strip's factor, five times that bound and more.
  const Patch p = ceiling_square();
  const Vec3 x(0.0), n(0.0, 0.0, 1.0);
  const Vec3 from = x + n * 1e-6;
  const double whole = point_polygon_form_factor(x, n, p.polygon);
  const geometry::OcclusionTree occluder = sheet_occluder(0.2);
  const double exact = visible_part_form_factor(0.4);
  const double five = whole * visible_fraction(&occluder, from, p, 1e-6);
  EXPECT_EQ(five, whole);
  const double resolved = undecided_patch_integral(x, n, from, p, nullptr, 1.0, whole, 5.0,
                                                   occluder, 1e-6, geometry::ShaftFaces{});
  const double half_cell = 0.5 / kSubcellsPerSide;
  const double strip = visible_part_form_factor(half_cell) - visible_part_form_factor(0.0);
  EXPECT_NEAR(resolved, exact, 0.2 * strip);
  EXPECT_GT(std::abs(five - exact), 5.0 * std::abs(resolved - exact));
  // A patch the occluder cannot touch, and one wholly in its shadow: its verdict alone decides,
  // to the bit.
  EXPECT_EQ(undecided_patch_integral(x, n, from, p, nullptr, 1.0, whole, 5.0, sheet_occluder(0.3),
                                     1e-6, geometry::ShaftFaces{}),
            whole);
  EXPECT_EQ(undecided_patch_integral(x, n, from, p, nullptr, 1.0, whole, 5.0, sheet_occluder(-1.0),
                                     1e-6, geometry::ShaftFaces{}),
            0.0);
}

}  // namespace
}  // namespace luxgrid::calc::indirect
