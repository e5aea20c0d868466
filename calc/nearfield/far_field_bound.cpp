#include "calc/nearfield/far_field_bound.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <thread>

#include "calc/nearfield/illuminance.h"
#include "calc/nearfield/models.h"

namespace luxgrid::nearfield {
namespace {

constexpr double kGammaStepDeg = 180.0 / (kGammaSamples - 1);
constexpr double kCStepDeg = 360.0 / kCSamples;

// Receivers dimmer than this fraction of the emitter's peak illuminance at the same distance
// (I_max / d^2) are held to an absolute error of tolerance x that floor instead of a relative
// one: the promise covers points brighter than 1 % of a surface's maximum (docs/accuracy.md), and a
// direction at the dark edge of a beam would otherwise ask for the near field out to any
// distance for a value nobody reads. 1e-3 leaves a factor 10 to the 1 % line.
constexpr double kDimFloor = 1e-3;

// Receiver normals tried per direction: facing the emitter, and tilted by this angle towards
// four sides (along gamma and along C). Tilted receivers weigh the near side of the opening
// more than the far side, which the point model cannot; 75 degrees (cos 0.26) covers a floor
// lit from 3.7 times its height away and walls lit at a slant.
constexpr double kReceiverTiltRad = 75.0 * kDegToRad;

// Dilation (below): the footprint half-width D / 2d is taken this many times, and neighbours
// up to this many samples away are looked at (3 gamma steps = 15 degrees, less delta0: a
// neighbour failing everywhere charges 9.2 D there, beyond that its pull is below what most
// directions measure anyway).
constexpr double kFootprintMargin = 2.0;
constexpr int kDilationReach = 3;

// A direction failing out to the ladder's end keeps the near field at every distance.
constexpr float kNearEverywhere = 1e6f;  // x D

Vec3 direction_of_sample(int g, int c) {
  // Luminaire frame: the opening emits towards -z (emitter.h), C = 0 along +x.
  return photometry::direction_of(c * kCStepDeg * kDegToRad, g * kGammaStepDeg * kDegToRad);
}

double rung_over_D(int k) { return kLadderStart * std::pow(kLadderRatio, k); }

struct Probe {
  const Emitter& e;
  const Model& model;
  double tolerance;  // already divided by the safety factor
  double peak_cd;

  // True if the far field is within tolerance at distance rung k along local direction u for
  // every tried receiver normal.
  bool far_ok(const Vec3& u, int k) const {
    const double d = rung_over_D(k) * e.largest_dimension_m;
    const Vec3 w = e.rotation * u;
    const Vec3 p = e.centroid + d * w;
    Vec3 side1 = glm::cross(u, Vec3(0, 0, 1));
    if (glm::length(side1) < 1e-6) side1 = Vec3(0, 1, 0);
    side1 = glm::normalize(side1);
    const Vec3 side2 = glm::cross(u, side1);
    const double floor_lx = kDimFloor * peak_cd / (d * d);
    const Vec3 sides[] = {Vec3(0.0), side1, -side1, side2, -side2};
    for (const Vec3& s : sides) {
      const Vec3 n_local = glm::length(s) > 0 ? -u * std::cos(kReceiverTiltRad) + s * std::sin(kReceiverTiltRad) : -u;
      const Vec3 n = e.rotation * n_local;
      const double near = illuminance(e, p, n, model);
      const double far = far_field_illuminance(e, p, n);
      if (std::abs(near - far) > tolerance * std::max(near, floor_lx)) return false;
    }
    return true;
  }

