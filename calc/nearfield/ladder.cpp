// The accuracy ladder above the paper's cubature: fixed subdivision of every fan triangle, and
// an adaptive rung (docs/nearfield.md, "The ladder").
#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "calc/nearfield/table_rung_scratch.h"
#include "calc/nearfield/triangle_rule.h"

namespace luxgrid::nearfield {
namespace {

// Budgets of the adaptive rung per receiver point (intensity lookups, splits): a distribution with
// a discontinuity (a cut-off beam) never passes a local test along the cut and would otherwise
// refine it forever.
constexpr int kMaxAdaptiveSamples = 20000;
constexpr int kMaxAdaptiveSplits = 5000;

// Sample index of grid point (i, j), i along apex->b, j along apex->c, i + j <= n: row j holds
// n + 1 - j points.
inline int grid_index(int i, int j, int n) { return j * (n + 1) - j * (j - 1) / 2 + i; }

}  // namespace

double subdivided_illuminance(const Emitter& e, const Vec3& point, const Vec3& normal, int n,
                              TriangleRule rule, const geometry::Visibility* occluder) {
  if (e.is_point())
    return !occluder || occluder->visible(e.centroid, point)
               ? far_field_illuminance(e, point, normal)
               : 0.0;
  n = std::max(1, n);
  const ReceiverFan fan = build_fan(e, point, normal, horizon_shift_m(e));
  if (fan.triangles == 0) return 0.0;
  const SampleContext sample(e, fan, occluder, point);
  thread_local std::vector<FanSample> grid;
  grid.resize(static_cast<std::size_t>((n + 1) * (n + 2) / 2));
  const double inv_n = 1.0 / n;
  double sum = 0.0;
  for (int t = 0; t < fan.triangles; ++t) {
    const Vec3 a = fan.apex, ab = (fan.rim[t] - a) * inv_n, ac = (fan.rim[t + 1] - a) * inv_n;
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i + j <= n; ++i)
        grid[grid_index(i, j, n)] = sample(a + double(i) * ab + double(j) * ac);
    for (int j = 0; j < n; ++j)
      for (int i = 0; i + j < n; ++i) {
        const FanSample& p00 = grid[grid_index(i, j, n)];
        const FanSample& p10 = grid[grid_index(i + 1, j, n)];
        const FanSample& p01 = grid[grid_index(i, j + 1, n)];
        sum += triangle_estimate(p00, p10, p01, sample, rule);
        if (i + j + 2 <= n)
          sum += triangle_estimate(p10, grid[grid_index(i + 1, j + 1, n)], p01, sample, rule);
      }
  }
  return sanitize_illuminance(sum);
}

namespace {

// With an occluder, a cell whose nodes disagree on visibility has a shadow edge inside it; its
// |coarse - fine| can be small by accident (the edge between two nodes), so its indicator is at
// least this fraction of its value: the fraction of the cell that a linear interpolation of the
// visibility can misclassify is at most about half. The edge is then split until the cells on it
// carry less than the tolerance, and the value converges to the visible part.
constexpr double kMixedVisibilityErrorFraction = 0.1;

// With an occluder, the stopping test also accepts an error below this fraction of the
// unoccluded value (the coarse fan estimate without visibility): deep in a penumbra, where a
// sliver of the emitter is seen, a purely relative test chases a thin strip to the lookup budget
// (20000 lookups and as many visibility queries per point) for light that is a thousandth of
// what the unshadowed point gets. 2e-4 of it is below any reading a designer uses.
constexpr double kPenumbraAbsoluteFraction = 2e-4;

// One triangle of the adaptive rung with its corner samples, its edge midpoints (the children's
// corners, kept so a split does not look them up again), its own estimate, the sum of its four
// children's estimates, and their difference (the error indicator).
struct Cell {
  FanSample a, b, c;
  FanSample ab, bc, ca;
  double fine = 0.0;
  double error = 0.0;
};

struct ByError {
  bool operator()(const Cell& x, const Cell& y) const { return x.error < y.error; }
};

class GlobalRefiner {
 public:
  GlobalRefiner(const SampleContext& sample, TriangleRule rule) : sample_(sample), rule_(rule) {}

