#include <lacrima/editing/KeyReduction.h>
#include <lacrima/editing/LiveTake.h>

#include <algorithm>

namespace lacrima::editing {

LiveTakeKeys planLiveTakeKeys(const KeyframeSequence& keys, const FapAnimation& take, double start,
                              const ChannelMask& channels, double tolerance,
                              Interpolation interpolation) {
  LiveTakeKeys result;
  result.framesRecorded = take.frameCount();
  ChannelMask chosen = channels & take.animated;
  chosen.reset(static_cast<std::size_t>(channelIndex(1)));
  chosen.reset(static_cast<std::size_t>(channelIndex(2)));
  if (take.frames.empty() || chosen.none() || !(take.fps > 0)) return result;

  // Reduce on the chosen channels only: the others must not keep frames alive.
  FapAnimation chosenTake = take;
  chosenTake.animated = chosen;
  chosenTake.highLevel.clear();
  const std::vector<int> kept = reduceKeyFrames(chosenTake, tolerance);
  result.maxError = reductionError(chosenTake, kept);
  const double end = start + take.duration();

  std::vector<double> removeTimes;
  std::vector<Keyframe> written;
  const auto inSpan = [&](double t) {
    return t >= start - kSameKeyTime && t <= end + kSameKeyTime;
  };
  const auto keyTime = [&](int frame) { return start + frame / take.fps; };
  // Existing keys in the span lose the chosen channels, unless a kept frame rewrites them.
  for (const Keyframe& key : keys.keys()) {
    if (!inSpan(key.time) || (key.channels & chosen).none()) continue;
    const bool rewritten = std::any_of(kept.begin(), kept.end(), [&](int f) {
      return std::abs(keyTime(f) - key.time) < kSameKeyTime;
    });
    if (rewritten) continue;
    Keyframe stripped = key;
    for (int c = 0; c < kChannelCount; ++c)
      if (chosen.test(static_cast<std::size_t>(c))) stripped.clear(fapNumber(c));
    removeTimes.push_back(key.time);
    written.push_back(std::move(stripped));
  }
  for (const int f : kept) {
    const double t = keyTime(f);
    Keyframe key;
    const int existing = findKey(keys, t);
    if (existing >= 0) {
      key = keys.keys()[static_cast<std::size_t>(existing)];
    } else {
      key.time = t;
      key.interpolation = interpolation;
    }
    for (int c = 0; c < kChannelCount; ++c)
      if (chosen.test(static_cast<std::size_t>(c)))
        key.set(fapNumber(c),
                take.frames[static_cast<std::size_t>(f)][static_cast<std::size_t>(c)]);
    written.push_back(std::move(key));
  }
  std::sort(written.begin(), written.end(),
            [](const Keyframe& a, const Keyframe& b) { return a.time < b.time; });
  std::sort(removeTimes.begin(), removeTimes.end());
  result.change = planReplace(keys, removeTimes, written);
  result.keysWritten = static_cast<int>(kept.size());
  return result;
}

}  // namespace lacrima::editing
