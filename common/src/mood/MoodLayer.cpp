#include <lacrima/common/mood/MoodLayer.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace lacrima::inline common {

MoodLayerTake::MoodLayerTake(const MoodCurves& curves, const MoodLayer& layer, double fps)
    : curves_(curves), seed_(layer.seed), start_(layer.start), end_(layer.end), fps_(fps) {
  if (!(layer.start >= 0 && layer.end > layer.start && layer.end <= kMaxMoodSeconds))
    throw std::invalid_argument("expected a time range from 0 to 86400 s, its end after its start");
  // The take Generate crying... writes from the curves (planMoodGeneration): its time 0 is the
  // layer's start, its moods the curves at project time.
  take_ = generateMoodTake([this](double t) { return curves_.at(start_ + t); }, seed_,
                           end_ - start_, fps_);
}

bool MoodLayerTake::generatedFrom(const MoodCurves& curves, const MoodLayer& layer,
                                  double fps) const {
  return seed_ == layer.seed && start_ == layer.start && end_ == layer.end && fps_ == fps &&
         curves_ == curves;
}

MoodLayerTake::Position MoodLayerTake::position(double seconds) const {
  const double at = (seconds - start_) * fps_;
  const std::size_t last = take_.animation.frames.size() - 1;
  // A small tolerance so that start + k / fps, computed in floating point, lands on frame k.
  const double whole = std::floor(at + 1e-6);
  if (!(whole >= 0)) return {0, 0.0};
  if (whole >= static_cast<double>(last)) return {last, 0.0};
  return {static_cast<std::size_t>(whole), std::clamp(at - whole, 0.0, 1.0)};
}

FapValues MoodLayerTake::channelsAt(double seconds) const {
  const auto [frame, fraction] = position(seconds);
  const FapValues& a = take_.animation.frames[frame];
  if (fraction == 0.0) return a;
  const FapValues& b = take_.animation.frames[frame + 1];
  FapValues values{};
  const auto f = static_cast<float>(fraction);
  for (int i = 0; i < kChannelCount; ++i) values[i] = a[i] + f * (b[i] - a[i]);
  return values;
}

FaceColours MoodLayerTake::coloursAt(double seconds) const {
  const auto [frame, fraction] = position(seconds);
  const FaceColours& a = take_.colours[frame];
  if (fraction == 0.0) return a;
  const FaceColours& b = take_.colours[frame + 1];
  return {a.redness + fraction * (b.redness - a.redness), a.blush + fraction * (b.blush - a.blush)};
}

std::size_t MoodLayerTake::bytes() const {
  return take_.animation.frames.capacity() * sizeof(FapValues) +
         take_.colours.capacity() * sizeof(FaceColours);
}

FapValues addMoodFrame(const FapValues& below, const FapValues& generated,
                       const ChannelMask& channels) {
  FapValues mixed = below;
  for (int i = 0; i < kChannelCount; ++i)
    if (channels.test(i)) mixed[i] += generated[i];
  for (int fap : {kTearLeftFap, kTearRightFap}) {
    const int i = channelIndex(fap);
    if (channels.test(i))
      mixed[i] = std::clamp(std::round(mixed[i]), 0.0f, static_cast<float>(kMaxTearParticles));
  }
  return mixed;
}

FapValues mixMoodLayer(const FapValues& below, const MoodLayerTake* take, double seconds) {
  if (!take || !take->covers(seconds)) return below;
  return addMoodFrame(below, take->channelsAt(seconds), take->channels());
}

KeyedColours mixMoodColours(const KeyedColours& keyed, const MoodLayerTake* take, double seconds) {
  if (!take || !take->covers(seconds)) return keyed;
  const FaceColours generated = take->coloursAt(seconds);
  return {generated.redness, generated.blush};
}

std::vector<IntensityKey> moodColourKeys(const MoodTake& take, double FaceColours::*colour,
                                         double start) {
  std::vector<IntensityKey> keys;
  const double fps = take.animation.fps;
  const int every = std::max(1, static_cast<int>(kColourKeyStep * fps));
  const int last = static_cast<int>(take.colours.size()) - 1;
  for (int i = 0; i <= last; i += every) {
    keys.push_back({start + i / fps, take.colours[static_cast<std::size_t>(i)].*colour,
                    Interpolation::Linear});
    if (i < last && i + every > last) i = last - every;  // always key the last frame
  }
  return keys;
}

FaceColourCurves bakeMoodColours(const FaceColourCurves& keyed, const MoodLayerTake& take) {
  const auto baked = [&](const IntensityCurve& curve, double FaceColours::*colour) {
    std::vector<IntensityKey> keys;
    for (const IntensityKey& key : curve.keys())
      if (!take.covers(key.time)) keys.push_back(key);
    const std::vector<IntensityKey> generated = moodColourKeys(take.take(), colour, take.start());
    keys.insert(keys.end(), generated.begin(), generated.end());
    return IntensityCurve(std::move(keys));
  };
  return {baked(keyed.redness, &FaceColours::redness), baked(keyed.blush, &FaceColours::blush)};
}

const MoodLayerTake* MoodLayerCache::take(const MoodCurves& curves,
                                          const std::optional<MoodLayer>& layer, double fps) {
  if (!layer) {
    take_.reset();
    shown_.reset();
    return nullptr;
  }
  if (!take_ || !take_->generatedFrom(curves, *layer, fps)) {
    take_.reset();  // the old frames go before the new ones are allocated
    shown_.reset();
    take_ = std::make_shared<const MoodLayerTake>(curves, *layer, fps);
    ++generations_;
  }
  shown_ = layer->muted ? nullptr : take_;
  return shown_.get();
}

}  // namespace lacrima::inline common