  FanSample at(const Vec3& r) {
    ++samples_;
    return sample_(r);
  }
  Cell make(const FanSample& a, const FanSample& b, const FanSample& c, double coarse) {
    Cell cell{a, b, c, at((a.r + b.r) * 0.5), at((b.r + c.r) * 0.5), at((c.r + a.r) * 0.5)};
    const FanSample &ab = cell.ab, &bc = cell.bc, &ca = cell.ca;
    cell.fine =
        estimate(a, ab, ca) + estimate(ab, b, bc) + estimate(ca, bc, c) + estimate(ab, bc, ca);
    cell.error = std::abs(cell.fine - coarse);
    if (sample_.occluder) {
      const double v = a.vis + b.vis + c.vis + ab.vis + bc.vis + ca.vis;
      if (v > 0.0 && v < 6.0)
        cell.error = std::max(cell.error, kMixedVisibilityErrorFraction * std::abs(cell.fine));
    }
    return cell;
  }
  double estimate(const FanSample& a, const FanSample& b, const FanSample& c) const {
    return triangle_estimate(a, b, c, sample_, rule_);
  }
  int samples() const { return samples_; }

 private:
  const SampleContext& sample_;
  TriangleRule rule_;
  int samples_ = 0;
};

// Globally adaptive: always split the cell with the largest indicator, until the summed
// indicators are below rel_tol times the estimate or the lookup budget is spent.
double adaptive_fan(const Emitter& e, const Vec3& point, const Vec3& normal, double rel_tol,
                    TriangleRule rule, double* error_lx, int* samples,
                    const geometry::Visibility* occluder, int max_splits = kMaxAdaptiveSplits) {
  if (error_lx) *error_lx = 0.0;
  if (samples) *samples = 0;
  if (e.is_point())
    return !occluder || occluder->visible(e.centroid, point)
               ? far_field_illuminance(e, point, normal)
               : 0.0;
  const ReceiverFan fan = build_fan(e, point, normal, horizon_shift_m(e));
  if (fan.triangles == 0) return 0.0;
  const SampleContext sample(e, fan, occluder, point);
  GlobalRefiner refiner(sample, rule);
  thread_local std::vector<Cell> heap;
  heap.clear();
  const FanSample apex = refiner.at(fan.apex);
  FanSample prev = refiner.at(fan.rim[0]);
  double value = 0.0, error = 0.0;
  for (int i = 0; i < fan.triangles; ++i) {
    const FanSample next = refiner.at(fan.rim[i + 1]);
    heap.push_back(refiner.make(apex, prev, next, refiner.estimate(apex, prev, next)));
    value += heap.back().fine;
    error += heap.back().error;
    prev = next;
  }
  std::make_heap(heap.begin(), heap.end(), ByError{});
  double floor_lx = 0.0;
  if (occluder) {
    // Unoccluded coarse estimate on the fan's own vertices (1 + rim lookups, no visibility).
    const SampleContext open(e, fan);
    const FanSample o_apex = open(fan.apex);
    FanSample o_prev = open(fan.rim[0]);
    double open_lx = 0.0;
    for (int i = 0; i < fan.triangles; ++i) {
      const FanSample o_next = open(fan.rim[i + 1]);
      open_lx += triangle_estimate(o_apex, o_prev, o_next, open, rule);
      o_prev = o_next;
    }
    floor_lx = kPenumbraAbsoluteFraction * std::abs(open_lx);
  }
  int splits = 0;
  while (error > std::max(rel_tol * value, floor_lx) && refiner.samples() < kMaxAdaptiveSamples &&
         splits < max_splits) {
    std::pop_heap(heap.begin(), heap.end(), ByError{});
    const Cell t = heap.back();
    heap.pop_back();
    ++splits;
    const FanSample &ab = t.ab, &bc = t.bc, &ca = t.ca;
    const FanSample* kids[4][3] = {
        {&t.a, &ab, &ca}, {&ab, &t.b, &bc}, {&ca, &bc, &t.c}, {&ab, &bc, &ca}};
    value -= t.fine;
    error -= t.error;
    for (auto& k : kids) {
      const Cell child = refiner.make(*k[0], *k[1], *k[2], refiner.estimate(*k[0], *k[1], *k[2]));
      value += child.fine;
      error += child.error;
      heap.push_back(child);
      std::push_heap(heap.begin(), heap.end(), ByError{});
    }
  }
  // Re-sum: the running totals lose digits to the subtractions.
  value = 0.0;
  error = 0.0;
  for (const Cell& c : heap) value += c.fine, error += c.error;
  if (error_lx) *error_lx = error;
  if (samples) *samples = refiner.samples();
  return sanitize_illuminance(value);
}

}  // namespace

double adaptive_illuminance(const Emitter& e, const Vec3& point, const Vec3& normal, double rel_tol,
                            double* error_lx, const geometry::Visibility* occluder) {
  return adaptive_fan(e, point, normal, rel_tol, TriangleRule::two_kernel, error_lx, nullptr,
                      occluder);
}

