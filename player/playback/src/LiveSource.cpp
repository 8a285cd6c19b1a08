// LiveSource (LiveSource.h): the newest frame wins and is posed at once; the tears step on a
// worker with the display's clock and are drawn over the face when they are ready.
#include <lacrima/playback/LiveSource.h>

#include <lacrima/common/mood/MoodGenerator.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace lacrima::playback {

namespace {

// Live streams have no progress through an animation: the eye redness follows the tears shed.
SceneSettings liveScene() {
  SceneSettings scene;
  scene.redness = SceneSettings::Redness::Tears;
  return scene;
}

// The worker shares its rig by shared_ptr; the source's rig is its owner's, which outlives the
// source and so the worker (joined by its destructor): share it without owning it.
std::shared_ptr<const HeadRig> unowned(const HeadRig& rig) {
  return {std::shared_ptr<const HeadRig>{}, &rig};
}

}  // namespace

struct LiveSource::State {
  FrameProducer face;  // poses only, on the caller's thread
  PreviewWorker tears;
  SceneSettings scene = liveScene();
  FapValues newest{};
  ChannelMask newestMask;
  double newestArrival = -1;
  bool fresh = false;  // newest not shown yet
  float tearCounts[2] = {0, 0};
  FapValues shown{};
  double shownArrival = -1;
  double time = 0;   // of the last tear step asked for (or the last seek without tears)
  double clock = 0;  // of the last seek
  bool started = false;
  double fps = 0;
  long long received = 0, dropped = 0, frames = 0, stepsRequested = 0;
  bool everTears = false;
  // What the display is given: the face with the tear frame drawn over it.
  FrameView composed;
  long long faceRevision = -1, revision = 0;
  std::shared_ptr<const PreviewFrame> tearFrame;
  bool composedOnce = false;
  // The crying generator, once moods were set; kept while frames drive the face.
  std::unique_ptr<MoodGenerator> generator;
  bool moodDriven = false, moodFresh = false;
  MoodLevels moods;
  std::uint64_t seed = 1;
  double moodTime = 0;   // the generator's clock: the display's steps added up
  double moodClock = 0;  // the seek that last stepped it

  explicit State(const HeadRig& rig)
      : face(rig, liveScene()), tears(unowned(rig), liveScene(), TearSources{}) {
    tears.setStepsDryRequests(true);  // tears shed run down and dry as in a file
  }

  // A new take that starts from a neutral face, so the first moods ease in rather than jump.
  void startGenerator() {
    generator = std::make_unique<MoodGenerator>(seed);
    moodTime = 0;
    generator->step(0, MoodLevels{});
    moodFresh = true;
  }

  // The generator `dt` seconds on (0: its frame again): its channels, and its colours keyed on
  // the face (compose() draws them over the tears' own).
  FapValues generate(double dt) {
    moodTime += dt;
    const MoodFrame frame = generator->step(moodTime, moods);
    face.setKeyedColours({frame.colours.redness, frame.colours.blush});
    moodFresh = false;
    ++frames;
    return frame.channels;
  }

  FapValues valuesToShow() const {
    FapValues values = newest;
    const int faps[2] = {kTearLeftFap, kTearRightFap};
    for (int eye = 0; eye < 2; ++eye) {
      const auto c = static_cast<std::size_t>(channelIndex(faps[eye]));
      if (!newestMask.test(c)) values[c] = tearCounts[eye];
    }
    return values;
  }

  // A new revision only when the face or the tear frame changed: the display skips the rest.
  const FrameView& compose() {
    const FrameView& posed = face.view();
    auto frame = tears.currentFrame();
    if (composedOnce && posed.revision == faceRevision && frame == tearFrame) return composed;
    composedOnce = true;
    faceRevision = posed.revision;
    tearFrame = std::move(frame);
    composed = tearFrame ? tearFrame->over(posed) : posed;
    if (moodDriven) {  // the generator's colours replace what the tears would make
      composed.overlays.redness = posed.overlays.redness;
      composed.overlays.blush = posed.overlays.blush;
    }
    composed.revision = ++revision;
    return composed;
  }
};

LiveSource::LiveSource(const HeadRig& rig) : state_(std::make_unique<State>(rig)) {
  state_->compose();
}
LiveSource::~LiveSource() = default;

void LiveSource::push(const FapValues& values, const ChannelMask& mask, double arrival) {
  State& s = *state_;
  if (s.fresh) ++s.dropped;
  s.newest = values;
  s.newestMask = mask;
  s.newestArrival = arrival;
  s.fresh = true;
  ++s.received;
  if (s.moodDriven) {
    s.moodDriven = false;  // the newest message wins: frames again
    s.face.setKeyedColours({});
  }
  if (mask.test(channelIndex(kTearLeftFap)) || mask.test(channelIndex(kTearRightFap)))
    s.everTears = true;
}

void LiveSource::setTears(float left, float right) {
  const auto clean = [](float v) {
    return std::isfinite(v) ? std::clamp(std::floor(v), 0.0F, float(kMaxTearParticles)) : 0.0F;
  };
  state_->tearCounts[0] = clean(left);
  state_->tearCounts[1] = clean(right);
}

