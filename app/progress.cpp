#include "app/progress.h"

#include <unistd.h>
#include <chrono>
#include <cstdio>
#include <memory>
#include <mutex>

namespace luxgrid::app {

namespace {
bool& shown() {
  static bool value = false;
  return value;
}
}  // namespace

calc::Progress make_progress(const std::string& label) {
  if (!isatty(STDERR_FILENO)) return {};
  struct State {
    std::mutex mutex;
    std::chrono::steady_clock::time_point last{};
  };
  auto state = std::make_shared<State>();
  return [state, label](double f) {
    std::lock_guard lock(state->mutex);
    const auto now = std::chrono::steady_clock::now();
    if (now - state->last < std::chrono::milliseconds(200) && f < 1.0) return;
    state->last = now;
    std::fprintf(stderr, "\r%s %3d %%", label.c_str(), static_cast<int>(f * 100.0));
    std::fflush(stderr);
    shown() = true;
  };
}

void end_progress() {
  if (shown()) std::fprintf(stderr, "\r\033[K");
  shown() = false;
}

}  // namespace luxgrid::app
