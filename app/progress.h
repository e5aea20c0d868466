#pragma once
// A progress line on stderr ("direct  42 %"), only when stderr is a terminal, at most every
// 0.2 s; safe to call from worker threads.
#include <string>

#include "calc/direct.h"

namespace luxgrid::app {

calc::Progress make_progress(const std::string& label);
void end_progress();

}  // namespace luxgrid::app
