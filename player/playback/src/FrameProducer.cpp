// FrameProducer (FrameProducer.h): pose blending every frame; the tear simulation, its surface
// and trails only when the channels and the scene call for them.
#include "Overlays.h"

#include <lacrima/common/Milliseconds.h>
#include <lacrima/playback/FrameProducer.h>
#include <lacrima/playback/TearQualityOptions.h>
#include <lacrima/tears/DropCaps.h>
#include <lacrima/tears/SurfaceMesher.h>
#include <lacrima/tears/TearSimulation.h>
#include <lacrima/tears/TrailBuilder.h>

#include <cmath>
#include <optional>
#include <stdexcept>

namespace lacrima::playback {

namespace {

tears::TearSettings settingsFor(const SceneSettings& scene) {
  tears::TearSettings settings;
  for (const auto& [name, value] : scene.simulation) settings.set(name, value);
  return settings;
}

}  // namespace

bool tearsCommanded(const HeadRig& rig, const FapValues& values) {
  for (int fap : {kTearLeftFap, kTearRightFap}) {
    const float v = values[static_cast<std::size_t>(channelIndex(fap))];
    if (!rig.rig.disabled(fap) && std::isfinite(v) && v >= 1.0f) return true;
  }
  return false;
}

bool restartsTears(const SceneSettings& before, const SceneSettings& after) {
  return before.simulation != after.simulation || before.quality != after.quality;
}

// Everything that evolves with the tears; the face is re-blended from `values`.
class FrameProducer::Checkpoint {
 public:
  std::optional<tears::TearCheckpoint> simulation;  // absent: no tears had been simulated
  int generation = 0;                               // of the simulation it was taken from
  tears::TrailBuilder trails;
  bool trailsCurrent = false;
  FapValues values{};
  double progress = 0;

  explicit Checkpoint(tears::TrailBuilder t) : trails(std::move(t)) {}
};

std::size_t FrameProducer::bytes(const Checkpoint& checkpoint) {
  return sizeof(Checkpoint) - sizeof(tears::TrailBuilder) + checkpoint.trails.bytes() +
         (checkpoint.simulation ? checkpoint.simulation->bytes() : 0);
}

struct FrameProducer::State {
  const HeadRig& rig;
  SceneSettings scene;
  TearSources sources;
  tears::TearSettings settings;
  tears::SimulationOptions options;  // of the quality chosen
  std::vector<Eigen::Vector3i> skin;

  // Created by the first tear and kept: checkpoints restore into the object that took them.
  // `pristine` is its state before any step, which is what "no tears" restores to; a new
  // object (new parameters or sources) starts a new generation, older checkpoints of it are void.
  std::unique_ptr<tears::TearSimulation> simulation;
  std::optional<tears::TearCheckpoint> pristine;
  int generation = 0;
  tears::SurfaceMesher mesher;
  tears::DropCaps caps;  // small drops on the skin; the mesher skips their particles
  tears::TrailBuilder trails;
  bool surfaceCurrent = false;  // the mesher's surface is of the current particles
  // The trail builder has seen every frame since it was made. One that missed frames (trails
  // switched off meanwhile) would join a drop's old section to its new place in one long
  // stroke, so it is replaced by a fresh one when trails are switched back on.
  bool trailsCurrent = true;

  Eigen::Matrix3Xf positions, normals;
  FapValues values{};  // of the face now shown
  double progress = 0;
  KeyedColours keyed;
  FrameView view;
  ProducerTimes times;
  ProducerCounters counters;

  State(const HeadRig& r, const SceneSettings& s)
      : rig(r),
        scene(s),
        settings(settingsFor(s)),
        options(playback::simulationOptions(s.quality)),
        skin(skinTriangles(r)),
        caps(skin),
        trails(skin) {
    positions = rig.head.positions;
    normals = rig.head.normals;
  }

  int particles() const { return simulation ? simulation->particles().size() : 0; }