  // d_far / D along u: the first rung from which the far field passes, by bisection on the
  // ladder (the error falls with distance; a bump between rungs is what the dilation and the
  // safety factor are for).
  float d_far_over_D(const Vec3& u) const {
    // The first rung first: most directions pass there (median 2 D on every file tried), and
    // checking it before the last halves the map's cost.
    if (far_ok(u, 0)) return static_cast<float>(rung_over_D(0));
    if (!far_ok(u, kLadderRungs - 1)) return kNearEverywhere;
    int lo = 0, hi = kLadderRungs - 1;  // lo fails, hi passes
    while (hi - lo > 1) {
      const int mid = (lo + hi) / 2;
      (far_ok(u, mid) ? hi : lo) = mid;
    }
    return static_cast<float>(rung_over_D(hi));
  }
};

// How far a kink can lie from the nearest sample (rad): 0 when every measured angle of the
// table is on a sample line (gamma a multiple of 5 degrees, C of 7.5: the samples then sit on the
// kinks themselves) or when there is no table (analytic profiles have no kinks); else half a
// gamma step, the most a kink can hide between two samples along gamma.
double kink_slack_rad(const Emitter& e) {
  const photometry::TableView view = e.distribution->table_view();
  if (!view.table) return 0.0;
  const auto on_lines = [](const std::vector<double>& angles_rad, double step_deg) {
    return std::all_of(angles_rad.begin(), angles_rad.end(), [&](double a) {
      const double k = a * kRadToDeg / step_deg;
      return std::abs(k - std::round(k)) < 1e-6;
    });
  };
  const auto& grid = view.table->grid();
  return on_lines(grid.gamma_rad, kGammaStepDeg) && on_lines(grid.c_rad, kCStepDeg)
             ? 0.0
             : 0.5 * kGammaStepDeg * kDegToRad;
}

double relative_gradient_per_deg(const Emitter& e, double c_deg, double g_deg) {
  auto I = [&](double c, double g) { return e.distribution->intensity(photometry::direction_of(c * kDegToRad, g * kDegToRad)); };
  const double i0 = I(c_deg, g_deg);
  if (!(i0 > 0.0)) return 0.0;
  const double dg = (I(c_deg, g_deg + 0.5) - I(c_deg, g_deg - 0.5));
  const double dc = (I(c_deg + 0.5, g_deg) - I(c_deg - 0.5, g_deg)) / std::max(std::sin(g_deg * kDegToRad), 1e-3);
  return std::hypot(dg, dc) / i0;
}

}  // namespace

double promised_tolerance(const Model& m) {
  return m.kind == ModelKind::high ? kHighPromise : kStandardPromise;
}

double FarFieldBound::distance_over_D(const Vec3& u) const {
  const photometry::PhotometricAngles a = photometry::angles_of(u);
  const double gamma_deg = a.gamma * kRadToDeg, c_deg = a.c * kRadToDeg;
  const double fg = std::clamp(gamma_deg / kGammaStepDeg, 0.0, kGammaSamples - 1.0);
  const double fc = c_deg / kCStepDeg;
  const int g0 = std::min(static_cast<int>(fg), kGammaSamples - 2);
  const int c0 = static_cast<int>(fc) % kCSamples, c1 = (c0 + 1) % kCSamples;
  const double tg = fg - g0, tc = fc - std::floor(fc);
  // Bilinear in 1 / d_far (the angular footprint a receiver needs): continuous, and a direction
  // needing the near field everywhere (1 / d_far = 0) does not swamp a whole cell.
  auto at = [&](int g, int c) { return 1.0 / static_cast<double>(d_far_over_D[g * kCSamples + c]); };
  const double inv = (1 - tg) * ((1 - tc) * at(g0, c0) + tc * at(g0, c1)) + tg * ((1 - tc) * at(g0 + 1, c0) + tc * at(g0 + 1, c1));
  return 1.0 / std::max(inv, 1.0 / kNearEverywhere);
}

double FarFieldBound::far_weight(const Vec3& u, double distance_m) const {
  const double start = distance_over_D(u) * largest_dimension_m;
  const double t = (distance_m - start) / ((kBlendWidth - 1.0) * start);
  if (t <= 0.0) return 0.0;
  if (t >= 1.0) return 1.0;
  return t * t * (3.0 - 2.0 * t);
}

std::shared_ptr<const FarFieldBound> build_far_field_bound(const Emitter& e, const Model& near_model,
                                                           double tolerance) {
  auto bound = std::make_shared<FarFieldBound>();
  bound->tolerance = tolerance;
  bound->largest_dimension_m = e.largest_dimension_m;
  constexpr int n = kGammaSamples * kCSamples;
  std::vector<float> raw(n, static_cast<float>(kLadderStart));
  if (e.is_point() || !(e.largest_dimension_m > 0.0)) {
    bound->d_far_over_D = raw;
    bound->min_over_D = bound->max_over_D = bound->median_over_D = kLadderStart;
    return bound;
  }
  double peak = 0.0;
  for (int i = 0; i < n; ++i) peak = std::max(peak, e.distribution->intensity(direction_of_sample(i / kCSamples, i % kCSamples)));
  const Probe probe{e, near_model, tolerance / kBoundSafetyFactor, peak};
  // Directions in parallel (the nearfield library has no TBB; the samples are independent).
  const unsigned threads = std::max(1u, std::min(8u, std::thread::hardware_concurrency()));
  std::vector<std::thread> pool;
  for (unsigned t = 0; t < threads; ++t) {
    pool.emplace_back([&, t] {
      for (int i = static_cast<int>(t); i < n; i += static_cast<int>(threads))
        raw[i] = probe.d_far_over_D(direction_of_sample(i / kCSamples, i % kCSamples));
    });
  }
  for (auto& th : pool) th.join();
  // The poles are one direction each: charge every C sample of rows 0 and last with the worst of
  // the pole row and its neighbour row (the footprint there spans all C).
  for (int pole : {0, kGammaSamples - 1}) {
    const int next = pole == 0 ? 1 : kGammaSamples - 2;
    float worst = 0.0f;
    for (int c = 0; c < kCSamples; ++c) worst = std::max({worst, raw[pole * kCSamples + c], raw[next * kCSamples + c]});
    for (int c = 0; c < kCSamples; ++c) raw[pole * kCSamples + c] = worst;
  }
  // Dilation. The point model fails around a kink within about the opening's angular
  // half-width D / 2d of it: a neighbour s' at angle delta that needs the near field out to R'
  // charges this sample with min(R', kFootprintMargin / (2 (delta - delta0))) (the distance at
  // which its footprint no longer reaches here), delta0 = kink_slack_rad (a kink lying between
  // two samples). A coarse full 3 x 3 max instead put whole 10-degree bands in the near
  // field at every distance (2.5 x the open plan's cost) for a kink whose error is 0.5 degrees wide.
  const double delta0 = kink_slack_rad(e);
  bound->d_far_over_D.assign(n, 0.0f);
  for (int g = 0; g < kGammaSamples; ++g)
    for (int c = 0; c < kCSamples; ++c) {
      const Vec3 here = direction_of_sample(g, c);
      double v = 0.0;
      for (int dg = -kDilationReach; dg <= kDilationReach; ++dg)
        for (int dc = -kDilationReach; dc <= kDilationReach; ++dc) {
          const int gg = g + dg, cc = (c + dc + kCSamples) % kCSamples;
          if (gg < 0 || gg >= kGammaSamples) continue;
          const double r = raw[gg * kCSamples + cc];
          const double excess = angle_between(here, direction_of_sample(gg, cc)) - delta0;
          v = std::max(v, excess <= 1e-12 ? r : std::min(r, kFootprintMargin / (2.0 * excess)));
        }
      bound->d_far_over_D[g * kCSamples + c] = static_cast<float>(v);
    }
  // Summary for the plan, over the undilated samples (what each direction measured).
  std::vector<float> sorted = raw;
  std::sort(sorted.begin(), sorted.end());
  bound->min_over_D = sorted.front();
  bound->max_over_D = sorted.back();
  bound->median_over_D = sorted[n / 2];
  bound->near_everywhere_somewhere = sorted.back() >= kNearEverywhere;
  const auto worst = std::max_element(raw.begin(), raw.end()) - raw.begin();
  bound->worst_gamma_deg = (worst / kCSamples) * kGammaStepDeg;
  bound->worst_c_deg = (worst % kCSamples) * kCStepDeg;
  bound->worst_gradient_per_deg = relative_gradient_per_deg(e, bound->worst_c_deg, bound->worst_gamma_deg);
  return bound;
}

std::string describe(const FarFieldBound& b) {
  char buf[320];
  // Up to 8 D the opening's geometry alone (slanted receivers) explains the distance (a
  // Lambertian square measures 7.2 D); beyond, the table does.
  const char* why = b.max_over_D <= 8.0              ? "smooth distribution (geometry of the opening)"
                    : b.worst_gradient_per_deg > 0.05 ? "sharp beam"
                                                      : "kinks or curvature between measured angles";
  if (b.near_everywhere_somewhere) {
    std::snprintf(buf, sizeof buf,
                  "%s: near field at every distance at C %.1f gamma %.0f deg, from %.1f D elsewhere "
                  "(median %.1f D, D = %.2f m); far field within %.2g %% beyond",
                  why, b.worst_c_deg, b.worst_gamma_deg, b.min_over_D, b.median_over_D, b.largest_dimension_m,
                  100 * b.tolerance);
  } else {
    std::snprintf(buf, sizeof buf,
                  "%s: near field out to %.1f D (at C %.1f gamma %.0f deg, intensity changing %.1f %%/deg), "
                  "%.1f D at least, median %.1f D (D = %.2f m); far field within %.2g %% beyond",
                  why, b.max_over_D, b.worst_c_deg, b.worst_gamma_deg, 100 * b.worst_gradient_per_deg,
                  b.min_over_D, b.median_over_D, b.largest_dimension_m, 100 * b.tolerance);
  }
  return buf;
}

}  // namespace luxgrid::nearfield
