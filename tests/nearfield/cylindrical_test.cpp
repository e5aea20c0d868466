// Cylindrical and semi-cylindrical illuminance from area luminaires (docs/nearfield.md): every
// near-field rung against a brute-force integral written here, independently of the rungs (a
// midpoint sum over the opening with the weights spelt out from their definitions, not through
// receiver_kernel.h), and against closed forms where they exist.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include <glm/gtc/matrix_transform.hpp>

#include "calc/nearfield/illuminance.h"
#include "calc/nearfield/models.h"
#include "nearfield_test_support.h"
#include "photometry/photometry.h"

namespace luxgrid::nearfield {
namespace {

// The issue's promise for `standard`: within 1 % of the truth.
constexpr double kPromise = 0.01;

enum class What { cylindrical, semi_cylindrical };

// Brute force: the opening (a parallelogram: make_emitter's rectangle) cut into n x n cells, one
// midpoint each, of (I / A) dA w / d^2 -- the area form with L dA cos_e = I dA / A (Luksch et al.
// 2020 Eq. 2), I the file's intensity towards the receiver. The weight w, from the definitions
// (EN 13201-2 / EN 12464-1): sin(eps) / pi for a cylinder; sin(eps) (1 + cos(alpha)) / pi for
// the half cylinder facing `facing`, alpha the angle between `facing` and the horizontal
// direction to the element (by atan2, not by a dot product as in the code under test).
double brute_force(const Emitter& e, const Vec3& x, What what, const Vec3& facing, int n) {
  const Vec3 o = e.vertices[0], su = e.vertices[1] - e.vertices[0],
             sv = e.vertices[3] - e.vertices[0];
  const double cell = glm::length(glm::cross(su, sv)) / (double(n) * n);
  double sum = 0.0;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      const Vec3 y = o + (i + 0.5) / n * su + (j + 0.5) / n * sv;
      const Vec3 r = y - x;
      const double d2 = glm::dot(r, r);
      const Vec3 u = r / std::sqrt(d2);
      const double sin_eps = std::hypot(u.x, u.y);
      double w = sin_eps / kPi;
      if (what == What::semi_cylindrical) {
        const double alpha = std::atan2(u.y, u.x) - std::atan2(facing.y, facing.x);
        w *= 1.0 + std::cos(alpha);
      }
      sum += e.intensity_towards(-u) / e.area_m2 * cell * w / d2;
    }
  }
  return sum;
}

// The brute force at n and 2n: both returned so a test can see it has converged.
struct Truth {
  double value, coarse;
};
Truth truth(const Emitter& e, const Vec3& x, What what, const Vec3& facing = Vec3(1, 0, 0)) {
  constexpr int kCells = 600;  // per side; 2 x 600 = 1200: 1.4e6 lookups
  return {brute_force(e, x, what, facing, 2 * kCells), brute_force(e, x, what, facing, kCells)};
}

Receiver receiver_for(What what, const Vec3& facing) {
  return what == What::cylindrical ? Receiver::cylindrical() : Receiver::semi_cylindrical(facing);
}

Emitter ledvance(const Vec3& position, const glm::dmat3& rotation) {
  const auto ph = photometry::load_photometry_file(
      std::string(LUXGRID_SOURCE_DIR) + "/tests/data/photometry/ldt/ledvance_flmax_asym_isym0.ldt");
  return make_emitter(ph.opening, position, rotation, ph.distribution);
}

glm::dmat3 rotation_xyz_deg(double rx, double ry, double rz) {
  // calc::rotation_xyz's convention (R = Rz Ry Rx); only the tilted case below uses x and y.
  const auto rot = [](double deg, const Vec3& axis) {
    return glm::dmat3(glm::rotate(glm::dmat4(1.0), deg * kDegToRad, axis));
  };
  return rot(rz, Vec3(0, 0, 1)) * rot(ry, Vec3(0, 1, 0)) * rot(rx, Vec3(1, 0, 0));
}

