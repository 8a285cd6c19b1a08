#pragma once
// Internal to the graph editor's sources: the layout constants its view, input and painting
// share.
#include <lacrima/editing/KeyChange.h>

#include <cmath>

namespace lacrima::editor::detail {

constexpr double kRulerHeight = 22.0;  // the time ruler along the top
constexpr double kAxisWidth = 56.0;    // the value labels along the left
constexpr double kHitRadius = 7.0;     // how near a key or handle a click must be, px
constexpr double kKeyRadius = 4.5;
constexpr double kHandleRadius = 3.0;
constexpr double kMinScale = 0.5;        // px per second
constexpr double kMaxScale = 20000.0;    // a frame at 25 fps is 800 px
constexpr double kMinValueScale = 1e-6;  // px per value unit
constexpr double kMaxValueScale = 1e7;

inline bool sameTime(double a, double b) { return std::abs(a - b) < editing::kSameKeyTime; }

}  // namespace lacrima::editor::detail
