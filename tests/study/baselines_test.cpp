// The accuracy study's baselines (study/baselines.h): finite and >= 0 where the near-field
// models meet their hard cases, and equal to the far field far away, where every model of an
// emitter must agree with the point source it looks like.
#include <gtest/gtest.h>

#include <cmath>

#include "calc/nearfield/models.h"
#include "study/accuracy_study.h"
#include "tests/nearfield/nearfield_test_support.h"

namespace luxgrid::study {
namespace {

using nearfield::Emitter;
using nearfield::testing::kUp;
using nearfield::testing::paper_emitter;

const AccuracyModel kBaselines[] = {AccuracyModel::structured_sampling(),
                                    AccuracyModel::most_representative_point(),
                                    AccuracyModel::monte_carlo(16)};

TEST(Baselines, FiniteAndNonNegativeInAndNearTheEmitterPlaneAndAtItsCorners) {
  // The configurations where the fan degenerates: the receiver in the emitter's plane (the
  // horizon shift), on its edge or corner, grazing normals, behind the opening.
  const Emitter plane = paper_emitter(0.0, kPi, nearfield::testing::isotropic());
  const Emitter raised = paper_emitter(0.5, kPi, nearfield::testing::batwing());
  for (const AccuracyModel& m : kBaselines) {
    for (double dz : {0.0, 1e-12, -1e-9, 1e-6, -1e-2})
      for (Vec3 n : {Vec3(1, 0, 0), Vec3(0, 0, 1), Vec3(0, 0, -1), glm::normalize(Vec3(1, 0, -1))})
        for (Vec3 p : {Vec3(0.0), Vec3(0.7, 0.1, 0.0), Vec3(0.5, 0.5, 0.0), Vec3(-2.0, 0.3, 0.0)}) {
          const double v = evaluate(m, plane, p + Vec3(0, 0, dz), n, 1);
          EXPECT_TRUE(std::isfinite(v) && v >= 0.0) << m.name << " at dz " << dz << " -> " << v;
        }
    for (Vec3 p : {Vec3(0.5, 0.5, 0.0), Vec3(1.0, 0.0, 0.0), Vec3(0.5, 0.1, 0.5)}) {
      const double v = evaluate(m, raised, p, kUp, 1);
      EXPECT_TRUE(std::isfinite(v) && v >= 0.0) << m.name << " -> " << v;
    }
    // Above the emitter, facing up: the opening lies below the receiver's horizon.
    EXPECT_EQ(evaluate(m, raised, Vec3(0.0, 0.0, 2.0), kUp, 1), 0.0) << m.name;
  }
}

TEST(Baselines, AgreeWithTheFarFieldFarAway) {
  // 20 m away the 1 x 1 opening subtends 0.05 rad: every sampling of it sees nearly one
  // direction. Structured sampling and Monte Carlo average L over the opening: within 0.2 %.
  // MRP samples L at one point off the centroid: 1.3 % off at 20 m for this profile, so 2 %.
  const Emitter e = paper_emitter(20.0, kPi, nearfield::testing::batwing());
  const Vec3 p(1.0, 2.0, 0.0);
  const double ff = nearfield::far_field_illuminance(e, p, kUp);
  for (const AccuracyModel& m :
       {AccuracyModel::structured_sampling(), AccuracyModel::monte_carlo(256)})
    EXPECT_NEAR(evaluate(m, e, p, kUp, 1), ff, 2e-3 * ff) << m.name;
  EXPECT_NEAR(evaluate(AccuracyModel::most_representative_point(), e, p, kUp, 1), ff, 2e-2 * ff);
}

TEST(Baselines, MonteCarloIsReproducibleForASeedAndVariesWithIt) {
  const Emitter e = paper_emitter(0.5, kPi, nearfield::testing::batwing());
  const AccuracyModel mc = AccuracyModel::monte_carlo(64);
  const Vec3 p(0.3, 0.2, 0.0);
  EXPECT_EQ(evaluate(mc, e, p, kUp, 7), evaluate(mc, e, p, kUp, 7));
  EXPECT_NE(evaluate(mc, e, p, kUp, 7), evaluate(mc, e, p, kUp, 8));
}

}  // namespace
}  // namespace luxgrid::study
