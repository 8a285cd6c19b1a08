// Playback (Playback.h): frames fed to the producer in order, checkpoints as they pass, replays
// from the nearest earlier checkpoint when going back.
#include <lacrima/common/FapChannels.h>
#include <lacrima/playback/AnimationFile.h>
#include <lacrima/playback/Playback.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>

namespace lacrima::playback {

struct Playback::State {
  const HeadRig& rig;
  const int firstInterval;
  const std::size_t budget;
  int interval;
  FrameProducer producer;
  FapAnimation animation;
  std::string path;
  Warnings warnings;
  SceneSettings scene;
  TearSources sources;
  FaceColourCurves colours;
  std::shared_ptr<const MoodLayerTake> mood;  // a project's mood layer, for its colours
  double colourStart = 0;

  KeyedColours coloursAt(double seconds) const {
    return mixMoodColours(colours.at(seconds), mood.get(), seconds);
  }
  // Producer state just BEFORE producing frame k, by k. Going to frame f restores the largest
  // k <= f and produces k..f, so a restore is always followed by a fresh frame.
  struct Stored {
    std::shared_ptr<const FrameProducer::Checkpoint> checkpoint;
    std::size_t bytes = 0;
  };
  std::map<int, Stored> checkpoints;
  std::size_t held = 0;  // bytes in `checkpoints`
  int nextFrame = 0;     // the next frame to produce
  double time = 0;
  long long simulated = 0;

  State(const HeadRig& r, int checkpointInterval, std::size_t checkpointBudget)
      : rig(r),
        firstInterval(std::max(1, checkpointInterval)),
        budget(checkpointBudget),
        interval(firstInterval),
        producer(r) {}

  void clearCheckpoints() {
    checkpoints.clear();
    held = 0;
    interval = firstInterval;
  }

  void keep(int frame) {
    Stored stored{producer.checkpoint(), 0};
    stored.bytes = FrameProducer::bytes(*stored.checkpoint);
    held += stored.bytes;
    checkpoints[frame] = std::move(stored);
    // Over budget: keep every other one (the multiples of twice the interval; frame 0's is
    // one), so they stay evenly spaced and later ones are taken at the new spacing.
    while (held > budget && checkpoints.size() > 1 &&
           interval <= std::numeric_limits<int>::max() / 2) {
      interval *= 2;
      for (auto it = checkpoints.begin(); it != checkpoints.end();) {
        if (it->first % interval != 0) {
          held -= it->second.bytes;
          it = checkpoints.erase(it);
        } else {
          ++it;
        }
      }
    }
  }

  double progressAt(double seconds) const {
    const double d = animation.duration();
    return d > 0 ? std::clamp(seconds / d, 0.0, 1.0) : 0.0;
  }

  int frameAt(double seconds) const {
    const int last = animation.frameCount() - 1;
    // A small tolerance so that t = k / fps, computed in floating point, lands on frame k.
    return std::clamp(static_cast<int>(std::floor(seconds * animation.fps + 1e-6)), 0, last);
  }

