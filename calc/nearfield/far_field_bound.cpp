#include "calc/nearfield/far_field_bound.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <utility>

#include "calc/nearfield/fixed_rule.h"
#include "calc/nearfield/illuminance.h"
#include "calc/nearfield/map_symmetry.h"
#include "calc/nearfield/models.h"
#include "calc/nearfield/table_far_bound.h"
#include "calc/nearfield/table_rung_scratch.h"
#include "util/ordered_tasks.h"

namespace luxgrid::nearfield {
namespace {

constexpr double kGammaStepDeg = 180.0 / (kGammaSamples - 1);
constexpr double kCStepDeg = 360.0 / kCSamples;

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

// The search below tries a direction's last rung right after rung 0 when the last is at most
// this (5 D, its receivers no farther; far_field_bound.h's MapDemand).
constexpr int kCapFirstRungs = 5;

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
  // The near rung is the table rung (standard and high without an occluder; table_light_vector
  // says whether the distribution has a table).
  bool uses_table;

  // Every vertex of the opening strictly in front of the receiver's plane: no horizon clip.
  bool sees_whole_opening(const Vec3& point, const Vec3& normal) const {
    for (const Vec3& v : e.vertices)
      if (!(glm::dot(v - point, normal) > 0.0)) return false;
    return !e.vertices.empty();
  }

  // The receiver normals tried at rung k along u (luminaire frame): facing the opening and
  // tilted towards four sides; and the receiver point.
  struct Rung {
    Vec3 point;
    std::array<Vec3, 5> normals;
    double floor_lx;
  };
  Rung rung(const Vec3& u, int k) const {
    const double d = rung_over_D(k) * e.largest_dimension_m;
    Rung r;
    r.point = e.centroid + d * (e.rotation * u);
    Vec3 side1 = glm::cross(u, Vec3(0, 0, 1));
    if (glm::length(side1) < 1e-6) side1 = Vec3(0, 1, 0);
    side1 = glm::normalize(side1);
    const Vec3 side2 = glm::cross(u, side1);
    const Vec3 sides[] = {Vec3(0.0), side1, -side1, side2, -side2};
    for (int i = 0; i < 5; ++i) {
      const Vec3& s = sides[i];
      const Vec3 n_local = glm::length(s) > 0
                               ? -u * std::cos(kReceiverTiltRad) + s * std::sin(kReceiverTiltRad)
                               : -u;
      r.normals[i] = e.rotation * n_local;
    }
    r.floor_lx = kDimFloor * peak_cd / (d * d);
    return r;
  }

