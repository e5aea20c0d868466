// The table's far-field bound (calc/nearfield/table_far_bound.h) bounds the map's cells in
// parallel: the map it returns must be the same bits as the one the cells give taken one after
// another, in order, on one thread.
#include <gtest/gtest.h>

#include <cstring>
#include <random>
#include <string>
#include <vector>

#include <tbb/task_arena.h>
#include <glm/gtc/matrix_transform.hpp>

#include "calc/nearfield/emitter.h"
#include "calc/nearfield/far_field_bound.h"
#include "calc/nearfield/table_far_bound.h"
#include "photometry/photometry.h"

namespace luxgrid::nearfield {
namespace {

std::vector<float> bound_in_arena(int threads, const Emitter& e, double budget,
                                  const std::vector<float>& wanted) {
  tbb::task_arena arena(threads);
  std::vector<float> out;
  arena.execute([&] { out = table_far_bound_over_D(e, budget, wanted); });
  return out;
}

TEST(TableFarBound, CellsInParallelGiveTheSerialMapBitForBit) {
  // Tables of every kind the bound reads: coarse and fine C planes, quadrant and full symmetry,
  // a type B flood (its grid is not the luminaire's frame), a spot, a road light.
  const char* files[] = {
      "ldt/zumtobel_mirel_isym4.ldt",
      "ldt/sample06_spot_coarse.ldt",
      "ldt/ledvance_flmax_asym_isym0.ldt",
      "ies/flood_typeb_lm02_45x45.ies",
      "ies/rab_roadway_quadrant_lm02.ies",
      "ies/erco_qrcbc35_lm86_spot.ies",
      "ies/itl_indoor_quadrant_lm02_120lamps.ies",
  };
  // Placed and turned arbitrarily (the bound lives in the luminaire frame).
  const glm::dmat3 rot(glm::rotate(glm::dmat4(1.0), 0.7, glm::normalize(Vec3(1.0, 2.0, 3.0))));
  std::mt19937_64 rng(37);
  std::bernoulli_distribution half(0.5);
  int bounded = 0;
  for (const char* rel : files) {
    SCOPED_TRACE(rel);
    const photometry::Photometry ph = photometry::load_photometry_file(
        std::string(LUXGRID_SOURCE_DIR) + "/tests/data/photometry/" + rel);
    const Emitter e = make_emitter(ph.opening, Vec3(1.0, -2.0, 3.0), rot, ph.distribution);
    // Every sample wanted, and a random half (cells left out between cells bounded).
    std::vector<float> every(kGammaSamples * kCSamples, 1.0f), some(every.size(), 0.0f);
    for (float& w : some) w = half(rng) ? 1.0f : 0.0f;
    for (const std::vector<float>* wanted : {&every, &some}) {
      const std::vector<float> serial = bound_in_arena(1, e, 0.005, *wanted);
      const std::vector<float> parallel = bound_in_arena(2, e, 0.005, *wanted);
      if (serial.empty()) continue;  // no bilinear table behind it: the bound does not apply
      ++bounded;
      ASSERT_EQ(parallel.size(), serial.size());
      EXPECT_EQ(std::memcmp(parallel.data(), serial.data(), serial.size() * sizeof(float)), 0);
      // Not a trivial map: some wanted sample needs more than the ladder's start.
      bool beyond_start = false;
      for (std::size_t i = 0; i < serial.size(); ++i)
        beyond_start = beyond_start || ((*wanted)[i] > 0.0f && serial[i] > kLadderStart);
      EXPECT_TRUE(beyond_start);
    }
  }
  // At least five of the files have a bilinear table behind them (two demands each).
  EXPECT_GE(bounded, 10);
}

}  // namespace
}  // namespace luxgrid::nearfield
