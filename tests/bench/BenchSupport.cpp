#include "BenchSupport.h"

#include <lacrima/common/Milliseconds.h>
#include <lacrima/rigging/DefaultHead.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace lacrima::bench {

Timing timeRuns(int runs, const std::function<void()>& body) {
  body();  // warm caches and allocators so the first run is not an outlier
  std::vector<double> ms;
  ms.reserve(static_cast<size_t>(runs));
  for (int i = 0; i < runs; ++i) {
    const auto start = SteadyClock::now();
    body();
    ms.push_back(millisecondsSince(start));
  }
  std::sort(ms.begin(), ms.end());
  Timing t;
  t.runs = runs;
  if (!ms.empty()) {
    t.medianMs = ms[ms.size() / 2];
    t.minMs = ms.front();
    t.maxMs = ms.back();
  }
  return t;
}

void writeTiming(JsonWriter& json, std::string_view name, const Timing& t,
                 std::optional<double> targetBelow) {
  json.key(name);
  json.beginObject();
  json.field("median", t.medianMs);
  json.field("min", t.minMs);
  json.field("max", t.maxMs);
  json.field("runs", t.runs);
  if (targetBelow) {
    json.field("target_below", *targetBelow);
    json.field("pass", t.medianMs < *targetBelow);
  }
  json.endObject();
}

static long long statusField(const char* field) {
  std::ifstream status("/proc/self/status");
  std::string line;
  const std::string prefix = std::string(field) + ":";
  while (std::getline(status, line)) {
    if (line.rfind(prefix, 0) == 0) {
      std::istringstream fields(line.substr(prefix.size()));
      long long kib = 0;
      fields >> kib;
      return kib * 1024;
    }
  }
  return 0;
}

long long residentBytes() { return statusField("VmRSS"); }
long long peakResidentBytes() { return statusField("VmHWM"); }

bool resetPeakMemory() {
  std::ofstream refs("/proc/self/clear_refs");
  refs << "5";
  refs.flush();
  return static_cast<bool>(refs);
}

std::optional<int> missingDisplayOrHead(const char* subcommand) {
  if (std::getenv("DISPLAY") == nullptr || !*std::getenv("DISPLAY")) {
    std::fprintf(stderr,
                 "lacrima-bench %s: needs an X display (OGRE renders through GLX); run it as\n"
                 "  xvfb-run -a -s \"-screen 0 1280x1024x24\" lacrima-bench %s\n",
                 subcommand, subcommand);
    return 1;
  }
  if (!rigging::defaultHeadAvailable()) {
    std::fprintf(stderr,
                 "lacrima-bench %s: skipped: the default head is not fetched "
                 "(packaging/fetch-default-head.sh)\n",
                 subcommand);
    return 0;
  }
  return std::nullopt;
}

}  // namespace lacrima::bench
