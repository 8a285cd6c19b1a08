#include <lacrima/common/mood/MoodRandom.h>

#include <cmath>

namespace lacrima::inline common {
namespace {

double knotValue(std::uint64_t seed, std::int64_t knot) {
  return 2.0 * unitInterval(mixBits(seed ^ mixBits(static_cast<std::uint64_t>(knot)))) - 1.0;
}

}  // namespace

double smoothNoise(std::uint64_t seed, double x) {
  // Far beyond any take (3e7 years at one wiggle a second), and a knot index that still fits in
  // 64 bits: the cast below would be undefined past it.
  if (!(std::abs(x) < 1e15)) x = 0;
  const double base = std::floor(x);  // exact: floor rounds nothing
  const double u = x - base;
  const double fade = u * u * u * (u * (u * 6 - 15) + 10);
  const auto knot = static_cast<std::int64_t>(base);
  const double a = knotValue(seed, knot);
  const double b = knotValue(seed, knot + 1);
  return a + fade * (b - a);
}

}  // namespace lacrima::inline common
