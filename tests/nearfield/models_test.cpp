// Values of every rung against closed forms and against each other.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include "calc/nearfield/illuminance.h"
#include "calc/nearfield/models.h"
#include "nearfield_test_support.h"
#include "photometry/photometry.h"

namespace luxgrid::nearfield {
namespace {

using testing::kUp;
using testing::paper_emitter;

// Exact E below the centre of an a x b uniform rectangle at distance h (parallel planes),
// configuration factor of a corner-aligned rectangle summed over four quadrants.
double exact_below_centre(double luminance, double a, double b, double h) {
  const double x = a / 2 / h, y = b / 2 / h;
  const double f = 2.0 / kPi *
                   (x / std::sqrt(1 + x * x) * std::atan(y / std::sqrt(1 + x * x)) +
                    y / std::sqrt(1 + y * y) * std::atan(x / std::sqrt(1 + y * y)));
  return luminance * kPi * f;  // E = pi L F, four quadrants each F/4 -> sum F (x, y half sizes)
}

TEST(Lambert, MatchesParallelRectangleClosedForm) {
  for (double h : {0.1, 1.0, 2.5}) {
    const Emitter e = paper_emitter(h, kPi, testing::lambertian(1000.0));
    const double exact = exact_below_centre(1000.0, 1.0, 1.0, h);
    EXPECT_NEAR(lambert_uniform_illuminance(e, Vec3(0.0), kUp, 1000.0), exact, 1e-10 * exact) << h;
  }
}

TEST(Reference, AgreesWithLambertOnCosineEmitter) {
  for (double h : {0.1, 1.0, 2.5})
    for (double theta : {kPi / 2, 5 * kPi / 8, 3 * kPi / 4, 7 * kPi / 8, kPi})
      for (Vec3 p : {Vec3(0.0), Vec3(0.3, -0.2, 0.0), Vec3(-1.5, 0.7, 0.0), Vec3(0.6, 0.5, 0.0)}) {
        const Emitter e = paper_emitter(h, theta, testing::lambertian(1000.0));
        const double exact = lambert_uniform_illuminance(e, p, kUp, 1000.0);
        const ReferenceResult r = reference_illuminance(e, p, kUp, 1e-7);
        EXPECT_TRUE(r.converged);
        // Points in the emitter plane (theta = pi/2, x = 0) are moved off it by the horizon
        // shift (1.4e-6 m here), which changes E by O(shift / h) of I0 / h^2: the floor.
        const double floor = 1e-5 * 1000.0 / (h * h);
        EXPECT_NEAR(r.illuminance_lx, exact, 1e-6 * exact + floor) << h << " " << theta;
        if (p.x != 0.0) {
          EXPECT_LE(std::abs(r.illuminance_lx - exact), r.error_estimate_lx + 1e-9 * exact);
        }
      }
}

TEST(PaperCubature, ReproducesIssueFigures) {
  // Issue 5: uniform 1 x 1 emitter, -6 % at distance 1 and -28 % at 0.1 below its centre;
  // batwing +9 % at 1 and -15 % at 0.1 (measured with an independent re-implementation).
  struct Case {
    double h;
    photometry::DistributionPtr d;
    double expected_rel;
  };
  for (const Case& c :
       {Case{1.0, testing::lambertian(), -0.06}, Case{0.1, testing::lambertian(), -0.28},
        Case{1.0, testing::batwing(), 0.09}, Case{0.1, testing::batwing(), -0.15}}) {
    const Emitter e = paper_emitter(c.h, kPi, c.d);
    const double ref = reference_illuminance(e, Vec3(0.0), kUp, 1e-8).illuminance_lx;
    const double rel = paper_cubature_illuminance(e, Vec3(0.0), kUp) / ref - 1.0;
    EXPECT_NEAR(rel, c.expected_rel, 0.01) << c.h;
  }
}

TEST(Ladder, SubdivisionConverges) {
  // Planar midpoint subdivision of the fan triangles: not monotone at the first levels for the
  // batwing at h = 0.1 (the error changes sign), then about 4x per level.
  for (auto dist : {testing::lambertian(), testing::batwing()}) {
    const Emitter e = paper_emitter(0.1, kPi, dist);
    const double ref = reference_illuminance(e, Vec3(0.0), kUp, 1e-9).illuminance_lx;
    double e4 =
        std::abs(subdivided_illuminance(e, Vec3(0.0), kUp, 16, TriangleRule::paper) / ref - 1);
    double e5 =
        std::abs(subdivided_illuminance(e, Vec3(0.0), kUp, 32, TriangleRule::paper) / ref - 1);
    EXPECT_LT(e4, 0.016);
    EXPECT_LT(e5, e4 / 3.0);
    EXPECT_LT(e5, 0.004);
  }
}

TEST(Ladder, LambertRulesAreExactForUniformEmitter) {
  for (double h : {0.1, 1.0})
    for (double theta : {kPi / 2, 3 * kPi / 4, kPi}) {
      const Emitter e = paper_emitter(h, theta, testing::lambertian(1000.0));
      for (Vec3 p : {Vec3(0.0), Vec3(0.4, 0.45, 0.0), Vec3(2.0, -1.0, 0.0)}) {
        const double exact = lambert_uniform_illuminance(e, p, kUp, 1000.0);
        // In the emitter plane the horizon shift (1.4e-6 m) is the only difference.
        const double tol =
            1e-9 * exact + (p.x == 0.0 && theta == kPi / 2 ? 1e-5 * 1000.0 / (h * h) : 1e-12);
        for (TriangleRule rule :
             {TriangleRule::lambert_mean, TriangleRule::lambert_product, TriangleRule::two_kernel})
          EXPECT_NEAR(subdivided_illuminance(e, p, kUp, 1, rule), exact, tol);
        EXPECT_NEAR(standard_illuminance(e, p, kUp), exact, tol);
      }
    }
}

TEST(Standard, WithinOnePercentOfReferenceOnProtocolSample) {
  for (auto dist : {testing::lambertian(), testing::batwing(), testing::spot(1000.0, 10.0),
                    testing::isotropic()})
    for (double h : {0.1, 1.0, 2.5})
      for (double theta : {kPi / 2, 5 * kPi / 8, 3 * kPi / 4, 7 * kPi / 8, kPi}) {
        const Emitter e = paper_emitter(h, theta, dist);
        for (double x = -2.5; x <= 2.5; x += 1.0)
          for (double y = -2.5; y <= 2.5; y += 0.75) {
            const Vec3 p(x + 0.013, y + 0.007, 0.0);
            const double ref = reference_illuminance(e, p, kUp, 1e-6).illuminance_lx;
            const double got = standard_illuminance(e, p, kUp);
            EXPECT_NEAR(got, ref, 0.01 * ref + 1e-9) << h << " " << theta << " " << x << " " << y;
          }
      }
}

// Issue 5: `standard` within 1 % of the reference at every point of the paper's protocol, here
// with a tabulated spot (zumtobel_arcos3_isym1.ldt: bilinear between its angles, so the
// integrand has kinks, the hardest case for the error indicators), the batwing and the cosine
// emitter; heights 0.1 / 1 / 2.5, the five orientations, a 6 x 6 raster over the 5 x 5 region.
// Tolerance: 1 % of the point's own reference value (the issue's claim, per point), plus 1e-4 of
// the brightest point of the same height and orientation. Why the floor: the study's measure is
// the error relative to the cell's maximum (study/accuracy_study.cpp, max_rel), and a point far
// outside the spot's beam gets < 1e-3 of the peak, where the far tier's area-form cubature
// (tolerance 3e-3 of the point's own value) can stop early on the table's kinks: measured 2.1 %
// of 7e-4 of the peak at h = 0.1, orientation pi/2, (-1.25, +-1.25), i.e. 1.5e-5 of the peak.
// The floor is 100x below the 1 % claim on the study's measure; every point brighter than 1e-3
// of the peak is within 1 % of its own value (measured worst 0.79 %, printed below).
TEST(Standard, WithinOnePercentOfReferenceOnProtocolSampleWithLdtSpot) {
  const auto spot = photometry::load_photometry_file(
      std::string(LUXGRID_SOURCE_DIR) + "/tests/data/photometry/ldt/zumtobel_arcos3_isym1.ldt");
  double worst = 0.0;
  for (auto dist : {spot.distribution, testing::batwing(), testing::lambertian()})
    for (double h : {0.1, 1.0, 2.5})
      for (double theta : {kPi / 2, 5 * kPi / 8, 3 * kPi / 4, 7 * kPi / 8, kPi}) {
        const Emitter e = paper_emitter(h, theta, dist);
        std::vector<Vec3> points;
        std::vector<double> refs;
        double max_ref = 0.0;
        for (int j = 0; j < 6; ++j)
          for (int i = 0; i < 6; ++i) {
            points.emplace_back(-2.5 + (i + 0.5) * 5.0 / 6.0, -2.5 + (j + 0.5) * 5.0 / 6.0, 0.0);
            refs.push_back(reference_illuminance(e, points.back(), kUp, 1e-6).illuminance_lx);
            max_ref = std::max(max_ref, refs.back());
          }
        for (std::size_t k = 0; k < points.size(); ++k) {
          const double got = standard_illuminance(e, points[k], kUp);
          EXPECT_NEAR(got, refs[k], 0.01 * refs[k] + 1e-4 * max_ref)
              << h << " " << theta << " " << points[k].x << " " << points[k].y;
          if (refs[k] > 1e-3 * max_ref) {
            worst = std::max(worst, std::abs(got / refs[k] - 1.0));
            EXPECT_NEAR(got, refs[k], 0.01 * refs[k])
                << h << " " << theta << " " << points[k].x << " " << points[k].y;
          }
        }
      }
  std::printf("standard vs reference, worst relative error where E > 1e-3 max: %.2e\n", worst);
}

TEST(FarField, InverseSquareCosine) {
  const Emitter e = paper_emitter(2.0, kPi, testing::isotropic(500.0));
  EXPECT_DOUBLE_EQ(far_field_illuminance(e, Vec3(0.0), kUp), 500.0 / 4.0);
  // 45 degrees: cos / d^2 with d^2 = 8.
  EXPECT_NEAR(far_field_illuminance(e, Vec3(2.0, 0.0, 0.0), kUp), 500.0 * std::sqrt(0.5) / 8.0,
              1e-12);
  EXPECT_EQ(far_field_illuminance(e, Vec3(0.0, 0.0, 3.0), kUp), 0.0);  // behind the receiver
}

TEST(EntryPoint, EveryModelNamesItselfAndAgreesFarAway) {
  const Emitter e = paper_emitter(20.0, kPi, testing::batwing());
  const double ff = illuminance(e, Vec3(1.0, 2.0, 0.0), kUp, Model::far_field());
  for (const Model& m :
       {Model::paper_cubature(), Model::subdivided(2), Model::lambert_subdivided(1),
        Model::adaptive(1e-4), Model::standard(), Model::reference()}) {
    EXPECT_FALSE(to_string(m).empty());
    EXPECT_NEAR(illuminance(e, Vec3(1.0, 2.0, 0.0), kUp, m), ff, 2e-3 * ff) << to_string(m);
  }
}

}  // namespace
}  // namespace luxgrid::nearfield

namespace luxgrid::nearfield {
namespace {
TEST(Ladder, TwoKernelRuleIsExactForIsotropicEmitter) {
  // Exact reference: the area integral of I0 cos_r / d^2 / A, which the two-kernel rule
  // integrates in closed form (single-layer potential gradient).
  for (double h : {0.1, 1.0})
    for (double theta : {5 * kPi / 8, kPi}) {
      const Emitter e = paper_emitter(h, theta, testing::isotropic(1000.0));
      for (Vec3 p : {Vec3(0.0), Vec3(0.4, 0.45, 0.0), Vec3(2.0, -1.0, 0.0)}) {
        const double ref = reference_illuminance(e, p, kUp, 1e-10).illuminance_lx;
        EXPECT_NEAR(subdivided_illuminance(e, p, kUp, 1, TriangleRule::two_kernel), ref,
                    1e-7 * ref);
      }
    }
}
}  // namespace
}  // namespace luxgrid::nearfield
