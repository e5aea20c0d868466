// Luminous openings: LM-63 sign rules, EULUMDAT circular areas, the emitter polygon, tilt.
#include <gtest/gtest.h>

#include <filesystem>

#include "photometry/derived_photometry.h"
#include "photometry/opening.h"
#include "photometry/tilt.h"

namespace luxgrid::photometry {
namespace {

using Shape = LuminousOpening::Shape;

double signed_area_about_minus_z(const std::vector<Vec3>& p) {
  Vec3 n(0.0);
  for (std::size_t k = 0; k < p.size(); ++k) n += glm::cross(p[k], p[(k + 1) % p.size()]);
  return -0.5 * n.z;  // positive when the winding's normal is -z
}

TEST(Opening, Lm63SignRules) {
  std::string w;
  EXPECT_EQ(ies_opening(0, 0, 0, w).shape, Shape::point);
  auto r = ies_opening(0.2, 0.6, 0, w);  // width 0.2 along y, length 0.6 along x
  EXPECT_EQ(r.shape, Shape::rectangle);
  EXPECT_DOUBLE_EQ(r.length, 0.6);
  EXPECT_DOUBLE_EQ(r.width, 0.2);
  EXPECT_EQ(ies_opening(-0.3, 0, 0, w).description, "round");
  EXPECT_EQ(ies_opening(-0.3, -0.3, 0, w).description, "circle");
  EXPECT_EQ(ies_opening(-0.3, -0.5, 0, w).description, "ellipse");
  EXPECT_EQ(ies_opening(-0.3, -0.3, 0.1, w).description, "vertical cylinder");
  EXPECT_EQ(ies_opening(-0.3, -0.3, -0.3, w).description, "sphere");
  EXPECT_EQ(ies_opening(-0.3, 1.2, -0.3, w).description, "horizontal cylinder along C0-C180");
  EXPECT_TRUE(w.empty());
  EXPECT_EQ(ies_opening(0, -0.32, 0, w).shape, Shape::disk);
  EXPECT_FALSE(w.empty());
}

TEST(Opening, PolygonWindsCounterClockwiseSeenFromBelow) {
  LuminousOpening rect;
  rect.shape = Shape::rectangle;
  rect.length = 0.6;
  rect.width = 0.2;
  const auto p = opening_polygon(rect);
  ASSERT_EQ(p.size(), 4u);
  EXPECT_NEAR(signed_area_about_minus_z(p), 0.12, 1e-15);
  for (const auto& v : p) EXPECT_EQ(v.z, 0.0);
  LuminousOpening disk;
  disk.shape = Shape::disk;
  disk.length = disk.width = 1.0;
  for (int n : {3, 8, 64}) {
    const auto q = opening_polygon(disk, n);
    ASSERT_EQ(q.size(), static_cast<std::size_t>(n));
    EXPECT_NEAR(signed_area_about_minus_z(q), 0.5 * n * 0.25 * std::sin(2 * kPi / n), 1e-12);
    EXPECT_NEAR(q[0].x, 0.5, 1e-15);
  }
  EXPECT_TRUE(opening_polygon(LuminousOpening{}).empty());
  EXPECT_NEAR(opening_area_m2(disk), kPi / 4, 1e-15);
}

TEST(Opening, CorpusIesFeetAndLdtCircles) {
  const auto dir = std::filesystem::path(LUXGRID_SOURCE_DIR) / "tests/data/photometry";
  const Photometry a = load_photometry_file(dir / "ies/kurtversen_par38_iesna91.ies");
  EXPECT_EQ(a.opening.shape, Shape::disk);
  EXPECT_NEAR(a.opening.length, 0.6 * 0.3048, 1e-12);
  const Photometry b = load_photometry_file(dir / "ldt/zumtobel_arcos3_isym1.ldt");
  EXPECT_EQ(b.opening.shape, Shape::disk);
  EXPECT_NEAR(b.opening.length, 0.110, 1e-12);
  const Photometry c = load_photometry_file(dir / "ldt/zumtobel_slotlight_isym4.ldt");
  EXPECT_EQ(c.opening.shape, Shape::rectangle);
  EXPECT_NEAR(c.opening.length, 2.0, 1e-12);
  EXPECT_NEAR(c.opening.width, 0.072, 1e-12);
}

TEST(Tilt, IncludeIsReadAndInterpolated) {
  const Photometry p =
      load_photometry_file(std::filesystem::path(LUXGRID_SOURCE_DIR) /
                           "tests/data/photometry/ies/synthetic_tilt_include_lm02.ies");
  ASSERT_TRUE(p.tilt);
  EXPECT_EQ(p.tilt->lamp_to_luminaire_geometry, 1);
  EXPECT_EQ(p.tilt->angle_deg, (std::vector<double>{0, 45, 90, 180}));
  EXPECT_EQ(p.tilt->factor, (std::vector<double>{1.0, 0.9, 0.8, 1.0}));
  EXPECT_NEAR(p.tilt->factor_at(22.5), 0.95, 1e-15);
  EXPECT_NEAR(p.tilt->factor_at(-135), 0.9, 1e-15);
  EXPECT_NEAR(p.distribution->intensity({0, 0, -1}), 1000.0, 1e-9);
}

TEST(Derived, BeamAnglesOfACosinePowerBeam) {
  // I = cos^8(gamma) on a 0.5 deg table: half-intensity at acos(0.5^(1/8)) = 23.9 deg.
  SphericalGrid g;
  g.c_rad = {0.0};
  for (int j = 0; j <= 180; ++j) {
    g.gamma_rad.push_back(j * 0.5 * kDegToRad);
    g.cd.push_back(std::pow(std::cos(g.gamma_rad.back()), 8));
  }
  const TabularDistribution t(g, Interpolation::bicubic);
  const BeamAngles b = beam_angles(t, 0.0);
  EXPECT_NEAR(b.beam_deg, 2 * std::acos(std::pow(0.5, 1.0 / 8)) * kRadToDeg, 0.02);
  EXPECT_NEAR(b.field_deg, 2 * std::acos(std::pow(0.1, 1.0 / 8)) * kRadToDeg, 0.02);
}

}  // namespace
}  // namespace luxgrid::photometry
