#include <lacrima/common/FapTable.h>
#include <lacrima/common/Keyframes.h>
#include <lacrima/common/mood/MoodGenerator.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace lacrima::inline common {
namespace {

// The streams each part draws from (streamSeed); fixed, so a new part never shifts another's.
enum Stream : std::uint64_t { kTears = 1, kExpression, kSobs, kLaughter, kGaze, kBlinks };

double unitLevel(double level) { return std::isfinite(level) ? std::clamp(level, 0.0, 1.0) : 0.0; }

}  // namespace

ChannelRange generatedRange(int fap) {
  if (isHighLevelFap(fap)) return {0, 0};
  const FapInfo& info = fapInfo(fap);
  const float min = info.bidirectional ? static_cast<float>(info.sliderMin)
                                       : static_cast<float>(std::max(0, info.sliderMin));
  return {min, static_cast<float>(info.sliderMax)};
}

MoodGenerator::MoodGenerator(std::uint64_t seed)
    : tears_(streamSeed(seed, kTears)),
      expression_(streamSeed(seed, kExpression)),
      sob_(streamSeed(seed, kSobs)),
      laughter_(streamSeed(seed, kLaughter)),
      gaze_(streamSeed(seed, kGaze)),
      blinks_(streamSeed(seed, kBlinks)) {}

MoodFrame MoodGenerator::step(double seconds, const MoodLevels& levels) {
  if (!std::isfinite(seconds)) seconds = last_;
  const double dt = started_ ? std::max(0.0, seconds - last_) : 0.0;
  if (started_) seconds = std::max(seconds, last_);
  MoodLevels target;
  for (int m = 0; m < kMoodCount; ++m) target.level[m] = unitLevel(levels.level[m]);
  for (int m = 0; m < kMoodCount; ++m)
    eased_.level[m] =
        started_ ? approach(eased_.level[m], target.level[m], dt, kMoodLag) : target.level[m];
  started_ = true;
  last_ = seconds;

  const MoodLevels& mood = eased_;
  tears_.advance(dt, mood);
  sob_.advance(seconds, mood[Mood::Sadness], mood[Mood::Anger]);
  laughter_.advance(seconds, mood[Mood::Joy]);
  gaze_.advance(seconds, mood[Mood::Sadness], mood[Mood::Shame]);
  blinks_.advance(seconds, dt, tears_.tearful(), tears_.crying());
  colour_.advance(dt, tears_.tearful(), mood);

  MoodFrame frame;
  expression_.apply(mood, tears_.crying(), seconds, frame.channels);
  sob_.apply(frame.channels);
  laughter_.apply(frame.channels);
  gaze_.apply(frame.channels);
  blinks_.apply(frame.channels);
  const auto [left, right] = tears_.counts();
  frame.channels[channelIndex(kTearLeftFap)] = static_cast<float>(left);
  frame.channels[channelIndex(kTearRightFap)] = static_cast<float>(right);
  for (int fap = 1; fap <= kChannelCount; ++fap) {
    const ChannelRange range = generatedRange(fap);
    float& value = frame.channels[channelIndex(fap)];
    value = std::clamp(std::round(value), range.min, range.max);
  }
  frame.colours = colour_.colours();
  return frame;
}

MoodTake generateMoodTake(const MoodScript& script, std::uint64_t seed, double seconds,
                          double fps) {
  return generateMoodTake([&script](double t) { return script.at(t); }, seed, seconds, fps);
}

MoodTake generateMoodTake(const std::function<MoodLevels(double)>& moodsAt, std::uint64_t seed,
                          double seconds, double fps) {
  if (!(fps > 0 && fps <= 1000))
    throw std::invalid_argument("expected a frame rate in (0, 1000] per second");
  if (!(seconds >= 0 && seconds <= kMaxMoodSeconds))
    throw std::invalid_argument("expected a length from 0 to 86400 s");
  const double frames = std::floor(seconds * fps + 1e-9) + 1;
  if (frames > kMaxBakedFrames)
    throw std::invalid_argument(std::to_string(static_cast<long long>(frames)) +
                                " frames; at most " +
                                std::to_string(static_cast<long long>(kMaxBakedFrames)) +
                                " can be played or exported (shorten it or lower the rate)");
  const auto n = static_cast<std::size_t>(frames);
  MoodTake take;
  take.animation.name = "mood";
  take.animation.fps = fps;
  take.animation.frames.reserve(n);
  take.colours.reserve(n);
  MoodGenerator generator(seed);
  for (std::size_t i = 0; i < n; ++i) {
    const double t = static_cast<double>(i) / fps;
    const MoodFrame frame = generator.step(t, moodsAt(t));
    take.animation.frames.push_back(frame.channels);
    take.colours.push_back(frame.colours);
  }
  take.animation.animated = take.animation.usedChannels();
  return take;
}

}  // namespace lacrima::inline common
