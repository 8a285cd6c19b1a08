#include <lacrima/editing/IntensityKeyEdits.h>
#include <lacrima/editing/KeyChange.h>

#include <algorithm>
#include <cmath>

namespace lacrima::editing {

std::vector<IntensityKey> withKeyAt(std::vector<IntensityKey> keys, double seconds, double value) {
  const auto at = std::find_if(keys.begin(), keys.end(), [&](const IntensityKey& key) {
    return std::abs(key.time - seconds) < kSameKeyTime;
  });
  if (at != keys.end())
    at->value = value;
  else
    keys.push_back({seconds, value, Interpolation::Smooth});
  return keys;
}

std::vector<IntensityKey> withoutKeyAt(std::vector<IntensityKey> keys, double seconds) {
  std::erase_if(
      keys, [&](const IntensityKey& key) { return std::abs(key.time - seconds) < kSameKeyTime; });
  return keys;
}

}  // namespace lacrima::editing