  // d_far / D and d_fixed / D along u: for each, the first rung from which the model is within
  // tolerance at every tried normal, by bisection on the ladder (the error falls with distance;
  // a bump between rungs is what the dilation and the safety factor are for). A verdict stops
  // at its first failing normal, and the near-field values (the expensive part) are kept per
  // rung and normal, so the two searches share them.
  // What one direction measured: both distances, and the relative error each model showed
  // there at its chosen rung (the worst of the five normals; 0 where a direction failed
  // everywhere, as the model is then not used along it).
  struct Measured {
    float far_over_D, fixed_over_D;
    float far_error, fixed_error;
  };
  // The same as rungs: the first passing rung of each search (-1: none passed; the fixed rule's
  // also -1 when it was not measured) and the errors there.
  struct Rungs {
    int far, fixed;
    float far_error, fixed_error;
  };
  // `last`: the last rung tried (the ladder's end, or the first rung at or beyond the farthest
  // receiver of a MapDemand); failing there is "near field at every distance tried". The same
  // for the fixed rule, `fixed_last` (-1: not measured, its distance is the far field's).
  Rungs distances_over_D(const Vec3& u, int last = kLadderRungs - 1,
                         int fixed_last = kLadderRungs - 1) const {
    std::array<std::array<double, 5>, kLadderRungs> near;
    for (auto& row : near) row.fill(-1.0);
    std::array<signed char, kLadderRungs> far_seen, fixed_seen;  // -1 unknown, 0 fails, 1 passes
    std::array<float, kLadderRungs> far_err{}, fixed_err{};      // worst error of a passing rung
    far_seen.fill(-1);
    fixed_seen.fill(-1);
    // The table rung's light vector per rung (computed once, then n . vector for every normal
    // that sees the whole opening: docs/nearfield.md, "Cost of the map").
    std::array<Vec3, kLadderRungs> light_vector;
    std::array<signed char, kLadderRungs> has_vector;  // -1 not tried, 0 no table, 1 computed
    has_vector.fill(-1);
    TableRungScratch scratch;  // the table rung's buffers, for this direction's rungs
    auto near_value = [&](int k, const Rung& r, int i) {
      if (uses_table && sees_whole_opening(r.point, r.normals[i])) {
        if (has_vector[k] < 0)
          has_vector[k] = table_light_vector(e, r.point, light_vector[k], scratch) ? 1 : 0;
        if (has_vector[k] == 1)
          return sanitize_illuminance(glm::dot(r.normals[i], light_vector[k]));
      }
      return illuminance(e, r.point, r.normals[i], model, nullptr, &scratch);
    };
    auto verdict = [&](int k, bool fixed) {
      signed char& seen = (fixed ? fixed_seen : far_seen)[k];
      if (seen >= 0) return seen == 1;
      const Rung r = rung(u, k);
      seen = 1;
      double worst = 0.0;
      for (int i = 0; i < 5 && seen; ++i) {
        if (near[k][i] < 0.0) near[k][i] = near_value(k, r, i);
        const double model_lx =
            fixed ? fixed_rule_illuminance(e, r.point, Receiver::planar(r.normals[i]))
                  : far_field_illuminance(e, r.point, r.normals[i]);
        const double error = std::abs(near[k][i] - model_lx) / std::max(near[k][i], r.floor_lx);
        if (!(error <= tolerance)) seen = 0;
        worst = std::max(worst, error);
      }
      (fixed ? fixed_err : far_err)[k] = static_cast<float>(worst);
      return seen == 1;
    };
    // Returns the first passing rung within [0, last], or -1 when `last` fails too. Galloping
    // (rungs 0, 1, 3, 7, 15, last, then bisection inside the bracket): a failing verdict stops
    // at its first failing normal and is cheap, a passing one costs all five, so the search
    // tries to pass as few times as it can.
    // A direction whose receivers all lie within kCapFirstRungs of the ladder's start (a
    // MapDemand's) is tried at `last` first: failing there (the near field out to the farthest
    // receiver: a smooth opening needs 5 to 7 D in front of it) ends the search after one
    // verdict, without the nearest rung, whose near value costs the most (the opening is seen
    // widest there). Where the error falls with distance, as the ladder assumes, every nearer
    // rung fails too; where it would not, keeping the near field is the safe side.
    auto search = [&](bool fixed, int last) {
      int lo = -1, hi = -1;  // lo fails (or -1: none tried), hi passes
      if (last > 1 && last <= kCapFirstRungs && !verdict(last, fixed)) return -1;
      for (int k = 0;; k = std::min(2 * k + 1, last)) {
        if (verdict(k, fixed)) {
          hi = k;
          break;
        }
        lo = k;
        if (k == last) return -1;
      }
      while (hi - lo > 1) {
        const int mid = (lo + hi) / 2;
        (verdict(mid, fixed) ? hi : lo) = mid;
      }
      return hi;
    };
    const int far = search(false, last);
    const float far_error = far < 0 ? 0.0f : far_err[far];
    // The fixed rule is used only nearer than d_far, so only the rungs below it matter.
    if (far == 0 || fixed_last < 0) return {far, -1, far_error, 0.0f};
    const int fixed = search(true, std::min(far < 0 ? last : far, fixed_last));
    return {far, fixed, far_error, fixed < 0 ? 0.0f : fixed_err[fixed]};
  }
};

// What a sample whose searches end at `last` and `fixed_last` reads from rungs measured for its
// class (map_symmetry.h) with the class's largest: the same rungs where they lie within its own
// searches, else failing there (the near field out to its farthest receiver). For the sample
// that set the class's searches, exactly what its own search found.
Probe::Measured for_sample(const Probe::Rungs& r, int last, int fixed_last) {
  const auto over_D = [](int k) {
    return k < 0 ? kNearEverywhere : static_cast<float>(rung_over_D(k));
  };
  const int far = r.far >= 0 && r.far <= last ? r.far : -1;
  Probe::Measured m{over_D(far), over_D(far), far < 0 ? 0.0f : r.far_error, 0.0f};
  if (far == 0 || fixed_last < 0) return m;
  if (r.fixed >= 0 && r.fixed <= std::min(far < 0 ? last : far, fixed_last)) {
    m.fixed_over_D = over_D(r.fixed);
    m.fixed_error = r.fixed_error;
  }
  return m;
}

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
  auto I = [&](double c, double g) {
    return e.distribution->intensity(photometry::direction_of(c * kDegToRad, g * kDegToRad));
  };
  const double i0 = I(c_deg, g_deg);
  if (!(i0 > 0.0)) return 0.0;
  const double dg = (I(c_deg, g_deg + 0.5) - I(c_deg, g_deg - 0.5));
  const double dc =
      (I(c_deg + 0.5, g_deg) - I(c_deg - 0.5, g_deg)) / std::max(std::sin(g_deg * kDegToRad), 1e-3);
  return std::hypot(dg, dc) / i0;
}

}  // namespace

