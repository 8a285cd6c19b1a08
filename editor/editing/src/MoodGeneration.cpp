#include <lacrima/common/mood/MoodLayer.h>
#include <lacrima/editing/KeyReduction.h>
#include <lacrima/editing/MoodGeneration.h>

#include <cmath>
#include <stdexcept>

namespace lacrima::editing {

MoodGenerationPlan planMoodGeneration(const KeyframeSequence& keys,
                                      const MoodGenerationRequest& request) {
  if (!(request.start >= 0 && request.end > request.start && request.end <= kMaxMoodSeconds))
    throw std::invalid_argument("expected a time range from 0 to 86400 s, its end after its start");
  if (!(request.tolerance >= 0) || !std::isfinite(request.tolerance))
    throw std::invalid_argument("expected a reduction tolerance >= 0");
  const auto moodsAt = [&request](double t) {
    return request.curves ? request.curves->at(request.start + t) : request.script.at(t);
  };
  MoodTake take = generateMoodTake(moodsAt, request.seed, request.end - request.start, request.fps);
  if (request.addToKeys) {
    const ChannelMask moved = take.animation.animated;
    for (std::size_t f = 0; f < take.animation.frames.size(); ++f) {
      FapValues& frame = take.animation.frames[f];
      frame = addMoodFrame(keys.evaluate(request.start + static_cast<double>(f) / request.fps),
                           frame, moved);
    }
  }
  MoodGenerationPlan plan;
  plan.frames = take.animation.frameCount();
  plan.channels = take.animation.usedChannels();
  const std::vector<int> kept = reduceKeyFrames(take.animation, request.tolerance);
  plan.keys = static_cast<int>(kept.size());

  // The old keys in the range, without the generated channels; then the generated keys, each
  // joining an old key at its time.
  std::vector<double> removed;
  std::vector<Keyframe> written;
  for (const Keyframe& key : keys.keys()) {
    if (key.time < request.start - kSameKeyTime || key.time > request.end + kSameKeyTime) continue;
    removed.push_back(key.time);
    Keyframe rest = key;
    for (int fap = 1; fap <= kChannelCount; ++fap)
      if (plan.channels.test(channelIndex(fap))) rest.clear(fap);
    written.push_back(std::move(rest));  // no channels left: the key goes
  }
  for (int frame : kept) {
    const double time = request.start + frame / request.fps;
    Keyframe* key = nullptr;
    for (Keyframe& old : written)
      if (std::abs(old.time - time) <= kSameKeyTime) key = &old;
    if (!key) {
      Keyframe fresh;
      fresh.time = time;
      fresh.interpolation = Interpolation::Linear;
      written.push_back(fresh);
      key = &written.back();
    }
    const FapValues& values = take.animation.frames[static_cast<std::size_t>(frame)];
    for (int fap = 1; fap <= kChannelCount; ++fap)
      if (plan.channels.test(channelIndex(fap))) key->set(fap, values[channelIndex(fap)]);
  }
  plan.change = planReplace(keys, removed, written);
  return plan;
}

}  // namespace lacrima::editing
