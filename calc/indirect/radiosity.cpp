#include "calc/indirect/radiosity.h"

#include <cmath>
#include <limits>

#include <tbb/parallel_for.h>

namespace luxgrid::calc::indirect {

namespace {
// Shooting points sit this far in front of their patch, so that visibility tests from a wall
// patch do not start on the wall.
constexpr double kShootLift_m = 1e-6;
// A receiver whose plane passes within this distance of the shooting point sees it edge-on.
constexpr double kMinPlaneDistance_m = 1e-9;
// The geometric tail is added once the bounce ratio has changed by less than this (relative)
// over the last sweep; below it the tail's shape error is negligible against the tolerances.
constexpr double kRatioStability = 1e-4;
constexpr int kMinSweepsBeforeTail = 4;

double l1(const std::vector<double>& v) {
  double s = 0.0;
  for (double x : v) s += std::abs(x);
  return s;
}

// Fraction of `target` visible from `from`: its centroid and the midpoints between centroid and
// each vertex.
double visible_fraction(const Vec3& from, const Patch& target, const OcclusionFn& occluded) {
  if (!occluded) return 1.0;
  const Vec3 lift = target.normal * kShootLift_m;
  int seen = occluded(from, target.centroid + lift) ? 0 : 1;
  for (const auto& v : target.polygon)
    if (!occluded(from, 0.5 * (v + target.centroid) + lift)) ++seen;
  return static_cast<double>(seen) / static_cast<double>(target.polygon.size() + 1);
}
}  // namespace

FormFactorMatrix form_factors(const PatchMesh& mesh, int room, const OcclusionFn& occluded,
                              double far_ratio, bool renormalise) {
  FormFactorMatrix F;
  F.begin = mesh.room_begin[room];
  F.n = mesh.room_begin[room + 1] - F.begin;
  F.renormalised = renormalise;
  const size_t n = F.n;
  F.gather.assign(n * n, 0.0f);
  std::vector<double> correction(n, 0.0);
  tbb::parallel_for(size_t(0), n, [&](size_t j) {
    const Patch& src = mesh.patches[F.begin + j];
    const Vec3 from = src.centroid + src.normal * kShootLift_m;
    std::vector<double> row(n, 0.0);
    double sum = 0.0;
    for (size_t i = 0; i < n; ++i) {
      if (i == j) continue;
      const Patch& dst = mesh.patches[F.begin + i];
      if (!(glm::dot(dst.normal, src.centroid - dst.centroid) > kMinPlaneDistance_m)) continue;
      if (!(glm::dot(src.normal, dst.centroid - src.centroid) > -dst.diameter_m)) continue;
      const double d = glm::length(dst.centroid - src.centroid);
      double f = d > far_ratio * dst.diameter_m
                     ? point_kernel_form_factor(src.centroid, src.normal, dst.centroid, dst.normal,
                                                dst.area_m2)
                     : point_polygon_form_factor(src.centroid, src.normal, dst.polygon);
      if (f > 0.0) f *= visible_fraction(from, dst, occluded);
      row[i] = f;
      sum += f;
    }
    correction[j] = std::abs(1.0 - sum);
    const double scale = renormalise && sum > 0.0 ? 1.0 / sum : 1.0;
    for (size_t i = 0; i < n; ++i) F.gather[i * n + j] = static_cast<float>(row[i] * scale);
  });
  for (double c : correction) F.max_row_correction = std::max(F.max_row_correction, c);
  return F;
}

RadiosityResult solve_radiosity(const FormFactorMatrix& F, const std::vector<double>& reflectance,
                                const std::vector<double>& incident_flux_lm, int bounces,
                                double tolerance, int max_bounces) {
  const size_t n = F.n;
  RadiosityResult res;
  std::vector<double> delta(n), next(n);
  for (size_t i = 0; i < n; ++i) delta[i] = reflectance[i] * incident_flux_lm[i];
  res.exitant_flux_lm = delta;
  res.bounces_run = 1;
  double delta_norm = l1(delta);
  res.bounce_flux_lm.push_back(delta_norm);
  double total = delta_norm;
  if (n == 0 || total == 0.0) return res;

  auto sweep = [&]() {
    tbb::parallel_for(size_t(0), n, [&](size_t i) {
      const float* row = F.gather.data() + i * n;
      double s = 0.0;
      for (size_t j = 0; j < n; ++j) s += static_cast<double>(row[j]) * delta[j];
      next[i] = reflectance[i] * s;
    });
    delta.swap(next);
    for (size_t i = 0; i < n; ++i) res.exitant_flux_lm[i] += delta[i];
    const double prev_norm = delta_norm;
    delta_norm = l1(delta);
    res.bounce_flux_lm.push_back(delta_norm);
    total += delta_norm;
    ++res.bounces_run;
    return prev_norm > 0.0 ? delta_norm / prev_norm : 0.0;
  };

  const int target = bounces > 0 ? bounces : max_bounces;
  double ratio_prev = std::numeric_limits<double>::quiet_NaN();
  while (res.bounces_run < target) {
    const double r = sweep();
    if (bounces > 0) continue;
    if (!(r < 1.0)) {  // no absorption: the series does not converge
      ratio_prev = r;
      continue;
    }
    const double tail = delta_norm * r / (1.0 - r);
    if (tail <= tolerance * total) {
      res.residual = tail / total;
      return res;
    }
    const int sweeps = res.bounces_run - 1;
    if (sweeps >= kMinSweepsBeforeTail && std::abs(r - ratio_prev) <= kRatioStability * r) {
      // Geometric remainder, distributed like the last bounce (the dominant eigenvector).
      const double factor = r / (1.0 - r);
      for (size_t i = 0; i < n; ++i) res.exitant_flux_lm[i] += delta[i] * factor;
      res.tail_added = true;
      // Error of the tail: the ratio may still drift by |r - r_prev| per sweep.
      res.residual = delta_norm * std::abs(r - ratio_prev) / ((1.0 - r) * (1.0 - r)) / (total + tail);
      return res;
    }
    ratio_prev = r;
  }
  // Fixed N (or the cap): the light not followed is roughly the next bounces' share.
  if (res.bounce_flux_lm.size() >= 2) {
    const double r = res.bounce_flux_lm.back() / res.bounce_flux_lm[res.bounce_flux_lm.size() - 2];
    res.residual = r < 1.0 ? delta_norm * r / (1.0 - r) / total
                           : std::numeric_limits<double>::infinity();
  } else {
    // One bounce: estimate the next bounce from the mean reflectance (flux-weighted).
    double rho = 0.0;
    for (size_t i = 0; i < n; ++i) rho += reflectance[i] * delta[i];
    rho /= total;
    res.residual = rho < 1.0 ? rho / (1.0 - rho) : std::numeric_limits<double>::infinity();
  }
  return res;
}

}  // namespace luxgrid::calc::indirect
