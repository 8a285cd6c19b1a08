#pragma once
// Small helpers shared by lacrima-bench subcommands: wall-clock timing with medians, and the
// process's peak resident memory, so each benchmark can put cost beside what it measures.
#include <chrono>
#include <functional>
#include <string>
#include <vector>

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

// Tiny JSON object builder: enough for flat and nested figures, keys kept in insertion order.
class JsonObject {
public:
  JsonObject& add(const std::string& key, double value);
  JsonObject& add(const std::string& key, long long value);
  JsonObject& add(const std::string& key, int value) { return add(key, static_cast<long long>(value)); }
  JsonObject& add(const std::string& key, bool value);
  JsonObject& add(const std::string& key, const std::string& value);
  JsonObject& add(const std::string& key, const char* value) { return add(key, std::string(value)); }
  JsonObject& add(const std::string& key, const JsonObject& value);
  std::string toString() const;

private:
  std::vector<std::pair<std::string, std::string>> fields_;  // key, encoded value
};

}  // namespace lacrima::bench
