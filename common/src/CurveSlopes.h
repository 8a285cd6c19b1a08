#pragma once
// Internal to lacrima_common: one channel's curve as knots, and the Steffen (1990) slopes that
// Smooth segments and auto Bézier handles share (Keyframes.cpp evaluates with them,
// CurveHandles.cpp shows the handles they imply). Not installed: the slopes are an
// implementation detail of KeyframeSequence.
#include <lacrima/common/Keyframes.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <span>

namespace lacrima::inline common::detail {

// One point of one channel's curve: a key that sets the channel.
struct Knot {
  double time;
  double value;
  KeyShape shape;  // shape.interpolation: of the segment that starts here
};

inline Knot knotOf(const Keyframe& key, int channel) {
  return {key.time, key.values[channel], key.shape(fapNumber(channel))};
}

inline int sign(double x) { return (x > 0.0) - (x < 0.0); }

inline double secant(const Knot& a, const Knot& b) {
  return (b.value - a.value) / (b.time - a.time);
}

// Steffen's slope at an interior knot. With same-signed secants it equals
// min(2|d0|, 2|d1|, |p|) in their direction; at a local extremum (signs differ or one is 0)
// it is 0.
inline double interiorSlope(const Knot& previous, const Knot& knot, const Knot& next) {
  const double h0 = knot.time - previous.time;
  const double h1 = next.time - knot.time;
  const double d0 = secant(previous, knot);
  const double d1 = secant(knot, next);
  const double p = (d0 * h1 + d1 * h0) / (h0 + h1);
  return (sign(d0) + sign(d1)) * std::min({std::abs(d0), std::abs(d1), std::abs(p) / 2.0});
}

// Steffen's one-sided slope at an end knot: the slope of the parabola through the end and
// its two neighbours, set to 0 if it opposes the adjacent secant and capped at twice it.
// With only two knots the curve is the straight line between them.
inline double endSlope(const Knot& end, const Knot& near, const Knot* far) {
  const double d1 = secant(end, near);
  if (!far) return d1;
  const double h1 = std::abs(near.time - end.time);
  const double h2 = std::abs(far->time - near.time);
  const double d2 = secant(near, *far);
  const double p = d1 * (1.0 + h1 / (h1 + h2)) - d2 * h1 / (h1 + h2);
  if (p * d1 <= 0.0) return 0.0;
  if (std::abs(p) > 2.0 * std::abs(d1)) return 2.0 * d1;
  return p;
}

// Slope at knots[i], looking at most one knot to either side (two at the ends), so a
// window of the knots around a segment gives the same slopes as the whole curve.
inline double slopeAt(std::span<const Knot> knots, std::size_t i) {
  const std::size_t n = knots.size();
  if (n < 2) return 0.0;
  const Knot* thirdFromStart = n > 2 ? &knots[2] : nullptr;
  const Knot* thirdFromEnd = n > 2 ? &knots[n - 3] : nullptr;
  if (i == 0) return endSlope(knots[0], knots[1], thirdFromStart);
  if (i == n - 1) return endSlope(knots[n - 1], knots[n - 2], thirdFromEnd);
  return interiorSlope(knots[i - 1], knots[i], knots[i + 1]);
}

// A Bézier key's handle on the side of a segment of duration h: its own, or, for auto handles,
// a third of the segment along the Smooth curve's slope, which makes the Bézier segment that
// very Hermite cubic (x(u) is then linear in u).
inline Handle outHandle(const Knot& knot, double slope, double h) {
  if (knot.shape.handles != HandleType::Auto) return knot.shape.out;
  return {h / 3.0, slope * h / 3.0};
}

inline Handle inHandle(const Knot& knot, double slope, double h) {
  if (knot.shape.handles != HandleType::Auto) return knot.shape.in;
  return {-h / 3.0, -slope * h / 3.0};
}

}  // namespace lacrima::inline common::detail
