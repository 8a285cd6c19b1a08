#pragma once
// An animation playing on a rigged head: a FAP file or a project, its frames fed to a
// FrameProducer at the file's rate, with seeking. The tears are deterministic, so going back
// restores the nearest earlier checkpoint (one every `checkpointInterval` frames) and replays
// forward from it; going forward steps on from the current frame.
//
// The checkpoints' memory is bounded: when they hold more than `checkpointBudget` bytes (a
// checkpoint is about 3.5 MB at 10,000 tear particles, so a 10-minute animation at one a second
// would hold 2 GB), every other one is dropped and the interval doubles. Seeking back then
// replays more frames, never more memory; frame 0's checkpoint always stays.
//
// The tears advance once per animation frame (dt = 1 / fps). Between frames, the face is
// interpolated (FapAnimation::sample) so a viewport rendering faster than the file stays smooth.
#include <lacrima/common/Diagnostics.h>
#include <lacrima/common/FapAnimation.h>
#include <lacrima/common/ProjectDocument.h>
#include <lacrima/playback/AnimationSource.h>
#include <lacrima/playback/FrameProducer.h>

#include <cstddef>
#include <memory>
#include <string>

namespace lacrima::playback {

class Playback : public AnimationSource {
 public:
  static constexpr std::size_t kCheckpointBudget = std::size_t{512} << 20;

  explicit Playback(const HeadRig& rig, int checkpointInterval = 50,
                    std::size_t checkpointBudget = kCheckpointBudget);
  ~Playback() override;

  // A .fap file or a project (.json, .lacrima). Throws FileError (file, line, what was expected);
  // on error the current animation stays loaded. Shows the first frame.
  void open(const std::string& path);
  void setAnimation(FapAnimation animation, const SceneSettings& scene = {},
                    const TearSources& sources = {});
  // Colours keyed over the animation (a project's, FaceColours.h), read at startTime + the
  // playing time; they replace the computed redness and blush. open() sets a project's;
  // setAnimation() clears them. They never restart the tears. `mood`: a project's mood layer,
  // whose colours replace them within its range (mixMoodColours, MoodLayer.h).
  void setColourCurves(FaceColourCurves curves, double startTime = 0,
                       std::shared_ptr<const MoodLayerTake> mood = {});
  // Drops the tear channels (FAP 69/70) from the animation loaded: the same face, colours and
  // timing without a tear, and no simulation (the "without tears" half of a paired stimulus).
  // Shows the current time again.
  void removeTears();
  const FapAnimation& animation() const;
  const std::string& path() const;   // empty when set from memory
  const Warnings& warnings() const;  // the FAP reader's for the open file
  const TearSources& tearSources() const;

  bool seekable() const override { return true; }
  int frameCount() const override;
  double frameRate() const override;
  double duration() const override;
  // True when the animation drives a tear channel; false means no simulation will ever run.
  bool hasTears() const override;

  void setScene(const SceneSettings& scene) override;  // simulation changes restart the tears
  const SceneSettings& scene() const override;
  // FrameProducer::setSimulationThreads; kept for every animation opened later.
  void setSimulationThreads(int threads) override;

  // Shows time t (clamped to the animation): the tears at the last whole frame <= t, the face
  // interpolated at t.
  const FrameView& seek(double seconds) override;
  const FrameView& view() const override;
  int currentFrame() const override;  // the last whole frame the tears have reached
  double currentTime() const override;

  // Neutral face, all tears gone, time 0. Checkpoints stay valid; the next seek plays from the
  // first frame.
  void reset() override;

  const FrameProducer& producer() const override;
  int checkpointCount() const;
  std::size_t checkpointBytes() const;  // what they hold now
  int checkpointInterval() const;       // frames between them now (doubled at each thinning)
  long long framesSimulated() const;    // produce() calls so far (replays after seeks included)

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace lacrima::playback