void expect_rungs_match(const char* label, const Emitter& e, const Vec3& x, What what,
                        const Vec3& facing = Vec3(1, 0, 0)) {
  const Truth t = truth(e, x, what, facing);
  // The brute force converges like h^2 on smooth cells and h on a cell across a table kink;
  // 600 -> 1200 moving it by < 1e-3 puts the finer value well inside the 1 % being tested.
  ASSERT_NEAR(t.coarse, t.value, 1e-3 * t.value) << label;
  const Receiver r = receiver_for(what, facing);
  const double standard = illuminance(e, x, r, Model::standard());
  const double high = illuminance(e, x, r, Model::high());
  const double reference = illuminance(e, x, r, Model::reference());
  const double far = illuminance(e, x, r, Model::far_field());
  const double hybrid = hybrid_illuminance(e, x, r, Model::standard());
  std::printf(
      "%-44s brute %10.2f  standard %10.2f (%+.4f %%)  high %10.2f (%+.4f %%)  reference %10.2f "
      "(%+.4f %%)  far %10.2f\n",
      label, t.value, standard, 100 * (standard / t.value - 1), high, 100 * (high / t.value - 1),
      reference, 100 * (reference / t.value - 1), far);
  EXPECT_NEAR(standard, t.value, kPromise * t.value) << label;
  EXPECT_NEAR(hybrid, t.value, kPromise * t.value) << label;
  // high promises 0.3 % (docs/accuracy.md); the reference 1e-6 of its own integrand, which the
  // brute force matches to its own convergence (1e-3 between 600 and 1200 cells, so 0.3 % here
  // too).
  EXPECT_NEAR(high, t.value, 3e-3 * t.value) << label;
  EXPECT_NEAR(reference, t.value, 3e-3 * t.value) << label;
}

// The issue's scene: the Ledvance flood at (5, 5, 3) turned 25 degrees about z, 0.4 x 0.65 m
// opening facing down. Before: 0 lx at (5, 5, 2) (far field: the light arrives from straight
// above, sin(eps) = 0) against 2399 lx, and 31 828 lx against 48 687 lx at (5.2, 4.6, 2.8).
TEST(Cylindrical, LedvancePointsOfTheIssueAgainstBruteForce) {
  const Emitter e = ledvance(Vec3(5, 5, 3), rotation_xyz_deg(0, 0, 25));
  expect_rungs_match("ledvance (5, 5, 2) cylindrical", e, Vec3(5, 5, 2), What::cylindrical);
  expect_rungs_match("ledvance (5.2, 4.6, 2.8) cylindrical", e, Vec3(5.2, 4.6, 2.8),
                     What::cylindrical);
  expect_rungs_match("ledvance (5, 5, 2) semi-cyl facing +x", e, Vec3(5, 5, 2),
                     What::semi_cylindrical, Vec3(1, 0, 0));
  expect_rungs_match("ledvance (5.2, 4.6, 2.8) semi-cyl facing -y", e, Vec3(5.2, 4.6, 2.8),
                     What::semi_cylindrical, Vec3(0, -1, 0));
  expect_rungs_match("ledvance (5.2, 4.6, 2.8) semi-cyl facing +y", e, Vec3(5.2, 4.6, 2.8),
                     What::semi_cylindrical, Vec3(0, 1, 0));
}

TEST(Cylindrical, IssueValuesOfTheBruteForceReproduced) {
  // The issue quotes its brute force to four digits; ours agrees to that.
  const Emitter e = ledvance(Vec3(5, 5, 3), rotation_xyz_deg(0, 0, 25));
  EXPECT_NEAR(truth(e, Vec3(5, 5, 2), What::cylindrical).value, 2399.0, 1.0);
  EXPECT_NEAR(truth(e, Vec3(5.2, 4.6, 2.8), What::cylindrical).value, 48687.0, 10.0);
}

