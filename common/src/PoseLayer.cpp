#include <lacrima/common/PoseLayer.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace lacrima::inline common {
namespace {

// Any ordinary low-level channel: no rounding, no code semantics.
constexpr int kCurveFap = 3;

}  // namespace

void PoseLayer::setPoseValue(int fap, float value) {
  if (!isValidFap(fap) || isHighLevelFap(fap)) {
    throw std::invalid_argument("a layer cannot hold channel " + std::to_string(fap));
  }
  channels_.set(channelIndex(fap));
  pose_[channelIndex(fap)] = value;
}

void PoseLayer::setIntensityKeys(std::vector<IntensityKey> keys) {
  std::vector<Keyframe> knots;
  knots.reserve(keys.size());
  for (const IntensityKey& key : keys) {
    Keyframe knot;
    knot.time = key.time;  // KeyframeSequence refuses a time that is not finite
    knot.interpolation = key.interpolation;
    knot.set(kCurveFap, static_cast<float>(key.value));
    knots.push_back(knot);
  }
  curve_ = KeyframeSequence(std::move(knots));
  keys_.clear();
  for (const Keyframe& knot : curve_.keys()) {
    keys_.push_back({knot.time, knot.value(kCurveFap), knot.interpolation});
  }
}

double PoseLayer::intensityAt(double seconds) const {
  if (keys_.empty()) return 0.0;
  return curve_.evaluate(seconds)[channelIndex(kCurveFap)];
}

bool PoseLayer::operator==(const PoseLayer& other) const {
  if (name != other.name || muted != other.muted || channels_ != other.channels_ ||
      keys_ != other.keys_) {
    return false;
  }
  for (int i = 0; i < kChannelCount; ++i) {
    if (channels_.test(i) && pose_[i] != other.pose_[i]) return false;
  }
  return true;
}

FapValues mixLayers(const FapValues& keyed, std::span<const PoseLayer> layers, double seconds) {
  FapValues mixed = keyed;
  ChannelMask touched;
  for (const PoseLayer& layer : layers) {
    if (layer.muted || !layer.hasIntensity()) continue;
    const double w = layer.intensityAt(seconds);
    if (w == 0.0) continue;
    touched |= layer.channels();
    for (int i = 0; i < kChannelCount; ++i) {
      if (layer.channels().test(i))
        mixed[i] += static_cast<float>(w * layer.poseValue(fapNumber(i)));
    }
  }
  for (int fap : {kTearLeftFap, kTearRightFap}) {
    const int i = channelIndex(fap);
    if (touched.test(i)) {
      mixed[i] = std::clamp(std::round(mixed[i]), 0.0f, static_cast<float>(kMaxTearParticles));
    }
  }
  return mixed;
}

}  // namespace lacrima::inline common
