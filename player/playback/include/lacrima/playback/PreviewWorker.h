#pragma once
// The tears of a live preview on their own thread, so the window never waits for them.
//
// A PreviewWorker owns a FrameProducer and a thread that alone touches it. The UI thread hands
// over requests (channel values, dt, animation progress) and takes back finished frames:
//
//   UI thread                          worker thread
//   request(r1) ──────────────────────> produce(r1)  ...  publish frame 1 -> frameReady()
//   request(r2) -> pending                                 |
//   request(r3) -> replaces r2 (dropped)                   v
//   currentFrame() = frame 1           produce(r3) ...     publish frame 3
//
// Frames are dropped, never queued: while a step runs, a newer request replaces the pending
// one, so at most one step runs and one waits, whatever the request rate (the simulation then
// advances by the newest request's dt per step: slower than the wall clock, never further
// behind). A PreviewFrame owns copies of what it shows, so the UI draws it while the next step
// runs.
//
// Only what a scene calls for is simulated: a request whose tear channels are all 0 (or whose
// eyes the rig disables) clears the tears instead of stepping them, and clearTears() does the
// same. A live stream (LiveSource) turns that off with setStepsDryRequests(true): channels at 0
// are then stepped as in a file (the particles beyond the count leave, the trails dry). Both take
// effect for the UI at once: currentFrame() becomes null before returning, and the step still
// running (which cannot be interrupted) is discarded when it ends. Changing the simulation
// parameters or the tear sources does too (the producer restarts the tears).
//
// Each step is the FrameProducer's produce(), unchanged: answering every request in turn
// (waitIdle() between them) gives bit-identical frames to a FrameProducer called directly.
//
// Lifetime: the worker shares the rig, so it may outlive its owner's interest in that head.
// stop() lets the running step end without starting another and returns at once; the
// destructor also waits for the thread (at most the one running step). No callback runs after
// the destructor returns. Engine-free: the standard library's threads, no Qt, no OGRE.
#include <lacrima/playback/FrameProducer.h>
#include <lacrima/tears/ParticleSet.h>
#include <lacrima/tears/SurfaceMesher.h>
#include <lacrima/tears/TrailBuilder.h>

#include <condition_variable>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>

namespace lacrima::playback {

// Advance the tears by `dt` seconds with these channel values (FrameProducer::produce).
struct PreviewRequest {
  FapValues values{};
  double dt = 0;
  double progress = 0;  // through the animation, [0, 1] (the redness ramp)
};

// A finished frame: the tears (and the overlay weights they drive) of one step, copied out of
// the producer. The face is not included: a preview poses it on its own thread at once.
class PreviewFrame {
 public:
  long long request = 0;  // sequence number of the request it answers (1, 2, ...)
  int particleCount = 0;  // simulated, whether or not particle spheres are drawn
  ProducerTimes times;    // of the step that made it
  OverlayWeights overlays;
  double particleRadius = 0;
  // Present when the scene draws them (FrameView's rules).
  std::optional<tears::ParticleSet> particles;
  std::optional<tears::TearSurface> surface, drops;
  std::optional<tears::TrailMesh> trails;

  // `face` (a posed frame of the same head) with these tears and overlays; pointers into this
  // frame and into `face`'s buffers. The revision is left as `face` has it.
  FrameView over(const FrameView& face) const;
};

struct PreviewWorkerCounters {
  long long requests = 0;   // request() calls
  long long steps = 0;      // produce() calls
  long long dropped = 0;    // requests replaced before they ran
  long long discarded = 0;  // finished steps not handed out (tears cleared meanwhile)
  long long clears = 0;     // tears cleared on the worker
};

class PreviewWorker {
 public:
  // `simulationThreads`: FrameProducer::setSimulationThreads, before the thread starts.
  PreviewWorker(std::shared_ptr<const HeadRig> rig, const SceneSettings& scene,
                const TearSources& sources, int simulationThreads = 0);
  ~PreviewWorker();
  PreviewWorker(const PreviewWorker&) = delete;
  PreviewWorker& operator=(const PreviewWorker&) = delete;

  // Called on the worker thread each time a new frame is published (post it to your own
  // thread from there). Set it before the first request.
  void setFrameReady(std::function<void()> callback);
  // Tests only: runs on the worker thread just before each step, outside the lock (a test
  // holds a step "running" with it).
  void setBeforeStep(std::function<void()> hook);
  // On: a request without a tear channel is stepped like any other (FrameProducer::produce
  // decides what is left to simulate) instead of clearing the tears. Off by default.
  void setStepsDryRequests(bool on);

  // Queues `r`, replacing a request not yet started. Without a tear channel > 0 this is
  // clearTears() (and nothing is simulated).
  void request(const PreviewRequest& r);
  // No tears from now on: currentFrame() is null at once; the worker clears its simulation.
  void clearTears();
  // As clearTears(), and the redness and the producer's counters start again too
  // (FrameProducer::reset; the worker's own face goes neutral).
  void reset();
  // FrameProducer::setSimulationThreads for the following steps (the tears are the same for
  // any count, so nothing restarts).
  void setSimulationThreads(int threads);
  // Effects and simulation overrides / tear sources for the following steps. A change of the
  // simulation parameters or of the sources clears the tears as clearTears() does.
  void setScene(const SceneSettings& scene);
  void setTearSources(const TearSources& sources);

  // The newest frame of the current tears (null before the first or after a clear).
  std::shared_ptr<const PreviewFrame> currentFrame() const;
  // A request is waiting or a step (or clear) running.
  bool busy() const;
  // Blocks until nothing is waiting or running (tests, benchmarks, batch screenshots).
  void waitIdle() const;
  // Lets the running step finish and starts nothing more; returns at once. frameReady is not
  // called for a step ending after this (a call already under way may still finish).
  void stop();
  // The thread has left its loop after stop(): destroying the worker now does not wait.
  bool stopped() const;
  PreviewWorkerCounters counters() const;

 private:
  void run();

  std::shared_ptr<const HeadRig> rig_;
  FrameProducer producer_;  // the worker thread's alone once it runs

  mutable std::mutex mutex_;
  mutable std::condition_variable wake_, idle_;
  // Guarded by mutex_.
  std::optional<PreviewRequest> pending_;
  long long pendingNumber_ = 0, requests_ = 0;
  bool clearPending_ = false, resetPending_ = false;
  bool stepsDry_ = false;
  std::optional<int> threadsPending_;
  bool tearsAsked_ = false;  // a request since the last clear (else a clear has nothing to do)
  std::optional<SceneSettings> scenePending_;
  std::optional<TearSources> sourcesPending_;
  SceneSettings scene_;  // as last set (decides what a setScene change clears)
  TearSources sources_;
  // Bumped by every clear: a step that started in an older epoch is discarded when it ends.
  long long epoch_ = 0;
  bool running_ = false, stopping_ = false, exited_ = false;
  std::shared_ptr<const PreviewFrame> current_;
  PreviewWorkerCounters counters_;
  std::function<void()> frameReady_, beforeStep_;

  std::thread thread_;  // last: starts once everything above exists
};

}  // namespace lacrima::playback
