#include <lacrima/common/IntensityCurve.h>

namespace lacrima::inline common {
namespace {

// Any ordinary low-level channel: no rounding, no code semantics.
constexpr int kCurveFap = 3;

}  // namespace

IntensityCurve::IntensityCurve(std::vector<IntensityKey> keys) {
  std::vector<Keyframe> knots;
  knots.reserve(keys.size());
  for (const IntensityKey& key : keys) {
    Keyframe knot;
    knot.time = key.time;  // KeyframeSequence refuses a time that is not finite
    knot.interpolation = key.interpolation;
    knot.set(kCurveFap, static_cast<float>(key.value));
    knots.push_back(knot);
  }
  knots_ = KeyframeSequence(std::move(knots));
  for (const Keyframe& knot : knots_.keys())
    keys_.push_back({knot.time, knot.value(kCurveFap), knot.interpolation});
}

double IntensityCurve::at(double seconds) const {
  if (keys_.empty()) return 0.0;
  return knots_.evaluate(seconds)[channelIndex(kCurveFap)];
}

}  // namespace lacrima::inline common
