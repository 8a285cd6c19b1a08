#pragma once
// A live stream on a rigged head: frames pushed as they arrive (from a network input, a test or
// a benchmark), the newest one shown. Not seekable. Each seek(t) of the display clock shows the
// newest frame and advances the tears by the time since the previous call (capped, so a stalled
// display slows the tears down instead of making them jump), so the tears keep running between
// frames and after a stream stops, at the pace the display asks.
//
// Tear channels a frame does not carry (a phone's blendshapes cannot) come from setTears(), the
// player's own controls.
//
// Moods (docs/mood.md) drive the face instead of frames: after setMoods() the crying generator
// (MoodGenerator) makes every channel and the face colours at the display's clock, until the
// next frame is pushed; the next setMoods() takes over again (the newest message wins). New
// levels are targets the generator's moods ease toward (MoodGenerator::kMoodLag), so a change
// never jumps. The generator's tear channels are the tears: none is simulated while it makes
// none.
#include <lacrima/common/FapChannels.h>
#include <lacrima/common/mood/Moods.h>
#include <lacrima/playback/AnimationSource.h>

#include <cstdint>
#include <memory>

namespace lacrima::playback {

class LiveSource : public AnimationSource {
 public:
  // Longest step of the tears per seek(): a display that stalls longer loses that time.
  static constexpr double kMaxStep = 0.1;
  // Shortest step worth simulating: a display asking more often only re-poses the face.
  static constexpr double kMinStep = 1.0 / 240.0;

  explicit LiveSource(const HeadRig& rig);
  ~LiveSource() override;

  // The newest frame: `mask` names the channels it sets (others neutral), `arrival` when it came
  // (seconds of the caller's clock; kept for latency figures). A frame not yet shown when the
  // next one comes is dropped (counted).
  void push(const FapValues& values, const ChannelMask& mask, double arrival);
  // Particles at each eye for frames that carry no tear channel.
  void setTears(float left, float right);
  float tearsLeft() const;
  float tearsRight() const;

  // The generator's moods from now on (each clamped to [0, 1]); it starts, with moodSeed(), if it
  // was not driving the face.
  void setMoods(const MoodLevels& levels);
  // Another take: the generator starts again from `seed` at the moods set (its tears well anew).
  void setMoodSeed(std::uint64_t seed);
  std::uint64_t moodSeed() const;
  const MoodLevels& moods() const;
  bool moodDriven() const;  // the generator drives the face (no frame pushed since setMoods)

  long long framesReceived() const;
  long long framesDropped() const;  // replaced before any seek() showed them
  // Arrival time of the frame the last seek() showed first; negative when it showed no new one.
  double shownArrival() const;
  // The values the last seek() showed, tears included.
  const FapValues& shownValues() const;

  bool seekable() const override { return false; }
  const FrameView& seek(double seconds) override;
  const FrameView& view() const override;
  double currentTime() const override;
  int currentFrame() const override;
  int frameCount() const override;
  double frameRate() const override;
  void setFrameRate(double fps);  // the rate the stream names, when it names one
  double duration() const override { return 0; }
  bool hasTears() const override;
  void setScene(const SceneSettings& scene) override;
  const SceneSettings& scene() const override;
  void setSimulationThreads(int threads) override;
  void reset() override;
  const FrameProducer& producer() const override;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace lacrima::playback
