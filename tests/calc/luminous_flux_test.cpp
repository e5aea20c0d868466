// calc::luminous_flux: a type C table is read at the quadrature nodes' own angles, any other
// distribution per direction. Checked against the exact flux of a constant and of a cosine
// table, and against the per-direction path on real, asymmetric and bicubic files.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <memory>

#include "calc/scaled_distribution.h"
#include "photometry/photometry.h"
#include "photometry/tabular_distribution.h"
#include "tests/calc/opaque_distribution.h"

namespace luxgrid::calc {
namespace {

// A 5-degree type C grid over the whole sphere, I(C, gamma) from `cd_of`.
template <class F>
photometry::TabularDistribution grid_of(const F& cd_of) {
  photometry::SphericalGrid g;
  for (int i = 0; i < 72; ++i) g.c_rad.push_back(i * 5.0 * kPi / 180.0);
  for (int j = 0; j <= 36; ++j) g.gamma_rad.push_back(j * 5.0 * kPi / 180.0);
  for (double c : g.c_rad)
    for (double gamma : g.gamma_rad) g.cd.push_back(cd_of(c, gamma));
  return photometry::TabularDistribution(std::move(g));
}

// A constant I0 sends 4 pi I0 (Gauss-Legendre is exact for it: rounding only, 1e-12).
// I0 max(0, cos gamma) on the lower hemisphere sends pi I0; the table interpolates the cosine
// linearly between 5-degree rows, which is below it by at most (5 deg)^2 / 8 = 1e-3 of it, so
// the flux lies within [0.998, 1] of pi I0.
TEST(LuminousFlux, ConstantAndCosineTablesGiveTheirExactFlux) {
  const double I0 = 250.0;
  const auto constant = grid_of([&](double, double) { return I0; });
  EXPECT_NEAR(luminous_flux(constant), 4.0 * kPi * I0, 1e-12 * 4.0 * kPi * I0);
  const auto cosine = grid_of([&](double, double g) { return I0 * std::max(0.0, std::cos(g)); });
  const double flux = luminous_flux(cosine);
  EXPECT_LE(flux, kPi * I0 * (1.0 + 1e-12));
  EXPECT_GE(flux, kPi * I0 * 0.998);
}

// The table read at the nodes' angles and the same table asked per direction: the angles differ
// by rounding only (~1e-16 rad), so the fluxes agree to 1e-12, on an asymmetric floodlight, a
// bilateral roadway optic and a quadrant-symmetric file read bicubically.
TEST(LuminousFlux, TableAtTheNodesAnglesEqualsThePerDirectionPath) {
  for (const char* name :
       {"ldt/ledvance_flmax_asym_isym0.ldt", "ies/rab_roadway_bilateral_lm02.ies",
        "ies/erco_t26_lm86_quadrant.ies"}) {
    const photometry::Photometry p = photometry::load_photometry_file(
        std::filesystem::path(LUXGRID_SOURCE_DIR) / "tests/data/photometry" / name);
    const auto* table = p.distribution->table_view().table;
    ASSERT_NE(table, nullptr) << name;
    for (const auto mode :
         {photometry::Interpolation::bilinear, photometry::Interpolation::bicubic}) {
      const auto d = table->with_interpolation(mode);
      const double by_table = luminous_flux(*d), by_direction = luminous_flux(Opaque(*d));
      ASSERT_GT(by_direction, 0.0) << name;
      EXPECT_NEAR(by_table, by_direction, 1e-12 * by_direction) << name << " " << to_string(mode);
    }
  }
}

}  // namespace
}  // namespace luxgrid::calc
