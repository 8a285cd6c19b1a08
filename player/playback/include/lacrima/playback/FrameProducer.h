#pragma once
// Turns FAP values into frames: pose blending, then -- only when a tear channel is non-zero or
// tears are still on the face -- the tear simulation, its surface and its trails, and the
// texture-blend weights. Shared by the player (driven by Playback) and the editor's live preview
// (driven by the sliders). Engine-free: no OGRE, no Qt Widgets.
#include <lacrima/common/FapChannels.h>
#include <lacrima/common/ProjectDocument.h>
#include <lacrima/playback/FrameView.h>
#include <lacrima/playback/HeadRig.h>
#include <lacrima/tears/SimulationOptions.h>
#include <lacrima/tears/TearSettings.h>

#include <cstdint>
#include <memory>

namespace lacrima::playback {

// Milliseconds spent per stage in the last produce() call, and the simulation's sub-steps in
// it (0 when no tears were simulated): what a quality level costs (TearQualityOptions.h).
struct ProducerTimes {
  double blend = 0, simulation = 0, surface = 0, trails = 0;
  long long substeps = 0;
  double total() const { return blend + simulation + surface + trails; }
};

// Work counters since construction or reset(): tests use them to prove effects on demand.
struct ProducerCounters {
  long long frames = 0, blends = 0, simulationSteps = 0, surfaceRuns = 0, trailRuns = 0;
};

// Whether `values` ask `rig` for tears: a tear channel (FAP 69 / 70) at 1 or more whose eye the
// rig does not disable (a head without an eye weeps none, RigBuilder.h). TearSimulation reads
// the counts the same way (floor, at least 0).
bool tearsCommanded(const HeadRig& rig, const FapValues& values);

// Whether going from scene `before` to `after` restarts the tears: the tear parameters or the
// quality (level or advanced choices) differ. The effect toggles never restart them.
bool restartsTears(const SceneSettings& before, const SceneSettings& after);

class FrameProducer {
 public:
  explicit FrameProducer(const HeadRig& rig, const SceneSettings& scene = {});
  ~FrameProducer();
  FrameProducer(const FrameProducer&) = delete;
  FrameProducer& operator=(const FrameProducer&) = delete;

  // Effects, simulation overrides and quality. Changing the simulation parameters or the
  // quality restarts the tears (restartsTears).
  void setScene(const SceneSettings& scene);
  const SceneSettings& scene() const;
  // What the next tears are simulated with: simulationOptions(scene().quality) with the threads
  // set here.
  const tears::SimulationOptions& simulationOptions() const;
  // Threads the tear simulation shares (SimulationOptions::threads; 0, the default, lets the
  // simulation choose: LACRIMA_THREADS, else every hardware thread). The tears are the same for
  // any count, so nothing restarts: tears already under way keep theirs, the next ones use it.
  void setSimulationThreads(int threads);
  // Tear sources in the head frame; nullopt entries keep the rig's default under each eye.
  void setTearSources(const TearSources& sources);

  // Colours the animation keys for the frames that follow (a project's colour curves at their
  // time; Playback sets them before each frame): each replaces the computed one (Overlays.h).
  // Default: none.
  void setKeyedColours(const KeyedColours& colours);

  // Advances by dt seconds with these channel values. `progress` in [0, 1] is how far through
  // the animation this frame is (the 2009 redness ramp); the editor passes 0 or its time ratio.
  const FrameView& produce(const FapValues& values, double dt, double progress);
  // Re-blends the face for `values` without advancing the tears (scrubbing between frames,
  // slider drags in a paused editor).
  const FrameView& pose(const FapValues& values);
  // Same, moving the redness ramp to `progress` too (a player between two frames).
  const FrameView& pose(const FapValues& values, double progress);
  const FrameView& view() const;

  // Neutral face, no tears, no trails, redness 0.
  void reset();
  // No tears and no trails; the face and the redness stay as they are.
  void clearTears();

  // Full state of the tears (simulation, trails, wetness history): restoring it and producing
  // the same inputs again gives bitwise-identical frames. A checkpoint holding tears is void
  // once the tear parameters, quality or sources change (restore throws
  // std::invalid_argument); one taken before any tear stays valid. The face is re-blended from
  // the checkpoint's values.
  class Checkpoint;
  std::shared_ptr<const Checkpoint> checkpoint() const;
  void restore(const Checkpoint& checkpoint);
  // Memory a checkpoint holds: the simulation's state, the trails, the face's values.
  static std::size_t bytes(const Checkpoint& checkpoint);

  const ProducerTimes& lastTimes() const;
  const ProducerCounters& counters() const;
  int particleCount() const;
  // tears::stateHash of the particles now (0 before any tear): what batches record to prove
  // that two runs simulated the same tears, bit for bit.
  std::uint64_t tearStateHash() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace lacrima::playback