// A tilted flood (the issue's rotation [20, -35, 60]): the vertical through the receiver pierces
// the opening's plane off its foot point, so the cylinder's weight has its cone vertex inside a
// table cell of the table rung.
TEST(Cylindrical, TiltedLedvanceAgainstBruteForce) {
  const Emitter e = ledvance(Vec3(5, 5, 3), rotation_xyz_deg(20, -35, 60));
  expect_rungs_match("tilted ledvance (5, 5, 2) cylindrical", e, Vec3(5, 5, 2), What::cylindrical);
  expect_rungs_match("tilted ledvance (4.6, 5.3, 2.6) cylindrical", e, Vec3(4.6, 5.3, 2.6),
                     What::cylindrical);
  expect_rungs_match("tilted ledvance (4.6, 5.3, 2.6) semi-cyl facing [1,1]", e,
                     Vec3(4.6, 5.3, 2.6), What::semi_cylindrical, glm::normalize(Vec3(1, 1, 0)));
}

// Analytic profiles (no table rung: the area form at the rung's tolerance) against the brute force.
TEST(Cylindrical, AnalyticProfilesAgainstBruteForce) {
  for (auto [name, dist] :
       {std::pair{"batwing", testing::batwing()}, std::pair{"spot", testing::spot()}}) {
    const Emitter e = testing::paper_emitter(1.0, kPi, dist, 1.0, 0.6);
    for (const Vec3& x : {Vec3(0.2, 0.1, 0.5), Vec3(0.9, -0.4, 0.0), Vec3(0.0, 0.0, 0.8)}) {
      const std::string label =
          std::string(name) + " (" + std::to_string(x.x) + ", " + std::to_string(x.z) + ")";
      expect_rungs_match((label + " cyl").c_str(), e, x, What::cylindrical);
      expect_rungs_match((label + " semi").c_str(), e, x, What::semi_cylindrical, Vec3(0, 1, 0));
    }
  }
}

// A point on the axis of a horizontal Lambertian disk of radius R, luminance L, h below it:
// element at radius r sees it at sin(eps) = r / d, cos_e = h / d, so
//   E_cyl = (1 / pi) integral L cos_e sin(eps) / d^2 dA = 2 L h integral_0^R r^2 / (r^2 + h^2)^2 dr
//         = L (atan(R / h) - R h / (R^2 + h^2)),
// and E_sc the same for any facing: the f . u term is odd in the azimuth and integrates to 0.
TEST(Cylindrical, OnTheAxisOfALambertianDiskClosedForm) {
  constexpr double kRadius = 0.3, kIntensity = 1000.0;
  photometry::LuminousOpening disk;
  disk.shape = photometry::LuminousOpening::Shape::disk;
  disk.length = disk.width = 2 * kRadius;
  // The disk is a regular N-gon of the disk's area (emitter.h); at 128 sides its outline is
  // within (pi / 128)^2 / 2 = 3e-4 of the circle, which bounds the change of the integral.
  const Emitter e = make_emitter(disk, Vec3(0, 0, 2), glm::dmat3(1.0),
                                 testing::lambertian(kIntensity), kMaxDiskSegments);
  const double luminance = kIntensity / e.area_m2;
  for (double h : {0.05, 0.3, 1.0, 2.0}) {
    const Vec3 x(0, 0, 2 - h);
    const double exact =
        luminance * (std::atan(kRadius / h) - kRadius * h / (kRadius * kRadius + h * h));
    for (const Model& m : {Model::standard(), Model::high(), Model::reference()}) {
      EXPECT_NEAR(illuminance(e, x, Receiver::cylindrical(), m), exact, 3e-4 * exact)
          << h << " " << to_string(m);
      EXPECT_NEAR(illuminance(e, x, Receiver::semi_cylindrical(Vec3(0, 1, 0)), m), exact,
                  3e-4 * exact)
          << h << " " << to_string(m);
    }
  }
}

