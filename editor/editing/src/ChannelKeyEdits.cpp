#include <lacrima/editing/ChannelKeyEdits.h>

#include "TouchedKeys.h"

#include <algorithm>
#include <cmath>

namespace lacrima::editing {
namespace {

// The selected channel keys that exist, at their keys' exact times, sorted and unique.
std::vector<ChannelKey> existing(const KeyframeSequence& keys,
                                 std::span<const ChannelKey> selection) {
  std::vector<ChannelKey> out;
  out.reserve(selection.size());
  for (const ChannelKey& wanted : selection) {
    if (!isValidFap(wanted.fap)) continue;
    const Keyframe* key = keyAtTime(keys, wanted.time);
    if (key && key->has(wanted.fap)) out.push_back({wanted.fap, key->time});
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

// Channel keys gathered per key: one lookup per key instead of one per channel.
struct TimeChannels {
  double time;
  ChannelMask channels;
};

std::vector<TimeChannels> byTime(std::vector<ChannelKey> keys) {
  std::sort(keys.begin(), keys.end(),
            [](const ChannelKey& a, const ChannelKey& b) { return a.time < b.time; });
  std::vector<TimeChannels> out;
  for (const ChannelKey& k : keys) {
    // existing() gave every channel key its key's exact time.
    if (out.empty() || out.back().time != k.time) out.push_back({k.time, {}});
    out.back().channels.set(static_cast<std::size_t>(channelIndex(k.fap)));
  }
  return out;
}

template <typename Visit>
void forEachChannel(const ChannelMask& channels, Visit visit) {
  for (int i = 0; i < kChannelCount; ++i)
    if (channels.test(static_cast<std::size_t>(i))) visit(fapNumber(i));
}

void sortUnique(std::vector<ChannelKey>& keys) {
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
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
  const std::vector<TimeChannels> moving = byTime(existing(keys, selection));
  if (moving.empty() || frames == 0 || !(fps > 0.0)) return {};
  // Never before 0 s: the block stops at the start.
  frames = std::max(frames, -static_cast<int>(std::floor(moving.front().time * fps + 1e-6)));
  if (frames == 0) return {};

  // Take every moving channel out first, then write them at their new times: channel keys
  // that trade places, or move onto a time another moving one leaves, come out right.
  TouchedKeys touched(keys);
  for (const TimeChannels& at : moving) {
    Keyframe& key = touched.at(at.time, Interpolation::Linear);
    forEachChannel(at.channels, [&](int fap) { key.clear(fap); });
  }
  ChannelKeyEdit edit;
  for (const TimeChannels& at : moving) {
    const Keyframe& source = *keyAtTime(keys, at.time);
    const double to = std::max(0.0, shiftedByFrames(at.time, frames, fps));
    Keyframe& target = touched.at(to, source.interpolation);
    forEachChannel(at.channels, [&](int fap) {
      target.takeChannel(source, fap);
      edit.selection.push_back({fap, target.time});
    });
  }
  sortUnique(edit.selection);
  edit.change = touched.plan();
  return edit;
}

ChannelKeyEdit deleteChannelKeys(const KeyframeSequence& keys,
                                 std::span<const ChannelKey> selection) {
  TouchedKeys touched(keys);
  for (const TimeChannels& at : byTime(existing(keys, selection))) {
    Keyframe& key = touched.at(at.time, Interpolation::Linear);
    forEachChannel(at.channels, [&](int fap) { key.clear(fap); });
  }
  return {touched.plan(), {}};
}

ChannelKeyClip copyChannelKeys(const KeyframeSequence& keys,
                               std::span<const ChannelKey> selection) {
  const std::vector<TimeChannels> copied = byTime(existing(keys, selection));
  ChannelKeyClip clip;
  if (copied.empty()) return clip;
  const double first = copied.front().time;
  for (const TimeChannels& at : copied) {
    const Keyframe& source = *keyAtTime(keys, at.time);
    Keyframe key;
    key.time = at.time - first;
    key.interpolation = source.interpolation;
    forEachChannel(at.channels, [&](int fap) { key.takeChannel(source, fap); });
    clip.keys.push_back(std::move(key));
  }
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
