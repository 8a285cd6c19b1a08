#include <lacrima/common/Keyframes.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <span>
#include <stdexcept>
#include <string>

namespace lacrima::inline common {
namespace {

// Keys closer than this are the same key: far below a frame at any sane rate, far above
// the rounding error of times computed as frame / fps.
constexpr double kSameTime = 1e-9;

// A bake allocates frames * 280 bytes up front; 2^24 frames (4.7 GB, 8.8 days at 22 fps)
// is beyond any real use, and refusing it beats being killed by the out-of-memory handler.
constexpr double kMaxBakedFrames = 16777216.0;

// One point of one channel's curve: a key that sets the channel.
struct Knot {
  double time;
  double value;
  Interpolation mode;  // of the segment that starts here
};

void requireValidFps(double fps, const char* caller) {
  if (!std::isfinite(fps) || fps <= 0.0) {
    throw std::invalid_argument(std::string(caller) + ": fps must be finite and > 0, got " +
                                std::to_string(fps));
  }
}

void requireFiniteTime(double seconds) {
  // A NaN time would break the ordering every other operation relies on.
  if (!std::isfinite(seconds)) {
    throw std::invalid_argument("keyframe time must be finite, got " + std::to_string(seconds));
  }
}

int sign(double x) { return (x > 0.0) - (x < 0.0); }

double secant(const Knot& a, const Knot& b) { return (b.value - a.value) / (b.time - a.time); }

// Steffen's slope at an interior knot. With same-signed secants it equals
// min(2|d0|, 2|d1|, |p|) in their direction; at a local extremum (signs differ or one is 0)
// it is 0.
double interiorSlope(const Knot& previous, const Knot& knot, const Knot& next) {
  const double h0 = knot.time - previous.time;
  const double h1 = next.time - knot.time;
  const double d0 = secant(previous, knot);
  const double d1 = secant(knot, next);
  const double p = (d0 * h1 + d1 * h0) / (h0 + h1);
  return (sign(d0) + sign(d1)) * std::min({std::abs(d0), std::abs(d1), std::abs(p) / 2.0});
}

// Steffen's one-sided slope at an end knot: the slope of the parabola through the end and
// its two neighbours, set to 0 if it opposes the adjacent secant and capped at twice it.
// With only two knots the curve is the straight line between them.
double endSlope(const Knot& end, const Knot& near, const Knot* far) {
  const double d1 = secant(end, near);
  if (!far) return d1;
  const double h1 = std::abs(near.time - end.time);
  const double h2 = std::abs(far->time - near.time);
  const double d2 = secant(near, *far);
  const double p = d1 * (1.0 + h1 / (h1 + h2)) - d2 * h1 / (h1 + h2);
  if (p * d1 <= 0.0) return 0.0;
  if (std::abs(p) > 2.0 * std::abs(d1)) return 2.0 * d1;
  return p;
}

// Slope at knots[i], looking at most one knot to either side (two at the ends), so a
// window of the knots around a segment gives the same slopes as the whole curve.
double slopeAt(std::span<const Knot> knots, std::size_t i) {
  const std::size_t n = knots.size();
  if (n < 2) return 0.0;
  const Knot* thirdFromStart = n > 2 ? &knots[2] : nullptr;
  const Knot* thirdFromEnd = n > 2 ? &knots[n - 3] : nullptr;
  if (i == 0) return endSlope(knots[0], knots[1], thirdFromStart);
  if (i == n - 1) return endSlope(knots[n - 1], knots[n - 2], thirdFromEnd);
  return interiorSlope(knots[i - 1], knots[i], knots[i + 1]);
}

// Cubic Hermite between a and b. Why it cannot overshoot: with d the secant and
// alpha = ma / d, beta = mb / d, Steffen's slopes give alpha, beta in [0, 2] (both slopes
// are 0 when d is 0), and Fritsch & Carlson (1980) show the cubic is monotone whenever
// alpha, beta are in [0, 3]. A monotone curve stays between its end values; the final
// clamp only absorbs floating-point rounding.
double hermite(const Knot& a, const Knot& b, double ma, double mb, double t) {
  const double h = b.time - a.time;
  const double s = (t - a.time) / h;
  const double r = 1.0 - s;
  const double rise = (b.value - a.value) * s * s * (3.0 - 2.0 * s);
  const double bend = h * (ma * s * r * r - mb * s * s * r);
  return std::clamp(a.value + rise + bend, std::min(a.value, b.value), std::max(a.value, b.value));
}

// Value of a channel's curve at t, where `reached` knots lie at or before t.
double curveValue(int fap, std::span<const Knot> knots, std::size_t reached, double t) {
  if (reached == 0) return knots.front().value;
  const Knot& a = knots[reached - 1];
  // High-level FAPs are viseme/expression codes: halfway between viseme 3 and viseme 7 is
  // not viseme 5, so a code holds until the next key.
  if (reached == knots.size() || isHighLevelFap(fap)) return a.value;
  const Knot& b = knots[reached];
  if (a.mode == Interpolation::Linear) {
    return a.value + (t - a.time) / (b.time - a.time) * (b.value - a.value);
  }
  return hermite(a, b, slopeAt(knots, reached - 1), slopeAt(knots, reached), t);
}

float channelValue(int fap, double value) {
  if (isTearChannel(fap)) return static_cast<float>(std::max(0.0, std::round(value)));
  return static_cast<float>(value);
}

ChannelMask unionOfChannels(const std::vector<Keyframe>& keys) {
  ChannelMask mask;
  for (const Keyframe& key : keys) mask |= key.channels;
  return mask;
}

Knot knotOf(const Keyframe& key, int index) {
  return {key.time, key.values[index], key.interpolation};
}

// The scalar dialect's convention: the code is select1, shown at full weight.
void fillHighLevel(FapAnimation& animation) {
  const auto code = [](float value) {
    return static_cast<int>(std::lround(std::clamp(static_cast<double>(value), -1e9, 1e9)));
  };
  animation.highLevel.resize(animation.frames.size());
  for (std::size_t i = 0; i < animation.frames.size(); ++i) {
    HighLevelFrame& frame = animation.highLevel[i];
    frame.viseme.select1 = code(animation.frames[i][channelIndex(1)]);
    frame.viseme.blend = 63;
    frame.expression.select1 = code(animation.frames[i][channelIndex(2)]);
    frame.expression.intensity1 = 63;
  }
}

ChannelMask nonZeroChannels(const FapAnimation& animation) {
  ChannelMask mask;
  for (const FapValues& frame : animation.frames) {
    for (int i = 0; i < kChannelCount; ++i) {
      if (frame[i] != 0.0f) mask.set(i);
    }
  }
  return mask;
}

}  // namespace

std::string_view toString(Interpolation mode) {
  return mode == Interpolation::Smooth ? "smooth" : "linear";
}

std::optional<Interpolation> interpolationFromString(std::string_view text) {
  if (text == "linear") return Interpolation::Linear;
  if (text == "smooth") return Interpolation::Smooth;
  return std::nullopt;
}

void Keyframe::set(int fap, float v) {
  if (!isValidFap(fap)) throw std::out_of_range("no channel " + std::to_string(fap));
  channels.set(channelIndex(fap));
  values[channelIndex(fap)] = v;
}

void Keyframe::clear(int fap) {
  if (!isValidFap(fap)) throw std::out_of_range("no channel " + std::to_string(fap));
  channels.reset(channelIndex(fap));
  values[channelIndex(fap)] = 0.0f;
}

bool Keyframe::operator==(const Keyframe& other) const {
  if (time != other.time || interpolation != other.interpolation || channels != other.channels) {
    return false;
  }
  for (int i = 0; i < kChannelCount; ++i) {
    if (channels.test(i) && values[i] != other.values[i]) return false;
  }
  return true;
}

KeyframeSequence::KeyframeSequence(std::vector<Keyframe> keys) {
  for (const Keyframe& key : keys) requireFiniteTime(key.time);
  // Sort an index so that, among keys at the same time, the one given last can win.
  std::vector<std::size_t> order(keys.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return keys[a].time < keys[b].time; });
  keys_.reserve(keys.size());
  std::size_t keptIndex = 0;
  for (std::size_t index : order) {
    Keyframe& key = keys[index];
    if (!keys_.empty() && std::abs(key.time - keys_.back().time) < kSameTime) {
      if (index > keptIndex) {
        keys_.back() = std::move(key);
        keptIndex = index;
      }
      continue;
    }
    keys_.push_back(std::move(key));
    keptIndex = index;
  }
}