  void produceUpTo(int frame) {
    if (frame < nextFrame - 1) {
      auto it = checkpoints.upper_bound(frame);
      if (it == checkpoints.begin()) {  // frame 0's is taken first, so this is only a guard
        producer.reset();
        nextFrame = 0;
      } else {
        --it;
        producer.restore(*it->second.checkpoint);
        nextFrame = it->first;
      }
    }
    const double dt = 1.0 / animation.fps;
    for (; nextFrame <= frame; ++nextFrame) {
      if (nextFrame % interval == 0 && !checkpoints.contains(nextFrame)) keep(nextFrame);
      producer.setKeyedColours(coloursAt(colourStart + nextFrame / animation.fps));
      producer.produce(animation.frames[static_cast<std::size_t>(nextFrame)], dt,
                       progressAt(nextFrame / animation.fps));
      ++simulated;
    }
  }
};

Playback::Playback(const HeadRig& rig, int checkpointInterval, std::size_t checkpointBudget)
    : state_(std::make_unique<State>(rig, checkpointInterval, checkpointBudget)) {}

Playback::~Playback() = default;

void Playback::open(const std::string& path) {
  AnimationFile file = readAnimationFile(path);  // throws; nothing has changed yet
  try {
    setAnimation(std::move(file.animation), file.scene, file.tearSources);
    setColourCurves(std::move(file.colours), file.startTime, std::move(file.moodTake));
  } catch (const std::invalid_argument& e) {
    throw FileError({path, 0, 0}, e.what());
  }
  state_->path = path;
  state_->warnings = std::move(file.warnings);
}

void Playback::setAnimation(FapAnimation animation, const SceneSettings& scene,
                            const TearSources& sources) {
  if (animation.frames.empty()) throw std::invalid_argument("the animation has no frames");
  if (!(animation.fps > 0) || !std::isfinite(animation.fps))
    throw std::invalid_argument("the animation's frame rate is not a positive number");
  for (const auto& point : {sources.left, sources.right})
    if (point && !point->allFinite())
      throw std::invalid_argument("a tear source is not a finite point");
  State& s = *state_;
  s.producer.setScene(scene);  // throws for invalid tear parameters before anything changes
  s.animation = std::move(animation);
  s.scene = scene;
  s.sources = sources;
  s.colours = {};
  s.mood.reset();
  s.colourStart = 0;
  s.path.clear();
  s.warnings.clear();
  s.clearCheckpoints();
  s.producer.setTearSources(sources);
  s.producer.reset();
  s.nextFrame = 0;
  s.time = 0;
  seek(0);
}

void Playback::setColourCurves(FaceColourCurves curves, double startTime,
                               std::shared_ptr<const MoodLayerTake> mood) {
  State& s = *state_;
  s.colours = std::move(curves);
  s.mood = std::move(mood);
  s.colourStart = std::isfinite(startTime) ? startTime : 0.0;
  if (!s.animation.frames.empty()) seek(s.time);  // the frame shown takes them at once
}

void Playback::removeTears() {
  State& s = *state_;
  if (!s.animation.hasTears()) return;
  for (FapValues& frame : s.animation.frames) {
    frame[channelIndex(kTearLeftFap)] = 0;
    frame[channelIndex(kTearRightFap)] = 0;
  }
  s.clearCheckpoints();
  s.producer.reset();
  s.nextFrame = 0;
  seek(s.time);
}

const FapAnimation& Playback::animation() const { return state_->animation; }
const std::string& Playback::path() const { return state_->path; }
const Warnings& Playback::warnings() const { return state_->warnings; }
const TearSources& Playback::tearSources() const { return state_->sources; }

int Playback::frameCount() const { return state_->animation.frameCount(); }
double Playback::frameRate() const { return state_->animation.fps; }
double Playback::duration() const { return state_->animation.duration(); }
bool Playback::hasTears() const { return state_->animation.hasTears(); }

void Playback::setScene(const SceneSettings& scene) {
  State& s = *state_;
  const bool restart = restartsTears(s.scene, scene);
  s.producer.setScene(scene);
  s.scene = scene;
  if (restart && !s.animation.frames.empty()) {
    // New parameters make every stored state wrong: replay from the start to where we were,
    // so the picture is what a straight play with these parameters shows.
    s.clearCheckpoints();
    s.nextFrame = 0;
    seek(s.time);
  }
}

void Playback::setSimulationThreads(int threads) { state_->producer.setSimulationThreads(threads); }

const SceneSettings& Playback::scene() const { return state_->scene; }

const FrameView& Playback::seek(double seconds) {
  State& s = *state_;
  if (s.animation.frames.empty()) return s.producer.view();
  const double t = std::isfinite(seconds) ? std::clamp(seconds, 0.0, s.animation.duration()) : 0.0;
  s.produceUpTo(s.frameAt(t));
  s.time = t;
  s.producer.setKeyedColours(s.coloursAt(s.colourStart + t));
  return s.producer.pose(s.animation.sample(t), s.progressAt(t));
}

const FrameView& Playback::view() const { return state_->producer.view(); }
int Playback::currentFrame() const { return std::max(0, state_->nextFrame - 1); }
double Playback::currentTime() const { return state_->time; }

void Playback::reset() {
  State& s = *state_;
  s.producer.reset();
  s.nextFrame = 0;
  s.time = 0;
}

const FrameProducer& Playback::producer() const { return state_->producer; }
int Playback::checkpointCount() const { return static_cast<int>(state_->checkpoints.size()); }
std::size_t Playback::checkpointBytes() const { return state_->held; }
int Playback::checkpointInterval() const { return state_->interval; }
long long Playback::framesSimulated() const { return state_->simulated; }

}  // namespace lacrima::playback
