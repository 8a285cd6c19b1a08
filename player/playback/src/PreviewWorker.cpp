// PreviewWorker (PreviewWorker.h): one FrameProducer stepped on its own thread; the newest
// request wins, stale results are thrown away.
#include <lacrima/playback/PreviewWorker.h>

#include <stdexcept>
#include <utility>

#if defined(__linux__)
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>
#endif

namespace lacrima::playback {

namespace {

constexpr int kWorkerNice = 5;  // ~1/3 of the UI thread's share of a busy core

// Copies out of the producer what the frame shows, so the producer may step again.
std::shared_ptr<PreviewFrame> snapshot(const FrameView& view, int particleCount,
                                       const ProducerTimes& times, long long request) {
  auto frame = std::make_shared<PreviewFrame>();
  frame->request = request;
  frame->particleCount = particleCount;
  frame->times = times;
  frame->overlays = view.overlays;
  frame->particleRadius = view.particleRadius;
  if (view.particles) frame->particles = *view.particles;
  if (view.surface) frame->surface = *view.surface;
  if (view.drops) frame->drops = *view.drops;
  if (view.trails) frame->trails = *view.trails;
  return frame;
}

}  // namespace

FrameView PreviewFrame::over(const FrameView& face) const {
  FrameView view = face;
  view.particles = particles ? &*particles : nullptr;
  view.particleRadius = particles ? particleRadius : 0;
  view.surface = surface ? &*surface : nullptr;
  view.drops = drops ? &*drops : nullptr;
  view.trails = trails ? &*trails : nullptr;
  view.overlays = overlays;
  return view;
}

PreviewWorker::PreviewWorker(std::shared_ptr<const HeadRig> rig, const SceneSettings& scene,
                             const TearSources& sources, int simulationThreads)
    : rig_(rig ? std::move(rig)
               : throw std::invalid_argument("PreviewWorker: no head rig to preview")),
      producer_(*rig_, scene),
      scene_(scene),
      sources_(sources) {
  producer_.setTearSources(sources);
  producer_.setSimulationThreads(simulationThreads);
  thread_ = std::thread([this] { run(); });
}

PreviewWorker::~PreviewWorker() {
  stop();
  thread_.join();
}

void PreviewWorker::setFrameReady(std::function<void()> callback) {
  const std::lock_guard lock(mutex_);
  frameReady_ = std::move(callback);
}

void PreviewWorker::setBeforeStep(std::function<void()> hook) {
  const std::lock_guard lock(mutex_);
  beforeStep_ = std::move(hook);
}

void PreviewWorker::setStepsDryRequests(bool on) {
  const std::lock_guard lock(mutex_);
  stepsDry_ = on;
}

void PreviewWorker::request(const PreviewRequest& r) {
  {
    std::unique_lock lock(mutex_);
    if (!stepsDry_ && !tearsCommanded(*rig_, r.values)) {
      lock.unlock();
      clearTears();
      return;
    }
    ++counters_.requests;
    if (pending_) ++counters_.dropped;
    pending_ = r;
    tearsAsked_ = true;
    pendingNumber_ = ++requests_;
  }
  wake_.notify_one();
}

void PreviewWorker::clearTears() {
  {
    const std::lock_guard lock(mutex_);
    if (pending_) ++counters_.dropped;
    pending_.reset();
    if (!tearsAsked_) return;  // none asked for since the last clear: nothing to clear
    tearsAsked_ = false;
    ++epoch_;
    current_.reset();
    clearPending_ = true;
  }
  wake_.notify_one();
}

void PreviewWorker::reset() {
  {
    const std::lock_guard lock(mutex_);
    if (pending_) ++counters_.dropped;
    pending_.reset();
    tearsAsked_ = false;
    ++epoch_;
    current_.reset();
    clearPending_ = true;
    resetPending_ = true;
  }
  wake_.notify_one();
}

void PreviewWorker::setSimulationThreads(int threads) {
  {
    const std::lock_guard lock(mutex_);
    threadsPending_ = threads;
  }
  wake_.notify_one();
}

void PreviewWorker::setScene(const SceneSettings& scene) {
  {
    const std::lock_guard lock(mutex_);
    if (scene == scene_) return;
    if (restartsTears(scene_, scene)) {
      ++epoch_;  // the producer restarts the tears
      current_.reset();
    }
    scene_ = scene;
    scenePending_ = scene;
  }
  wake_.notify_one();
}

void PreviewWorker::setTearSources(const TearSources& sources) {
  {
    const std::lock_guard lock(mutex_);
    if (sources == sources_) return;
    ++epoch_;  // the producer restarts the tears
    current_.reset();
    sources_ = sources;
    sourcesPending_ = sources;
  }
  wake_.notify_one();
}

std::shared_ptr<const PreviewFrame> PreviewWorker::currentFrame() const {
  const std::lock_guard lock(mutex_);
  return current_;
}

bool PreviewWorker::busy() const {
  const std::lock_guard lock(mutex_);
  return running_ || pending_ || clearPending_ || scenePending_ || sourcesPending_ ||
         threadsPending_;
}

void PreviewWorker::waitIdle() const {
  std::unique_lock lock(mutex_);
  idle_.wait(lock, [this] {
    return stopping_ || !(running_ || pending_ || clearPending_ || scenePending_ ||
                          sourcesPending_ || threadsPending_);
  });
}

void PreviewWorker::stop() {
  {
    const std::lock_guard lock(mutex_);
    stopping_ = true;
    frameReady_ = nullptr;
  }
  wake_.notify_one();
  idle_.notify_all();
}

bool PreviewWorker::stopped() const {
  const std::lock_guard lock(mutex_);
  return exited_;
}

PreviewWorkerCounters PreviewWorker::counters() const {
  const std::lock_guard lock(mutex_);
  return counters_;
}

void PreviewWorker::run() {
#if defined(__linux__)
  // A little below the thread that owns the window (Linux schedules threads as tasks, each
  // with its own nice value): when the cores are busy, the UI thread and the GL driver's
  // threads (llvmpipe renders on the CPU) come first and the tears wait. Best effort: a refusal
  // changes nothing but that.
  setpriority(PRIO_PROCESS, static_cast<id_t>(syscall(SYS_gettid)), kWorkerNice);
#endif
  for (;;) {
    // Take everything waiting in one go, under the lock; work outside it.
    std::optional<PreviewRequest> request;
    std::optional<SceneSettings> scene;
    std::optional<TearSources> sources;
    std::optional<int> threads;
    bool clear = false, reset = false;
    long long number = 0, epoch = 0;
    std::function<void()> beforeStep;
    {
      std::unique_lock lock(mutex_);
      wake_.wait(lock, [this] {
        return stopping_ || pending_ || clearPending_ || scenePending_ || sourcesPending_ ||
               threadsPending_;
      });
      if (stopping_) break;
      request = std::exchange(pending_, std::nullopt);
      scene = std::exchange(scenePending_, std::nullopt);
      sources = std::exchange(sourcesPending_, std::nullopt);
      clear = std::exchange(clearPending_, false);
      reset = std::exchange(resetPending_, false);
      threads = std::exchange(threadsPending_, std::nullopt);
      number = pendingNumber_;
      epoch = epoch_;
      beforeStep = beforeStep_;
      running_ = true;
    }

    if (scene) producer_.setScene(*scene);
    if (sources) producer_.setTearSources(*sources);
    if (threads) producer_.setSimulationThreads(*threads);
    if (reset) {
      producer_.reset();
    } else if (clear) {
      producer_.clearTears();
    }
    std::shared_ptr<PreviewFrame> frame;
    if (request) {
      if (beforeStep) beforeStep();
      const FrameView& view = producer_.produce(request->values, request->dt, request->progress);
      frame = snapshot(view, producer_.particleCount(), producer_.lastTimes(), number);
    } else if (scene && !clear && producer_.particleCount() > 0) {
      // Only the effects changed (spheres on, surface off, ...): show the same tears anew.
      frame = snapshot(producer_.view(), producer_.particleCount(), {}, number);
    }

    std::function<void()> frameReady;
    {
      const std::lock_guard lock(mutex_);
      if (request) ++counters_.steps;
      if (clear) ++counters_.clears;
      if (frame && epoch == epoch_) {
        current_ = frame;
        frameReady = frameReady_;
      } else if (frame) {
        ++counters_.discarded;
      }
    }
    // Before the worker counts as idle: waitIdle() returns after the owner has been told.
    if (frameReady) frameReady();
    {
      const std::lock_guard lock(mutex_);
      running_ = false;
    }
    idle_.notify_all();
  }
  {
    const std::lock_guard lock(mutex_);
    exited_ = true;
  }
  idle_.notify_all();
}

}  // namespace lacrima::playback