double KeyframeSequence::startTime() const { return keys_.empty() ? 0.0 : keys_.front().time; }

double KeyframeSequence::endTime() const { return keys_.empty() ? 0.0 : keys_.back().time; }

int KeyframeSequence::insert(const Keyframe& key) {
  requireFiniteTime(key.time);
  // First key not earlier than key.time - kSameTime: either the same key or the next one.
  const auto at = std::partition_point(keys_.begin(), keys_.end(), [&](const Keyframe& k) {
    return k.time <= key.time - kSameTime;
  });
  const int index = static_cast<int>(at - keys_.begin());
  if (at != keys_.end() && std::abs(at->time - key.time) < kSameTime) {
    // Merge channels only: the existing key keeps its time and its segment's mode, so
    // keying one more channel never reshapes the curves of the others.
    for (int i = 0; i < kChannelCount; ++i) {
      if (key.channels.test(i)) at->set(fapNumber(i), key.values[i]);
    }
    return index;
  }
  keys_.insert(at, key);
  return index;
}

void KeyframeSequence::remove(int index) {
  if (index < 0 || index >= static_cast<int>(keys_.size())) {
    throw std::out_of_range("no key " + std::to_string(index));
  }
  keys_.erase(keys_.begin() + index);
}

FapValues KeyframeSequence::evaluate(double seconds) const {
  if (std::isnan(seconds)) throw std::invalid_argument("evaluate: time is NaN");
  FapValues result{};
  const std::size_t split = static_cast<std::size_t>(
      std::upper_bound(keys_.begin(), keys_.end(), seconds,
                       [](double t, const Keyframe& k) { return t < k.time; }) -
      keys_.begin());

  // Per channel, the knots its value at `seconds` depends on: up to two at or before it
  // (window slots 1, 0) and two after it (slots 2, 3); slopeAt never looks further.
  std::array<std::array<Knot, 4>, kChannelCount> window{};
  std::array<int, kChannelCount> before{}, after{};
  ChannelMask wanted;
  wanted.set();
  for (std::size_t k = split; k-- > 0 && wanted.any();) {
    const ChannelMask hit = keys_[k].channels & wanted;
    for (int i = 0; i < kChannelCount; ++i) {
      if (!hit.test(i)) continue;
      window[i][1 - before[i]] = knotOf(keys_[k], i);
      if (++before[i] == 2) wanted.reset(i);
    }
  }
  wanted.set();
  for (std::size_t k = split; k < keys_.size() && wanted.any(); ++k) {
    const ChannelMask hit = keys_[k].channels & wanted;
    for (int i = 0; i < kChannelCount; ++i) {
      if (!hit.test(i)) continue;
      window[i][2 + after[i]] = knotOf(keys_[k], i);
      if (++after[i] == 2) wanted.reset(i);
    }
  }

  for (int i = 0; i < kChannelCount; ++i) {
    const int count = before[i] + after[i];
    if (count == 0) continue;
    const std::span<const Knot> knots(window[i].data() + (2 - before[i]),
                                      static_cast<std::size_t>(count));
    const int fap = fapNumber(i);
    result[i] =
        channelValue(fap, curveValue(fap, knots, static_cast<std::size_t>(before[i]), seconds));
  }
  return result;
}

