#include "calc/nearfield/map_symmetry.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "calc/nearfield/far_field_bound.h"
#include "photometry/tabular_distribution.h"
#include "util/robust_math.h"

namespace luxgrid::nearfield {
namespace {

// How close a mirrored vertex or node must come to one of the originals, x D: far below any
// opening a manufacturer draws, far above the rounding of the luminaire's rotation.
constexpr double kMirrorTolerance = 1e-9;
// How close a mirrored C plane must come to one of the table's (rad).
constexpr double kPlaneTolerance_rad = 1e-9;

// The mirror images of the luminaire frame: across the plane C 0-180 (y -> -y) and across the
// plane C 90-270 (x -> -x).
enum class Mirror { across_c0, across_c90 };

Vec3 mirrored(const Vec3& v, Mirror m) {
  return m == Mirror::across_c0 ? Vec3(v.x, -v.y, v.z) : Vec3(-v.x, v.y, v.z);
}

double mirrored_c(double c_rad, Mirror m) {
  const double c = m == Mirror::across_c0 ? -c_rad : kPi - c_rad;
  return c - 2.0 * kPi * std::floor(c / (2.0 * kPi));
}

// Every point of `local` (luminaire frame, relative to the opening's centroid) has a mirror
// image among them with the same weight.
bool mirrors_onto_itself(const std::vector<Vec3>& local, const std::vector<double>& weight,
                         Mirror m, double tolerance_m) {
  for (std::size_t i = 0; i < local.size(); ++i) {
    const Vec3 image = mirrored(local[i], m);
    bool found = false;
    for (std::size_t j = 0; j < local.size() && !found; ++j)
      found = glm::length(local[j] - image) <= tolerance_m &&
              std::abs(weight[j] - weight[i]) <= 1e-12 * std::max(1.0, std::abs(weight[i]));
    if (!found) return false;
  }
  return true;
}

// Every C plane of the table has a mirror image among its planes with the same candela values.
bool table_mirrors_onto_itself(const photometry::SphericalGrid& grid, Mirror m) {
  const std::size_t nc = grid.c_rad.size(), ng = grid.gamma_rad.size();
  if (nc == 1) return true;  // rotationally symmetric
  for (std::size_t i = 0; i < nc; ++i) {
    const double image = mirrored_c(grid.c_rad[i], m);
    std::size_t j = 0;
    for (; j < nc; ++j) {
      const double gap = std::abs(grid.c_rad[j] - image);
      if (std::min(gap, 2.0 * kPi - gap) <= kPlaneTolerance_rad) break;
    }
    if (j == nc) return false;
    for (std::size_t k = 0; k < ng; ++k)
      if (grid.at(i, k) != grid.at(j, k)) return false;
  }
  return true;
}

bool emitter_mirrors_onto_itself(const Emitter& e, Mirror m) {
  const photometry::TableView view = e.distribution->table_view();
  if (!view.table || !table_mirrors_onto_itself(view.table->grid(), m)) return false;
  const auto local = [&](const std::vector<Vec3>& world) {
    std::vector<Vec3> out;
    for (const Vec3& p : world) out.push_back(e.world_to_local * (p - e.centroid));
    return out;
  };
  const double tolerance_m = kMirrorTolerance * e.largest_dimension_m;
  return mirrors_onto_itself(local(e.vertices), std::vector<double>(e.vertices.size(), 1.0), m,
                             tolerance_m) &&
         mirrors_onto_itself(local(e.rule_nodes), e.rule_weights, m, tolerance_m);
}

// The sample index of a sample's mirror image (the grid's C samples are symmetric about both
// planes: C = 0 and C = 180 degrees are samples, kCSamples is a multiple of 4).
int mirrored_sample(int i, Mirror m) {
  static_assert(kCSamples % 4 == 0);
  const int g = i / kCSamples, c = i % kCSamples;
  const int image = m == Mirror::across_c0 ? kCSamples - c : kCSamples / 2 - c;
  return g * kCSamples + (image + kCSamples) % kCSamples;
}

}  // namespace

std::vector<int> map_sample_representatives(const Emitter& e, bool near_is_table) {
  std::vector<Mirror> mirrors;
  if (near_is_table && !e.is_point())
    for (Mirror m : {Mirror::across_c0, Mirror::across_c90})
      if (emitter_mirrors_onto_itself(e, m)) mirrors.push_back(m);
  constexpr int n = kGammaSamples * kCSamples;
  std::vector<int> rep(n);
  for (int i = 0; i < n; ++i) {
    const int g = i / kCSamples;
    if (g == 0 || g == kGammaSamples - 1) {
      rep[i] = g * kCSamples;
      continue;
    }
    // The class of i: its images under the mirrors and their product (the two commute).
    rep[i] = i;
    for (Mirror m : mirrors) rep[i] = std::min(rep[i], mirrored_sample(i, m));
    if (mirrors.size() == 2)
      rep[i] = std::min(rep[i], mirrored_sample(mirrored_sample(i, mirrors[0]), mirrors[1]));
  }
  return rep;
}

}  // namespace luxgrid::nearfield
