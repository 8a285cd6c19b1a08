#include <lacrima/common/CurveHandles.h>

#include "CurveSlopes.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

namespace lacrima::inline common {
namespace {

using namespace detail;

// The channel's knots around keys()[keyIndex]: up to two of its keys on either side, which is
// all slopeAt looks at (two at an end: see CurveSlopes.h). `at` is the key's place in it.
struct KnotWindow {
  std::array<Knot, 5> knots{};
  std::size_t count = 0;
  std::size_t at = 0;
  std::span<const Knot> span() const { return {knots.data(), count}; }
};

KnotWindow windowAround(const KeyframeSequence& sequence, int fap, int keyIndex) {
  const auto& keys = sequence.keys();
  if (!isValidFap(fap)) throw std::out_of_range("no channel " + std::to_string(fap));
  if (keyIndex < 0 || keyIndex >= static_cast<int>(keys.size()))
    throw std::out_of_range("no key " + std::to_string(keyIndex));
  const std::size_t key = static_cast<std::size_t>(keyIndex);
  if (!keys[key].has(fap)) {
    throw std::out_of_range("key " + std::to_string(keyIndex) + " does not set channel " +
                            std::to_string(fap));
  }
  const int channel = channelIndex(fap);
  std::array<Knot, 2> before{};
  std::size_t nBefore = 0;
  for (std::size_t k = key; k-- > 0 && nBefore < 2;)
    if (keys[k].has(fap)) before[nBefore++] = knotOf(keys[k], channel);
  KnotWindow window;
  for (std::size_t i = nBefore; i-- > 0;) window.knots[window.count++] = before[i];
  window.at = window.count;
  window.knots[window.count++] = knotOf(keys[key], channel);
  for (std::size_t k = key + 1, nAfter = 0; k < keys.size() && nAfter < 2; ++k) {
    if (!keys[k].has(fap)) continue;
    window.knots[window.count++] = knotOf(keys[k], channel);
    ++nAfter;
  }
  return window;
}

}  // namespace

double smoothSlope(const KeyframeSequence& keys, int fap, int keyIndex) {
  const KnotWindow window = windowAround(keys, fap, keyIndex);
  return slopeAt(window.span(), window.at);
}

EffectiveHandles effectiveHandles(const KeyframeSequence& keys, int fap, int keyIndex) {
  const KnotWindow window = windowAround(keys, fap, keyIndex);
  const Knot& knot = window.knots[window.at];
  const double slope = slopeAt(window.span(), window.at);
  EffectiveHandles handles;
  handles.hasIn = window.at > 0;
  handles.hasOut = window.at + 1 < window.count;
  // An end key has one segment; its auto handle on the other side mirrors that one, so that it
  // is drawn (and, once dragged, aligned) along the same tangent.
  const double hIn = handles.hasIn ? knot.time - window.knots[window.at - 1].time : 0.0;
  const double hOut = handles.hasOut ? window.knots[window.at + 1].time - knot.time : 0.0;
  handles.in = inHandle(knot, slope, handles.hasIn ? hIn : hOut);
  handles.out = outHandle(knot, slope, handles.hasOut ? hOut : hIn);
  return handles;
}

BezierTimeSolve solveBezierTime(const std::array<double, 4>& x, double t,
                                BezierSolverSettings settings) {
  const auto [x0, x1, x2, x3] = x;
  const auto cubic = [](double p0, double p1, double p2, double p3, double u) {
    const double r = 1.0 - u;
    return r * r * r * p0 + 3.0 * u * r * r * p1 + 3.0 * u * u * r * p2 + u * u * u * p3;
  };
  // x'(u) = 3 [(1-u)^2 (x1-x0) + 2u(1-u) (x2-x1) + u^2 (x3-x2)]
  const auto slope = [](double p0, double p1, double p2, double p3, double u) {
    const double r = 1.0 - u;
    return 3.0 * (r * r * (p1 - p0) + 2.0 * u * r * (p2 - p1) + u * u * (p3 - p2));
  };
  BezierTimeSolve solve;
  double lo = 0.0, hi = 1.0;
  solve.u = (t - x0) / (x3 - x0);
  for (; solve.steps < settings.maxSteps; ++solve.steps) {
    const double error = cubic(x0, x1, x2, x3, solve.u) - t;
    if (std::abs(error) <= settings.tolerance * std::max(1.0, std::abs(t))) break;
    (error > 0.0 ? hi : lo) = solve.u;
    const double dx = slope(x0, x1, x2, x3, solve.u);
    const double newton = dx > 0.0 ? solve.u - error / dx : -1.0;
    solve.u = (newton > lo && newton < hi) ? newton : 0.5 * (lo + hi);
  }
  return solve;
}

}  // namespace lacrima::inline common