double adaptive_illuminance(const Emitter& e, const Vec3& point, const Vec3& normal, double rel_tol,
                            TriangleRule rule, double* error_lx, int* samples,
                            const geometry::Visibility* occluder) {
  return adaptive_fan(e, point, normal, rel_tol, rule, error_lx, samples, occluder);
}

namespace {

// The near tier of `standard` (docs/nearfield.md, "The standard rung"): the area form
//   E = (1/A) integral of I(-w) cos_r / d^2 dA
// over each fan triangle (apex a = CP), in Duffy coordinates: t along the rim edge b -> c and,
// along the ray from the apex through q(t) = b + t (c - b), the sinh coordinate tau of the
// near-singular-integral literature (Johnston and Elliott 2005): with v the ray's unit
// direction, kappa = a . v and beta = |a - kappa v| (the receiver's distance from the ray's
// line, >= the plane distance, so > 0 by the horizon shift), the point at in-plane distance rho
// from the apex is at d = beta cosh(tau), rho + kappa = beta sinh(tau), and
//   dA / d^2 = (|ab x ac| / |q - a|^2) (rho / d) dt dtau,
// a bounded, smooth density even when the receiver is 1e-6 of the size from the emitter (the
// 1/d^2 peak becomes a plain interval of length ~ ln(size / distance) in tau). Each cell (a
// rectangle of (t, sigma), sigma in [0, 1] spanning the ray's tau range) gets a 3 x 3 and a 2 x 2
// Gauss-Legendre tensor rule. The same nodes also integrate the Lambert kernel
// cos_e cos_r / d^2, whose exact value per fan triangle is the projected solid angle P: the
// triangle's result is (integral of I .. / A) x P / (integral of the kernel), which is exact for
// any uniform (Lambertian) emitter whatever the nodes, and the error indicator of a cell is the
// difference of the two rules after the same correction (zero for a Lambertian emitter).
// Globally adaptive: the cell with the largest indicator is split in four first.

struct GaussRule {
  int n;
  double x[3];  // nodes on [0, 1]
  double w[3];  // weights, sum 1
};
constexpr double kG2 = 0.21132486540518711775;  // (1 - 1/sqrt(3)) / 2
constexpr double kG3 = 0.11270166537925831148;  // (1 - sqrt(3/5)) / 2
constexpr GaussRule kGauss2{2, {kG2, 1.0 - kG2, 0.0}, {0.5, 0.5, 0.0}};
constexpr GaussRule kGauss3{3, {kG3, 0.5, 1.0 - kG3}, {5.0 / 18.0, 8.0 / 18.0, 5.0 / 18.0}};

// Budget of the near tier per receiver point (intensity lookups). A tabulated profile is
// bilinear between its angles, so the indicator keeps seeing its kinks; measured on the
// protocol, the worst point (the arcos3 spot 0.1 below the emitter) is within 1.2e-3 of its
// value after 2000 lookups, where the indicator still asks for more; with 1000 it is 7e-3, with
// 500 9 %.
constexpr long kNearMaxLookups = 2000;

struct SinhTriangle {
  Vec3 a, b, c;        // relative to the shifted receiver; a = CP
  double area2 = 0.0;  // |ab x ac|
};

struct SinhCell {
  int tri = 0;
  double t0 = 0.0, t1 = 1.0, s0 = 0.0, s1 = 1.0;
  double qi = 0.0;  // 3 x 3 rule: integral of I cos_r / d^2 dA (cd; / A gives lx)
  double qg = 0.0;  // 3 x 3 rule: integral of cos_e cos_r / d^2 dA (sr)
  double error = 0.0;
};

struct BySinhError {
  bool operator()(const SinhCell& x, const SinhCell& y) const { return x.error < y.error; }
};

class SinhRule {
 public:
  SinhRule(const Emitter& e, const Vec3& normal, double plane_distance)
      : e_(e), normal_(normal), plane_distance_(plane_distance) {}