double promised_tolerance(const Model& m) {
  return m.kind == ModelKind::high ? kHighPromise : kStandardPromise;
}

namespace {

// Where a local direction falls in the sample grid: the cell's corner and its fractions.
struct GridSpot {
  int g0, c0, c1;
  double tg, tc;
};

GridSpot spot_of(const photometry::PhotometricAngles& a) {
  const double gamma_deg = a.gamma * kRadToDeg, c_deg = a.c * kRadToDeg;
  const double fg = std::clamp(gamma_deg / kGammaStepDeg, 0.0, kGammaSamples - 1.0);
  const double fc = c_deg / kCStepDeg;
  GridSpot s;
  s.g0 = std::min(static_cast<int>(fg), kGammaSamples - 2);
  s.c0 = static_cast<int>(fc) % kCSamples;
  s.c1 = (s.c0 + 1) % kCSamples;
  s.tg = fg - s.g0;
  s.tc = fc - std::floor(fc);
  return s;
}
GridSpot spot_of(const Vec3& u) { return spot_of(photometry::angles_of(u)); }

// Bilinear in 1 / d (the angular footprint a receiver needs): continuous, and a direction
// needing the near field everywhere (1 / d = 0) does not swamp a whole cell.
// `inverse`: 1 / map per sample, made once (the same doubles), or empty.
double interpolate_over_D(const std::vector<float>& map, const std::vector<double>& inverse,
                          const GridSpot& s) {
  auto at = [&](int g, int c) {
    const int i = g * kCSamples + c;
    return inverse.empty() ? 1.0 / static_cast<double>(map[i]) : inverse[i];
  };
  const double inv = (1 - s.tg) * ((1 - s.tc) * at(s.g0, s.c0) + s.tc * at(s.g0, s.c1)) +
                     s.tg * ((1 - s.tc) * at(s.g0 + 1, s.c0) + s.tc * at(s.g0 + 1, s.c1));
  return 1.0 / std::max(inv, 1.0 / kNearEverywhere);
}

std::vector<double> inverse_of(const std::vector<float>& map) {
  std::vector<double> inverse(map.size());
  for (std::size_t i = 0; i < map.size(); ++i) inverse[i] = 1.0 / static_cast<double>(map[i]);
  return inverse;
}

// Smoothstep from `start` to kBlendWidth x start: value and slope continuous along a ray.
double ramp(double distance_m, double start_m) {
  const double t = (distance_m - start_m) / ((kBlendWidth - 1.0) * start_m);
  if (t <= 0.0) return 0.0;
  if (t >= 1.0) return 1.0;
  return t * t * (3.0 - 2.0 * t);
}

// Each sample charged with what its neighbours need, scaled by the footprint (see the caller);
// only where `wanted` is positive (the samples a demand reads), the rest 0.
std::vector<float> dilate(const std::vector<float>& raw, double delta0,
                          const std::vector<float>& wanted) {
  // The samples' directions, made once: each is read by up to 49 neighbours.
  std::vector<Vec3> dir(raw.size());
  for (int g = 0; g < kGammaSamples; ++g)
    for (int c = 0; c < kCSamples; ++c) dir[g * kCSamples + c] = direction_of_sample(g, c);
  std::vector<float> out(raw.size(), 0.0f);
  for (int g = 0; g < kGammaSamples; ++g)
    for (int c = 0; c < kCSamples; ++c) {
      if (!(wanted[g * kCSamples + c] > 0.0f)) continue;
      const Vec3& here = dir[g * kCSamples + c];
      double v = 0.0;
      for (int dg = -kDilationReach; dg <= kDilationReach; ++dg)
        for (int dc = -kDilationReach; dc <= kDilationReach; ++dc) {
          const int gg = g + dg, cc = (c + dc + kCSamples) % kCSamples;
          if (gg < 0 || gg >= kGammaSamples) continue;
          const double r = raw[gg * kCSamples + cc];
          const double excess = angle_between(here, dir[gg * kCSamples + cc]) - delta0;
          v = std::max(v, excess <= 1e-12 ? r : std::min(r, kFootprintMargin / (2.0 * excess)));
        }
      out[g * kCSamples + c] = static_cast<float>(v);
    }
  return out;
}

// The poles are one direction each: charge every C sample of rows 0 and last with the worst of
// the pole row and its neighbour row (the footprint there spans all C).
void merge_poles(std::vector<float>& raw) {
  for (int pole : {0, kGammaSamples - 1}) {
    const int next = pole == 0 ? 1 : kGammaSamples - 2;
    float worst = 0.0f;
    for (int c = 0; c < kCSamples; ++c)
      worst = std::max({worst, raw[pole * kCSamples + c], raw[next * kCSamples + c]});
    for (int c = 0; c < kCSamples; ++c) raw[pole * kCSamples + c] = worst;
  }
}

// Which samples a demand reads and which it measures, each with its farthest receiver (x D;
// 0: none).
struct Needs {
  std::vector<float> read_over_D;     // read by a pair's interpolation (one sample of margin)
  std::vector<float> measure_over_D;  // read, or read by a read sample's dilation or pole
  // The same for the fixed rule's distances (read where the fixed rule may serve a pair).
  std::vector<float> fixed_read_over_D, fixed_measure_over_D;
  static Needs everything() {
    const auto all = std::vector<float>(kGammaSamples * kCSamples, kNearEverywhere);
    return {all, all, all, all};
  }
};

// The larger value over the samples within `reach` of each (in gamma, and in C around the circle).
std::vector<float> max_filter(const std::vector<float>& v, int reach) {
  std::vector<float> along_c(v.size(), 0.0f), out(v.size(), 0.0f);
  for (int g = 0; g < kGammaSamples; ++g)
    for (int c = 0; c < kCSamples; ++c)
      for (int dc = -reach; dc <= reach; ++dc)
        along_c[g * kCSamples + c] = std::max(along_c[g * kCSamples + c],
                                              v[g * kCSamples + (c + dc + kCSamples) % kCSamples]);
  for (int g = 0; g < kGammaSamples; ++g)
    for (int dg = -reach; dg <= reach; ++dg)
      if (g + dg >= 0 && g + dg < kGammaSamples)
        for (int c = 0; c < kCSamples; ++c)
          out[g * kCSamples + c] =
              std::max(out[g * kCSamples + c], along_c[(g + dg) * kCSamples + c]);
  return out;
}

// What reaches read: one sample of margin around the four a pair reads (its direction here and
// in the run are the same doubles, but the margin costs little and takes rounding out of the
// argument); what they measure: those and their neighbours in the dilation, and merge_poles
// makes a pole sample the worst of its row and the next, at every C.
void read_and_measure(const std::vector<float>& reach, std::vector<float>& read,
                      std::vector<float>& measure) {
  read = max_filter(reach, 1);
  measure = max_filter(read, kDilationReach);
  for (int pole : {0, kGammaSamples - 1}) {
    const int next = pole == 0 ? 1 : kGammaSamples - 2;
    float farthest = 0.0f;
    for (int c = 0; c < kCSamples; ++c)
      farthest = std::max(farthest, measure[pole * kCSamples + c]);
    for (int row : {pole, next})
      for (int c = 0; c < kCSamples; ++c)
        measure[row * kCSamples + c] = std::max(measure[row * kCSamples + c], farthest);
  }
}

Needs needs_of(const MapDemand& demand) {
  Needs n;
  read_and_measure(demand.reach_over_D(), n.read_over_D, n.measure_over_D);
  read_and_measure(demand.fixed_reach_over_D(), n.fixed_read_over_D, n.fixed_measure_over_D);
  return n;
}

// The last rung a sample needs: the first at or beyond its farthest receiver (failing there, the
// far field fails at every receiver), at most the ladder's end.
int last_rung_for(float reach_over_D) {
  for (int k = 0; k < kLadderRungs - 1; ++k)
    if (rung_over_D(k) >= reach_over_D) return k;
  return kLadderRungs - 1;
}

}  // namespace

