// CIE 190's UGR table: the flux transfer against the standard's printed transfer factors, a
// Lambertian luminaire's 4H x 8H value against an independent hand computation, crosswise =
// endwise for a rotationally symmetric file, and the flux correction.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <utility>

#include "calc/glare/flux_transfer.h"
#include "calc/glare/guth_position_index.h"
#include "calc/glare/ugr_table.h"
#include "calc/scaled_distribution.h"
#include "photometry/builtin.h"
#include "photometry/photometry.h"
#include "tests/calc/opaque_distribution.h"

namespace luxgrid::calc::glare {
namespace {

// Howell's catalogue C-11: two unit squares one unit apart exchange 0.19982.
TEST(FluxTransfer, ParallelSquaresFormFactor) {
  EXPECT_NEAR(parallel_rectangles_form_factor(1.0, 1.0, 1.0), 0.19982, 5e-5);
}

// CIE 190 Table 5, room index k = 2.67 (a 4H x 8H room), as transcribed in eulumdat-ugr's
// background.py ([eulumdat-ugr]): the indirect flux reaching the walls per lumen of direct flux
// on the floor (F_T,FW), on the walls (F_T,WW - 1) and on the ceiling (F_T,CW). The standard
// prints three decimals: the tolerance is half a unit of the last one.
TEST(FluxTransfer, ReproducesCie190TransferFactors) {
  struct Row {
    double c, w, f, FW, WW1, CW;
  };
  const Row rows[] = {{0.7, 0.5, 0.2, 0.115, 0.211, 0.307},
                      {0.7, 0.3, 0.2, 0.106, 0.117, 0.283},
                      {0.5, 0.5, 0.2, 0.100, 0.187, 0.211},
                      {0.5, 0.3, 0.2, 0.093, 0.104, 0.196},
                      {0.3, 0.3, 0.2, 0.081, 0.092, 0.114}};
  for (const Row& r : rows) {
    const ThreeSurfaces rho{r.f, r.w, r.c};
    EXPECT_NEAR(indirect_flux(4.0, 8.0, 1.0, rho, {1.0, 0.0, 0.0}).walls, r.FW, 5e-4);
    EXPECT_NEAR(indirect_flux(4.0, 8.0, 1.0, rho, {0.0, 1.0, 0.0}).walls, r.WW1, 5e-4);
    EXPECT_NEAR(indirect_flux(4.0, 8.0, 1.0, rho, {0.0, 0.0, 1.0}).walls, r.CW, 5e-4);
  }
}

// Fraction of a downward Lambertian point source's flux that lands on an a x b rectangle with a
// corner straight below it at depth h ([Howell] B-3, the parallel differential-to-rectangle form
// factor).
double corner_fraction(double a, double b, double h) {
  a /= h;
  b /= h;
  const double sa = std::sqrt(1 + a * a), sb = std::sqrt(1 + b * b);
  return (a / sa * std::atan(b / sa) + b / sb * std::atan(a / sb)) / (2.0 * kPi);
}

// The 4H x 8H, 0.7/0.5/0.2 value of a Lambertian luminaire (I = I0 cos gamma, flat 0.3 x 0.3 m
// opening, 1000 lm: I0 = 1000 / pi), computed here independently of the table code: luminance
// I0 / A everywhere, omega = A cos(gamma) / d^2 summed over the 16 x 32 grid at S = 0.25 H in the
// Guth field, the floor's direct flux from the closed-form corner fractions instead of the
// table's quadrature, then the (tested) three-surface transfer. The table's quadrature of the
// floor flux converges to ~1e-4, which moves UGR by < 0.01; 0.02 allows for it.
TEST(UgrTable, LambertianFourByEightMatchesHandComputation) {
  const double I0 = 1000.0 / kPi, side = 0.3, A = side * side;
  const photometry::LambertianDistribution lambert(I0);
  photometry::LuminousOpening o;
  o.shape = photometry::LuminousOpening::Shape::rectangle;
  o.length = o.width = side;
  const double H = kTableH_m, S = 0.25 * H, X = 4 * H, Y = 8 * H;
  double sum = 0.0, floor_lm = 0.0;
  int n = 0;
  for (int j = 0; j < 32; ++j)
    for (int i = 0; i < 16; ++i) {
      const double x = -0.5 * X + S * (i + 0.5), y = S * (j + 0.5);  // T = x, R = y
      ++n;
      floor_lm += kPi * I0 *
                  (corner_fraction(x + 0.5 * X, y, H) + corner_fraction(0.5 * X - x, y, H) +
                   corner_fraction(x + 0.5 * X, Y - y, H) + corner_fraction(0.5 * X - x, Y - y, H));
      if (!in_guth_field(y, x, H)) continue;
      const double d2 = x * x + y * y + H * H;
      const double L = I0 / A, omega = A * (H / std::sqrt(d2)) / d2,
                   p = guth_position_index(H / y, x / y);
      sum += L * L * omega / (p * p);
    }
  const double total_lm = n * kPi * I0;
  const ThreeSurfaces in =
      indirect_flux(X, Y, H, {0.2, 0.5, 0.7}, {floor_lm, total_lm - floor_lm, 0.0});
  const double Lb = in.walls / (2 * H * (X + Y)) / kPi;
  const double hand = 8.0 * std::log10(0.25 * sum / Lb);
  const TableRoom room{4, 8};
  const auto cross = table_ugr(lambert, o, room, kTableReflectances[0], Viewing::crosswise);
  const auto end = table_ugr(lambert, o, room, kTableReflectances[0], Viewing::endwise);
  ASSERT_TRUE(cross && end);
  EXPECT_NEAR(*cross, hand, 0.02);
  EXPECT_NEAR(*end, hand, 0.02);  // rotationally symmetric, flat opening: the same
}

// A rotationally symmetric file with a flat round opening: every cell crosswise equals endwise
// (the two differ only in which C plane faces the observer). 1e-6 UGR: the table is
// C-independent, so only rounding differs.
TEST(UgrTable, RotationallySymmetricFileIsTheSameCrosswiseAndEndwise) {
  const auto file = std::filesystem::path(LUXGRID_SOURCE_DIR) /
                    "tests/data/photometry/ies/interlight_ovni_lm02_nonascii.ies";
  const photometry::Photometry p = photometry::load_photometry_file(file);
  ASSERT_EQ(p.symmetry, photometry::Symmetry::rotational);
  ASSERT_EQ(p.opening.height, 0.0);
  const UgrTable t = ugr_table(p.distribution, p.opening, table_lamp_flux_lm(p, *p.distribution));
  ASSERT_EQ(t.crosswise.size(), kTableRooms.size());
  for (size_t i = 0; i < kTableRooms.size(); ++i)
    for (size_t r = 0; r < 5; ++r) {
      ASSERT_TRUE(t.crosswise[i][r] && t.endwise[i][r]);
      EXPECT_NEAR(*t.crosswise[i][r], *t.endwise[i][r], 1e-6)
          << "room " << i << ", reflectances " << r;
    }
}

// UGR grows by 8 log10(k) when a luminaire's flux grows k times (L and Lb both scale by k); the
// table, normalised to 1000 lm of lamp flux, does not change, and its correction is
// 8 log10(F / 1000).
TEST(UgrTable, FluxCorrection) {
  auto lambert = std::make_shared<photometry::LambertianDistribution>(1000.0 / kPi);
  photometry::LuminousOpening o;
  o.shape = photometry::LuminousOpening::Shape::disk;
  o.length = o.width = 0.25;
  const TableRoom room{4, 8};
  const ScaledDistribution tripled(lambert, 3.0);
  const auto a = table_ugr(*lambert, o, room, kTableReflectances[0], Viewing::crosswise);
  const auto b = table_ugr(tripled, o, room, kTableReflectances[0], Viewing::crosswise);
  ASSERT_TRUE(a && b);
  EXPECT_NEAR(*b - *a, 8.0 * std::log10(3.0), 1e-9);
  const UgrTable at_1000 = ugr_table(lambert, o, 1000.0);
  const UgrTable at_3000 = ugr_table(std::make_shared<ScaledDistribution>(lambert, 3.0), o, 3000.0);
  EXPECT_NEAR(at_3000.correction, 8.0 * std::log10(3.0), 1e-12);
  EXPECT_NEAR(*at_3000.crosswise[10][0], *at_1000.crosswise[10][0], 1e-9);  // row 10: 4H x 8H
  EXPECT_NEAR(*at_1000.crosswise[10][0], *a, 1e-9);
}

// A type C table is read once at the quadrature cells' own angles and serves both viewings by
// shifting the azimuth a quarter or half turn; the general path turns every direction by the
// viewing's rotation and asks the distribution. On asymmetric files (a floodlight with one
// lopsided side, a bilateral roadway optic) both give the same UGR in every room: only the
// angles' rounding differs (~1e-15 in a cell's position), so 1e-9 UGR. The viewings themselves
// differ by far more than that on these files, so a wrong shift cannot pass.
TEST(UgrTable, TableReadAtTheCellsAnglesEqualsTheTurnedDirections) {
  // The files, and how far apart their two viewings are at least (measured: 3.3 and 0.026 UGR).
  const std::pair<const char*, double> files[] = {{"ldt/ledvance_flmax_asym_isym0.ldt", 1.0},
                                                  {"ies/rab_roadway_bilateral_lm02.ies", 0.01}};
  for (const auto& [name, viewings_apart] : files) {
    const photometry::Photometry p = photometry::load_photometry_file(
        std::filesystem::path(LUXGRID_SOURCE_DIR) / "tests/data/photometry" / name);
    ASSERT_NE(p.distribution->table_view().table, nullptr) << name;
    double largest_difference = 0.0;
    for (const TableRoom room : {TableRoom{2, 2}, TableRoom{4, 8}, TableRoom{12, 4}}) {
      const TableUgrs both = table_ugrs(*p.distribution, p.opening, room, kTableReflectances[0]);
      const Opaque opaque(*p.distribution);
      const auto c = table_ugr(opaque, p.opening, room, kTableReflectances[0], Viewing::crosswise);
      const auto e = table_ugr(opaque, p.opening, room, kTableReflectances[0], Viewing::endwise);
      ASSERT_TRUE(both.crosswise && both.endwise && c && e) << name;
      EXPECT_NEAR(*both.crosswise, *c, 1e-9)
          << name << " " << room.x_H << "H x " << room.y_H << "H";
      EXPECT_NEAR(*both.endwise, *e, 1e-9) << name << " " << room.x_H << "H x " << room.y_H << "H";
      largest_difference = std::max(largest_difference, std::abs(*c - *e));
    }
    EXPECT_GT(largest_difference, viewings_apart) << name;
  }
}

}  // namespace
}  // namespace luxgrid::calc::glare
