#include <lacrima/editing/ChannelKeyEdits.h>

#include <algorithm>
#include <cmath>
#include <map>

namespace lacrima::editing {
namespace {

// Orders times, taking two within kSameKeyTime as the same key (as findKey does).
struct TimeLess {
  bool operator()(double a, double b) const { return a < b - kSameKeyTime; }
};

// The keys an edit touches, as they will be after it: copies of the document's keys at those
// times, or new keys. Every touched key is written back (an emptied one removes its key).
class TouchedKeys {
 public:
  explicit TouchedKeys(const KeyframeSequence& keys) : keys_(keys) {}

  // The key at `seconds`: already touched, else the document's, else a new one with `mode`.
  Keyframe& at(double seconds, Interpolation mode) {
    const auto found = touched_.find(seconds);
    if (found != touched_.end()) return found->second;
    const int index = findKey(keys_, seconds);
    Keyframe key;
    if (index >= 0) {
      key = keys_.keys()[static_cast<std::size_t>(index)];
    } else {
      key.time = seconds;
      key.interpolation = mode;
    }
    return touched_.emplace(key.time, std::move(key)).first->second;
  }

  KeyChange plan() const {
    std::vector<Keyframe> written;
    written.reserve(touched_.size());
    for (const auto& [time, key] : touched_) written.push_back(key);
    return planReplace(keys_, {}, written);
  }

 private:
  const KeyframeSequence& keys_;
  std::map<double, Keyframe, TimeLess> touched_;
};

const Keyframe* keyAt(const KeyframeSequence& keys, double seconds) {
  const int index = findKey(keys, seconds);
  return index < 0 ? nullptr : &keys.keys()[static_cast<std::size_t>(index)];
}

// The selected channel keys that exist, at their keys' exact times, sorted and unique.
std::vector<ChannelKey> existing(const KeyframeSequence& keys,
                                 std::span<const ChannelKey> selection) {
  std::vector<ChannelKey> out;
  out.reserve(selection.size());
  for (const ChannelKey& wanted : selection) {
    if (!isValidFap(wanted.fap)) continue;
    const Keyframe* key = keyAt(keys, wanted.time);
    if (key && key->has(wanted.fap)) out.push_back({wanted.fap, key->time});
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

void sortUnique(std::vector<ChannelKey>& keys) {
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
}

// `seconds` moved by whole frames: on-grid times land exactly on the grid (no drift from
// repeated moves), off-grid times (hand-edited files) keep their offset from it.
double shiftedTime(double seconds, int frames, double fps) {
  const double onGrid = seconds * fps;
  if (std::abs(onGrid - std::round(onGrid)) < 1e-6) return (std::round(onGrid) + frames) / fps;
  return seconds + frames / fps;
}

// As EditorModel::snapTime: a key within half a frame, else the nearest frame, never < 0.
double snappedTime(const KeyframeSequence& keys, double seconds, double fps) {
  seconds = std::max(0.0, std::isfinite(seconds) ? seconds : 0.0);
  const auto& all = keys.keys();
  const auto after = std::lower_bound(all.begin(), all.end(), seconds,
                                      [](const Keyframe& k, double t) { return k.time < t; });
  double best = -1.0;
  double bestDistance = 0.5 / fps;
  for (auto k = after == all.begin() ? after : after - 1; k != all.end() && k <= after; ++k) {
    const double d = std::abs(k->time - seconds);
    if (d < bestDistance) {
      bestDistance = d;
      best = k->time;
    }
  }
  return best >= 0.0 ? best : std::round(seconds * fps) / fps;
}

}  // namespace

std::size_t ChannelKeyClip::channelKeyCount() const {
  std::size_t count = 0;
  for (const Keyframe& key : keys) count += key.channels.count();
  return count;
}

ChannelKeyEdit moveChannelKeys(const KeyframeSequence& keys, std::span<const ChannelKey> selection,
                               int frames, double fps) {
  const std::vector<ChannelKey> moving = existing(keys, selection);
  if (moving.empty() || frames == 0 || !(fps > 0.0)) return {};
  // Never before 0 s: the block stops at the start.
  double earliest = moving.front().time;
  for (const ChannelKey& k : moving) earliest = std::min(earliest, k.time);
  frames = std::max(frames, -static_cast<int>(std::floor(earliest * fps + 1e-6)));
  if (frames == 0) return {};

  // Take every moving channel out first, then write them at their new times: channel keys
  // that trade places, or move onto a time another moving one leaves, come out right.
  TouchedKeys touched(keys);
  for (const ChannelKey& k : moving) touched.at(k.time, Interpolation::Linear).clear(k.fap);
  ChannelKeyEdit edit;
  for (const ChannelKey& k : moving) {
    const Keyframe& source = *keyAt(keys, k.time);
    const double to = std::max(0.0, shiftedTime(k.time, frames, fps));
    Keyframe& target = touched.at(to, source.interpolation);
    target.takeChannel(source, k.fap);
    edit.selection.push_back({k.fap, target.time});
  }
  sortUnique(edit.selection);
  edit.change = touched.plan();
  return edit;
}

ChannelKeyEdit deleteChannelKeys(const KeyframeSequence& keys,
                                 std::span<const ChannelKey> selection) {
  TouchedKeys touched(keys);
  for (const ChannelKey& k : existing(keys, selection))
    touched.at(k.time, Interpolation::Linear).clear(k.fap);
  return {touched.plan(), {}};
}

ChannelKeyClip copyChannelKeys(const KeyframeSequence& keys,
                               std::span<const ChannelKey> selection) {
  const std::vector<ChannelKey> copied = existing(keys, selection);
  ChannelKeyClip clip;
  if (copied.empty()) return clip;
  double first = copied.front().time;
  for (const ChannelKey& k : copied) first = std::min(first, k.time);
  std::map<double, Keyframe, TimeLess> byTime;
  for (const ChannelKey& k : copied) {
    const Keyframe& source = *keyAt(keys, k.time);
    auto [slot, added] = byTime.try_emplace(k.time);
    if (added) {
      slot->second.time = k.time - first;
      slot->second.interpolation = source.interpolation;
    }
    slot->second.takeChannel(source, k.fap);
  }
  for (auto& [time, key] : byTime) clip.keys.push_back(std::move(key));
  return clip;
}

ChannelKeyEdit pasteChannelKeys(const KeyframeSequence& keys, const ChannelKeyClip& clip, double at,
                                double fps) {
  if (clip.empty() || !(fps > 0.0) || !std::isfinite(at)) return {};
  TouchedKeys touched(keys);
  ChannelKeyEdit edit;
  for (const Keyframe& source : clip.keys) {
    const double t = snappedTime(keys, at + source.time, fps);
    Keyframe& target = touched.at(t, source.interpolation);
    for (int fap = 1; fap <= kChannelCount; ++fap) {
      if (!source.has(fap)) continue;
      target.takeChannel(source, fap);
      edit.selection.push_back({fap, target.time});
    }
  }
  sortUnique(edit.selection);
  edit.change = touched.plan();
  return edit;
}

}  // namespace lacrima::editing
