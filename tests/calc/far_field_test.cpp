// The far-field point model against closed forms, and the rotation convention.
#include <gtest/gtest.h>

#include <cmath>

#include "calc/direct.h"
#include "calc/pipeline.h"
#include "photometry/builtin.h"
#include "project/project_file.h"

namespace luxgrid::calc {
namespace {

Luminaire point_luminaire(photometry::DistributionPtr d, Vec3 pos,
                          glm::dmat3 rot = glm::dmat3(1.0)) {
  Luminaire l;
  l.distribution = std::move(d);
  l.pose.position = pos;
  l.pose.rotation = rot;
  return l;
}

// An analytic test distribution that is not rotationally symmetric: I = 100 + 50 cos(C) cos(C)...
// concretely I(dir) = 100 * (1 + x^2 + 2 y^2) so C0 and C90 differ (at gamma 90: 200 vs 300 cd).
class AsymmetricDistribution final : public photometry::IntensityDistribution {
 public:
  double intensity(const Vec3& d) const override {
    return 100.0 * (1.0 + d.x * d.x + 2.0 * d.y * d.y);
  }
};

TEST(FarField, IsotropicInverseSquareCosine) {
  const auto lum =
      point_luminaire(std::make_shared<photometry::IsotropicDistribution>(1000.0), {0, 0, 3});
  for (double r : {0.0, 0.7, 2.0, 5.0}) {
    const double d = std::hypot(3.0, r);
    // Exact formula; 1e-12 relative covers double rounding.
    EXPECT_NEAR(far_field_illuminance(lum, {r, 0, 0}, {0, 0, 1}), 1000.0 * 3.0 / (d * d * d),
                1e-12 * 1000.0 / 9.0);
  }
}

TEST(FarField, LightFromBehindIsZeroAndAlwaysFinite) {
  const auto lum =
      point_luminaire(std::make_shared<photometry::IsotropicDistribution>(1000.0), {0, 0, 3});
  EXPECT_EQ(far_field_illuminance(lum, {1, 0, 0}, {0, 0, -1}), 0.0);  // receiver faces away
  EXPECT_EQ(far_field_illuminance(lum, {0, 0, 3}, {0, 0, 1}), 0.0);   // at the source itself
  EXPECT_EQ(far_field_illuminance(lum, {5, 0, 3}, {-1, 0, 0}), 1000.0 / 25.0);  // in its plane
}

TEST(FarField, LambertianCie171Case52) {
  // CIE 171 case 5.2: E = I0 h^2 / d^4.
  const auto lum =
      point_luminaire(std::make_shared<photometry::LambertianDistribution>(1000.0), {2, 2, 3});
  const double d2 = 9.0 + 4.0 + 4.0;
  EXPECT_NEAR(far_field_illuminance(lum, {4, 4, 0}, {0, 0, 1}), 1000.0 * 9.0 / (d2 * d2), 1e-12);
}

TEST(FarField, RotationAboutZBy90SwapsC0AndC90) {
  auto dist = std::make_shared<AsymmetricDistribution>();
  const auto plain = point_luminaire(dist, {0, 0, 2});
  const auto turned = point_luminaire(dist, {0, 0, 2}, rotation_xyz(0, 0, kPi / 2));
  // A point along +x sees the C0 plane of the plain luminaire; after turning the luminaire 90 deg
  // about z its C90 plane points along -x... and its C0 plane along +y.
  const Vec3 up(0, 0, 1);
  EXPECT_NEAR(far_field_illuminance(turned, {0, 1.5, 0}, up),
              far_field_illuminance(plain, {1.5, 0, 0}, up), 1e-12);
  EXPECT_NEAR(far_field_illuminance(turned, {1.5, 0, 0}, up),
              far_field_illuminance(plain, {0, -1.5, 0}, up), 1e-12);
  EXPECT_GT(far_field_illuminance(plain, {0, 1.5, 0}, up),
            far_field_illuminance(plain, {1.5, 0, 0}, up) * 1.05);
}

TEST(FarField, RotationOrderIsXThenYThenZ) {
  // [90, 0, 90]: x first turns local +y to world +z, then z turns world +x to +y.
  const glm::dmat3 r = rotation_xyz(kPi / 2, 0, kPi / 2);
  const Vec3 ex = r * Vec3(1, 0, 0), ey = r * Vec3(0, 1, 0);
  EXPECT_NEAR(glm::length(ex - Vec3(0, 1, 0)), 0.0, 1e-15);
  EXPECT_NEAR(glm::length(ey - Vec3(0, 0, 1)), 0.0, 1e-15);
  // A luminaire tilted +30 deg about y aims its nadir towards -x.
  const Vec3 nadir = rotation_xyz(0, kPi / 6, 0) * Vec3(0, 0, -1);
  EXPECT_NEAR(nadir.x, -0.5, 1e-15);
  EXPECT_NEAR(nadir.z, -std::sqrt(3.0) / 2, 1e-15);
}

TEST(FarField, GridSumsLuminairesAndAppliesMaintenanceFactor) {
  const auto doc = nlohmann::json::parse(R"({
    "format": "luxgrid-project/1", "name": "two sources",
    "settings": {"maintenance_factor": 0.5, "near_field": "never", "indirect": "off"},
    "photometry": { "iso": { "builtin": "isotropic", "intensity_cd": 400 } },
    "rooms": [ { "name": "r", "outline": [[0,0],[4,0],[4,4],[0,4]], "height": 3 } ],
    "luminaires": [ { "photometry": "iso", "array": {"origin": [1, 2, 2], "count": [2, 1], "spacing": [2, 1]} } ],
    "surfaces": [ { "name": "p", "points": [ {"at": [2, 2, 0], "normal": [0, 0, 1]} ] } ]
  })");
  const Results r = run_scene(project::parse_project(doc, "p.json", ".").scene);
  const double d = std::sqrt(5.0);
  const double each = 400.0 * 2.0 / (d * d * d);
  // Every part is maintained: x 0.5, so E_direct = E (no indirect light).
  EXPECT_NEAR(r.surfaces[0].E_direct[0], each, 1e-12);
  EXPECT_NEAR(r.surfaces[0].E[0], each, 1e-12);
  EXPECT_DOUBLE_EQ(r.maintenance_factor, 0.5);
}

}  // namespace
}  // namespace luxgrid::calc
