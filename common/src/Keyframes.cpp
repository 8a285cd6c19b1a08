#include <lacrima/common/Keyframes.h>

#include "CurveSlopes.h"

#include <lacrima/common/CurveHandles.h>
#include <lacrima/common/JsonWriter.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <span>
#include <stdexcept>
#include <string>

namespace lacrima::inline common {
namespace {

using namespace detail;

// Keys closer than this are the same key: far below a frame at any sane rate, far above
// the rounding error of times computed as frame / fps.
constexpr double kSameTime = 1e-9;

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

// The Bézier segment from a to b, with handles ha (a's out) and hb (b's in), at time t:
//   P(u) = (1-u)^3 P0 + 3u(1-u)^2 P1 + 3u^2(1-u) P2 + u^3 P3,  u in [0, 1],
//   P0 = (ta, va), P1 = P0 + ha, P2 = P3 + hb, P3 = (tb, vb).
// A curve of time must give one value per time, so x(u) must not turn back. Each handle's time
// is first clamped into the segment, then, if the two together reach past it, both are scaled
// down about their keys (keeping their directions) until they just meet: then
// x1 - x0, x2 - x1, x3 - x2 >= 0 and x'(u), a Bernstein combination of them, is >= 0.
// u for t is found by solveBezierTime (CurveHandles.h): bisection safeguarding Newton steps.
double bezier(const Knot& a, const Knot& b, Handle ha, Handle hb, double t) {
  const double h = b.time - a.time;
  const auto clampTime = [](Handle handle, double lo, double hi) {
    const double dt = std::clamp(handle.dt, lo, hi);
    // Scaling the value with the time keeps the handle's slope when it is shortened.
    const double scale = handle.dt != 0.0 ? dt / handle.dt : 0.0;
    return Handle{dt, handle.dv * scale};
  };
  ha = clampTime(ha, 0.0, h);
  hb = clampTime(hb, -h, 0.0);
  const double reach = ha.dt - hb.dt;
  if (reach > h) {
    const double scale = h / reach;
    ha = {ha.dt * scale, ha.dv * scale};
    hb = {hb.dt * scale, hb.dv * scale};
  }
  const double x0 = a.time, x1 = a.time + ha.dt, x2 = b.time + hb.dt, x3 = b.time;
  const double y0 = a.value, y1 = a.value + ha.dv, y2 = b.value + hb.dv, y3 = b.value;
  const auto cubic = [](double p0, double p1, double p2, double p3, double u) {
    const double r = 1.0 - u;
    return r * r * r * p0 + 3.0 * u * r * r * p1 + 3.0 * u * u * r * p2 + u * u * u * p3;
  };
  const double u = solveBezierTime({x0, x1, x2, x3}, t).u;
  return cubic(y0, y1, y2, y3, u);
}

// Value of a channel's curve at t, where `reached` knots lie at or before t.
double curveValue(int fap, std::span<const Knot> knots, std::size_t reached, double t) {
  if (reached == 0) return knots.front().value;
  const Knot& a = knots[reached - 1];
  // High-level FAPs are viseme/expression codes: halfway between viseme 3 and viseme 7 is
  // not viseme 5, so a code holds until the next key.
  if (reached == knots.size() || isHighLevelFap(fap)) return a.value;
  const Knot& b = knots[reached];
  switch (a.shape.interpolation) {
    case Interpolation::Constant:
      return a.value;
    case Interpolation::Linear:
      return a.value + (t - a.time) / (b.time - a.time) * (b.value - a.value);
    case Interpolation::Smooth:
      return hermite(a, b, slopeAt(knots, reached - 1), slopeAt(knots, reached), t);
    case Interpolation::Bezier: {
      const double h = b.time - a.time;
      return bezier(a, b, outHandle(a, slopeAt(knots, reached - 1), h),
                    inHandle(b, slopeAt(knots, reached), h), t);
    }
  }
  return a.value;
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
  switch (mode) {
    case Interpolation::Linear:
      return "linear";
    case Interpolation::Smooth:
      return "smooth";
    case Interpolation::Constant:
      return "constant";
    case Interpolation::Bezier:
      return "bezier";
  }
  return "linear";
}

std::optional<Interpolation> interpolationFromString(std::string_view text) {
  for (Interpolation mode : {Interpolation::Linear, Interpolation::Smooth, Interpolation::Constant,
                             Interpolation::Bezier}) {
    if (text == toString(mode)) return mode;
  }
  return std::nullopt;
}

std::string_view toString(HandleType type) {
  switch (type) {
    case HandleType::Auto:
      return "auto";
    case HandleType::Aligned:
      return "aligned";
    case HandleType::Free:
      return "free";
  }
  return "auto";
}

std::optional<HandleType> handleTypeFromString(std::string_view text) {
  for (HandleType type : {HandleType::Auto, HandleType::Aligned, HandleType::Free}) {
    if (text == toString(type)) return type;
  }
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
  std::erase_if(ownShapes_, [&](const auto& own) { return own.first == channelIndex(fap); });
}

bool Keyframe::hasOwnShape(int fap) const {
  return std::any_of(ownShapes_.begin(), ownShapes_.end(),
                     [&](const auto& own) { return own.first == channelIndex(fap); });
}

KeyShape Keyframe::shape(int fap) const {
  const int index = channelIndex(fap);
  const auto at = std::lower_bound(ownShapes_.begin(), ownShapes_.end(), index,
                                   [](const auto& own, int i) { return own.first < i; });
  if (at != ownShapes_.end() && at->first == index) return at->second;
  return KeyShape{interpolation, HandleType::Auto, {}, {}};
}

void Keyframe::setShape(int fap, KeyShape shape) {
  if (!isValidFap(fap)) throw std::out_of_range("no channel " + std::to_string(fap));
  if (shape.handles == HandleType::Auto) shape.in = shape.out = Handle{};
  const int index = channelIndex(fap);
  const auto at = std::lower_bound(ownShapes_.begin(), ownShapes_.end(), index,
                                   [](const auto& own, int i) { return own.first < i; });
  const bool stored = at != ownShapes_.end() && at->first == index;
  const bool isDefault = shape == KeyShape{interpolation, HandleType::Auto, {}, {}};
  if (isDefault) {
    if (stored) ownShapes_.erase(at);
  } else if (stored) {
    at->second = shape;
  } else {
    ownShapes_.insert(at, {index, shape});
  }
}

void Keyframe::setInterpolationOfAll(Interpolation mode) {
  const auto shapes = ownShapes_;
  interpolation = mode;
  ownShapes_.clear();
  for (auto [index, shape] : shapes) {
    shape.interpolation = mode;
    setShape(fapNumber(index), shape);
  }
}

void Keyframe::takeChannel(const Keyframe& other, int fap) {
  if (!other.has(fap)) {
    clear(fap);
    return;
  }
  set(fap, other.value(fap));
  setShape(fap, other.shape(fap));
}

bool Keyframe::operator==(const Keyframe& other) const {
  if (time != other.time || interpolation != other.interpolation || channels != other.channels) {
    return false;
  }
  for (int i = 0; i < kChannelCount; ++i) {
    if (!channels.test(i)) continue;
    if (values[i] != other.values[i] || shape(fapNumber(i)) != other.shape(fapNumber(i))) {
      return false;
    }
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
    // A channel with a shape of its own brings it; the others take the existing key's default.
    for (int i = 0; i < kChannelCount; ++i) {
      if (!key.channels.test(i)) continue;
      const int fap = fapNumber(i);
      at->set(fap, key.values[i]);
      at->setShape(fap, key.hasOwnShape(fap)
                            ? key.shape(fap)
                            : KeyShape{at->interpolation, HandleType::Auto, {}, {}});
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

double bakedFrameCount(double fps, double start, double end) {
  if (end < start) return 0;
  return std::floor((end - start) * fps + 1e-6) + 1.0;
}

std::string bakeLengthProblem(double fps, double start, double end) {
  const double frames = bakedFrameCount(fps, start, end);
  if (frames <= kMaxBakedFrames) return {};
  return "the animation runs from " + formatJsonNumber(start) + " s to " + formatJsonNumber(end) +
         " s, " + formatJsonNumber(frames) + " frames at " + formatJsonNumber(fps) +
         " fps; at most " + formatJsonNumber(kMaxBakedFrames) +
         " frames can be played or exported (shorten it or lower the frame rate)";
}

FapAnimation KeyframeSequence::bake(double fps) const {
  if (keys_.empty()) {
    requireValidFps(fps, "bake");
    FapAnimation animation;
    animation.fps = fps;
    return animation;
  }
  return bake(fps, startTime(), endTime());
}

FapAnimation KeyframeSequence::bake(double fps, double start, double end) const {
  requireValidFps(fps, "bake");
  requireFiniteTime(start);
  requireFiniteTime(end);
  FapAnimation animation;
  animation.fps = fps;
  if (end < start) return animation;

  const double frames = bakedFrameCount(fps, start, end);
  if (!(frames <= kMaxBakedFrames)) {
    // Printed as a double: the count may exceed every integer type (a key at 6e66 s).
    throw std::length_error("bake: " + formatJsonNumber(frames) + " frames exceed the limit of " +
                            formatJsonNumber(kMaxBakedFrames));
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
