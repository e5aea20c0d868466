#include "calc/indirect/partial_visibility.h"

#include <array>
#include <span>

#include "calc/indirect/subcells.h"

namespace luxgrid::calc::indirect {

namespace {

constexpr int kSide = kSubcellsPerSide;

// The share of a cell's five samples (its centre, whose verdict `centre_seen` is known, and the
// midpoints towards its corners, lifted) seen from `from`: the midpoints by the faces left
// undecided where a shaft verdict narrowed them, by a trace otherwise.
double five_sample_share(const Vec3& from, const SubcellCorners& cell, const Vec3& centre,
                         bool centre_seen, const Vec3& lift, const geometry::Visibility& visibility,
                         const geometry::ShaftFaces* faces) {
  std::array<Vec3, 4> towards;
  for (size_t c = 0; c < 4; ++c) towards[c] = 0.5 * (cell[c] + centre) + lift;
  int count = centre_seen ? 1 : 0;
  if (faces) {
    for (const Vec3& s : towards) count += visibility.visible_among(from, s, *faces) ? 1 : 0;
  } else {
    std::array<bool, 4> seen;
    visibility.visible_from(from, towards, seen.data());
    for (const bool s : seen) count += s ? 1 : 0;
  }
  return count / 5.0;
}

}  // namespace

double partial_cells_integral(const Vec3& x, const Vec3& n, const Vec3& from, const Patch& p,
                              const double* cell_weight, double uniform_weight, double far_ratio,
                              const geometry::Visibility& visibility, double lift_m,
                              const geometry::ShaftFaces& faces) {
  const double cell_diameter = p.diameter_m / kSide;
  const double cell_area = p.area_m2 / (kSide * kSide);
  const double near_d2 = far_ratio * far_ratio * cell_diameter * cell_diameter;
  const Vec3 lift = p.normal * lift_m;
  std::array<SubcellCorners, kSide * kSide> cells;
  std::array<Vec3, kSide * kSide> centres;
  for (int a = 0; a < kSide; ++a)
    for (int b = 0; b < kSide; ++b) {
      const int k = a * kSide + b;
      cells[k] = subcell_corners(p, a, b);
      centres[k] = 0.25 * (cells[k][0] + cells[k][1] + cells[k][2] + cells[k][3]);
    }
  // Every cell's centre first, from the faces left where the patch's verdict narrowed them: the
  // cells where the verdict changes are the edge's.
  const bool narrowed = faces.narrowed();
  const geometry::ShaftFaces* among = narrowed ? &faces : nullptr;
  std::array<bool, kSide * kSide> centre_seen{};
  {
    std::array<Vec3, kSide * kSide> lifted;
    for (int k = 0; k < kSide * kSide; ++k) lifted[k] = centres[k] + lift;
    static_assert(kSide * kSide <= geometry::Visibility::kMaxSegmentsFrom);
    if (narrowed) {
      for (int k = 0; k < kSide * kSide; ++k)
        centre_seen[k] = visibility.visible_among(from, lifted[k], faces);
    } else {
      visibility.visible_from(from, lifted, centre_seen.data());
    }
  }
  // Every centre agreeing in a patch whose own verdict is partial: the edge passes between them
  // (a shadow sliver along the border, or a thin occluder's shadow between centres). Each cell's
  // own verdict among the patch's faces finds it, where they are narrowed. Not otherwise: a test
  // that cannot narrow (the obstacles-only filter of a convex room) calls every shaft near an
  // obstacle partial, hidden ones too, and sixteen verdicts among all faces for each such patch
  // cost a single-threaded run of tests/unusual/coincident_faces/box_given_twice 3.5 times its CPU.
  bool by_cell = narrowed;
  for (int k = 1; k < kSide * kSide; ++k) by_cell = by_cell && centre_seen[k] == centre_seen[0];
  const auto differs = [&](int k, int a, int b) {
    return a >= 0 && a < kSide && b >= 0 && b < kSide &&
           centre_seen[a * kSide + b] != centre_seen[k];
  };
  // by_cell: the verdicts of the patch's quarters (2 x 2 cells each) among the patch's faces,
  // asked when a cell of the quarter first needs one. A quarter proven `visible` or `hidden` is
  // so for each of its cells, which take that share (1 or 0: what their own verdict, or all five
  // samples, would give); a cell of a `partial` quarter is classified among the faces the quarter
  // left, fewer than the patch's. An edge along one border leaves two quarters to go cell by
  // cell: 4 + 8 verdicts instead of 16.
  static_assert(kSide % 2 == 0);
  constexpr int kHalf = kSide / 2;
  std::array<geometry::Shaft, 4> quarter_verdict;
  std::array<geometry::ShaftFaces, 4> quarter_faces;
  std::array<bool, 4> quarter_asked{};
  const auto quarter = [&](int a, int b) {
    const int qa = a / kHalf, qb = b / kHalf, q = qa * 2 + qb;
    if (!quarter_asked[q]) {
      // Counter-clockwise like the cells: corner 0 of its first cell, 1 along a, 2 opposite, 3
      // along b.
      const int a0 = qa * kHalf, b0 = qb * kHalf, a1 = a0 + kHalf - 1, b1 = b0 + kHalf - 1;
      const std::array<Vec3, 4> corners = {
          cells[a0 * kSide + b0][0] + lift, cells[a1 * kSide + b0][1] + lift,
          cells[a1 * kSide + b1][2] + lift, cells[a0 * kSide + b1][3] + lift};
      quarter_verdict[q] = visibility.classify_within(std::span<const Vec3>(&from, 1), corners,
                                                      faces, quarter_faces[q]);
      quarter_asked[q] = true;
    }
    return q;
  };
  double sum = 0.0;
  for (int a = 0; a < kSide; ++a)
    for (int b = 0; b < kSide; ++b) {
      const int k = a * kSide + b;
      const double w = cell_weight ? cell_weight[k] : uniform_weight;
      if (!(w > 0.0)) continue;
      const double f = subcell_form_factor(x, n, p, cells[k], centres[k], cell_area, near_d2);
      if (!(f > 0.0)) continue;
      double seen = centre_seen[k] ? 1.0 : 0.0;
      if (by_cell) {
        const int q = quarter(a, b);
        if (quarter_verdict[q] != geometry::Shaft::partial) {
          sum += w * f * (quarter_verdict[q] == geometry::Shaft::visible ? 1.0 : 0.0);
          continue;
        }
        std::array<Vec3, 4> corners;
        for (size_t c = 0; c < 4; ++c) corners[c] = cells[k][c] + lift;
        geometry::ShaftFaces cell_faces;
        const geometry::Shaft verdict = visibility.classify_within(
            std::span<const Vec3>(&from, 1), corners, quarter_faces[q], cell_faces);
        if (verdict == geometry::Shaft::partial)
          seen = five_sample_share(from, cells[k], centres[k], centre_seen[k], lift, visibility,
                                   &cell_faces);
        else
          seen = verdict == geometry::Shaft::visible ? 1.0 : 0.0;
      } else if (differs(k, a - 1, b) || differs(k, a + 1, b) || differs(k, a, b - 1) ||
                 differs(k, a, b + 1)) {
        // The edge runs through or beside this cell: its midpoints towards its corners too.
        seen =
            five_sample_share(from, cells[k], centres[k], centre_seen[k], lift, visibility, among);
      }
      sum += w * f * seen;
    }
  return sum;
}

double undecided_patch_integral(const Vec3& x, const Vec3& n, const Vec3& from, const Patch& p,
                                const double* cell_weight, double uniform_weight, double whole,
                                double far_ratio, const geometry::Visibility& visibility,
                                double lift_m, const geometry::ShaftFaces& among) {
  std::array<Vec3, 4> corners;
  for (size_t c = 0; c < 4; ++c) corners[c] = p.polygon[c] + p.normal * lift_m;
  geometry::ShaftFaces faces;
  switch (visibility.classify_within(std::span<const Vec3>(&from, 1), corners, among, faces)) {
    case geometry::Shaft::visible: return whole;
    case geometry::Shaft::hidden: return 0.0;
    case geometry::Shaft::partial: break;
  }
  return partial_cells_integral(x, n, from, p, cell_weight, uniform_weight, far_ratio, visibility,
                                lift_m, faces);
}

}  // namespace luxgrid::calc::indirect
