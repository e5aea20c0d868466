#include "cli/threads.h"

#include <cstdlib>
#include <string>

#include "util/error.h"

namespace luxgrid::cli {

std::optional<int> requested_threads(std::optional<int> option) {
  if (option) return option;
  const char* env = std::getenv("LUXGRID_THREADS");
  if (!env || !*env) return std::nullopt;
  char* end = nullptr;
  const long v = std::strtol(env, &end, 10);
  if (end == env || *end != '\0' || v < 1 || v > kMaxThreads) {
    throw InputError("LUXGRID_THREADS: expected a whole number from 1 to " +
                     std::to_string(kMaxThreads) + ", got '" + env + "'");
  }
  return static_cast<int>(v);
}

std::unique_ptr<tbb::global_control> limit_threads(std::optional<int> threads) {
  if (!threads) return nullptr;
  return std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                               static_cast<std::size_t>(*threads));
}

}  // namespace luxgrid::cli
