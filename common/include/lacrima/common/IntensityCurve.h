#pragma once
// One number over time keyed like any channel (Keyframes.h: holds before its first key and
// after its last, each key's interpolation for the segment it starts): a layer's intensity
// (PoseLayer.h) and a face colour (FaceColours.h).
#include <lacrima/common/Keyframes.h>

#include <vector>

namespace lacrima::inline common {

struct IntensityKey {
  double time = 0.0;  // seconds
  double value = 0.0;
  Interpolation interpolation = Interpolation::Smooth;
  bool operator==(const IntensityKey&) const = default;
};

class IntensityCurve {
 public:
  IntensityCurve() = default;
  // Sorted by time; of keys closer than 1e-9 s the one given last wins. Times must be finite.
  explicit IntensityCurve(std::vector<IntensityKey> keys);

  const std::vector<IntensityKey>& keys() const { return keys_; }
  bool empty() const { return keys_.empty(); }
  double at(double seconds) const;  // 0 without keys
  double startTime() const { return keys_.empty() ? 0.0 : keys_.front().time; }
  double endTime() const { return keys_.empty() ? 0.0 : keys_.back().time; }

  bool operator==(const IntensityCurve& other) const { return keys_ == other.keys_; }

 private:
  std::vector<IntensityKey> keys_;
  // The curve as one channel of a private sequence, so it is interpolated by the very code
  // that interpolates every channel.
  KeyframeSequence knots_;
};

}  // namespace lacrima::inline common
