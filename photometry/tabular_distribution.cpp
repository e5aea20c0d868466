#include "photometry/tabular_distribution.h"

#include <algorithm>
#include <cmath>

#include <glm/matrix.hpp>

#include "util/error.h"
#include "util/simd.h"
#include "util/table_angle.h"

namespace luxgrid::photometry {

namespace {
// Angles closer than this (radians, ~6e-8 deg) are the same angle: files print angles with at
// most 4 decimals, so this only absorbs degree-to-radian rounding.
constexpr double kAngleEps = 1e-9;

bool is_uniform(const std::vector<double>& v, double period_end, double& inv_step) {
  if (v.size() < 2) return false;
  const double step = (period_end > 0 ? period_end - v.front() : v.back() - v.front()) /
                      static_cast<double>(period_end > 0 ? v.size() : v.size() - 1);
  if (std::abs(v.front()) > kAngleEps) return false;
  for (std::size_t k = 0; k < v.size(); ++k)
    if (std::abs(v[k] - v.front() - step * static_cast<double>(k)) > 1e-9) return false;
  inv_step = 1.0 / step;
  return true;
}

// Weights of the four samples around a segment [t1, t2] for a cubic Hermite curve whose tangents
// are the finite differences of the neighbours (Catmull-Rom generalised to uneven spacing, so it
// still interpolates: w1 = 1, others 0 at s = 0). A missing neighbour (grid end) makes that
// tangent one-sided.
void hermite_weights(bool has0, double t0, double t1, double t2, bool has3, double t3, double s,
                     double w[4]) {
  const double s2 = s * s, s3 = s2 * s;
  const double h00 = 2 * s3 - 3 * s2 + 1, h10 = s3 - 2 * s2 + s, h01 = -2 * s3 + 3 * s2,
               h11 = s3 - s2;
  const double h = t2 - t1;
  w[0] = w[3] = 0.0;
  w[1] = h00;
  w[2] = h01;
  if (has0) {
    const double k = h10 * h / (t2 - t0);
    w[0] -= k;
    w[2] += k;
  } else {
    w[1] -= h10;
    w[2] += h10;
  }
  if (has3) {
    const double k = h11 * h / (t3 - t1);
    w[1] -= k;
    w[3] += k;
  } else {
    w[1] -= h11;
    w[2] += h11;
  }
}
}  // namespace

const char* to_string(Interpolation i) {
  return i == Interpolation::bilinear ? "bilinear" : "bicubic";
}

TabularDistribution::TabularDistribution(SphericalGrid grid, Interpolation mode,
                                         const glm::dmat3& table_from_luminaire)
    : grid_(std::move(grid)), mode_(mode), frame_(table_from_luminaire) {
  has_frame_ = frame_ != glm::dmat3(1.0);
  nc_ = grid_.c_rad.size();
  ng_ = grid_.gamma_rad.size();
  if (nc_ < 1 || ng_ < 2 || grid_.cd.size() != nc_ * ng_)
    throw CalculationError("TabularDistribution: grid needs >= 1 C plane and >= 2 gamma values");
  for (std::size_t k = 0; k + 1 < nc_; ++k)
    if (!(grid_.c_rad[k] < grid_.c_rad[k + 1]))
      throw CalculationError("TabularDistribution: C angles must increase");
  for (std::size_t k = 0; k + 1 < ng_; ++k)
    if (!(grid_.gamma_rad[k] < grid_.gamma_rad[k + 1]))
      throw CalculationError("TabularDistribution: gamma angles must increase");
  if (grid_.c_rad.front() < -kAngleEps || grid_.c_rad.back() >= kTwoPi - kAngleEps)
    throw CalculationError("TabularDistribution: C angles must lie in [0, 2 pi)");
  if (grid_.gamma_rad.front() < -kAngleEps || grid_.gamma_rad.back() > kPi + kAngleEps)
    throw CalculationError("TabularDistribution: gamma angles must lie in [0, pi]");
  for (double& v : grid_.cd)
    if (!std::isfinite(v) || v < 0.0)
      throw CalculationError("TabularDistribution: intensities must be finite and >= 0");

  // The poles are single directions: one value each, the mean of what the planes say there.
  auto average_row = [this](std::size_t j) {
    double sum = 0.0;
    for (std::size_t i = 0; i < nc_; ++i) sum += grid_.at(i, j);
    for (std::size_t i = 0; i < nc_; ++i) grid_.cd[i * ng_ + j] = sum / static_cast<double>(nc_);
  };
  if (grid_.average_poles && grid_.gamma_rad.front() <= kAngleEps) average_row(0);
  if (grid_.average_poles && grid_.gamma_rad.back() >= kPi - kAngleEps) average_row(ng_ - 1);

  g_front_ = grid_.gamma_rad.front();
  g_back_ = grid_.gamma_rad.back();
  c_uniform_ = nc_ > 1 && is_uniform(grid_.c_rad, kTwoPi, inv_dc_);
  g_uniform_ = is_uniform(grid_.gamma_rad, -1.0, inv_dg_);
  if (g_uniform_ && std::abs(g_front_) > kAngleEps) g_uniform_ = false;
}

double TabularDistribution::c_of(long k) const {
  const long n = static_cast<long>(nc_);
  long wraps = k >= 0 ? k / n : -((-k + n - 1) / n);
  return grid_.c_rad[static_cast<std::size_t>(k - wraps * n)] + kTwoPi * static_cast<double>(wraps);
}

bool TabularDistribution::gamma_cell(double g, std::size_t& j, double& tg) const {
  if (!(g >= g_front_ - kAngleEps && g <= g_back_ + kAngleEps)) return false;
  g = std::clamp(g, g_front_, g_back_);
  if (g_uniform_) {
    j = std::min(static_cast<std::size_t>(g * inv_dg_), ng_ - 2);
  } else {
    auto it = std::upper_bound(grid_.gamma_rad.begin(), grid_.gamma_rad.end(), g);
    j = std::min(
        static_cast<std::size_t>(std::max<std::ptrdiff_t>(it - grid_.gamma_rad.begin() - 1, 0)),
        ng_ - 2);
  }
  const double g0 = grid_.gamma_rad[j], g1 = grid_.gamma_rad[j + 1];
  tg = std::clamp((g - g0) / (g1 - g0), 0.0, 1.0);
  return true;
}

namespace {
// c in [0, 2 pi) (c_position's argument may be any real).
double wrap_c(double c) {
  if (!(c >= 0.0 && c < kTwoPi)) {
    c = std::fmod(c, kTwoPi);
    if (c < 0.0) c += kTwoPi;
    if (!(c < kTwoPi)) c = 0.0;
  }
  return c;
}
}  // namespace

TabularDistribution::CCell TabularDistribution::c_cell(double c) const {
  CCell out;
  if (nc_ == 1) return out;
  c = wrap_c(c);
  if (c_uniform_) {
    out.i = std::min(static_cast<std::size_t>(c * inv_dc_), nc_ - 1);
    out.c0 = grid_.c_rad[out.i];
    out.c1 = out.i + 1 < nc_ ? grid_.c_rad[out.i + 1] : kTwoPi;
  } else if (c < grid_.c_rad.front()) {  // wrap cell before the first plane
    out.i = nc_ - 1;
    out.c0 = grid_.c_rad.back() - kTwoPi;
    out.c1 = grid_.c_rad.front();
  } else {
    auto it = std::upper_bound(grid_.c_rad.begin(), grid_.c_rad.end(), c);
    out.i = static_cast<std::size_t>(it - grid_.c_rad.begin() - 1);
    out.c0 = grid_.c_rad[out.i];
    out.c1 = out.i + 1 < nc_ ? grid_.c_rad[out.i + 1] : grid_.c_rad.front() + kTwoPi;
  }
  return out;
}

TabularDistribution::CPosition TabularDistribution::c_position(double c) const {
  return c_position_in(c_cell(c), wrap_c(c));
}

bool TabularDistribution::locate(double c, double g, Cell& cell) const {
  if (!gamma_cell(g, cell.j, cell.tg)) return false;
  const CPosition p = c_position(c);
  cell.i = p.i;
  cell.tc = p.tc;
  return true;
}

double TabularDistribution::intensity_at(const CPosition& c, std::size_t j, double tg) const {
  const Cell cell{c.i, c.tc, j, tg};
  return mode_ == Interpolation::bilinear ? bilinear(cell) : bicubic(cell);
}

double TabularDistribution::bilinear(const Cell& k) const {
  const double* p0 = &grid_.cd[k.i * ng_ + k.j];
  const double a = p0[0] + k.tg * (p0[1] - p0[0]);
  if (nc_ == 1) return a;
  const std::size_t i1 = k.i + 1 < nc_ ? k.i + 1 : 0;
  const double* p1 = &grid_.cd[i1 * ng_ + k.j];
  const double b = p1[0] + k.tg * (p1[1] - p1[0]);
  return a + k.tc * (b - a);
}

double TabularDistribution::bicubic(const Cell& k) const {
  const auto& G = grid_.gamma_rad;
  const std::size_t j = k.j;
  const bool g_has0 = j > 0, g_has3 = j + 2 < ng_;
  double wg[4];
  hermite_weights(g_has0, g_has0 ? G[j - 1] : 0.0, G[j], G[j + 1], g_has3, g_has3 ? G[j + 2] : 0.0,
                  k.tg, wg);
  const std::size_t jlo = g_has0 ? j - 1 : j;  // first row with a (possibly zero) weight
  auto column = [&](std::size_t plane) {
    const double* p = &grid_.cd[plane * ng_];
    double s = wg[1] * p[j] + wg[2] * p[j + 1];
    if (g_has0) s += wg[0] * p[jlo];
    if (g_has3) s += wg[3] * p[j + 2];
    return s;
  };
  double v;
  if (nc_ == 1) {
    v = column(0);
  } else {
    const long i = static_cast<long>(k.i);
    double wc[4];
    hermite_weights(true, c_of(i - 1), c_of(i), c_of(i + 1), true, c_of(i + 2), k.tc, wc);
    const long n = static_cast<long>(nc_);
    v = 0.0;
    for (int q = 0; q < 4; ++q) {
      const long plane = ((i - 1 + q) % n + n) % n;
      v += wc[q] * column(static_cast<std::size_t>(plane));
    }
  }
  // Catmull-Rom overshoots next to steep edges; intensity is never negative.
  return v > 0.0 ? v : 0.0;
}

double TabularDistribution::intensity_at(double c, double g) const {
  Cell cell;
  if (!locate(c, g, cell)) return 0.0;
  return mode_ == Interpolation::bilinear ? bilinear(cell) : bicubic(cell);
}

double TabularDistribution::intensity(const Vec3& direction) const {
  const Vec3 d = has_frame_ ? frame_ * direction : direction;
  // The angles as angles_of gives them (intensity_distribution.h), C only where the table has
  // more than one plane.
  const double h = std::sqrt(d.x * d.x + d.y * d.y);
  return intensity_at(nc_ > 1 ? photometry::c_of(d.x, d.y, h) : 0.0, gamma_of(h, d.z));
}

namespace {

// The photometric angles of directions [0, n) (n a multiple of the lanes) as lanes, and whether
// the table gave each (table_angles_of); an AVX2 version where the processor has it.
LUXGRID_LANE void table_angles_run_kernel(const double* x, const double* y, const double* z,
                                          std::size_t n, double* c, double* gamma, bool* ok) {
  for (std::size_t k = 0; k < n; k += simd::kLanes) {
    simd::D4 lane_c, lane_gamma;
    const simd::L4 held = table_angles_of(simd::load<simd::D4>(x + k), simd::load<simd::D4>(y + k),
                                          simd::load<simd::D4>(z + k), lane_c, lane_gamma);
    simd::store(lane_c, c + k);
    simd::store(lane_gamma, gamma + k);
    for (int l = 0; l < simd::kLanes; ++l) ok[k + l] = held[l] != 0;
  }
}

LUXGRID_MULTIVERSION(void, table_angles_run,
                     (const double* x, const double* y, const double* z, std::size_t n, double* c,
                      double* gamma, bool* ok),
                     (x, y, z, n, c, gamma, ok), table_angles_run_kernel)

// Directions looked up per pass: the angles' buffers on the stack.
constexpr std::size_t kAnglesRun = 64;

}  // namespace

void TabularDistribution::intensities(const double* x, const double* y, const double* z,
                                      std::size_t n, double* out) const {
  if (has_frame_) {
    IntensityDistribution::intensities(x, y, z, n, out);
    return;
  }
  double c[kAnglesRun], gamma[kAnglesRun];
  bool ok[kAnglesRun];
  for (std::size_t begin = 0; begin < n; begin += kAnglesRun) {
    const std::size_t count = std::min(kAnglesRun, n - begin);
    const std::size_t lanes = count - count % simd::kLanes;
    table_angles_run(x + begin, y + begin, z + begin, lanes, c, gamma, ok);
    for (std::size_t k = 0; k < count; ++k) {
      const std::size_t i = begin + k;
      // As intensity(): C only where the table has more than one plane.
      out[i] = k < lanes && ok[k] ? intensity_at(nc_ > 1 ? c[k] : 0.0, gamma[k])
                                  : intensity(Vec3(x[i], y[i], z[i]));
    }
  }
}

Vec3 TabularDistribution::luminaire_direction(double c, double g) const {
  const Vec3 d = direction_of(c, g);
  return has_frame_ ? glm::transpose(frame_) * d : d;
}

std::shared_ptr<const TabularDistribution> TabularDistribution::with_interpolation(
    Interpolation mode) const {
  return std::make_shared<TabularDistribution>(grid_, mode, frame_);
}

std::shared_ptr<const TabularDistribution> TabularDistribution::scaled(double factor) const {
  SphericalGrid g = grid_;
  for (double& v : g.cd) v *= factor;
  return std::make_shared<TabularDistribution>(std::move(g), mode_, frame_);
}

}  // namespace luxgrid::photometry