FapAnimation KeyframeSequence::bake(double fps) const {
  requireValidFps(fps, "bake");
  FapAnimation animation;
  animation.fps = fps;
  if (keys_.empty()) return animation;

  const double start = startTime();
  const double frames = std::floor((endTime() - start) * fps + 1e-6) + 1.0;
  if (frames > kMaxBakedFrames) {
    throw std::length_error("bake: " + std::to_string(static_cast<long long>(frames)) +
                            " frames exceed the limit of " +
                            std::to_string(static_cast<long long>(kMaxBakedFrames)));
  }
  animation.frames.assign(static_cast<std::size_t>(frames), FapValues{});
  animation.animated = unionOfChannels(keys_);

  // One channel at a time, walking its knots and the frames together: O(frames + keys).
  std::vector<Knot> knots;
  knots.reserve(keys_.size());
  for (int i = 0; i < kChannelCount; ++i) {
    if (!animation.animated.test(i)) continue;
    knots.clear();
    for (const Keyframe& key : keys_) {
      if (key.channels.test(i)) knots.push_back(knotOf(key, i));
    }
    const int fap = fapNumber(i);
    std::size_t reached = 0;
    for (std::size_t f = 0; f < animation.frames.size(); ++f) {
      const double t = start + static_cast<double>(f) / fps;
      while (reached < knots.size() && knots[reached].time <= t) ++reached;
      animation.frames[f][i] = channelValue(fap, curveValue(fap, knots, reached, t));
    }
  }
  if (animation.animated.test(channelIndex(1)) || animation.animated.test(channelIndex(2))) {
    fillHighLevel(animation);
  }
  return animation;
}

KeyframeSequence KeyframeSequence::fromAnimation(const FapAnimation& animation,
                                                 Interpolation mode) {
  requireValidFps(animation.fps, "fromAnimation");
  const ChannelMask channels =
      animation.animated.any() ? animation.animated : nonZeroChannels(animation);
  std::vector<Keyframe> keys(animation.frames.size());
  for (std::size_t f = 0; f < keys.size(); ++f) {
    Keyframe& key = keys[f];
    key.time = static_cast<double>(f) / animation.fps;  // as bake() computes frame times
    key.interpolation = mode;
    key.channels = channels;
    for (int i = 0; i < kChannelCount; ++i) {
      if (channels.test(i)) key.values[i] = animation.frames[f][i];
    }
  }
  return KeyframeSequence(std::move(keys));
}

}  // namespace lacrima::inline common
