#include "calc/indirect/split_mask.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace luxgrid::calc::indirect {

namespace {

// Normals of one face agree to rounding; two faces of a room differ by far more.
constexpr double kSameNormalCosine = 1.0 - 1e-9;
// Centroids of grid neighbours (edge or corner) lie within this share of the sum of diameters:
// 0.5 for two equal squares touching at a corner, less along an edge.
constexpr double kNeighbourReach = 0.55;

bool same_face(const Patch& a, const Patch& b) {
  return a.face == b.face && a.face_index == b.face_index &&
         glm::dot(a.normal, b.normal) > kSameNormalCosine;
}

}  // namespace

std::vector<char> patches_to_split(const PatchMesh& mesh, size_t begin, size_t end,
                                   const std::vector<double>& exitant_flux_lm, double jump,
                                   size_t max_added) {
  std::vector<char> split(mesh.patches.size(), 0);
  // The largest relative jump of each patch to a neighbour (0: none), for the ones that can be cut.
  std::vector<double> score(end - begin, 0.0);
  for (size_t i = begin; i < end; ++i) {
    const Patch& a = mesh.patches[i];
    if (!a.has_quarters) continue;
    const double ma = exitant_flux_lm[i] / a.area_m2;
    for (size_t j = begin; j < end; ++j) {
      if (j == i) continue;
      const Patch& b = mesh.patches[j];
      if (!same_face(a, b)) continue;
      const Vec3 d = b.centroid - a.centroid;
      const double reach = kNeighbourReach * (a.diameter_m + b.diameter_m);
      if (glm::dot(d, d) > reach * reach) continue;
      const double mb = exitant_flux_lm[j] / b.area_m2;
      const double larger = std::max(ma, mb);
      if (larger > 0.0) score[i - begin] = std::max(score[i - begin], std::abs(ma - mb) / larger);
    }
  }
  std::vector<size_t> cut;
  for (size_t k = 0; k < score.size(); ++k)
    if (score[k] > jump) cut.push_back(k);
  const size_t most = max_added / 3;
  if (cut.size() > most) {
    std::stable_sort(cut.begin(), cut.end(),
                     [&](size_t x, size_t y) { return score[x] > score[y]; });
    cut.resize(most);
  }
  for (const size_t k : cut) split[begin + k] = 1;
  return split;
}

std::vector<double> ambient_exitance(const PatchMesh& mesh, size_t begin, size_t end,
                                     const std::vector<double>& incident_flux_lm) {
  std::vector<double> exitant(mesh.patches.size(), 0.0);
  double area_m2 = 0.0, rho_area = 0.0, reflected_lm = 0.0;
  for (size_t i = begin; i < end; ++i) {
    const Patch& p = mesh.patches[i];
    area_m2 += p.area_m2;
    rho_area += p.reflectance * p.area_m2;
    reflected_lm += p.reflectance * incident_flux_lm[i];
  }
  if (!(area_m2 > 0.0)) return exitant;
  const double rho_mean = rho_area / area_m2;
  // Reflectance 1 everywhere absorbs nothing: no finite ambient term, the first bounce alone.
  const double ambient_lx = rho_mean < 1.0 ? reflected_lm / (area_m2 * (1.0 - rho_mean)) : 0.0;
  for (size_t i = begin; i < end; ++i) {
    const Patch& p = mesh.patches[i];
    exitant[i] = p.reflectance * (incident_flux_lm[i] + p.area_m2 * ambient_lx);
  }
  return exitant;
}

}  // namespace luxgrid::calc::indirect