MapDemand::MapDemand()
    : reach_(kGammaSamples * kCSamples, 0.0f), fixed_reach_(kGammaSamples * kCSamples, 0.0f) {}

void MapDemand::add(const Vec3& local_dir, double distance_over_D, bool fixed_rule) {
  const GridSpot s = spot_of(local_dir);
  const auto d = static_cast<float>(std::min(distance_over_D, double{kNearEverywhere}));
  for (int g : {s.g0, s.g0 + 1})
    for (int c : {s.c0, s.c1}) {
      reach_[g * kCSamples + c] = std::max(reach_[g * kCSamples + c], d);
      if (fixed_rule)
        fixed_reach_[g * kCSamples + c] = std::max(fixed_reach_[g * kCSamples + c], d);
    }
  ++receivers_;
}

void MapDemand::merge(const MapDemand& other) {
  for (std::size_t i = 0; i < reach_.size(); ++i) {
    reach_[i] = std::max(reach_[i], other.reach_[i]);
    fixed_reach_[i] = std::max(fixed_reach_[i], other.fixed_reach_[i]);
  }
  receivers_ += other.receivers_;
}

double FarFieldBound::distance_over_D(const Vec3& u) const {
  return interpolate_over_D(d_far_over_D, inv_far_over_D, spot_of(u));
}

