#pragma once
// Keys written the short way in tests: keyAt(1.0, {{3, 120}, {69, 40}}, Interpolation::Smooth).
#include <lacrima/common/Keyframes.h>

#include <initializer_list>
#include <utility>

namespace lacrima::test {

inline Keyframe keyAt(double time, std::initializer_list<std::pair<int, float>> values,
                      Interpolation mode = Interpolation::Linear) {
  Keyframe key;
  key.time = time;
  key.interpolation = mode;
  for (const auto& [fap, value] : values) key.set(fap, value);
  return key;
}

}  // namespace lacrima::test
