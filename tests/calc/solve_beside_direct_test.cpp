// The reflected light's solution is solved beside the direct light (calc/pipeline.cpp,
// run_scene): the results must be the same bits as on one thread, where the two run one after the
// other.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <string>
#include <vector>

#include <tbb/task_arena.h>

#include "calc/pipeline.h"
#include "project/project_file.h"

namespace luxgrid::calc {
namespace {

bool same_bits(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

TEST(RunScene, ReflectedLightSolvedBesideTheDirectLightGivesOneThreadsResultsBitForBit) {
  // The office: near-field pairs under its panels, reflected light refined to 0.25 m patches,
  // UGR at observers (which reads the reflected light).
  const Scene scene =
      project::load_project(std::string(LUXGRID_SOURCE_DIR) + "/examples/office/project.json")
          .scene;
  Results serial, parallel;
  tbb::task_arena one(1), two(2);
  one.execute([&] { serial = run_scene(scene); });
  two.execute([&] { parallel = run_scene(scene); });
  ASSERT_EQ(serial.surfaces.size(), scene.surfaces.size());
  ASSERT_EQ(parallel.surfaces.size(), serial.surfaces.size());
  double reflected_lx = 0.0;
  for (std::size_t s = 0; s < serial.surfaces.size(); ++s) {
    const SurfaceResult &a = serial.surfaces[s], &b = parallel.surfaces[s];
    SCOPED_TRACE(a.grid.name);
    EXPECT_TRUE(same_bits(a.E_direct, b.E_direct));
    EXPECT_TRUE(same_bits(a.E_indirect, b.E_indirect));
    EXPECT_TRUE(same_bits(a.E, b.E));
    ASSERT_EQ(a.UGR_max.has_value(), b.UGR_max.has_value());
    if (a.UGR_max) {
      EXPECT_EQ(std::memcmp(&*a.UGR_max, &*b.UGR_max, sizeof(double)), 0);
    }
    for (double e : a.E_indirect) reflected_lx = std::max(reflected_lx, e);
  }
  // The reflected light ran (the comparison is not of zeros), and the plan's estimates agree.
  EXPECT_GT(reflected_lx, 10.0);
  ASSERT_EQ(serial.plan.estimates.size(), parallel.plan.estimates.size());
  for (std::size_t s = 0; s < serial.plan.estimates.size(); ++s) {
    EXPECT_EQ(serial.plan.estimates[s].total(), parallel.plan.estimates[s].total());
    EXPECT_EQ(serial.plan.estimates[s].patch_size, parallel.plan.estimates[s].patch_size);
  }
}

}  // namespace
}  // namespace luxgrid::calc