// A small disk far away is a point: the near-field integral tends to the point formula,
// E_cyl = I sin(eps) / (pi d^2), E_sc = E_cyl (1 + cos(alpha)); alpha = 0, 90, 180 degrees give
// 2, 1 and 0 times E_cyl.
TEST(Cylindrical, SmallDiskFarAwayIsThePointFormula) {
  constexpr double kIntensity = 500.0;
  photometry::LuminousOpening disk;
  disk.shape = photometry::LuminousOpening::Shape::disk;
  disk.length = disk.width = 0.05;
  for (auto dist : {testing::isotropic(kIntensity), testing::lambertian(kIntensity)}) {
    const Emitter e = make_emitter(disk, Vec3(0, 0, 3), glm::dmat3(1.0), dist);
    const Vec3 x(4, 0, 0);  // 5 m away = 100 D; sin(eps) = 0.8
    const Vec3 w = glm::normalize(x - e.centroid);
    const double d2 = 25.0;
    const double e_cyl = dist->intensity(w) * 0.8 / (kPi * d2);
    // The finite disk differs from the point by O((D / d)^2) = 1e-4.
    constexpr double kPointLimit = 2e-4;
    EXPECT_NEAR(illuminance(e, x, Receiver::cylindrical(), Model::standard()), e_cyl,
                kPointLimit * e_cyl);
    EXPECT_NEAR(illuminance(e, x, Receiver::cylindrical(), Model::far_field()), e_cyl,
                1e-12 * e_cyl);
    // The source lies towards -x seen from the receiver.
    EXPECT_NEAR(illuminance(e, x, Receiver::semi_cylindrical(Vec3(-1, 0, 0)), Model::standard()),
                2 * e_cyl, kPointLimit * e_cyl);
    EXPECT_NEAR(illuminance(e, x, Receiver::semi_cylindrical(Vec3(0, 1, 0)), Model::standard()),
                e_cyl, kPointLimit * e_cyl);
    EXPECT_NEAR(illuminance(e, x, Receiver::semi_cylindrical(Vec3(1, 0, 0)), Model::standard()),
                0.0, kPointLimit * e_cyl);
    EXPECT_NEAR(illuminance(e, x, Receiver::semi_cylindrical(Vec3(-1, 0, 0)), Model::far_field()),
                2 * e_cyl, 1e-12 * e_cyl);
    EXPECT_NEAR(illuminance(e, x, Receiver::semi_cylindrical(Vec3(1, 0, 0)), Model::far_field()),
                0.0, 1e-12);
  }
}

// The cylinder is the average of the vertical planes around it, and two opposite half cylinders
// make the whole: E_sc(f) + E_sc(-f) = 2 E_cyl at every rung.
TEST(Cylindrical, OppositeHalvesMakeTheWhole) {
  const Emitter e = ledvance(Vec3(5, 5, 3), rotation_xyz_deg(20, -35, 60));
  for (const Vec3& x : {Vec3(5, 5, 2), Vec3(4.6, 5.3, 2.6), Vec3(7, 3, 0)}) {
    for (const Model& m : {Model::far_field(), Model::standard(), Model::reference()}) {
      const double cyl = illuminance(e, x, Receiver::cylindrical(), m);
      const Vec3 f = glm::normalize(Vec3(0.3, -1, 0));
      const double sum = illuminance(e, x, Receiver::semi_cylindrical(f), m) +
                         illuminance(e, x, Receiver::semi_cylindrical(-f), m);
      // The far field and standard's table rung (fixed nodes) are linear in the weight: equal to
      // rounding. The reference refines each integrand on its own, each to 1e-4 of its value:
      // the two halves and the whole are each within 1e-4 x (2 cyl), so 4e-4 of cyl in all.
      const double tol = m.kind == ModelKind::reference ? 4e-4 : 1e-9;
      EXPECT_NEAR(sum, 2 * cyl, tol * cyl) << to_string(m);
    }
  }
}

}  // namespace
}  // namespace luxgrid::nearfield