double FarFieldBound::fixed_distance_over_D(const Vec3& u) const {
  return interpolate_over_D(d_fixed_over_D, inv_fixed_over_D, spot_of(u));
}

FarFieldBound::Weights FarFieldBound::weights(const Vec3& u, double distance_m) const {
  return weights_at(u, nullptr, distance_m);
}

FarFieldBound::Weights FarFieldBound::weights(const photometry::PhotometricAngles& angles,
                                              double distance_m) const {
  return weights_at(Vec3(0.0), &angles, distance_m);
}

FarFieldBound::Weights FarFieldBound::weights_at(const Vec3& u,
                                                 const photometry::PhotometricAngles* angles,
                                                 double distance_m) const {
  Weights w;
  // Most pairs of a large room: beyond every direction's band (interpolate_over_D never exceeds
  // the largest sample, so this is the answer the lookup below would give).
  if (distance_m >= far_everywhere_over_D * largest_dimension_m) {
    w.far = 1.0;
    w.far_start_m = far_everywhere_over_D / kBlendWidth * largest_dimension_m;
    return w;
  }
  const GridSpot s = angles ? spot_of(*angles) : spot_of(u);
  w.far_start_m = interpolate_over_D(d_far_over_D, inv_far_over_D, s) * largest_dimension_m;
  w.far = ramp(distance_m, w.far_start_m);
  if (w.far < 1.0) {
    w.fixed_start_m = interpolate_over_D(d_fixed_over_D, inv_fixed_over_D, s) * largest_dimension_m;
    w.fixed = ramp(distance_m, w.fixed_start_m);
  }
  return w;
}

