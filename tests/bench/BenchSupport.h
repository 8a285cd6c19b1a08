#pragma once
// Small helpers shared by lacrima-bench subcommands: wall-clock timing with medians, the
// process's peak resident memory, so each benchmark can put cost beside what it measures, and
// command-line number parsing.
#include <functional>
#include <string>

namespace lacrima::bench {

struct Timing {
  double medianMs = 0, minMs = 0, maxMs = 0;
  int runs = 0;
};

// Runs `body` `runs` times (after one warm-up run) and reports the spread in milliseconds.
Timing timeRuns(int runs, const std::function<void()>& body);

// Resident memory in bytes (VmRSS) and the peak since the last resetPeakMemory() (VmHWM).
// resetPeakMemory() uses /proc/self/clear_refs; returns false where the kernel refuses it,
// and the peak then covers the whole process lifetime.
long long residentBytes();
long long peakResidentBytes();
bool resetPeakMemory();

// A command-line whole number in [low, high]; false (out untouched) for anything else.
bool parseWholeNumber(const char* text, int low, int high, int& out);

}  // namespace lacrima::bench
