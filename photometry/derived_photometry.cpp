#include "photometry/derived_photometry.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/matrix.hpp>

#include "util/robust_math.h"

namespace luxgrid::photometry {

namespace {
// 4-point Gauss-Legendre nodes/weights on [-1, 1]: exact for cubics in C (bicubic cells) and,
// on pieces of <= 2 deg, sin(gamma) times a cubic to ~1e-13 relative.
constexpr double kGlX[4] = {-0.8611363115940526, -0.3399810435848563, 0.3399810435848563,
                            0.8611363115940526};
constexpr double kGlW[4] = {0.3478548451374538, 0.6521451548625461, 0.6521451548625461,
                            0.3478548451374538};
constexpr double kMaxGammaPieceRad = 2.0 * kDegToRad;
constexpr double kMaxCPieceRad = 15.0 * kDegToRad;

// Splits [a, b] at `cuts` and into pieces no wider than max_piece.
void pieces(const std::vector<double>& nodes, const std::vector<double>& cuts, double max_piece,
            std::vector<std::pair<double, double>>& out) {
  std::vector<double> pts = nodes;
  for (double c : cuts)
    if (c > nodes.front() && c < nodes.back()) pts.push_back(c);
  std::sort(pts.begin(), pts.end());
  pts.erase(std::unique(pts.begin(), pts.end(), [](double a, double b) { return b - a < 1e-12; }),
            pts.end());
  out.clear();
  for (std::size_t k = 0; k + 1 < pts.size(); ++k) {
    const double a = pts[k], b = pts[k + 1];
    const int n = pieces_of_at_most((b - a) / max_piece);
    for (int q = 0; q < n; ++q) out.emplace_back(a + (b - a) * q / n, a + (b - a) * (q + 1) / n);
  }
}
}  // namespace

FluxResult integrate_flux(const TabularDistribution& t) {
  const SphericalGrid& g = t.grid();
  const bool framed = t.has_frame();
  std::vector<std::pair<double, double>> gp, cp;
  pieces(g.gamma_rad, framed ? std::vector<double>{} : std::vector<double>{kPi / 2},
         kMaxGammaPieceRad, gp);
  if (g.c_rad.size() == 1) {
    cp = {{0.0, kTwoPi}};
  } else {
    std::vector<double> cn = g.c_rad;
    cn.push_back(g.c_rad.front() + kTwoPi);
    std::vector<double> cuts;
    if (framed)
      for (double c : {kPi / 2, 3 * kPi / 2, kPi / 2 + kTwoPi, 3 * kPi / 2 + kTwoPi})
        cuts.push_back(c);
    pieces(cn, cuts, kMaxCPieceRad, cp);
  }
  const glm::dmat3 to_lum = glm::transpose(t.table_from_luminaire());
  FluxResult r;
  for (const auto& [c0, c1] : cp) {
    const double hc = 0.5 * (c1 - c0), mc = 0.5 * (c1 + c0);
    const int nq_c = g.c_rad.size() == 1 ? 1 : 4;
    for (int qc = 0; qc < nq_c; ++qc) {
      const double c = nq_c == 1 ? 0.0 : mc + hc * kGlX[qc];
      const double wc = nq_c == 1 ? kTwoPi : hc * kGlW[qc];
      for (const auto& [g0, g1] : gp) {
        const double hg = 0.5 * (g1 - g0), mg = 0.5 * (g1 + g0);
        double sum = 0.0;
        for (int qg = 0; qg < 4; ++qg) {
          const double gamma = mg + hg * kGlX[qg];
          sum += kGlW[qg] * std::sin(gamma) * t.intensity_at(c, gamma);
        }
        const double piece = wc * hg * sum;
        r.total_lm += piece;
        bool down;
        if (!framed) {
          down = mg < kPi / 2;
        } else {
          down = (to_lum * direction_of(c, mg)).z < 0.0;
        }
        if (down) r.downward_lm += piece;
      }
    }
  }
  return r;
}

double plane_intensity(const IntensityDistribution& d, double c_deg, double s) {
  const double c = (s >= 0 ? c_deg : c_deg + 180.0) * kDegToRad;
  return d.intensity(direction_of(c, std::abs(s) * kDegToRad));
}

BeamAngles beam_angles(const IntensityDistribution& d, double c_deg) {
  constexpr double kStep = 0.05;
  const int n = static_cast<int>(360.0 / kStep);
  std::vector<double> v(static_cast<std::size_t>(n + 1));
  std::size_t peak = 0;
  for (int k = 0; k <= n; ++k) {
    v[static_cast<std::size_t>(k)] = plane_intensity(d, c_deg, -180.0 + k * kStep);
    if (v[static_cast<std::size_t>(k)] > v[peak]) peak = static_cast<std::size_t>(k);
  }
  BeamAngles out;
  const double imax = v[peak];
  if (!(imax > 0)) return out;
  auto width = [&](double fraction) {
    const double level = fraction * imax;
    double right = 180.0, left = -180.0;
    for (std::size_t k = peak; k + 1 < v.size(); ++k)
      if (v[k + 1] < level) {
        right = -180.0 + (static_cast<double>(k) + (v[k] - level) / (v[k] - v[k + 1])) * kStep;
        break;
      }
    for (std::size_t k = peak; k > 0; --k)
      if (v[k - 1] < level) {
        left = -180.0 + (static_cast<double>(k) - (v[k] - level) / (v[k] - v[k - 1])) * kStep;
        break;
      }
    return std::min(360.0, right - left);
  };
  out.beam_deg = width(0.5);
  out.field_deg = width(0.1);
  return out;
}

FluxRatios flux_ratios(const Photometry& p, const FluxResult& flux) {
  FluxRatios r;
  r.dff = flux.total_lm > 0 ? flux.downward_lm / flux.total_lm : 0.0;
  if (p.lamp_flux_lm && *p.lamp_flux_lm > 0) r.lor = flux.total_lm / *p.lamp_flux_lm;
  return r;
}

DerivedPhotometry derive(const Photometry& p) {
  DerivedPhotometry r;
  if (p.table) {
    const FluxResult f = integrate_flux(*p.table);
    r.flux_lm = f.total_lm;
    r.downward_flux_lm = f.downward_lm;
    const SphericalGrid& g = p.table->grid();
    std::size_t best = 0;
    for (std::size_t k = 1; k < g.cd.size(); ++k)
      if (g.cd[k] > g.cd[best]) best = k;
    r.max_cd = g.cd[best];
    const std::size_t ng = g.gamma_rad.size();
    r.max_direction = p.table->luminaire_direction(g.c_rad[best / ng], g.gamma_rad[best % ng]);
  } else if (p.distribution) {
    // A non-tabular distribution (builtin): integrate on a fine (C, gamma) grid instead.
    constexpr int kNc = 360, kNg = 360;
    const double dc = kTwoPi / kNc, dg = kPi / kNg;
    for (int i = 0; i < kNc; ++i)
      for (int j = 0; j < kNg; ++j) {
        const double c = (i + 0.5) * dc, gm = (j + 0.5) * dg;
        const double v = p.distribution->intensity(direction_of(c, gm));
        const double dphi = v * (std::cos(j * dg) - std::cos((j + 1) * dg)) * dc;
        r.flux_lm += dphi;
        if (gm < kPi / 2) r.downward_flux_lm += dphi;
        if (v > r.max_cd) {
          r.max_cd = v;
          r.max_direction = direction_of(c, gm);
        }
      }
  }
  if (!p.distribution) return r;
  const FluxRatios ratios = flux_ratios(p, {r.flux_lm, r.downward_flux_lm});
  r.dff = ratios.dff;
  r.lor = ratios.lor;
  const PhotometricAngles a = angles_of(r.max_direction);
  r.max_c_deg = a.c * kRadToDeg;
  r.max_gamma_deg = a.gamma * kRadToDeg;
  r.c0_c180 = beam_angles(*p.distribution, 0.0);
  r.c90_c270 = beam_angles(*p.distribution, 90.0);
  return r;
}

}  // namespace luxgrid::photometry
