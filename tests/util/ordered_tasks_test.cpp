// util/ordered_tasks.h: every task runs exactly once, on as many threads as the process allows,
// and on one thread in the list's order.
#include <gtest/gtest.h>

#include <atomic>
#include <cstddef>
#include <vector>

#include <tbb/global_control.h>

#include "util/ordered_tasks.h"

namespace luxgrid {
namespace {

TEST(OrderedTasks, EveryTaskRunsExactlyOnce) {
  for (const std::size_t count : {std::size_t{0}, std::size_t{1}, std::size_t{1000}}) {
    std::vector<std::atomic<int>> calls(count);
    run_in_list_order(count, [&](std::size_t k) { calls[k].fetch_add(1); });
    for (std::size_t k = 0; k < count; ++k) EXPECT_EQ(calls[k].load(), 1) << k << " of " << count;
  }
}

TEST(OrderedTasks, OneThreadTakesTheTasksInTheListsOrder) {
  // `luxgrid --threads 1` (tbb::global_control): one worker, so the order is the list's.
  const tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
  std::vector<std::size_t> order;
  run_in_list_order(100, [&](std::size_t k) { order.push_back(k); });
  ASSERT_EQ(order.size(), 100u);
  for (std::size_t k = 0; k < order.size(); ++k) EXPECT_EQ(order[k], k);
}

}  // namespace
}  // namespace luxgrid
