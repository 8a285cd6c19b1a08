#include <lacrima/editing/KeyChange.h>

#include <algorithm>
#include <cmath>
#include <optional>

namespace lacrima::editing {
namespace {

bool sameTime(double a, double b) { return std::abs(a - b) < kSameKeyTime; }

std::vector<double> sortedUnique(std::vector<double> times) {
  std::sort(times.begin(), times.end());
  std::vector<double> unique;
  unique.reserve(times.size());
  for (double t : times)
    if (unique.empty() || !sameTime(unique.back(), t)) unique.push_back(t);
  return unique;
}

bool containsTime(std::span<const double> sorted, double t) {
  const auto it = std::lower_bound(sorted.begin(), sorted.end(), t - kSameKeyTime);
  return it != sorted.end() && sameTime(*it, t);
}

// Above this many affected keys, rebuilding the vector once beats erasing one key at a time
// (each erase moves every later key).
constexpr std::size_t kRebuildThreshold = 16;

}  // namespace

int findKey(const KeyframeSequence& keys, double seconds) {
  const auto& all = keys.keys();
  const auto it = std::partition_point(
      all.begin(), all.end(), [&](const Keyframe& k) { return k.time <= seconds - kSameKeyTime; });
  if (it == all.end() || !sameTime(it->time, seconds)) return -1;
  return static_cast<int>(it - all.begin());
}

bool KeyChange::isNoOp() const { return before == after; }

KeyChange planReplace(const KeyframeSequence& keys, std::span<const double> removeTimes,
                      std::span<const Keyframe> written) {
  std::vector<double> all(removeTimes.begin(), removeTimes.end());
  for (const Keyframe& key : written) all.push_back(key.time);
  KeyChange change;
  change.times = sortedUnique(std::move(all));
  const std::vector<double> removed = sortedUnique({removeTimes.begin(), removeTimes.end()});

  for (double t : change.times) {
    const int index = findKey(keys, t);
    std::optional<Keyframe> result;
    if (index >= 0) {
      change.before.push_back(keys.keys()[index]);
      if (!containsTime(removed, t)) result = keys.keys()[index];
    }
    // The last written key at this time wins.
    for (auto it = written.rbegin(); it != written.rend(); ++it) {
      if (!sameTime(it->time, t)) continue;
      if (it->channels.any()) {
        result = *it;
        result->time = t;  // one time per affected slot, whatever rounding the caller had
      } else {
        result.reset();
      }
      break;
    }
    if (result) change.after.push_back(*result);
  }
  return change;
}

void applyKeys(KeyframeSequence& keys, std::span<const double> times,
               std::span<const Keyframe> side) {
  if (times.size() + side.size() <= kRebuildThreshold) {
    for (double t : times) {
      const int index = findKey(keys, t);
      if (index >= 0) keys.remove(index);
    }
    for (const Keyframe& key : side) keys.insert(key);
    return;
  }
  std::vector<Keyframe> kept;
  kept.reserve(keys.keys().size() + side.size());
  for (const Keyframe& key : keys.keys())
    if (!containsTime(times, key.time)) kept.push_back(key);
  kept.insert(kept.end(), side.begin(), side.end());
  keys = KeyframeSequence(std::move(kept));
}

}  // namespace lacrima::editing
