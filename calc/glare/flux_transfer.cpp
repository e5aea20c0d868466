#include "calc/glare/flux_transfer.h"

#include <array>
#include <cmath>

#include "util/robust_math.h"

namespace luxgrid::calc::glare {

double parallel_rectangles_form_factor(double a, double b, double c) {
  const double x = a / c, y = b / c;
  const double x1 = std::sqrt(1.0 + x * x), y1 = std::sqrt(1.0 + y * y);
  const double s = 0.5 * std::log((1.0 + x * x) * (1.0 + y * y) / (1.0 + x * x + y * y)) +
                   x * y1 * std::atan(x / y1) + y * x1 * std::atan(y / x1) - x * std::atan(x) -
                   y * std::atan(y);
  return 2.0 * s / (kPi * x * y);
}

ThreeSurfaces indirect_flux(double X, double Y, double H, const ThreeSurfaces& rho,
                            const ThreeSurfaces& direct) {
  // Surfaces 0 floor, 1 walls, 2 ceiling; F[i][j] from i to j (reciprocity A_i F_ij = A_j F_ji).
  const double A_f = X * Y, A_w = 2.0 * H * (X + Y);
  const double F_fc = parallel_rectangles_form_factor(X, Y, H);
  const double F_fw = 1.0 - F_fc;
  const double F_wf = A_f * F_fw / A_w;
  const double F[3][3] = {{0.0, F_fw, F_fc}, {F_wf, 1.0 - 2.0 * F_wf, F_wf}, {F_fc, F_fw, 0.0}};
  const double r[3] = {rho.floor, rho.walls, rho.ceiling};
  const double d[3] = {direct.floor, direct.walls, direct.ceiling};
  // (I - diag(rho) F^T) M = rho D, by Gaussian elimination (diagonally dominant: rho < 1).
  double A[3][4];
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) A[i][j] = (i == j ? 1.0 : 0.0) - r[i] * F[j][i];
    A[i][3] = r[i] * d[i];
  }
  for (int i = 0; i < 3; ++i)
    for (int k = i + 1; k < 3; ++k) {
      const double f = A[k][i] / A[i][i];
      for (int j = i; j < 4; ++j) A[k][j] -= f * A[i][j];
    }
  double M[3];
  for (int i = 2; i >= 0; --i) {
    double s = A[i][3];
    for (int j = i + 1; j < 3; ++j) s -= A[i][j] * M[j];
    M[i] = s / A[i][i];
  }
  std::array<double, 3> in{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) in[i] += M[j] * F[j][i];
  return {in[0], in[1], in[2]};
}

}  // namespace luxgrid::calc::glare