std::shared_ptr<const FarFieldBound> build_far_field_bound(const Emitter& e,
                                                           const Model& near_model,
                                                           double tolerance,
                                                           const MapDemand* demand,
                                                           bool share_mirror_images) {
  auto bound = std::make_shared<FarFieldBound>();
  bound->tolerance = tolerance;
  bound->largest_dimension_m = e.largest_dimension_m;
  constexpr int n = kGammaSamples * kCSamples;
  std::vector<float> raw(n, static_cast<float>(kLadderStart)), raw_fixed = raw;
  if (e.is_point() || !(e.largest_dimension_m > 0.0)) {
    bound->d_far_over_D = bound->d_fixed_over_D = raw;
    bound->min_over_D = bound->max_over_D = bound->median_over_D = kLadderStart;
    bound->fixed_median_over_D = bound->fixed_max_over_D = kLadderStart;
    bound->far_everywhere_over_D = kBlendWidth * kLadderStart;
    bound->inv_far_over_D = bound->inv_fixed_over_D = inverse_of(raw);
    return bound;
  }
  // What is measured: every sample out to the ladder's end, or what the demand reads.
  const Needs needs = demand ? needs_of(*demand) : Needs::everything();
  bound->restricted = demand != nullptr;
  double peak = 0.0;
  for (int i = 0; i < n; ++i)
    peak = std::max(peak,
                    e.distribution->intensity(direction_of_sample(i / kCSamples, i % kCSamples)));
  const Probe probe{e, near_model, tolerance / kBoundSafetyFactor, peak,
                    near_model.kind == ModelKind::standard || near_model.kind == ModelKind::high};
  // Each class of samples that measure the same (the pole rows; a direction and its mirror
  // image, map_symmetry.h) is measured once, by its representative, out to the farthest any of
  // them needs.
  std::vector<int> representative(n);
  if (share_mirror_images)
    representative = map_sample_representatives(e, probe.uses_table);
  else
    for (int i = 0; i < n; ++i) representative[i] = i;
  std::vector<float> class_measure(n, 0.0f), class_fixed(n, 0.0f);
  for (int i = 0; i < n; ++i) {
    if (!(needs.measure_over_D[i] > 0.0f)) continue;
    const int r = representative[i];
    class_measure[r] = std::max(class_measure[r], needs.measure_over_D[i]);
    class_fixed[r] = std::max(class_fixed[r], needs.fixed_measure_over_D[i]);
  }
  const auto fixed_last_for = [](float reach_over_D) {
    return reach_over_D > 0.0f ? last_rung_for(reach_over_D) : -1;
  };
  std::vector<int> todo;
  for (int i = 0; i < n; ++i)
    if (class_measure[i] > 0.0f) todo.push_back(i);
  std::vector<Probe::Rungs> rungs(n);
  // Directions in parallel (the samples are independent), each thread taking the next direction
  // not yet taken (util/ordered_tasks.h): their costs differ by orders of magnitude (a direction
  // whose far field holds at the first rung, one that climbs the whole ladder), so a fixed share
  // per thread left one thread working alone for much of the map.
  run_in_list_order(todo.size(), [&](std::size_t k) {
    const int i = todo[k];
    rungs[i] =
        probe.distances_over_D(direction_of_sample(i / kCSamples, i % kCSamples),
                               last_rung_for(class_measure[i]), fixed_last_for(class_fixed[i]));
  });
  bound->samples_measured = static_cast<int>(todo.size());
  std::vector<Probe::Measured> measured(n);
  std::vector<char> capped(n, 0);  // failed at its last rung short of the ladder's end
  for (int i = 0; i < n; ++i) {
    if (!(needs.measure_over_D[i] > 0.0f)) continue;
    const int last = last_rung_for(needs.measure_over_D[i]);
    measured[i] =
        for_sample(rungs[representative[i]], last, fixed_last_for(needs.fixed_measure_over_D[i]));
    raw[i] = measured[i].far_over_D;
    raw_fixed[i] = measured[i].fixed_over_D;
    capped[i] = raw[i] >= kNearEverywhere && last < kLadderRungs - 1;
  }
  for (const Probe::Measured& m : measured) {
    bound->far_error_measured =
        std::max(bound->far_error_measured, static_cast<double>(m.far_error));
    bound->fixed_error_measured =
        std::max(bound->fixed_error_measured, static_cast<double>(m.fixed_error));
  }
  merge_poles(raw);
  merge_poles(raw_fixed);
  // Dilation. The point model fails around a kink within about the opening's angular
  // half-width D / 2d of it: a neighbour s' at angle delta that needs the near field out to R'
  // charges this sample with min(R', kFootprintMargin / (2 (delta - delta0))) (the distance at
  // which its footprint no longer reaches here), delta0 = kink_slack_rad (a kink lying between
  // two samples). A coarse full 3 x 3 max instead put whole 10-degree bands in the near
  // field at every distance (2.5 x the open plan's cost) for a kink whose error is 0.5 degrees
  // wide. The fixed rule's nodes see the same footprint, so its map is dilated the same way.
  const double delta0 = kink_slack_rad(e);
  bound->d_far_over_D = dilate(raw, delta0, needs.read_over_D);
  bound->d_fixed_over_D = dilate(raw_fixed, delta0, needs.read_over_D);
  // The table's part of the error, bounded at every direction between the samples
  // (table_far_bound.h): no sample's distance below what it needs, so the measurement above
  // answers for the geometry, the bound for the table.
  const std::vector<float> table_need =
      table_far_bound_over_D(e, kTableShareOfPromise * tolerance, needs.read_over_D);
  for (std::size_t i = 0; i < table_need.size(); ++i)
    if (table_need[i] > bound->d_far_over_D[i]) {
      bound->d_far_over_D[i] = table_need[i];
      ++bound->samples_raised_by_table;
    }
  // A sample no pair reads: never asked; near field, should anything ask.
  for (int i = 0; i < n; ++i) {
    if (!(needs.read_over_D[i] > 0.0f))
      bound->d_far_over_D[i] = bound->d_fixed_over_D[i] = kNearEverywhere;
    bound->d_fixed_over_D[i] = std::min(bound->d_fixed_over_D[i], bound->d_far_over_D[i]);
  }
  // Beyond every read sample's band: a sample whose band reaches no receiver (near field out to
  // its farthest) counts with that farthest receiver instead, which no pair reading it is beyond.
  float far_everywhere = 0.0f;
  for (int i = 0; i < n; ++i)
    if (needs.read_over_D[i] > 0.0f)
      far_everywhere =
          std::max(far_everywhere, bound->d_far_over_D[i] < kNearEverywhere
                                       ? bound->d_far_over_D[i]
                                       : std::min(needs.read_over_D[i], kNearEverywhere));
  bound->far_everywhere_over_D = kBlendWidth * far_everywhere;
  bound->inv_far_over_D = inverse_of(bound->d_far_over_D);
  bound->inv_fixed_over_D = inverse_of(bound->d_fixed_over_D);
  // Summary for the plan over the samples the pairs read, undilated (what each direction
  // measured); those left to the near field out to their farthest receiver are counted apart.
  std::vector<float> far_read, fixed_read;
  int worst = -1, read = 0;
  for (int i = 0; i < n; ++i) {
    if (!(needs.read_over_D[i] > 0.0f)) continue;
    ++read;
    if (needs.fixed_read_over_D[i] > 0.0f) fixed_read.push_back(raw_fixed[i]);
    if (capped[i]) {
      ++bound->samples_capped;
      bound->capped_reach_over_D =
          std::max(bound->capped_reach_over_D, static_cast<double>(needs.read_over_D[i]));
      continue;
    }
    far_read.push_back(raw[i]);
    if (worst < 0 || raw[i] > raw[worst]) worst = i;
  }
  bound->samples_read = read;
  bound->fixed_samples_read = static_cast<int>(fixed_read.size());
  if (!fixed_read.empty()) {
    std::sort(fixed_read.begin(), fixed_read.end());
    bound->fixed_median_over_D = fixed_read[fixed_read.size() / 2];
    bound->fixed_max_over_D = fixed_read.back();
  }
  if (worst < 0) return bound;  // every read direction keeps the near field to its farthest point
  std::sort(far_read.begin(), far_read.end());
  bound->min_over_D = far_read.front();
  bound->max_over_D = far_read.back();
  bound->median_over_D = far_read[far_read.size() / 2];
  bound->near_everywhere_somewhere = far_read.back() >= kNearEverywhere;
  bound->worst_gamma_deg = (worst / kCSamples) * kGammaStepDeg;
  bound->worst_c_deg = (worst % kCSamples) * kCStepDeg;
  bound->worst_gradient_per_deg =
      relative_gradient_per_deg(e, bound->worst_c_deg, bound->worst_gamma_deg);
  return bound;
}

