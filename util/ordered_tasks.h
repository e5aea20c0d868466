#pragma once
// Tasks of very different costs run in parallel, taken in the list's order: each of oneTBB's
// workers (as many as the process allows: `luxgrid --threads`, tbb::global_control) takes the
// next task not yet taken until none is left. A parallel loop over the list would split it into
// ranges, and a range of costly tasks could be left to one thread at the end; taken in order,
// the costly tasks a caller puts first are started first and the cheap ones fill the gaps.
// Users: the far-field bound's directions (calc/nearfield/far_field_bound.cpp), whose costs
// differ by orders of magnitude, and the output files (report/write_outputs.cpp).
#include <algorithm>
#include <atomic>
#include <cstddef>

#include <tbb/global_control.h>
#include <tbb/parallel_for.h>
#include <tbb/partitioner.h>
#include <tbb/task_arena.h>

namespace luxgrid {

// Calls task(k) once for every k in [0, count), in parallel, each thread taking the next k not
// yet taken; returns when every call has returned. The calling thread is one of the workers.
template <class Task>
void run_in_list_order(std::size_t count, Task&& task) {
  if (count == 0) return;
  const std::size_t allowed = std::max<std::size_t>(
      1, std::min<std::size_t>(
             static_cast<std::size_t>(tbb::this_task_arena::max_concurrency()),
             tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism)));
  const int workers = static_cast<int>(std::min(allowed, count));
  std::atomic<std::size_t> next{0};
  tbb::parallel_for(
      0, workers,
      [&](int) {
        for (std::size_t k; (k = next.fetch_add(1, std::memory_order_relaxed)) < count;) task(k);
      },
      tbb::simple_partitioner());
}

}  // namespace luxgrid