  void integrate(const SinhTriangle& T, const GaussRule& g, double t0, double t1, double s0,
                 double s1, double& qi, double& qg) {
    qi = qg = 0.0;
    for (int i = 0; i < g.n; ++i) {
      const double t = t0 + (t1 - t0) * g.x[i];
      Vec3 v = T.b + t * (T.c - T.b) - T.a;
      const double m = glm::dot(v, v);
      if (!(m > 0.0)) continue;
      const double rho_end = std::sqrt(m);
      v /= rho_end;
      const double kappa = glm::dot(T.a, v);
      const double beta = glm::length(T.a - kappa * v);
      if (!(beta > 0.0)) continue;
      const double tau_a = std::asinh(kappa / beta), tau_b = std::asinh((rho_end + kappa) / beta);
      const double u0 = tau_a + (tau_b - tau_a) * s0, u1 = tau_a + (tau_b - tau_a) * s1;
      double si = 0.0, sg = 0.0;
      for (int j = 0; j < g.n; ++j) {
        const double tau = u0 + (u1 - u0) * g.x[j];
        const double rho = std::max(0.0, beta * std::sinh(tau) - kappa);
        const Vec3 p = T.a + rho * v;
        const double d = glm::length(p);
        if (!(d > 0.0)) continue;
        const Vec3 w = p / d;
        const double cos_r = glm::dot(w, normal_);
        if (!(cos_r > 0.0)) continue;
        const double intensity = e_.intensity_towards(-w);
        ++lookups_;
        const double f = g.w[j] * cos_r * rho / d;
        si += intensity * f;
        sg += plane_distance_ / d * f;
      }
      const double wt = g.w[i] * (u1 - u0) * T.area2 / m;
      qi += wt * si;
      qg += wt * sg;
    }
    qi *= t1 - t0;
    qg *= t1 - t0;
  }

  SinhCell make(const SinhTriangle& T, int tri, double t0, double t1, double s0, double s1) {
    SinhCell c{tri, t0, t1, s0, s1};
    double qi2 = 0.0, qg2 = 0.0;
    integrate(T, kGauss3, t0, t1, s0, s1, c.qi, c.qg);
    integrate(T, kGauss2, t0, t1, s0, s1, qi2, qg2);
    const double radiance_area = c.qg > 0.0 ? c.qi / c.qg : 0.0;  // L A of the cell
    c.error = std::abs((c.qi - qi2) - radiance_area * (c.qg - qg2)) / e_.area_m2;
    return c;
  }
  long lookups() const { return lookups_; }

 private:
  const Emitter& e_;
  Vec3 normal_;
  double plane_distance_;
  long lookups_ = 0;
};

double sinh_adaptive(const Emitter& e, const Vec3& point, const Vec3& normal, double rel_tol,
                     long max_lookups, bool* converged = nullptr) {
  if (converged) *converged = true;
  if (e.is_point()) return far_field_illuminance(e, point, normal);
  const ReceiverFan fan = build_fan(e, point, normal, horizon_shift_m(e));
  if (fan.triangles == 0) return 0.0;
  SinhRule rule(e, normal, fan.plane_distance);
  std::array<SinhTriangle, kMaxPolygonVertices> tris;
  std::array<double, kMaxPolygonVertices> tri_qi{}, tri_qg{};
  thread_local std::vector<SinhCell> heap;
  heap.clear();
  const double inv_area = 1.0 / e.area_m2;
  double value = 0.0, error = 0.0;
  for (int i = 0; i < fan.triangles; ++i) {
    SinhTriangle& T = tris[i];
    T = {fan.apex, fan.rim[i], fan.rim[i + 1]};
    T.area2 = glm::length(glm::cross(T.b - T.a, T.c - T.a));
    if (!(T.area2 > 0.0)) continue;
    heap.push_back(rule.make(T, i, 0.0, 1.0, 0.0, 1.0));
    value += heap.back().qi * inv_area;
    error += heap.back().error;
  }
  std::make_heap(heap.begin(), heap.end(), BySinhError{});
  while (!heap.empty() && error > rel_tol * value && rule.lookups() < max_lookups) {
    std::pop_heap(heap.begin(), heap.end(), BySinhError{});
    const SinhCell c = heap.back();
    heap.pop_back();
    value -= c.qi * inv_area;
    error -= c.error;
    const double tm = 0.5 * (c.t0 + c.t1), sm = 0.5 * (c.s0 + c.s1);
    const double ts[2][2] = {{c.t0, tm}, {tm, c.t1}}, ss[2][2] = {{c.s0, sm}, {sm, c.s1}};
    for (const auto& tt : ts)
      for (const auto& sr : ss) {
        heap.push_back(rule.make(tris[c.tri], c.tri, tt[0], tt[1], sr[0], sr[1]));
        value += heap.back().qi * inv_area;
        error += heap.back().error;
        std::push_heap(heap.begin(), heap.end(), BySinhError{});
      }
  }
  if (converged) *converged = error <= rel_tol * value;
  for (const SinhCell& c : heap) tri_qi[c.tri] += c.qi, tri_qg[c.tri] += c.qg;
  double sum = 0.0;
  for (int i = 0; i < fan.triangles; ++i) {
    if (!(tri_qg[i] > 0.0)) continue;
    const SinhTriangle& T = tris[i];
    const double projected = geometry::triangle_projected_solid_angle(
        glm::normalize(T.a), glm::normalize(T.b), glm::normalize(T.c), normal);
    sum += tri_qi[i] * inv_area * projected / tri_qg[i];
  }
  return sanitize_illuminance(sum);
}

}  // namespace