FarFieldBoundSummary summarize(const FarFieldBound& b) {
  using S = FarFieldBoundSummary;
  S out;
  const int far_measured = b.samples_read - b.samples_capped;
  if (b.restricted && far_measured > 0)
    out.scope = b.samples_capped > 0 ? S::Scope::demand_capped : S::Scope::demand;
  if (b.restricted && b.samples_read > 0 && b.samples_read == b.samples_capped)
    out.outcome = S::Outcome::near_at_every_point;
  else if (b.restricted && b.samples_read == 0)
    out.outcome = S::Outcome::no_point_in_reach;
  else if (b.near_everywhere_somewhere)
    out.outcome = S::Outcome::near_everywhere_somewhere;
  else
    out.outcome = S::Outcome::near_out_to;
  out.cause = b.max_over_D <= 8.0               ? S::Cause::smooth_distribution
              : b.worst_gradient_per_deg > 0.05 ? S::Cause::sharp_beam
                                                : S::Cause::kinks;
  if (b.restricted && b.fixed_samples_read == 0)
    out.fixed_rule = S::FixedRule::serves_none;
  else if (b.fixed_max_over_D >= kNearEverywhere)
    out.fixed_rule = S::FixedRule::not_every_direction;
  else
    out.fixed_rule = S::FixedRule::within;
  out.samples_read = b.samples_read;
  out.samples_capped = b.samples_capped;
  out.capped_reach_over_D = b.capped_reach_over_D;
  out.tolerance = b.tolerance;
  out.largest_dimension_m = b.largest_dimension_m;
  out.min_over_D = b.min_over_D;
  out.max_over_D = b.max_over_D;
  out.median_over_D = b.median_over_D;
  out.worst_c_deg = b.worst_c_deg;
  out.worst_gamma_deg = b.worst_gamma_deg;
  out.worst_gradient_per_deg = b.worst_gradient_per_deg;
  out.far_error_measured = b.far_error_measured;
  out.fixed_median_over_D = b.fixed_median_over_D;
  out.fixed_max_over_D = b.fixed_max_over_D;
  out.fixed_error_measured = b.fixed_error_measured;
  return out;
}

}  // namespace luxgrid::nearfield
