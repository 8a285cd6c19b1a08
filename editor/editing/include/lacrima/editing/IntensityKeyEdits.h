#pragma once
// Keying one number over time at the playhead (a layer's intensity, a mood; IntensityCurve.h):
// the same rule for both, as channel keys have it (a key within kSameKeyTime is the key there).
#include <lacrima/common/IntensityCurve.h>

#include <vector>

namespace lacrima::editing {

// `keys` with `value` at `seconds`: the key there takes the value, else a new Smooth key.
std::vector<IntensityKey> withKeyAt(std::vector<IntensityKey> keys, double seconds, double value);
// `keys` without the key at `seconds` (unchanged when there is none).
std::vector<IntensityKey> withoutKeyAt(std::vector<IntensityKey> keys, double seconds);

}  // namespace lacrima::editing
