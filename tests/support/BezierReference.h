#pragma once
// An independent evaluation of a cubic Bézier segment as a function of time, for tests that
// check KeyframeSequence's Bézier maths. It shares nothing with the library's solver: the
// curve point is found by de Casteljau subdivision (repeated midpoint splitting), and the
// parameter u for a time t by bisection on x(u), which is monotone for the handles tested.
#include <array>
#include <cmath>

namespace lacrima::test {

struct Point2 {
  double x, y;
};

// De Casteljau: three rounds of linear interpolation between the control points.
inline Point2 deCasteljau(const std::array<Point2, 4>& p, double u) {
  const auto lerp = [u](Point2 a, Point2 b) {
    return Point2{a.x + u * (b.x - a.x), a.y + u * (b.y - a.y)};
  };
  const Point2 a = lerp(p[0], p[1]), b = lerp(p[1], p[2]), c = lerp(p[2], p[3]);
  const Point2 d = lerp(a, b), e = lerp(b, c);
  return lerp(d, e);
}

// y at x = t on the segment, x(u) assumed non-decreasing; 200 halvings reach any double.
inline double bezierValueAtTime(const std::array<Point2, 4>& p, double t) {
  double lo = 0.0, hi = 1.0;
  for (int i = 0; i < 200 && hi - lo > 0.0; ++i) {
    const double mid = 0.5 * (lo + hi);
    if (mid == lo || mid == hi) break;
    (deCasteljau(p, mid).x < t ? lo : hi) = mid;
  }
  return deCasteljau(p, 0.5 * (lo + hi)).y;
}

}  // namespace lacrima::test
