#pragma once
// Keyframed FAP animation: keys at times in seconds, each setting any subset of the 70
// channels, baked to a dense FapAnimation at a frame rate.
//
// Per channel, only the keys that set it count. Before its first key a channel holds that
// key's value, after its last key the last value; a channel no key sets stays 0 (neutral).
// Between keys k and k+1 the mode of key k applies:
//   Linear: v = v_k + s (v_{k+1} - v_k),  s = (t - t_k) / (t_{k+1} - t_k)   (the 2009 editor)
//   Smooth: cubic Hermite with Steffen (1990) slopes
//             m_k = (sign d_{k-1} + sign d_k) min(|d_{k-1}|, |d_k|, |p_k| / 2),
//             d = secant slopes, p_k = (d_{k-1} h_k + d_k h_{k-1}) / (h_{k-1} + h_k),
//           one-sided at the ends; monotone on every interval, so it never overshoots the
//           values of the two keys around it.
// Tear channels (69, 70) are interpolated, then rounded to whole particle counts (>= 0).
// High-level channels (1, 2) hold each key's code until the next key (codes do not blend).
#include <lacrima/common/FapAnimation.h>

#include <optional>
#include <string_view>
#include <vector>

namespace lacrima::inline common {

enum class Interpolation { Linear, Smooth };

std::string_view toString(Interpolation mode);  // "linear" / "smooth"
std::optional<Interpolation> interpolationFromString(std::string_view text);

struct Keyframe {
  double time = 0.0;                                    // seconds
  Interpolation interpolation = Interpolation::Linear;  // of the segment that starts here
  ChannelMask channels;                                 // channels this key sets
  FapValues values{};  // indexed by channelIndex(fap); meaningful where `channels` is set

  bool has(int fap) const { return channels.test(channelIndex(fap)); }
  float value(int fap) const { return values[channelIndex(fap)]; }
  void set(int fap, float v);
  void clear(int fap);
  bool operator==(const Keyframe& other) const;  // compares only the channels set
};

// Keys sorted by time, at most one key per time.
class KeyframeSequence {
 public:
  KeyframeSequence() = default;
  explicit KeyframeSequence(std::vector<Keyframe> keys);  // sorts; later duplicates win

  const std::vector<Keyframe>& keys() const { return keys_; }
  bool empty() const { return keys_.empty(); }
  double startTime() const;  // 0 when empty
  double endTime() const;

  // Inserts, or merges the channels of `key` into an existing key at the same time
  // (|dt| < 1e-9 s). Returns the key's index.
  int insert(const Keyframe& key);
  void remove(int index);

  // All channels at time t seconds.
  FapValues evaluate(double seconds) const;

  // Dense frames from the first key to the last key inclusive at `fps`:
  // floor((end - start) * fps + 1e-6) + 1 frames; keys at 0 s and 1 s give 23 at 22 fps.
  // `animated` is the union of the keys' channels.
  FapAnimation bake(double fps) const;

  // Every frame of `animation` becomes a key at frame / fps holding its animated channels.
  static KeyframeSequence fromAnimation(const FapAnimation& animation,
                                        Interpolation mode = Interpolation::Linear);

 private:
  std::vector<Keyframe> keys_;
};

}  // namespace lacrima::inline common
