#include <lacrima/editing/CurveEdits.h>

#include "TouchedKeys.h"

#include <lacrima/common/CurveHandles.h>
#include <lacrima/editing/ChannelLimits.h>

#include <algorithm>
#include <cmath>
#include <optional>

namespace lacrima::editing {
namespace {

constexpr double kMaxHandleSeconds = 86400.0;

double length(Handle h) { return std::hypot(h.dt, h.dv); }

// `opposite` turned to point away from `along`, keeping its length (the Aligned rule). A
// zero-length `along` has no direction; `opposite` then stays.
Handle alignedOpposite(Handle along, Handle opposite) {
  const double l = length(along);
  if (!(l > 0.0)) return opposite;
  const double keep = length(opposite);
  return {-along.dt / l * keep, -along.dv / l * keep};
}

// Index of the channel's key before keys()[index], or -1.
int previousChannelKey(const KeyframeSequence& keys, int fap, int index) {
  for (int k = index - 1; k >= 0; --k)
    if (keys.keys()[static_cast<std::size_t>(k)].has(fap)) return k;
  return -1;
}

float sanitisedValue(int fap, double value, bool wholeValues) {
  if (!std::isfinite(value)) value = 0.0;
  if (wholeValues || isTearChannel(fap) || isHighLevelFap(fap)) value = std::round(value);
  const ChannelLimits limits = editLimits(fap);
  return static_cast<float>(std::clamp(value, double(limits.min), double(limits.max)));
}

}  // namespace

KeyChange setChannelKeyShapes(const KeyframeSequence& keys, std::span<const ChannelKey> selected,
                              Interpolation interpolation) {
  TouchedKeys touched(keys);
  for (const ChannelKey& channelKey : selected) {
    const Keyframe* source = keyAtTime(keys, channelKey.time);
    if (!source || !source->has(channelKey.fap)) continue;
    Keyframe& key = touched.at(source->time, source->interpolation);
    KeyShape shape = key.shape(channelKey.fap);
    shape.interpolation = interpolation;
    key.setShape(channelKey.fap, shape);
  }
  return touched.plan();
}

KeyChange setChannelKeyShapes(const KeyframeSequence& keys, std::span<const ChannelKey> selected,
                              HandleType handles) {
  TouchedKeys touched(keys);
  for (const ChannelKey& channelKey : selected) {
    const int index = findKey(keys, channelKey.time);
    if (index < 0 || !keys.keys()[static_cast<std::size_t>(index)].has(channelKey.fap)) continue;
    const EffectiveHandles now = effectiveHandles(keys, channelKey.fap, index);
    const Keyframe& source = keys.keys()[static_cast<std::size_t>(index)];
    Keyframe& key = touched.at(source.time, source.interpolation);
    KeyShape shape = key.shape(channelKey.fap);
    if (shape.handles == handles) continue;
    shape.handles = handles;
    shape.in = now.in;
    shape.out = now.out;
    if (handles == HandleType::Aligned) shape.in = alignedOpposite(shape.out, shape.in);
    key.setShape(channelKey.fap, shape);  // Auto: setShape drops the handles
  }
  return touched.plan();
}

KeyChange moveHandle(const KeyframeSequence& keys, int fap, double time, HandleSide side,
                     Handle offset) {
  const int index = findKey(keys, time);
  if (index < 0 || !std::isfinite(offset.dt) || !std::isfinite(offset.dv)) return {};
  const Keyframe& source = keys.keys()[static_cast<std::size_t>(index)];
  if (!source.has(fap)) return {};

  // A handle cannot point across its key: it would turn the curve back in time. Its reach is
  // bounded so that every curve value stays a float (a Bézier segment stays within its
  // control points): twice the channel's edit range in value, a day in time.
  const ChannelLimits limits = editLimits(fap);
  const double valueReach = 2.0 * (double(limits.max) - double(limits.min));
  offset.dv = std::clamp(offset.dv, -valueReach, valueReach);
  offset.dt = std::clamp(offset.dt, side == HandleSide::Out ? 0.0 : -kMaxHandleSeconds,
                         side == HandleSide::Out ? kMaxHandleSeconds : 0.0);

  const EffectiveHandles now = effectiveHandles(keys, fap, index);
  TouchedKeys touched(keys);
  Keyframe& key = touched.at(source.time, source.interpolation);
  KeyShape shape = key.shape(fap);
  if (shape.handles == HandleType::Auto) {
    shape.handles = HandleType::Aligned;
    shape.in = now.in;
    shape.out = now.out;
  }
  Handle& dragged = side == HandleSide::Out ? shape.out : shape.in;
  Handle& opposite = side == HandleSide::Out ? shape.in : shape.out;
  dragged = offset;
  if (shape.handles == HandleType::Aligned) opposite = alignedOpposite(dragged, opposite);

  if (side == HandleSide::Out) {
    shape.interpolation = Interpolation::Bezier;
  } else if (const int previous = previousChannelKey(keys, fap, index); previous >= 0) {
    const Keyframe& before = keys.keys()[static_cast<std::size_t>(previous)];
    Keyframe& earlier = touched.at(before.time, before.interpolation);
    KeyShape earlierShape = earlier.shape(fap);
    earlierShape.interpolation = Interpolation::Bezier;
    earlier.setShape(fap, earlierShape);
  }
  // `touched.at` may have grown its vector; find the key again before writing it.
  touched.at(source.time, source.interpolation).setShape(fap, shape);
  return touched.plan();
}

ChannelKeyMoveResult moveChannelKeys(const KeyframeSequence& keys,
                                     std::span<const ChannelKeyMove> moves, int frames, double fps,
                                     bool wholeValues) {
  struct Moving {
    int fap;
    Keyframe source;  // the document's key, whose channel `fap` moves
    double to;
    float value;
  };
  std::vector<Moving> moving;
  for (const ChannelKeyMove& move : moves) {
    const Keyframe* source = keyAtTime(keys, move.key.time);
    if (!source || !source->has(move.key.fap)) continue;
    const double to = frames == 0 || !(fps > 0.0)
                          ? source->time
                          : std::max(0.0, shiftedByFrames(source->time, frames, fps));
    moving.push_back(
        {move.key.fap, *source, to, sanitisedValue(move.key.fap, move.value, wholeValues)});
  }
  ChannelKeyMoveResult result;
  if (moving.empty()) return result;

  // Lift every moving channel first, then drop them at their new times, so keys moving onto
  // each other's old places (a run shifted by a frame) do not overwrite one another.
  TouchedKeys touched(keys);
  for (const Moving& m : moving) touched.at(m.source.time, m.source.interpolation).clear(m.fap);
  for (const Moving& m : moving) {
    Keyframe& target = touched.at(m.to, m.source.interpolation);
    target.takeChannel(m.source, m.fap);
    target.set(m.fap, m.value);
    result.moved.push_back({m.fap, target.time});
  }
  result.change = touched.plan();
  std::sort(result.moved.begin(), result.moved.end());
  return result;
}

KeyChange moveChannelKeyValue(const KeyframeSequence& keys, int fap, double time, double value,
                              bool wholeValues) {
  const ChannelKeyMove move{{fap, time}, value};
  return moveChannelKeys(keys, std::span(&move, 1), 0, 0.0, wholeValues).change;
}

KeyChange moveChannelKeyTime(const KeyframeSequence& keys, int fap, double time, int frames,
                             double fps) {
  const Keyframe* source = keyAtTime(keys, time);
  if (!source || !source->has(fap)) return {};
  const ChannelKeyMove move{{fap, time}, source->value(fap)};
  return moveChannelKeys(keys, std::span(&move, 1), frames, fps, false).change;
}

}  // namespace lacrima::editing
