#pragma once
// Keyframed FAP animation: keys at times in seconds, each setting any subset of the 70
// channels, baked to a dense FapAnimation at a frame rate.
//
// Per channel, only the keys that set it count. Before its first key a channel holds that
// key's value, after its last key the last value; a channel no key sets stays 0 (neutral).
// Each channel has its own shape at each of its keys (KeyShape; by default the key's
// `interpolation` with auto handles). Between keys k and k+1 of a channel, the interpolation
// of the channel's shape at key k applies:
//   Constant: v = v_k (a hold)
//   Linear:   v = v_k + s (v_{k+1} - v_k),  s = (t - t_k) / (t_{k+1} - t_k)   (the 2009 editor)
//   Smooth:   cubic Hermite with Steffen (1990) slopes
//               m_k = (sign d_{k-1} + sign d_k) min(|d_{k-1}|, |d_k|, |p_k| / 2),
//               d = secant slopes, p_k = (d_{k-1} h_k + d_k h_{k-1}) / (h_{k-1} + h_k),
//             one-sided at the ends; monotone on every interval, so it never overshoots the
//             values of the two keys around it.
//   Bezier:   the cubic Bézier from (t_k, v_k) through key k's out handle and key k+1's in
//             handle to (t_{k+1}, v_{k+1}), as a function of time (handles are limited to
//             the segment so that it is one). Auto handles lie a third of the segment
//             along the Smooth slope m_k, which gives exactly the Smooth curve.
// Tear channels (69, 70) are interpolated, then rounded to whole particle counts (>= 0).
// High-level channels (1, 2) hold each key's code until the next key (codes do not blend).
#include <lacrima/common/FapAnimation.h>

#include <optional>
#include <string_view>
#include <utility>
#include <vector>

namespace lacrima::inline common {

// The longest animation a bake produces: 2^20 frames (294 MB of frames; 13 hours at 22 fps,
// 17 minutes at the 1,000 fps a project may ask for). A bake allocates every frame up front,
// so a tiny file naming a key far away must be refused before that, not by the out-of-memory
// handler.
inline constexpr double kMaxBakedFrames = 1048576.0;
// The latest time a key may have, in seconds: a day. Handles reach a day along time too.
inline constexpr double kMaxKeyTime = 86400.0;

// Frames a bake at `fps` over [start, end] produces (as a double: any finite range and rate
// give a finite count, which may exceed every integer type).
double bakedFrameCount(double fps, double start, double end);
// Why a bake at `fps` over [start, end] is refused ("the animation runs from 0 s to 16000 s,
// 16000001 frames at 1000 fps; at most 1048576 frames can be played or exported (...)"), or
// empty when it fits within kMaxBakedFrames. The readers and the editor's export say this.
std::string bakeLengthProblem(double fps, double start, double end);

// How a channel's curve runs from one of its keys to the next.
enum class Interpolation { Linear, Smooth, Constant, Bezier };

std::string_view toString(Interpolation mode);  // "linear" / "smooth" / "constant" / "bezier"
std::optional<Interpolation> interpolationFromString(std::string_view text);

// The handles of a Bézier key. Auto handles are computed from the neighbouring keys (they make
// the Bézier curve equal to the Smooth one); dragging one makes it Aligned, as in Blender.
// Aligned handles stay on one line through the key; Free ones move independently.
enum class HandleType { Auto, Aligned, Free };

std::string_view toString(HandleType type);  // "auto" / "aligned" / "free"
std::optional<HandleType> handleTypeFromString(std::string_view text);

// A handle as an offset from its key: seconds along time, channel units along value.
struct Handle {
  double dt = 0.0;
  double dv = 0.0;
  bool operator==(const Handle&) const = default;
};

// How one channel's curve passes through one key: the interpolation of the channel's segment
// that starts at the key, and the key's handles (used by Bézier segments on either side).
// `in` points back in time (dt <= 0), `out` forward (dt >= 0). Auto handles store zeros.
struct KeyShape {
  Interpolation interpolation = Interpolation::Linear;
  HandleType handles = HandleType::Auto;
  Handle in, out;
  bool operator==(const KeyShape&) const = default;
};

struct Keyframe {
  double time = 0.0;                                    // seconds
  Interpolation interpolation = Interpolation::Linear;  // default of the channels' segments
  ChannelMask channels;                                 // channels this key sets
  FapValues values{};  // indexed by channelIndex(fap); meaningful where `channels` is set

  bool has(int fap) const { return channels.test(channelIndex(fap)); }
  float value(int fap) const { return values[channelIndex(fap)]; }
  void set(int fap, float v);
  void clear(int fap);  // also forgets the channel's shape

  // The channel's shape here: its own when it has one, else `interpolation` with auto handles.
  KeyShape shape(int fap) const;
  bool hasOwnShape(int fap) const;
  // Stores the channel's own shape; one equal to the key's default is not stored, so a key
  // written by an older Lacrima stays exactly what it was.
  void setShape(int fap, KeyShape shape);
  // Channels whose shape differs from the key's default (ascending channel index).
  const std::vector<std::pair<int, KeyShape>>& ownShapes() const { return ownShapes_; }
  // Sets the key's default and drops every channel's own interpolation (handles are kept).
  void setInterpolationOfAll(Interpolation mode);

  // Channel `fap` of `other` (value and shape) written here; removed here when `other` does
  // not set it. Moving or copying one channel's key between times goes through this.
  void takeChannel(const Keyframe& other, int fap);

  // Compares time, the channels set, their values and their effective shapes.
  bool operator==(const Keyframe& other) const;

 private:
  std::vector<std::pair<int, KeyShape>> ownShapes_;  // (channel index, shape), sorted
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
  // `animated` is the union of the keys' channels. More than kMaxBakedFrames frames throw
  // std::length_error before anything is allocated (readers refuse such files earlier, with
  // the file's name and place).
  FapAnimation bake(double fps) const;
  // The same over [start, end] (frames at start + i / fps), holding before and after the keys;
  // without keys, neutral frames.
  FapAnimation bake(double fps, double start, double end) const;

  // Every frame of `animation` becomes a key at frame / fps holding its animated channels.
  static KeyframeSequence fromAnimation(const FapAnimation& animation,
                                        Interpolation mode = Interpolation::Linear);

 private:
  std::vector<Keyframe> keys_;
};

}  // namespace lacrima::inline common