void LiveSource::setMoods(const MoodLevels& levels) {
  State& s = *state_;
  for (int m = 0; m < kMoodCount; ++m) {
    const double level = levels.level[static_cast<std::size_t>(m)];
    s.moods.level[static_cast<std::size_t>(m)] =
        std::isfinite(level) ? std::clamp(level, 0.0, 1.0) : 0.0;
  }
  if (!s.generator) s.startGenerator();
  if (!s.moodDriven) {
    s.moodFresh = true;
    s.moodClock = s.clock;
  }
  s.moodDriven = true;
}

void LiveSource::setMoodSeed(std::uint64_t seed) {
  State& s = *state_;
  s.seed = seed;
  if (s.generator) s.startGenerator();
}

std::uint64_t LiveSource::moodSeed() const { return state_->seed; }
const MoodLevels& LiveSource::moods() const { return state_->moods; }
bool LiveSource::moodDriven() const { return state_->moodDriven; }

float LiveSource::tearsLeft() const { return state_->tearCounts[0]; }
float LiveSource::tearsRight() const { return state_->tearCounts[1]; }
long long LiveSource::framesReceived() const { return state_->received; }
long long LiveSource::framesDropped() const { return state_->dropped; }
bool LiveSource::frameWaiting() const { return state_->fresh; }
double LiveSource::shownArrival() const { return state_->shownArrival; }
const FapValues& LiveSource::shownValues() const { return state_->shown; }

std::shared_ptr<const PreviewFrame> LiveSource::tearFrame() const { return state_->tearFrame; }
int LiveSource::particleCount() const {
  return state_->tearFrame ? state_->tearFrame->particleCount : 0;
}
long long LiveSource::tearStepsRequested() const { return state_->stepsRequested; }
long long LiveSource::tearStepsDone() const { return state_->tears.counters().steps; }
void LiveSource::waitForTears() const { state_->tears.waitIdle(); }
void LiveSource::setBeforeTearStep(std::function<void()> hook) {
  state_->tears.setBeforeStep(std::move(hook));
}

const FrameView& LiveSource::seek(double seconds) {
  State& s = *state_;
  if (!std::isfinite(seconds)) seconds = s.clock;
  if (!s.started) {
    s.started = true;
    s.time = seconds;
  }
  s.clock = seconds;
  FapValues values;
  if (s.moodDriven) {
    s.shownArrival = -1;
    const double moodDt = std::clamp(seconds - s.moodClock, 0.0, kMaxStep);
    if (moodDt >= kMinStep || s.moodFresh) {
      values = s.generate(moodDt >= kMinStep ? moodDt : 0.0);
      if (moodDt >= kMinStep) s.moodClock = seconds;
      s.face.pose(values);
    } else {
      values = s.shown;
    }
  } else {
    values = s.valuesToShow();
    s.shownArrival = s.fresh ? s.newestArrival : -1;
    if (s.fresh) {
      ++s.frames;
      s.face.pose(values);  // the newest frame goes straight to the display
    }
    s.fresh = false;
  }
  s.shown = values;
  // The tears start with the first values shown that ask for some: the player's counts for a
  // stream without tear channels, the generator's own once moods drive the face.
  if (values[channelIndex(kTearLeftFap)] >= 1 || values[channelIndex(kTearRightFap)] >= 1)
    s.everTears = true;
  const double dt = std::clamp(seconds - s.time, 0.0, kMaxStep);
  // Nothing to simulate before the first tears; while a step runs, the next waits for it (and
  // covers the time since this one), so no step is ever dropped.
  if (dt >= kMinStep && (!s.everTears || !s.tears.busy())) {
    s.time = seconds;
    if (s.everTears) {
      s.tears.request({values, dt, 0});
      ++s.stepsRequested;
    }
  }
  return s.compose();
}

const FrameView& LiveSource::view() const { return state_->composed; }
double LiveSource::currentTime() const { return state_->clock; }
int LiveSource::currentFrame() const {
  return static_cast<int>(std::min<long long>(state_->frames, std::numeric_limits<int>::max()));
}
int LiveSource::frameCount() const {
  return static_cast<int>(std::min<long long>(state_->received, std::numeric_limits<int>::max()));
}
double LiveSource::frameRate() const { return state_->fps; }
void LiveSource::setFrameRate(double fps) {
  state_->fps = std::isfinite(fps) && fps > 0 && fps <= 1000 ? fps : 0;
}
bool LiveSource::hasTears() const { return state_->everTears; }

void LiveSource::setScene(const SceneSettings& scene) {
  State& s = *state_;
  s.face.setScene(scene);  // throws for invalid parameters before anything changes
  s.tears.setScene(scene);
  s.scene = scene;
  s.compose();
}
const SceneSettings& LiveSource::scene() const { return state_->scene; }
void LiveSource::setSimulationThreads(int threads) { state_->tears.setSimulationThreads(threads); }

void LiveSource::reset() {
  State& s = *state_;
  s.face.reset();
  s.tears.reset();
  s.started = false;
  s.time = 0;
  s.clock = 0;
  s.fresh = s.received > 0;             // show the newest frame again on the next seek
  if (s.generator) s.startGenerator();  // and the generator's take from its start
  s.moodClock = 0;
  s.compose();
}

const FrameProducer& LiveSource::producer() const { return state_->face; }

}  // namespace lacrima::playback