  tears::TearSimulation& ensureSimulation() {
    if (!simulation) {
      // Skin first, then the eyes: contacts past the skin's triangles are on an eye, which the
      // trail builder (given the skin alone) ignores.
      std::vector<Eigen::Vector3i> collision = skin;
      const std::vector<Eigen::Vector3i> eyes = eyeTriangles(rig);
      collision.insert(collision.end(), eyes.begin(), eyes.end());
      simulation =
          std::make_unique<tears::TearSimulation>(rig.head.positions, collision, settings, options);
      simulation->setSource(tears::Eye::Left, sources.left.value_or(rig.rig.tearLeft.position));
      simulation->setSource(tears::Eye::Right, sources.right.value_or(rig.rig.tearRight.position));
      pristine = simulation->checkpoint();
      ++generation;
    }
    return *simulation;
  }

  // Back to no tears with the same simulation object.
  void restartSimulation() {
    if (simulation) simulation->restore(*pristine);
  }

  // No tears, no trails. `discard`: the simulation's parameters or sources change, so the next
  // tear builds a new one.
  void clearTears(bool discard) {
    if (discard) {
      simulation.reset();
      pristine.reset();
    } else {
      restartSimulation();
    }
    trails = tears::TrailBuilder(skin);
    trailsCurrent = true;
    surfaceCurrent = false;
  }

  // Returns true when the face changed.
  bool blend(const FapValues& v) {
    if (v == values && counters.blends > 0) return false;
    const auto start = SteadyClock::now();
    rig.blender->blend(v, positions, normals);
    times.blend = millisecondsSince(start);
    values = v;
    ++counters.blends;
    return true;
  }

  void meshSurface() {
    surfaceCurrent = false;
    if (!scene.surface || particles() == 0) return;
    const auto start = SteadyClock::now();
    caps.update(*simulation, positions);
    mesher.update(*simulation, tears::SurfaceMesherSettings{}.maxCubes, caps.skipped());
    times.surface = millisecondsSince(start);
    surfaceCurrent = true;
    ++counters.surfaceRuns;
  }

  void followTrails(double dt) {
    if (!scene.trails) {
      trailsCurrent = false;
      return;
    }
    if (!trailsCurrent) {
      trails = tears::TrailBuilder(skin);
      trailsCurrent = true;
    }
    if (!simulation || (particles() == 0 && trails.mesh().empty())) return;
    const auto start = SteadyClock::now();
    trails.update(*simulation, positions, dt);
    times.trails = millisecondsSince(start);
    ++counters.trailRuns;
  }

