#pragma once
// What the per-channel edits (ChannelKeyEdits, CurveEdits) share: the keys an edit touches,
// finding a key by time, and moving a time by whole frames. Private to lacrima_editing.
#include <lacrima/editing/KeyChange.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

namespace lacrima::editing {

// The key at `seconds` (within kSameKeyTime), or null.
inline const Keyframe* keyAtTime(const KeyframeSequence& keys, double seconds) {
  const int index = findKey(keys, seconds);
  return index < 0 ? nullptr : &keys.keys()[static_cast<std::size_t>(index)];
}

// `seconds` moved by whole frames of 1 / fps: on-grid times land exactly on the grid (no drift
// from repeated moves), off-grid times (hand-edited files) keep their offset from it. Never
// past kMaxKeyTime, the latest time a project file may hold.
inline double shiftedByFrames(double seconds, int frames, double fps) {
  const double onGrid = seconds * fps;
  const double shifted = std::abs(onGrid - std::round(onGrid)) < 1e-6
                             ? (std::round(onGrid) + frames) / fps
                             : seconds + frames / fps;
  return std::min(shifted, kMaxKeyTime);
}

// The keys an edit touches, as they will be after it: copies of the document's keys at those
// times, or new keys. Every touched key is written back (an emptied one removes its key).
class TouchedKeys {
 public:
  explicit TouchedKeys(const KeyframeSequence& keys) : keys_(keys) {}

  // The key at `seconds`: already touched, else the document's, else a new one with `mode` as
  // its default interpolation.
  Keyframe& at(double seconds, Interpolation mode) {
    const auto found = touched_.find(seconds);
    if (found != touched_.end()) return found->second;
    Keyframe key;
    if (const Keyframe* existing = keyAtTime(keys_, seconds)) {
      key = *existing;
    } else {
      key.time = seconds;
      key.interpolation = mode;
    }
    return touched_.emplace(key.time, std::move(key)).first->second;
  }

  // What planReplace(keys, {}, touched keys) gives, built directly: the touched times are
  // already sorted and unique, so this is O(k log n) where planReplace looks up each time among
  // the written keys (quadratic for a selection of every key in a long imported file).
  KeyChange plan() const {
    KeyChange change;
    change.times.reserve(touched_.size());
    for (const auto& [time, key] : touched_) {
      change.times.push_back(key.time);
      if (const Keyframe* before = keyAtTime(keys_, key.time)) change.before.push_back(*before);
      if (key.channels.any()) change.after.push_back(key);
    }
    return change;
  }

 private:
  // Orders times, taking two within kSameKeyTime as the same key (as findKey does).
  struct TimeLess {
    bool operator()(double a, double b) const { return a < b - kSameKeyTime; }
  };

  const KeyframeSequence& keys_;
  std::map<double, Keyframe, TimeLess> touched_;
};

}  // namespace lacrima::editing