// quality "standard" (docs/nearfield.md, "The standard rung"), without an occluder: the table
// rung for a tabulated distribution (above); for analytic ones (Lambertian, isotropic, the test
// profiles):
//  - near (receiver closer than kStandardAreaFormStart x largest dimension to the centroid): the
//    Duffy-sinh adaptive cubature above, until the summed indicators are below kStandardRelTol
//    of E or kNearMaxLookups lookups are spent. It replaces the two-kernel adaptive rung here,
//    which needed 8000 to 20000 lookups (the budget) at a tabulated spot 0.1 below the emitter
//    for the same accuracy (the two-kernel rung cost 620x the far field, 46 us per point).
//  - far: first the same cubature without splits (one 3 x 3 + 2 x 2 cell per fan triangle,
//    13 lookups each); when its indicator is already below kStandardRelTol of E (every
//    Lambertian point, where it is exact, and most smooth profiles) that is the value, else the
//    area-form reference at kStandardAreaFormRelTol, whose 7-point rule samples each triangle
//    more densely: on the tabulated spots the sinh indicator, small on the emitter's smooth
//    parts, can miss a kink between its nodes at a dim point (measured 3.8 % at 1 % of the
//    peak, zumtobel_intro, h = 2.5), while the reference's stays within 1 % of every point above
//    1e-3 of the peak (0.84 % worst, 10 data sets of the protocol).
// With an occluder the two-kernel adaptive rung is kept everywhere: its mixed-cell rule refines
// shadow edges (the Duffy-sinh cells know nothing of visibility).
// Tolerance: the indicator overstates the error of the finer sum; on the paper's protocol 3e-3
// gives at most 0.38 % error (two-kernel rung), while 1e-2 gives 4.8 %.
inline constexpr double kStandardRelTol = 3e-3;

// Beyond this distance from the centroid (x largest dimension) `standard` uses the far tier:
// there the integrand is smooth over the emitter, the degree-5 rule converges in a few levels and
// its error estimate is sharp. At 0.5 D the switch would give 1.7 % (two-kernel era measurement).
inline constexpr double kStandardAreaFormStart = 0.75;  // x largest dimension
// kStandardAreaFormRelTol (models.h): the far tier's area-form tolerance.

double standard_illuminance(const Emitter& e, const Vec3& point, const Vec3& normal,
                            const geometry::Visibility* occluder, TableRungScratch* scratch) {
  // A measured table (every photometric file of type C): the table rung, whose cells are the
  // table's own, so its kinks never sit inside a cell (table_cubature.cpp). On the paper's
  // protocol it is within 1.2e-4 of the cell maximum of the reference at every point and costs
  // less than the tiers below, whose error indicators misjudge those kinks.
  if (!scratch) {
    TableRungScratch own;
    return standard_illuminance(e, point, normal, occluder, &own);
  }
  double table_lux = 0.0;
  if (!occluder && table_aligned_illuminance(e, point, normal, table_lux, *scratch))
    return table_lux;
  if (!occluder && !e.is_point() &&
      glm::length(point - e.centroid) >= kStandardAreaFormStart * e.largest_dimension_m) {
    // First the Duffy-sinh cubature without splits: exact for a Lambertian emitter (the
    // indicator is then at rounding level), and enough for most smooth profiles.
    bool converged = false;
    const double first = sinh_adaptive(e, point, normal, kStandardRelTol, 0, &converged);
    if (converged) return first;
    return reference_illuminance(e, point, normal, kStandardAreaFormRelTol).illuminance_lx;
  }
  if (occluder)
    return adaptive_fan(e, point, normal, kStandardRelTol, TriangleRule::two_kernel, nullptr,
                        nullptr, occluder);
  // Near tier; when it spends its budget without meeting the tolerance (a narrow beam landing
  // inside a fan triangle: the ERCO spot 0.1 m under the opening was 2.4 % high at 2000
  // lookups, tests/nearfield/reference_peak_test.cpp), the two-kernel adaptive rung finishes
  // the point: dearer, but it converges there (0.25 %).
  bool converged = false;
  const double near = sinh_adaptive(e, point, normal, kStandardRelTol, kNearMaxLookups, &converged);
  if (converged) return near;
  return adaptive_fan(e, point, normal, kStandardRelTol, TriangleRule::two_kernel, nullptr, nullptr,
                      nullptr);
}

}  // namespace luxgrid::nearfield