  void publish(bool changed) {
    const OverlayWeights overlays = overlayWeights(scene, progress, simulation.get(), keyed);
    FrameView next;
    next.neutral = &rig.head;
    next.positions = &positions;
    next.normals = &normals;
    if (scene.particles && particles() > 0) {
      next.particles = &simulation->particles();
      next.particleRadius = simulation->particleRadius();
    }
    if (scene.surface && surfaceCurrent && !mesher.surface().empty())
      next.surface = &mesher.surface();
    if (scene.surface && surfaceCurrent && !caps.mesh().empty()) next.drops = &caps.mesh();
    if (scene.trails && trailsCurrent && !trails.mesh().empty()) next.trails = &trails.mesh();
    next.overlays = overlays;
    next.textureBlending = scene.textureBlending;
    changed = changed || next.particles != view.particles || next.surface != view.surface ||
              next.drops != view.drops || next.trails != view.trails ||
              next.overlays != view.overlays || next.textureBlending != view.textureBlending ||
              view.neutral == nullptr;
    next.revision = view.revision + (changed ? 1 : 0);
    view = next;
  }
};

FrameProducer::FrameProducer(const HeadRig& rig, const SceneSettings& scene)
    : state_(std::make_unique<State>(rig, scene)) {
  if (!rig.blender) throw std::invalid_argument("FrameProducer: the head rig has no pose blender");
  state_->blend(FapValues{});
  state_->publish(true);
}

FrameProducer::~FrameProducer() = default;

void FrameProducer::setScene(const SceneSettings& scene) {
  State& s = *state_;
  const tears::TearSettings settings = settingsFor(scene);  // throws before anything changes
  const bool restart = restartsTears(s.scene, scene);
  s.scene = scene;
  if (restart) {
    s.settings = settings;
    const int threads = s.options.threads;  // the caller's, not the quality's
    s.options = playback::simulationOptions(scene.quality);
    s.options.threads = threads;
    s.clearTears(true);
  }
  if (!s.surfaceCurrent) s.meshSurface();
  s.publish(restart);
}

const SceneSettings& FrameProducer::scene() const { return state_->scene; }

const tears::SimulationOptions& FrameProducer::simulationOptions() const { return state_->options; }

void FrameProducer::setSimulationThreads(int threads) { state_->options.threads = threads; }

void FrameProducer::setTearSources(const TearSources& sources) {
  if (sources == state_->sources) return;
  state_->sources = sources;
  state_->clearTears(true);
  state_->publish(true);
}

void FrameProducer::setKeyedColours(const KeyedColours& colours) { state_->keyed = colours; }

const FrameView& FrameProducer::produce(const FapValues& values, double dt, double progress) {
  State& s = *state_;
  s.times = {};
  ++s.counters.frames;
  bool changed = s.blend(values);
  s.progress = progress;
  // A head without an eye has that eye's tears disabled (RigBuilder.h): it simulates none.
  FapValues weeping = values;
  for (int fap : {kTearLeftFap, kTearRightFap})
    if (s.rig.rig.disabled(fap)) weeping[static_cast<std::size_t>(channelIndex(fap))] = 0.0f;
  const bool tearsWanted = tearsCommanded(s.rig, values) || s.particles() > 0;
  if (tearsWanted) {
    tears::TearSimulation& simulation = s.ensureSimulation();
    const long long substepsBefore = simulation.counters().substeps;
    const auto start = SteadyClock::now();
    simulation.step(s.positions, weeping, dt);
    s.times.simulation = millisecondsSince(start);
    s.times.substeps = simulation.counters().substeps - substepsBefore;
    ++s.counters.simulationSteps;
    changed = true;
  }
  s.surfaceCurrent = false;
  if (tearsWanted) s.meshSurface();
  const long long trailRuns = s.counters.trailRuns;
  s.followTrails(dt);
  changed = changed || s.counters.trailRuns != trailRuns;
  s.publish(changed);
  return s.view;
}

const FrameView& FrameProducer::pose(const FapValues& values) {
  return pose(values, state_->progress);
}

const FrameView& FrameProducer::pose(const FapValues& values, double progress) {
  State& s = *state_;
  const bool changed = s.blend(values);
  s.progress = progress;
  s.publish(changed);
  return s.view;
}

const FrameView& FrameProducer::view() const { return state_->view; }

void FrameProducer::clearTears() {
  State& s = *state_;
  s.clearTears(false);
  s.publish(true);
}

void FrameProducer::reset() {
  State& s = *state_;
  s.clearTears(false);
  s.counters = {};
  s.times = {};
  s.progress = 0;
  s.blend(FapValues{});
  s.publish(true);
}

std::shared_ptr<const FrameProducer::Checkpoint> FrameProducer::checkpoint() const {
  const State& s = *state_;
  auto c = std::make_shared<Checkpoint>(s.trails);
  if (s.simulation) {
    c->simulation = s.simulation->checkpoint();
    c->generation = s.generation;
  }
  c->trailsCurrent = s.trailsCurrent;
  c->values = s.values;
  c->progress = s.progress;
  return c;
}

void FrameProducer::restore(const Checkpoint& checkpoint) {
  State& s = *state_;
  if (checkpoint.simulation && (!s.simulation || checkpoint.generation != s.generation))
    throw std::invalid_argument(
        "FrameProducer::restore: the checkpoint was taken before the tear parameters or "
        "sources changed");
  if (checkpoint.simulation)
    s.simulation->restore(*checkpoint.simulation);
  else
    s.restartSimulation();
  s.trails = checkpoint.trails;
  s.trailsCurrent = checkpoint.trailsCurrent;
  s.progress = checkpoint.progress;
  s.blend(checkpoint.values);
  s.meshSurface();
  s.publish(true);
}

const ProducerTimes& FrameProducer::lastTimes() const { return state_->times; }
const ProducerCounters& FrameProducer::counters() const { return state_->counters; }
int FrameProducer::particleCount() const { return state_->particles(); }

std::uint64_t FrameProducer::tearStateHash() const {
  return state_->simulation ? tears::stateHash(state_->simulation->particles()) : 0;
}

}  // namespace lacrima::playback
