#pragma once
// How many worker threads the calculation may use: `--threads N`, else the environment variable
// LUXGRID_THREADS, else every core oneTBB sees. Applied for the whole process with
// tbb::global_control, so every parallel loop (direct light, indirect light, outputs) obeys it.
#include <memory>
#include <optional>

#include <tbb/global_control.h>

namespace luxgrid::cli {

// The most threads accepted (docs/reliability.md): far above any machine luxgrid runs on, low
// enough that a typo cannot ask the scheduler for millions of stacks.
inline constexpr int kMaxThreads = 1024;

// The count asked for (1..kMaxThreads), or nullopt when neither the option nor LUXGRID_THREADS
// is set. Throws InputError for a LUXGRID_THREADS that is not a whole number in that range.
std::optional<int> requested_threads(std::optional<int> option);

// Limits oneTBB to `threads` workers for as long as the returned object lives; null: no limit.
std::unique_ptr<tbb::global_control> limit_threads(std::optional<int> threads);

}  // namespace luxgrid::cli
