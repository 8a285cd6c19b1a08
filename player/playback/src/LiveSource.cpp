// LiveSource (LiveSource.h): the newest frame wins; the tears step with the display's clock.
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

}  // namespace

struct LiveSource::State {
  FrameProducer producer;
  SceneSettings scene = liveScene();
  FapValues newest{};
  ChannelMask newestMask;
  double newestArrival = -1;
  bool fresh = false;  // newest not shown yet
  float tears[2] = {0, 0};
  FapValues shown{};
  double shownArrival = -1;
  double time = 0;
  bool started = false;
  double fps = 0;
  long long received = 0, dropped = 0, frames = 0;
  bool everTears = false;
  // The crying generator, once moods were set; kept while frames drive the face.
  std::unique_ptr<MoodGenerator> generator;
  bool moodDriven = false, moodFresh = false;
  MoodLevels moods;
  std::uint64_t seed = 1;
  double moodTime = 0;  // the generator's clock: the display's steps added up

  explicit State(const HeadRig& rig) : producer(rig, liveScene()) {}

  // A new take that starts from a neutral face, so the first moods ease in rather than jump.
  void startGenerator() {
    generator = std::make_unique<MoodGenerator>(seed);
    moodTime = 0;
    generator->step(0, MoodLevels{});
    moodFresh = true;
  }

  // One frame of the generator `dt` seconds on (0: the face again, nothing simulated).
  const FrameView& generate(double dt) {
    moodTime += dt;
    const MoodFrame frame = generator->step(moodTime, moods);
    shown = frame.channels;
    if (shown[channelIndex(kTearLeftFap)] >= 1 || shown[channelIndex(kTearRightFap)] >= 1)
      everTears = true;
    producer.setKeyedColours({frame.colours.redness, frame.colours.blush});
    moodFresh = false;
    ++frames;
    return dt > 0 ? producer.produce(shown, dt, 0) : producer.pose(shown);
  }

  FapValues valuesToShow() const {
    FapValues values = newest;
    const int faps[2] = {kTearLeftFap, kTearRightFap};
    for (int eye = 0; eye < 2; ++eye) {
      const auto c = static_cast<std::size_t>(channelIndex(faps[eye]));
      if (!newestMask.test(c)) values[c] = tears[eye];
    }
    return values;
  }
};

LiveSource::LiveSource(const HeadRig& rig) : state_(std::make_unique<State>(rig)) {}
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
    s.producer.setKeyedColours({});
  }
  if (mask.test(channelIndex(kTearLeftFap)) || mask.test(channelIndex(kTearRightFap)))
    s.everTears = true;
}

void LiveSource::setTears(float left, float right) {
  const auto clean = [](float v) {
    return std::isfinite(v) ? std::clamp(std::floor(v), 0.0F, float(kMaxTearParticles)) : 0.0F;
  };
  state_->tears[0] = clean(left);
  state_->tears[1] = clean(right);
  if (state_->tears[0] > 0 || state_->tears[1] > 0) state_->everTears = true;
}

void LiveSource::setMoods(const MoodLevels& levels) {
  State& s = *state_;
  for (int m = 0; m < kMoodCount; ++m) {
    const double level = levels.level[m];
    s.moods.level[m] = std::isfinite(level) ? std::clamp(level, 0.0, 1.0) : 0.0;
  }
  if (!s.generator) s.startGenerator();
  if (!s.moodDriven) s.moodFresh = true;
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

float LiveSource::tearsLeft() const { return state_->tears[0]; }
float LiveSource::tearsRight() const { return state_->tears[1]; }
long long LiveSource::framesReceived() const { return state_->received; }
long long LiveSource::framesDropped() const { return state_->dropped; }
double LiveSource::shownArrival() const { return state_->shownArrival; }
const FapValues& LiveSource::shownValues() const { return state_->shown; }

const FrameView& LiveSource::seek(double seconds) {
  State& s = *state_;
  if (!std::isfinite(seconds)) seconds = s.time;
  if (!s.started) {
    s.started = true;
    s.time = seconds;
  }
  const double dt = std::clamp(seconds - s.time, 0.0, kMaxStep);
  if (s.moodDriven) {
    s.shownArrival = -1;
    if (dt >= kMinStep) {
      s.time = seconds;
      return s.generate(dt);
    }
    return s.moodFresh ? s.generate(0) : s.producer.view();
  }
  const FapValues values = s.valuesToShow();
  s.shownArrival = s.fresh ? s.newestArrival : -1;
  const bool wasFresh = s.fresh;
  s.fresh = false;
  s.shown = values;
  if (dt >= kMinStep) {
    s.time = seconds;
    if (wasFresh) ++s.frames;
    return s.producer.produce(values, dt, 0);
  }
  if (wasFresh) {
    ++s.frames;
    return s.producer.pose(values);
  }
  return s.producer.view();
}

const FrameView& LiveSource::view() const { return state_->producer.view(); }
double LiveSource::currentTime() const { return state_->time; }
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
  state_->producer.setScene(scene);  // throws for invalid parameters before anything changes
  state_->scene = scene;
}
const SceneSettings& LiveSource::scene() const { return state_->scene; }
void LiveSource::setSimulationThreads(int threads) {
  state_->producer.setSimulationThreads(threads);
}

void LiveSource::reset() {
  State& s = *state_;
  s.producer.reset();
  s.started = false;
  s.time = 0;
  s.fresh = s.received > 0;             // show the newest frame again on the next seek
  if (s.generator) s.startGenerator();  // and the generator's take from its start
}

const FrameProducer& LiveSource::producer() const { return state_->producer; }

}  // namespace lacrima::playback
