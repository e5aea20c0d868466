#include "calc/indirect/partial_visibility.h"

#include "calc/indirect/subcells.h"

namespace luxgrid::calc::indirect {

double partial_cells_integral(const Vec3& x, const Vec3& n, std::span<const Vec3> from,
                              const Patch& p, const double* cell_weight, double uniform_weight,
                              double far_ratio, const geometry::Visibility& visibility,
                              double lift_m, bool cell_midpoints) {
  const double cell_diameter = p.diameter_m / kSubcellsPerSide;
  const double cell_area = p.area_m2 / (kSubcellsPerSide * kSubcellsPerSide);
  const double near_d2 = far_ratio * far_ratio * cell_diameter * cell_diameter;
  const Vec3 lift = p.normal * lift_m;
  const int samples_per_cell = cell_midpoints ? 5 : 1;
  const double per_sample = 1.0 / static_cast<double>(samples_per_cell * from.size());
  double sum = 0.0;
  for (int a = 0; a < kSubcellsPerSide; ++a)
    for (int b = 0; b < kSubcellsPerSide; ++b) {
      const double w = cell_weight ? cell_weight[a * kSubcellsPerSide + b] : uniform_weight;
      if (!(w > 0.0)) continue;
      const SubcellCorners cell = subcell_corners(p, a, b);
      const Vec3 centre = 0.25 * (cell[0] + cell[1] + cell[2] + cell[3]);
      const double f = subcell_form_factor(x, n, p, cell, centre, cell_area, near_d2);
      if (!(f > 0.0)) continue;
      Vec3 samples[5] = {centre + lift};
      for (int c = 1; c < samples_per_cell; ++c) samples[c] = 0.5 * (cell[c - 1] + centre) + lift;
      int seen = 0;
      for (const Vec3& o : from)
        for (int c = 0; c < samples_per_cell; ++c)
          if (visibility.visible(o, samples[c])) ++seen;
      sum += w * f * (seen * per_sample);
    }
  return sum;
}

}  // namespace luxgrid::calc::indirect
