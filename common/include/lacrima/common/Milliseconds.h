#pragma once
// Stage timings in milliseconds, as the player, the editor and the benchmarks report them. The
// steady clock, since the wall clock may jump while a stage runs.
#include <chrono>

namespace lacrima::inline common {

using SteadyClock = std::chrono::steady_clock;

inline double millisecondsSince(SteadyClock::time_point start) {
  return std::chrono::duration<double, std::milli>(SteadyClock::now() - start).count();
}

}  // namespace lacrima::inline common
