// The hard cases: degenerate geometry, extreme scales, zero intensities.
// Invariant everywhere: finite, >= 0; plus the specific expectations named in each test.
#include <gtest/gtest.h>

#include <cmath>

#include "calc/nearfield/illuminance.h"
#include "calc/nearfield/models.h"
#include "calc/nearfield/receiver_fan.h"
#include "geometry/spherical.h"
#include "nearfield_test_support.h"

namespace luxgrid::nearfield {
namespace {

using testing::kUp;
using testing::paper_emitter;

const Model kAllModels[] = {Model::far_field(),    Model::paper_cubature(),
                            Model::subdivided(2),  Model::lambert_subdivided(1),
                            Model::adaptive(1e-3), Model::standard(),
                            Model::reference(1e-5)};  // the study's baselines: tests/study

void expect_sane_everywhere(const Emitter& e, const Vec3& p, const Vec3& n, const char* what) {
  for (const Model& m : kAllModels) {
    const double v = illuminance(e, p, n, m);
    EXPECT_TRUE(std::isfinite(v) && v >= 0.0) << what << " " << to_string(m) << " -> " << v;
  }
}

// Emitter facing down at z = 0 (plane z = 0), 1 x 1, centred at the origin.
Emitter ceiling_panel(photometry::DistributionPtr d = testing::isotropic()) {
  return paper_emitter(0.0, kPi, std::move(d));
}

TEST(HardCases, ReceiverInTheEmitterPlaneAndNearIt) {
  const Emitter e = ceiling_panel();
  for (double dz : {0.0, 1e-12, -1e-12, 1e-9, -1e-9, 1e-6, -1e-6, 1e-4, 1e-2, -1e-2})
    for (Vec3 n : {Vec3(1, 0, 0), Vec3(-1, 0, 0), Vec3(0, 0, 1), Vec3(0, 0, -1),
                   glm::normalize(Vec3(1, 0, -1))})
      for (Vec3 p : {Vec3(0.0), Vec3(0.7, 0.1, 0.0), Vec3(-2.0, 0.3, 0.0)})
        expect_sane_everywhere(e, p + Vec3(0, 0, dz), n, "near plane");
}

TEST(HardCases, WithoutTheHorizonShiftThePlaneGivesNaN) {
  // What the shift is for (receiver_fan.h): in the plane, L_e = I / (A cos) is infinite and the
  // solid angle 0, so the published cubature evaluates 0 * inf.
  const Emitter e = ceiling_panel();
  const Vec3 p(0.7, 0.1, 0.0), n(-1.0, 0.0, 0.0);  // beside the panel, looking at it
  EXPECT_TRUE(std::isnan(paper_cubature_raw(e, p, n, 0.0)));
  const double with_shift = paper_cubature_raw(e, p, n, horizon_shift_m(e));
  EXPECT_TRUE(std::isfinite(with_shift));
  EXPECT_GE(with_shift, 0.0);
}

TEST(HardCases, ShiftIsContinuousAcrossTheBand) {
  // Values 1e-12 .. 1e-2 m below an isotropic panel, beside it: continuous and monotone
  // (nearer the plane, more grazing light from the infinite-radiance edge-on emitter).
  const Emitter e = ceiling_panel();
  const Vec3 n(-1.0, 0.0, 0.0);
  double previous = illuminance(e, Vec3(0.7, 0.0, -1e-12), n, Model::standard());
  for (double dz : {1e-9, 1e-6, 1e-4, 1e-3, 1e-2}) {
    const double v = illuminance(e, Vec3(0.7, 0.0, -dz), n, Model::standard());
    EXPECT_LE(v, previous * (1 + 1e-9)) << dz;
    previous = v;
  }
}

TEST(HardCases, ClosestPointOnVertexAndEdgeAndReceiverOnEdgeOrCorner) {
  const Emitter e = paper_emitter(0.5, kPi, testing::batwing());
  // CP exactly on a vertex / edge (receiver below a corner / edge, and outside them).
  for (Vec3 p : {Vec3(0.5, 0.5, 0.0), Vec3(0.5, 0.0, 0.0), Vec3(1.0, 1.0, 0.0), Vec3(1.0, 0.0, 0.0),
                 Vec3(0.5, 0.5, 0.5), Vec3(0.5, 0.1, 0.5), Vec3(0.5, 0.5, 0.5 - 1e-13)})
    for (Vec3 n : {kUp, Vec3(-1, 0, 0), glm::normalize(Vec3(-1, -1, 1))})
      expect_sane_everywhere(e, p, n, "cp");
  const ReceiverFan vertex = build_fan(e, Vec3(1.0, 1.0, 0.0), kUp, horizon_shift_m(e));
  EXPECT_EQ(vertex.cp_case, ClosestPointCase::vertex);
  EXPECT_EQ(vertex.triangles, 2);  // apex at the vertex: no zero-area triangles
  const ReceiverFan edge = build_fan(e, Vec3(1.0, 0.2, 0.0), kUp, horizon_shift_m(e));
  EXPECT_EQ(edge.cp_case, ClosestPointCase::edge);
  EXPECT_EQ(edge.triangles, 3);
  const ReceiverFan inside = build_fan(e, Vec3(0.2, 0.2, 0.0), kUp, horizon_shift_m(e));
  EXPECT_EQ(inside.cp_case, ClosestPointCase::inside);
  EXPECT_EQ(inside.triangles, 4);
}

TEST(HardCases, EmitterBelowOrGrazingTheHorizon) {
  const Emitter e = paper_emitter(0.5, kPi, testing::isotropic());
  // Fully below the horizon: receiver normal points away.
  for (const Model& m : kAllModels)
    EXPECT_EQ(illuminance(e, Vec3(0.0), -kUp, m), 0.0) << to_string(m);
  // Partly below: receiver at the panel height looking up at a tilt; sliver clips.
  for (double tilt : {0.0, 1e-12, 1e-8, 1e-4, 0.1})
    for (Vec3 p : {Vec3(0.0, 0.0, 0.5), Vec3(0.0, 0.0, 0.5 - 1e-9), Vec3(2.0, 0.0, 0.5)}) {
      const Vec3 n = glm::normalize(Vec3(std::sin(tilt), 0.0, std::cos(tilt)));
      expect_sane_everywhere(e, p - Vec3(0, 0, 1e-7), n, "grazing");
      const OpeningPolygon clipped = clip_to_horizon(e, p, n);
      EXPECT_TRUE(clipped.n == 0 || clipped.n >= 3 || clipped.n < 3);  // any count is handled
    }
  // Horizon through a vertex only: a clip leaving fewer than three vertices (the corner once).
  const Vec3 corner(0.5, 0.5, 0.5);
  const Vec3 n = glm::normalize(Vec3(1.0, 1.0, 0.0));
  EXPECT_LT(clip_to_horizon(e, corner - Vec3(0, 0, 0.2), n).n, 3);
  expect_sane_everywhere(e, corner - Vec3(0, 0, 0.2), n, "vertex horizon");
}

TEST(HardCases, TriangleOverPiSteradian) {
  // A receiver just above the centroid of a large triangle sees nearly a hemisphere (2 pi sr):
  // Van Oosterom-Strackee's denominator is negative there, atan would return Omega - 2 pi < 0.
  const double eps = 0.01;
  const Vec3 a = glm::normalize(Vec3(1.0, 0.0, -eps)), b = glm::normalize(Vec3(-0.5, 0.866, -eps)),
             c = glm::normalize(Vec3(-0.5, -0.866, -eps));
  const double omega = geometry::triangle_solid_angle(a, b, c);
  EXPECT_GT(omega, kPi);
  EXPECT_LT(omega, 2 * kPi);
  const double den = 1.0 + glm::dot(a, b) + glm::dot(a, c) + glm::dot(b, c);
  EXPECT_LT(den, 0.0);  // the case that needs atan2
  // The fan's triangles share the same machinery: a receiver 1e-3 below a 100 x 1 panel.
  const Emitter e = paper_emitter(1e-3, kPi, testing::lambertian(1000.0), 100.0, 1.0);
  const Vec3 p(0.0, 0.4, 0.0);
  const double exact = lambert_uniform_illuminance(e, p, kUp, 1000.0 / e.area_m2);
  EXPECT_NEAR(illuminance(e, p, kUp, Model::standard()), exact, 1e-9 * exact);
  EXPECT_NEAR(illuminance(e, p, kUp, Model::paper_cubature()), exact, 0.35 * exact);
}

TEST(HardCases, PaperOrientationsSymmetry) {
  // Symmetric set-ups give symmetric values: mirror y -> -y for every orientation (tilt about y).
  for (double theta : {kPi / 2, 5 * kPi / 8, 3 * kPi / 4, 7 * kPi / 8, kPi}) {
    const Emitter e = paper_emitter(1.0, theta, testing::batwing());
    for (Vec3 p : {Vec3(0.3, 0.4, 0.0), Vec3(-1.0, 1.5, 0.0)})
      for (const Model& m : {Model::paper_cubature(), Model::standard(), Model::subdivided(2)}) {
        const double a = illuminance(e, p, kUp, m),
                     b = illuminance(e, Vec3(p.x, -p.y, p.z), kUp, m);
        EXPECT_NEAR(a, b, 1e-9 * std::max(a, 1e-300)) << theta << " " << to_string(m);
      }
  }
}

TEST(HardCases, TinyAndHugeScalesAgreeAfterScaling) {
  // E scales as 1/length^2 at fixed intensity: a 1 mm and a 1 km panel at the same relative
  // position must give 1e6 x and 1e-6 x the 1 m value.
  const Vec3 rel(0.3, -0.2, 0.0);
  for (const Model& m : {Model::paper_cubature(), Model::standard(), Model::far_field()}) {
    const double unit =
        illuminance(paper_emitter(0.4, 7 * kPi / 8, testing::batwing()), rel, kUp, m);
    for (double scale : {1e-3, 1e3}) {
      photometry::LuminousOpening o;
      o.shape = photometry::LuminousOpening::Shape::rectangle;
      o.length = o.width = scale;
      const Vec3 offset(1e3, -2e3, 5e2);  // far from the origin: relative coordinates matter
      const Emitter e = make_emitter(o, offset + Vec3(0, 0, 0.4 * scale),
                                     testing::rotation_about_y(kPi / 8), testing::batwing());
      const double v = illuminance(e, offset + rel * scale, kUp, m) * scale * scale;
      EXPECT_NEAR(v, unit, 1e-6 * unit) << to_string(m) << " " << scale;
    }
  }
}

TEST(HardCases, ZeroIntensityInSomeDirections) {
  const Emitter e = paper_emitter(0.3, kPi, std::make_shared<ZeroPatchDistribution>(1000.0));
  for (double x = -1.0; x <= 1.0; x += 0.25)
    for (double y = -1.0; y <= 1.0; y += 0.5)
      expect_sane_everywhere(e, Vec3(x, y, 0.0), kUp, "zero patch");
  // Only x >= 0 emits: a receiver far on the -x side gets nothing from any model.
  EXPECT_EQ(illuminance(e, Vec3(-3.0, 0.0, 0.0), kUp, Model::standard()), 0.0);
}

TEST(HardCases, ContinuityUnderSmallMoves) {
  // Two receivers 1e-6 m apart differ by at most 1e-4 relative (bound: |grad E| / E is below
  // ~ 1/h, 1e-6 / 0.1 = 1e-5, times a safety factor 10) for the deterministic models. Points
  // exactly in the emitter plane are excluded: there the one-sided opening's value jumps
  // between its front and its back (a physical discontinuity, see docs/nearfield.md).
  for (double theta : {kPi / 2, 3 * kPi / 4, kPi}) {
    const Emitter e = paper_emitter(0.1, theta, testing::batwing());
    for (Vec3 p : {Vec3(0.5, 0.5, 0.0), Vec3(-0.5, 0.2, 0.0), Vec3(-0.013, 0.007, 0.0),
                   Vec3(0.49, -0.5, 0.0)})
      for (const Model& m :
           {Model::paper_cubature(), Model::standard(), Model::lambert_subdivided(2)}) {
        const double a = illuminance(e, p, kUp, m),
                     b = illuminance(e, p + Vec3(1e-6, 1e-6, 0.0), kUp, m);
        EXPECT_NEAR(a, b, 1e-4 * std::max(a, b) + 1e-12) << theta << " " << to_string(m);
      }
  }
}

TEST(HardCases, FarAwayEveryModelTendsToTheFarField) {
  const Emitter e = paper_emitter(50.0, 3 * kPi / 4, testing::batwing());
  for (Vec3 p : {Vec3(10.0, 5.0, 0.0), Vec3(-20.0, 0.0, 0.0)}) {
    const double ff = far_field_illuminance(e, p, kUp);
    for (const Model& m : {Model::paper_cubature(), Model::standard(), Model::reference()})
      EXPECT_NEAR(illuminance(e, p, kUp, m), ff, 2e-3 * ff) << to_string(m);
  }
}

TEST(HardCases, StandardMatchesLambertOnCosineEmitterEverywhere) {
  // Per-rung tolerance on cosine distributions: standard is exact (1e-9), the paper's rule is
  // off by up to 28 % at h = 0.1 (docs/nearfield.md), k = 2 subdivision by up to 25 % (measured 20
  // %).
  for (double h : {0.1, 1.0})
    for (double theta : {5 * kPi / 8, kPi}) {
      const Emitter e = paper_emitter(h, theta, testing::lambertian(500.0));
      for (double x = -2.0; x <= 2.0; x += 0.5) {
        const Vec3 p(x, 0.1, 0.0);
        const double exact = lambert_uniform_illuminance(e, p, kUp, 500.0);
        EXPECT_NEAR(illuminance(e, p, kUp, Model::standard()), exact, 1e-9 * exact + 1e-12);
        EXPECT_NEAR(illuminance(e, p, kUp, Model::paper_cubature()), exact, 0.30 * exact + 1e-12);
        EXPECT_NEAR(illuminance(e, p, kUp, Model::subdivided(2)), exact, 0.25 * exact + 1e-12);
      }
    }
}

}  // namespace
}  // namespace luxgrid::nearfield
