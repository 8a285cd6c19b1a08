#pragma once
// A live stream on a rigged head: frames pushed as they arrive (from a network input, a test or
// a benchmark), the newest one shown. Not seekable. Each seek(t) of the display clock poses the
// face for the newest frame at once, on the caller's thread, and asks for the tears to advance
// by the time since their last step (capped, so a stalled display slows the tears down instead
// of making them jump): the tears keep running between frames and after a stream stops.
//
// The tears step on a worker thread (PreviewWorker, as the editor's preview), so a new frame is
// never kept waiting for a tear step: seek() shows the newest face with the tears of the last
// step that has finished. So the tears are one step behind the face; when a step takes longer
// than a display interval, the face is shown anew over the same tears until the step ends. A
// step is asked for only when the worker is idle, with the time since the previous step, so
// every step asked for runs, in order: the tears are the same as a FrameProducer called with
// the same values and steps on the caller's thread, for any thread count; only when they show
// depends on the worker's speed.
//
// Moods (docs/mood.md) drive the face instead of frames: after setMoods() the crying generator
// (MoodGenerator) makes every channel and the face colours at the display's clock, until the
// next frame is pushed; the next setMoods() takes over again (the newest message wins). New
// levels are targets the generator's moods ease toward (MoodGenerator::kMoodLag), so a change
// never jumps. The generator's tear channels are the tears: none is simulated while it makes
// none.
//
// Tear channels a frame does not carry (a phone's blendshapes cannot) come from setTears(), the
// player's own controls.
#include <lacrima/common/FapChannels.h>
#include <lacrima/common/mood/Moods.h>
#include <lacrima/playback/AnimationSource.h>
#include <lacrima/playback/PreviewWorker.h>

#include <cstdint>
#include <functional>
#include <memory>

namespace lacrima::playback {

class LiveSource : public AnimationSource {
 public:
  // Longest step of the tears: a display that stalls longer loses that time.
  static constexpr double kMaxStep = 0.1;
  // Shortest step worth simulating: a display asking more often only re-poses the face.
  static constexpr double kMinStep = 1.0 / 240.0;

  // `rig` outlives the source (the tear worker is joined by the destructor).
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

  long long framesReceived() const;
  long long framesDropped() const;  // replaced before any seek() showed them
  bool frameWaiting() const;        // a frame pushed that no seek() has shown yet
  // Arrival time of the frame the last seek() showed first; negative when it showed no new one.
  double shownArrival() const;
  // The values the last seek() showed, tears included.
  const FapValues& shownValues() const;

  // The generator's moods from now on (each clamped to [0, 1]); it starts, with moodSeed(), if it
  // was not driving the face.
  void setMoods(const MoodLevels& levels);
  // Another take: the generator starts again from `seed` at the moods set (its tears well anew).
  void setMoodSeed(std::uint64_t seed);
  std::uint64_t moodSeed() const;
  const MoodLevels& moods() const;
  bool moodDriven() const;  // the generator drives the face (no frame pushed since setMoods)

  // The tear frame the last seek() showed (null without tears), with its particle count and
  // the cost of the step that made it.
  std::shared_ptr<const PreviewFrame> tearFrame() const;
  int particleCount() const;
  // Tear steps asked for so far (each runs, in order) and those finished.
  long long tearStepsRequested() const;
  long long tearStepsDone() const;
  // Blocks until the tear step in flight (if any) has ended; the next seek() shows it. Tests,
  // benchmarks and scripted runs that want every seek to step.
  void waitForTears() const;
  // Tests only: runs on the worker thread just before each tear step (PreviewWorker).
  void setBeforeTearStep(std::function<void()> hook);

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
  // The face's producer (posed on the caller's thread; it never simulates). The tears' figures
  // are tearFrame()'s.
  const FrameProducer& producer() const override;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace lacrima::playback
