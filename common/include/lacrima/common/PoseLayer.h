#pragma once
// A pose mixed onto the keyed animation with an intensity of its own over time: a preset
// applied as a layer. Layers add, the way shape-key values mix:
//
//   v_c(t) = k_c(t) + sum over unmuted layers l of  w_l(t) p_{l,c}
//
// k_c the keyed curve of channel c, p_{l,c} the layer's pose (0 for channels it does not set)
// and w_l its intensity curve. The intensity is a curve like any channel's (Keyframes.h: holds
// before its first key and after its last, each key's interpolation for the segment it
// starts); a layer without intensity keys adds nothing. Tear channels are summed, then rounded
// to whole particles >= 0; viseme and expression codes (FAP 1, 2) are never layered, since a
// sum of codes names an unrelated code.
#include <lacrima/common/FapChannels.h>
#include <lacrima/common/IntensityCurve.h>

#include <span>
#include <string>
#include <vector>

namespace lacrima::inline common {

class PoseLayer {
 public:
  std::string name;
  bool muted = false;

  // The pose at intensity 1. FAP 1 and 2 are refused (std::invalid_argument).
  const ChannelMask& channels() const { return channels_; }
  float poseValue(int fap) const { return pose_[channelIndex(fap)]; }
  void setPoseValue(int fap, float value);

  const std::vector<IntensityKey>& intensityKeys() const { return intensity_.keys(); }
  // Sorted by time; of keys closer than 1e-9 s the one given last wins. Times must be finite.
  void setIntensityKeys(std::vector<IntensityKey> keys) {
    intensity_ = IntensityCurve(std::move(keys));
  }
  double intensityAt(double seconds) const { return intensity_.at(seconds); }  // 0 without keys
  bool hasIntensity() const { return !intensity_.empty(); }
  double startTime() const { return intensity_.startTime(); }
  double endTime() const { return intensity_.endTime(); }

  bool operator==(const PoseLayer& other) const;

 private:
  ChannelMask channels_;
  FapValues pose_{};
  IntensityCurve intensity_;
};

// `keyed` (the keys' values at `seconds`) with the unmuted layers added.
FapValues mixLayers(const FapValues& keyed, std::span<const PoseLayer> layers, double seconds);

}  // namespace lacrima::inline common
