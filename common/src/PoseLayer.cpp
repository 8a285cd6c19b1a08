#include <lacrima/common/PoseLayer.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace lacrima::inline common {

void PoseLayer::setPoseValue(int fap, float value) {
  if (!isValidFap(fap) || isHighLevelFap(fap)) {
    throw std::invalid_argument("a layer cannot hold channel " + std::to_string(fap));
  }
  channels_.set(channelIndex(fap));
  pose_[channelIndex(fap)] = value;
}

bool PoseLayer::operator==(const PoseLayer& other) const {
  if (name != other.name || muted != other.muted || channels_ != other.channels_ ||
      intensity_ != other.intensity_) {
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
