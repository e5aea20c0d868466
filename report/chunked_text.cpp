#include "report/chunked_text.h"

#include <algorithm>
#include <vector>

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

namespace luxgrid::report {

void write_chunked(std::size_t count, std::size_t chunk,
                   const std::function<void(std::size_t, std::size_t, std::string&)>& format,
                   const std::function<void(std::string_view)>& write) {
  chunk = std::max<std::size_t>(chunk, 1);
  const std::size_t chunks = (count + chunk - 1) / chunk;
  // Four ranges per worker in flight: enough for the work stealing to keep every worker busy
  // (the ranges of a CSV differ little in cost), few enough to keep a bounded amount of text.
  const std::size_t batch =
      4 * static_cast<std::size_t>(std::max(1, tbb::this_task_arena::max_concurrency()));
  std::vector<std::string> texts(std::min(batch, chunks));
  for (std::size_t first = 0; first < chunks; first += texts.size()) {
    const std::size_t n = std::min(texts.size(), chunks - first);
    tbb::parallel_for(std::size_t{0}, n, [&](std::size_t k) {
      const std::size_t begin = (first + k) * chunk;
      texts[k].clear();
      format(begin, std::min(count, begin + chunk), texts[k]);
    });
    for (std::size_t k = 0; k < n; ++k) write(texts[k]);
  }
}

}  // namespace luxgrid::report
