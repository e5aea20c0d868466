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
        std::array<Vec3, 4> corners;
        for (size_t c = 0; c < 4; ++c) corners[c] = cells[k][c] + lift;
        geometry::ShaftFaces cell_faces;
        const geometry::Shaft verdict =
            visibility.classify_within(std::span<const Vec3>(&from, 1), corners, faces, cell_faces);
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
