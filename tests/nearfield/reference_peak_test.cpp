// The reference integrator must see a narrow beam that lands exactly on a vertex of its first
// triangles: the fan's apex is the receiver's foot point, which is where a downlight's beam
// lands on a receiver right under the opening. Checked against a brute-force area integral.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "calc/nearfield/illuminance.h"
#include "calc/nearfield/models.h"
#include "nearfield_test_support.h"
#include "photometry/photometry.h"

namespace luxgrid::nearfield {
namespace {

// Midpoint rule over the rectangle opening (vertices 0, 1, 3 span it) of the area form
// E = (1/A) int I(-w) cos_r / d^2 dA, n x n cells.
double brute_force(const Emitter& e, const Vec3& p, const Vec3& normal, int n) {
  const Vec3 v0 = e.vertices[0], ds = e.vertices[1] - v0, dt = e.vertices[3] - v0;
  double sum = 0.0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const Vec3 r = v0 + ((i + 0.5) / n) * ds + ((j + 0.5) / n) * dt - p;
      const double d2 = glm::dot(r, r);
      const Vec3 w = r / std::sqrt(d2);
      const double cos_r = glm::dot(w, normal);
      if (cos_r > 0.0) sum += e.intensity_towards(-w) * cos_r / d2;
    }
  return sum / (double(n) * double(n));
}

TEST(ReferencePeak, NarrowSpotUnderTheOpening) {
  // ERCO Quintessence spot (I drops to half by 5 degrees): 0.1 m above the ground, its beam
  // covers a disc of about 9 mm radius around each receiver's foot point. Before the peak guard
  // the reference returned 310.2 lx here (its interior nodes never saw the beam), with an error
  // estimate of 1e-6.
  const auto ph = photometry::load_photometry_file(
      std::string(LUXGRID_SOURCE_DIR) + "/tests/data/photometry/ies/erco_qrcbc35_lm86_spot.ies");
  const Emitter e = testing::paper_emitter(0.1, kPi, ph.distribution);
  for (const Vec3 p : {Vec3(-0.31, -0.31, 0.0), Vec3(0.1, 0.05, 0.0), Vec3(-0.45, 0.2, 0.0)}) {
    // 1500 x 1500 cells of 0.67 mm resolve the 9 mm beam: the midpoint rule is then good to far
    // below 1e-4 here (2500 and 3000 cells per side agree with 1500 to 5 digits).
    const double truth = brute_force(e, p, testing::kUp, 1500);
    const ReferenceResult r = reference_illuminance(e, p, testing::kUp, 1e-6);
    // 1e-3: the brute force's own error is far below it; the reference asked for 1e-6.
    EXPECT_NEAR(r.illuminance_lx, truth, 1e-3 * truth) << "at " << p.x << ", " << p.y;
    EXPECT_NEAR(illuminance(e, p, testing::kUp, Model::standard()), truth, 1e-2 * truth)
        << "standard within its 1 % at " << p.x << ", " << p.y;
  }
}

}  // namespace
}  // namespace luxgrid::nearfield
