#pragma once
// Small helpers shared by lacrima-bench subcommands: wall-clock timing with medians, the
// process's peak resident memory, so each benchmark can put cost beside what it measures.
#include <lacrima/common/JsonWriter.h>

#include <functional>
#include <optional>
#include <string_view>

namespace lacrima::bench {

struct Timing {
  double medianMs = 0, minMs = 0, maxMs = 0;
  int runs = 0;
};

// Runs `body` `runs` times (after one warm-up run) and reports the spread in milliseconds.
Timing timeRuns(int runs, const std::function<void()>& body);

// `name`: {median, min, max, runs}, with target_below and pass when there is a target.
void writeTiming(JsonWriter& json, std::string_view name, const Timing& t,
                 std::optional<double> targetBelow = std::nullopt);

// Resident memory in bytes (VmRSS) and the peak since the last resetPeakMemory() (VmHWM).
// resetPeakMemory() uses /proc/self/clear_refs; returns false where the kernel refuses it,
// and the peak then covers the whole process lifetime.
long long residentBytes();
long long peakResidentBytes();
bool resetPeakMemory();

// For subcommands that render the default head with OGRE: the exit status to return now when
// there is no X display (1, with the xvfb-run advice) or no default head (0, skipped), else
// nullopt.
std::optional<int> missingDisplayOrHead(const char* subcommand);

}  // namespace lacrima::bench
