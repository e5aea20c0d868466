#include "calc/indirect/partial_visibility.h"

#include <array>

#include "calc/indirect/subcells.h"

namespace luxgrid::calc::indirect {

double partial_cells_integral(const Vec3& x, const Vec3& n, const Vec3& from, const Patch& p,
                              const double* cell_weight, double uniform_weight, double far_ratio,
                              const geometry::Visibility& visibility, double lift_m) {
  constexpr int kSide = kSubcellsPerSide;
  const double cell_diameter = p.diameter_m / kSide;
  const double cell_area = p.area_m2 / (kSide * kSide);
  const double near_d2 = far_ratio * far_ratio * cell_diameter * cell_diameter;
  const Vec3 lift = p.normal * lift_m;
  // Every cell's centre first: the cells where the verdict changes are the edge's.
  std::array<SubcellCorners, kSide * kSide> cells;
  std::array<Vec3, kSide * kSide> centres;
  std::array<Vec3, kSide * kSide> lifted;
  std::array<bool, kSide * kSide> centre_seen;
  for (int a = 0; a < kSide; ++a)
    for (int b = 0; b < kSide; ++b) {
      const int k = a * kSide + b;
      cells[k] = subcell_corners(p, a, b);
      centres[k] = 0.25 * (cells[k][0] + cells[k][1] + cells[k][2] + cells[k][3]);
      lifted[k] = centres[k] + lift;
    }
  static_assert(kSide * kSide <= geometry::Visibility::kMaxSegmentsFrom);
  visibility.visible_from(from, lifted, centre_seen.data());
  const auto differs = [&](int k, int a, int b) {
    return a >= 0 && a < kSide && b >= 0 && b < kSide &&
           centre_seen[a * kSide + b] != centre_seen[k];
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
      if (differs(k, a - 1, b) || differs(k, a + 1, b) || differs(k, a, b - 1) ||
          differs(k, a, b + 1)) {
        // The edge runs through or beside this cell: its midpoints towards its corners too.
        std::array<Vec3, 4> towards;
        std::array<bool, 4> towards_seen;
        for (size_t c = 0; c < 4; ++c) towards[c] = 0.5 * (cells[k][c] + centres[k]) + lift;
        visibility.visible_from(from, towards, towards_seen.data());
        int count = centre_seen[k] ? 1 : 0;
        for (const bool s : towards_seen) count += s ? 1 : 0;
        seen = count / 5.0;
      }
      sum += w * f * seen;
    }
  return sum;
}

}  // namespace luxgrid::calc::indirect
