#include "SkinCollider.h"
#include "VectorState.h"

#include <lacrima/tears/TearSimulation.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <stdexcept>

namespace lacrima::tears {
namespace {

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

void addCollisionCounters(TearCounters& total, const CollisionCounters& c) {
  total.odeQueries += c.odeQueries;
  total.trimeshUpdates += c.trimeshUpdates;
  total.sweptParticles += c.sweptParticles;
  total.contactsTracked += c.contactsTracked;
  total.bruteForceQueries += c.bruteForceQueries;
}

int clampCount(int count) { return std::clamp(count, 0, kMaxTearParticles); }

int countFromChannel(float value) {
  if (!(value > 0)) return 0;  // negative, zero and NaN
  return clampCount(static_cast<int>(std::min<float>(std::floor(value), float(kMaxTearParticles))));
}

double heightOf(const Eigen::Matrix3Xf& positions, const std::vector<int>& vertices) {
  float lo = positions(1, vertices.front()), hi = lo;
  for (int v : vertices) {
    lo = std::min(lo, positions(1, v));
    hi = std::max(hi, positions(1, v));
  }
  return std::max(1e-6, static_cast<double>(hi - lo));
}

std::uint64_t nextInstance() {
  static std::atomic<std::uint64_t> counter{0};
  return ++counter;
}

}  // namespace

// Everything restore() needs to make the future repeat. Left out on purpose: the pair geometry
// of a sub-step (ActivePairs, the force pass's float copies), which every sub-step rebuilds
// before reading, and the exposed grid, rebuilt on demand. The cell index is kept: the pair
// list searches its cells for strays until the next rebuild.
struct TearCheckpoint::State {
  std::uint64_t instance = 0;
  ParticleSet particles;
  VerletPairs candidates;  // when the pair list is next rebuilt decides the particle order
  CellIndex cells;         // the list's cells (stray searches)
  Emitter emitter;
  SkinCollider::Surface skin;
  bool skinStale = true;
  std::array<Eigen::Vector3d, 2> sources;
  Eigen::AlignedBox3d box;
  std::array<double, 2> trailVolume{0, 0};
  double lastSubstep = 0, lastNetAcceleration = -1;
};

TearCheckpoint::TearCheckpoint() = default;
TearCheckpoint::~TearCheckpoint() = default;
TearCheckpoint::TearCheckpoint(const TearCheckpoint&) = default;
TearCheckpoint& TearCheckpoint::operator=(const TearCheckpoint&) = default;
TearCheckpoint::TearCheckpoint(TearCheckpoint&&) noexcept = default;
TearCheckpoint& TearCheckpoint::operator=(TearCheckpoint&&) noexcept = default;

int TearCheckpoint::particleCount() const { return state_ ? state_->particles.size() : 0; }

std::size_t TearCheckpoint::bytes() const {
  if (!state_) return 0;
  const ParticleSet& p = state_->particles;
  const std::size_t n = static_cast<std::size_t>(p.size());
  const std::size_t perParticle = 3 * sizeof(Eigen::Vector3d) + 7 * sizeof(double) + sizeof(std::uint64_t) +
                                  sizeof(Eye) + sizeof(SkinContact);
  const std::size_t pairs = (n + 1 + state_->candidates.pairCount()) * sizeof(std::uint32_t) + n * sizeof(Eigen::Vector3d) +
                            n * (sizeof(int) + 3 * sizeof(double)) + state_->cells.cellCount() * 4 * sizeof(std::uint64_t);
  const std::size_t skin = static_cast<std::size_t>(state_->skin.vertices.size()) * sizeof(double) +
                           state_->skin.normals.size() * (sizeof(Eigen::Vector3d) + 1);
  return sizeof(State) + n * perParticle + pairs + skin;
}

TearCheckpoint TearSimulation::checkpoint() const {
  auto state = std::make_shared<TearCheckpoint::State>(TearCheckpoint::State{
      instance_, particles_, candidates_, cellIndex_, emitter_, collider_->surface(), skinStale_, sources_, box_, trailVolume_,
      lastSubstep_, lastNetAcceleration_});
  TearCheckpoint c;
  c.state_ = std::move(state);
  return c;
}

void TearSimulation::restore(const TearCheckpoint& checkpoint) {
  if (checkpoint.empty()) throw std::invalid_argument("restoring an empty tear checkpoint");
  const TearCheckpoint::State& s = *checkpoint.state_;
  if (s.instance != instance_) throw std::invalid_argument("the tear checkpoint was taken from another simulation");
  CollisionCounters c;
  collider_->restoreSurface(s.skin, c);
  addCollisionCounters(counters_, c);
  particles_ = s.particles;  // assignment: the buffers keep their capacity
  candidates_ = s.candidates;
  cellIndex_ = s.cells;
  emitter_ = s.emitter;
  skinStale_ = s.skinStale;
  sources_ = s.sources;
  box_ = s.box;
  trailVolume_ = s.trailVolume;
  lastSubstep_ = s.lastSubstep;
  lastNetAcceleration_ = s.lastNetAcceleration;
  exposedGridStale_ = true;
  times_ = {};
}

TearSimulation::TearSimulation(const Eigen::Matrix3Xf& rest, const std::vector<Eigen::Vector3i>& triangles,
                               const TearSettings& settings, const SimulationOptions& options)
    : instance_(nextInstance()), settings_(settings), options_(options),
      octree_(1.0),  // replaced below once the scale is known
      density_(1.0), pressure_(1.0, 0, 1, true), viscosity_(1.0, 0), mueller_(1.0, 0), akinci_(1.0, 0, 1),
      contact_(0, 0, 1, 1, 1), massLoss_(1, 1, 1), emitter_(1, 1), dfsph_(1.0, {}) {
  if (triangles.empty()) throw std::invalid_argument("the skin has no triangles");
  if (!rest.allFinite()) throw std::invalid_argument("skin positions are not finite");
  // Compact the skin: only vertices on skin triangles, in first-use order (deterministic).
  std::map<int, int> compact;
  for (const auto& t : triangles) {
    for (int a = 0; a < 3; ++a) {
      if (t[a] < 0 || t[a] >= rest.cols()) throw std::invalid_argument("skin triangle refers to a missing vertex");
      if (compact.emplace(t[a], static_cast<int>(skinVertices_.size())).second) skinVertices_.push_back(t[a]);
    }
  }
  for (const auto& t : triangles) skinTriangles_.emplace_back(compact[t[0]], compact[t[1]], compact[t[2]]);
  skinPositions_.resize(3, static_cast<Eigen::Index>(skinVertices_.size()));
  for (std::size_t v = 0; v < skinVertices_.size(); ++v)
    skinPositions_.col(static_cast<Eigen::Index>(v)) = rest.col(skinVertices_[v]).cast<double>();

  scale_ = UnitScale::fromHeadHeight(options_.headHeight > 0 ? options_.headHeight : heightOf(rest, skinVertices_));
  params_ = ScaledParameters::from(settings_, scale_);
  octree_ = Octree(params_.nodeSize);
  density_ = DensitySolver(params_.h);
  pressure_ = PressureForce(params_.h, params_.stiffness, params_.restDensity, options_.clampNegativePressure);
  viscosity_ = ViscosityForce(params_.h, params_.kinematicViscosity);
  mueller_ = MuellerSurfaceTension(params_.h, params_.tensionSigma);
  akinci_ = AkinciSurfaceTension(params_.h, params_.tensionGamma, params_.restDensity);
  contact_ = SkinContactForces(params_.adhesion, params_.friction, params_.restDensity, params_.particleMass,
                               params_.particleRadius);
  massLoss_ = TrailMassLoss(params_.particleMass, options_.trailDecayMetres * scale_.headUnitsPerMetre,
                            options_.massFloor);
  emitter_ = Emitter(params_.spacing, params_.particleMass);
  stepper_ = AdaptiveTimeStep(options_.lambdaCfl, options_.lambdaAcceleration, options_.lambdaViscosity);
  DivergenceFreeSettings dfsph;
  const double stiffness = settings_.pressure > 0 ? TearSettings{}.pressure / settings_.pressure : 1e3;
  dfsph.densityTolerance = std::clamp(options_.dfsphTolerance * stiffness, 1e-4, 0.1);
  dfsph.divergenceTolerance = dfsph.densityTolerance;
  dfsph.maxIterations = std::max(2, options_.dfsphMaxIterations);
  dfsph_ = DivergenceFreeSolver(params_.h, dfsph);

  Eigen::AlignedBox3d bounds;
  for (Eigen::Index v = 0; v < skinPositions_.cols(); ++v) bounds.extend(skinPositions_.col(v));
  const double height = bounds.sizes().y();
  // Default sources: the eyes of a typical head, ~0.11 head heights either side of the middle,
  // a third of the way down from the top, on the front; they snap to the nearest skin.
  const Eigen::Vector3d centre = bounds.center();
  sources_[0] = {centre.x() + 0.11 * height, bounds.max().y() - 0.35 * height, bounds.max().z()};
  sources_[1] = {centre.x() - 0.11 * height, bounds.max().y() - 0.35 * height, bounds.max().z()};
  box_ = bounds;
  box_.extend(sources_[0]);
  box_.extend(sources_[1]);
  const double margin = options_.boxMarginMetres * scale_.headUnitsPerMetre;
  box_.min().array() -= margin;
  box_.max().array() += margin;
  // ODE's envelope: the box grown by half again, room for any pose of the face.
  Eigen::AlignedBox3d envelope = box_;
  const Eigen::Vector3d grow = 0.5 * box_.sizes();
  envelope.min() -= grow;
  envelope.max() += grow;
  collider_ = std::make_unique<SkinCollider>(skinPositions_, skinTriangles_, envelope, params_.particleRadius,
                                             params_.contactBand, std::max(0.0, options_.collisionProbeKernels) * params_.h);
}

TearSimulation::~TearSimulation() = default;

std::unique_ptr<TearSimulation> TearSimulation::forHead(const HeadMesh& head, const TearSettings& settings,
                                                        const SimulationOptions& options, const HeadTearOptions& headOptions) {
  const HeadSubmesh* skin = head.findSubmesh("skin");
  if (!skin) throw std::invalid_argument("the head has no 'skin' sub-mesh");
  std::vector<Eigen::Vector3i> surface = skin->triangles;
  if (headOptions.eyesCollide)
    for (const char* name : {"eye_l", "eye_r", "cornea_l", "cornea_r"})
      if (const HeadSubmesh* eye = head.findSubmesh(name)) surface.insert(surface.end(), eye->triangles.begin(), eye->triangles.end());
  auto simulation = std::make_unique<TearSimulation>(head.positions, surface, settings, options);
  // The unit scale is the height of all collision vertices: the eyes lie inside the skin's.
  for (auto [eye, given] : {std::pair{Eye::Left, &headOptions.leftSource}, std::pair{Eye::Right, &headOptions.rightSource}})
    simulation->setSource(eye, *given ? **given : defaultTearSource(head, eye));
  return simulation;
}

Eigen::Vector3d TearSimulation::defaultTearSource(const HeadMesh& head, Eye eye) {
  const HeadSubmesh* skin = head.findSubmesh("skin");
  if (!skin || skin->triangles.empty()) throw std::invalid_argument("the head has no 'skin' sub-mesh");
  const HeadSubmesh* ball = head.findSubmesh(eye == Eye::Left ? "eye_l" : "eye_r");
  if (!ball || ball->vertexCount == 0) {
    // No eye to go by: the constructor's rule for a head of this skin's size.
    Eigen::AlignedBox3d bounds;
    for (const auto& t : skin->triangles)
      for (int a = 0; a < 3; ++a) bounds.extend(head.positions.col(t[a]).cast<double>());
    const double height = bounds.sizes().y(), side = eye == Eye::Left ? 1 : -1;
    return {bounds.center().x() + side * 0.11 * height, bounds.max().y() - 0.35 * height, bounds.max().z()};
  }
  // The eyeball: its mesh may be the front cap only, so the radius comes from the width and the
  // centre lies one radius behind the front-most point.
  Eigen::AlignedBox3d box;
  for (int v = ball->firstVertex; v < ball->firstVertex + ball->vertexCount; ++v)
    box.extend(head.positions.col(v).cast<double>());
  const double radius = 0.5 * std::max(box.sizes().x(), box.sizes().y());
  const Eigen::Vector3d centre(box.center().x(), box.center().y(), box.max().z() - radius);
  const double below = 25 * std::numbers::pi / 180;
  const Eigen::Vector3d target = centre + 1.1 * radius * Eigen::Vector3d(0, -std::sin(below), std::cos(below));
  // The nearest skin vertex (first in triangle order on ties: deterministic).
  double best = std::numeric_limits<double>::infinity();
  Eigen::Vector3d source = target;
  for (const auto& t : skin->triangles)
    for (int a = 0; a < 3; ++a) {
      const Eigen::Vector3d x = head.positions.col(t[a]).cast<double>();
      const double d = (x - target).squaredNorm();
      if (d < best) {
        best = d;
        source = x;
      }
    }
  return source;
}

void TearSimulation::setSource(Eye eye, const Eigen::Vector3d& point) {
  if (!point.allFinite()) throw std::invalid_argument("tear source is not finite");
  sources_[static_cast<std::size_t>(eye)] = point;
  box_.extend(point);
}

int TearSimulation::count(Eye eye) const {
  return static_cast<int>(std::count(particles_.eye.begin(), particles_.eye.end(), eye));
}

const UniformGrid& TearSimulation::grid() const {
  if (exposedGridStale_) {
    exposedGrid_.build(particles_.position, params_.h);
    exposedGridStale_ = false;
  }
  return exposedGrid_;
}

EyeWetness TearSimulation::wetness(Eye eye) const {
  EyeWetness w;
  w.count = count(eye);
  w.trailVolume = trailVolume_[static_cast<std::size_t>(eye)];
  const double referenceVolume = options_.wetnessReferenceParticles * params_.particleMass / params_.restDensity;
  w.skin = 1.0 - std::exp(-w.trailVolume / referenceVolume);
  w.eye = std::min(1.0, w.count / options_.wetnessReferenceParticles);
  return w;
}

void TearSimulation::step(const Eigen::Matrix3Xf& positions, const FapValues& channels, double dt) {
  step(positions, countFromChannel(channels[channelIndex(kTearLeftFap)]),
       countFromChannel(channels[channelIndex(kTearRightFap)]), dt);
}

void TearSimulation::updateSkin(const Eigen::Matrix3Xf& positions) {
  for (std::size_t v = 0; v < skinVertices_.size(); ++v)
    skinPositions_.col(static_cast<Eigen::Index>(v)) = positions.col(skinVertices_[v]).cast<double>();
  CollisionCounters c;
  if (skinStale_) {
    collider_->resetSurface(skinPositions_, c);
    skinStale_ = false;
  } else {
    collider_->moveSurface(skinPositions_, particles_, c);
  }
  addCollisionCounters(counters_, c);
}

SkinPoint TearSimulation::nearestSkinPoint(const Eigen::Vector3d& x, double radius) {
  SkinPoint result;
  SkinHit hit;
  CollisionCounters c;
  if (x.allFinite() && radius > 0 && collider_->nearest(x, radius, hit, c))
    result = {hit.triangle, hit.point, collider_->faceNormal(hit.triangle), hit.distance};
  addCollisionCounters(counters_, c);
  return result;
}

EmissionSite TearSimulation::siteFor(Eye eye) {
  const Eigen::Vector3d source = sources_[static_cast<std::size_t>(eye)];
  SkinHit hit;
  CollisionCounters c;
  EmissionSite site{source, Eigen::Vector3d::Zero()};
  // The skin within a few kernel radii of the source: emit on it, in front of it.
  if (collider_->nearest(source, 8 * params_.h, hit, c)) {
    const Eigen::Vector3d n = collider_->faceNormal(hit.triangle);
    site.normal = n;
    site.base = hit.point + 1.01 * params_.particleRadius * n;
  }
  addCollisionCounters(counters_, c);
  return site;
}

void TearSimulation::step(const Eigen::Matrix3Xf& positions, int leftCount, int rightCount, double dt) {
  clearUpperVectorState();
  ++counters_.frames;
  times_ = {};
  const std::array<int, 2> target{clampCount(leftCount), clampCount(rightCount)};
  if (positions.cols() < static_cast<Eigen::Index>(skinVertices_.empty() ? 0 : *std::max_element(skinVertices_.begin(), skinVertices_.end()) + 1))
    throw std::invalid_argument("fewer head positions than the skin refers to");

  if (target[0] == 0 && target[1] == 0 && particles_.empty()) {
    skinStale_ = true;  // on resume, take the skin as it is then, without carrying anything
    return;             // effects on demand: no skin update, no ODE, no grid
  }
  const auto emissionStart = Clock::now();
  // Count down first: it needs no geometry, and may leave nothing to simulate.
  for (int e = 0; e < 2; ++e) {
    const Eye eye = static_cast<Eye>(e);
    const int excess = count(eye) - target[static_cast<std::size_t>(e)];
    if (excess > 0) {
      double before = 0, after = 0;
      for (int i = 0; i < particles_.size(); ++i)
        if (particles_.eye[static_cast<std::size_t>(i)] == eye) before += particles_.mass[static_cast<std::size_t>(i)];
      counters_.removed += emitter_.removeOldest(particles_, eye, excess);
      candidates_.invalidate();
      for (int i = 0; i < particles_.size(); ++i)
        if (particles_.eye[static_cast<std::size_t>(i)] == eye) after += particles_.mass[static_cast<std::size_t>(i)];
      trailVolume_[static_cast<std::size_t>(e)] += (before - after) / params_.restDensity;  // dried on the skin
    }
  }
  exposedGridStale_ = true;
  if (target[0] == 0 && target[1] == 0) {
    skinStale_ = true;
    times_.emission = msSince(emissionStart);
    return;
  }
  times_.emission = msSince(emissionStart);

  const auto skinStart = Clock::now();
  updateSkin(positions);
  times_.collision += msSince(skinStart);

  const auto spawnStart = Clock::now();
  for (int e = 0; e < 2; ++e) {
    const Eye eye = static_cast<Eye>(e);
    const int missing = target[static_cast<std::size_t>(e)] - count(eye);
    if (missing > 0) {
      emitter_.spawn(particles_, eye, missing, siteFor(eye));
      candidates_.invalidate();
      counters_.spawned += missing;
    }
  }
  times_.emission += msSince(spawnStart);

  if (dt > 0 && std::isfinite(dt) && !particles_.empty()) {
    ++counters_.sphSteps;
    simulate(dt);
  }
}

void TearSimulation::recycleEscaped(std::array<EmissionSite, 2>& sites, std::array<bool, 2>& siteKnown) {
  // Escaped particles are re-emitted in their own slots: compacting would renumber every
  // particle after them and void the pair list, a full neighbour search every sub-step while
  // drops keep falling off the chin.
  for (auto& slots : escaped_) slots.clear();
  for (int i = 0; i < particles_.size(); ++i) {
    const auto s = static_cast<std::size_t>(i);
    if (!box_.contains(particles_.position[s])) escaped_[static_cast<std::size_t>(particles_.eye[s])].push_back(i);
  }
  for (int e = 0; e < 2; ++e) {
    const auto& slots = escaped_[static_cast<std::size_t>(e)];
    if (slots.empty()) continue;
    if (!siteKnown[static_cast<std::size_t>(e)]) {
      sites[static_cast<std::size_t>(e)] = siteFor(static_cast<Eye>(e));
      siteKnown[static_cast<std::size_t>(e)] = true;
    }
    emitter_.respawn(particles_, static_cast<Eye>(e), slots, sites[static_cast<std::size_t>(e)]);
    counters_.recycled += static_cast<long long>(slots.size());
  }
}

void TearSimulation::updatePairs() {
  const double h = params_.h;
  const double skin = std::max(0.0, options_.neighbourSkin) * h;
  if (options_.neighbours == NeighbourMethod::Octree) {
    // Comparison path: a fresh full search every sub-step, halved. The particles are still
    // sorted by the same cells as the grid path, so both methods keep the same particle order.
    if (!candidates_.valid()) {
      cellIndex_.build(particles_.position, h + skin);
      particles_.permute(cellIndex_.order());
    }
    octree_.find(particles_.position, h, fullList_);
    candidates_.fromFull(fullList_, particles_.position);
    ++counters_.neighbourSearches;
    return;
  }
  if (candidates_.refresh(cellIndex_, particles_.position)) {
    if (candidates_.hasStrays()) {
      ++counters_.straySubsteps;
      counters_.strays += candidates_.strayCount();
    }
    return;
  }
  cellIndex_.build(particles_.position, h + skin);
  particles_.permute(cellIndex_.order());  // now sorted position == particle index
  candidates_.build(cellIndex_, h, skin);
  ++counters_.neighbourSearches;
}

void TearSimulation::simulate(double frameDt) {
  const double h = params_.h;
  const Eigen::Vector3d g = gravity();
  const double minimumStep = frameDt / options_.maxSubsteps;
  const bool akinci = options_.surfaceTension == SurfaceTensionModel::Akinci;
  const bool dfsph = options_.pressureSolver == PressureSolver::Dfsph;
  // DFSPH has no equation of state: no sound speed in the CFL condition.
  const double soundSpeed = dfsph ? 0.0 : params_.soundSpeed;
  std::array<EmissionSite, 2> sites;
  std::array<bool, 2> siteKnown{false, false};
  double remaining = frameDt;
  CollisionCounters collision;

  while (remaining > 0 && !particles_.empty()) {
    auto start = Clock::now();
    updatePairs();
    times_.neighbours += msSince(start);

    start = Clock::now();
    density_.compute(particles_, candidates_, pairs_);
    if (dfsph) {
      std::fill(particles_.pressure.begin(), particles_.pressure.end(), 0.0);  // the solves replace it
      dfsph_.prepare(particles_, pairs_);
      const double expected = lastSubstep_ > 0 ? std::min(lastSubstep_, remaining) : remaining;
      counters_.divergenceIterations += dfsph_.solveDivergence(particles_, pairs_, expected);
      counters_.solverCapped += dfsph_.stats().divergenceCapped;
    } else {
      pressure_.computePressures(particles_);
    }
    times_.density += msSince(start);

    start = Clock::now();
    std::fill(particles_.acceleration.begin(), particles_.acceleration.end(), Eigen::Vector3d::Zero());
    const double relativeSpeed = forcePass_.run(particles_, pairs_, pressure_, viscosity_, akinci ? nullptr : &mueller_);
    if (akinci) akinci_.addAccelerations(particles_, pairs_);
    double maxAcceleration2 = 0, maxRate = 0;
    for (int i = 0; i < particles_.size(); ++i) {
      maxAcceleration2 = std::max(maxAcceleration2, particles_.acceleration[static_cast<std::size_t>(i)].squaredNorm());
      maxRate = std::max(maxRate, particles_.viscosityRate[static_cast<std::size_t>(i)]);
    }
    const double longest = options_.maxSubstepSeconds > 0 ? std::min(remaining, options_.maxSubstepSeconds) : remaining;
    // DFSPH: pressure is not in the accelerations yet, and surface tension alone is several g on
    // surface particles; what moves them is the balance, known after the solve. The last
    // sub-step's net acceleration stands in for it (the explicit one before there is any).
    const double accelerationBound = dfsph && lastNetAcceleration_ >= 0 ? lastNetAcceleration_ : std::sqrt(maxAcceleration2);
    StepChoice choice = stepper_.choose(h, soundSpeed, relativeSpeed, accelerationBound, maxRate, longest);
    if (longest < remaining && choice.limit == StepLimit::Frame) {
      // Capped by maxSubstepSeconds: even pieces of the frame, as for the other limits.
      choice.dt = remaining / std::ceil(remaining / longest * (1 - 1e-12));
    } else if (choice.limit == StepLimit::Frame) {
      choice.dt = remaining;
    }
    if (choice.limit == StepLimit::Cfl) ++counters_.cflLimited;
    if (choice.limit == StepLimit::Acceleration) ++counters_.accelerationLimited;
    if (choice.limit == StepLimit::Viscosity) ++counters_.viscosityLimited;
    const bool capped = choice.dt < minimumStep && choice.dt < remaining;
    if (capped) {
      // Last resort: the state asks for more sub-steps than a frame may take. Step at the cap
      // and clamp what would make that step unstable; every clamp is counted.
      ++counters_.substepCapHits;
      choice.dt = std::min(minimumStep, remaining);
      const double aLimit = stepper_.lambdaAcceleration() * stepper_.lambdaAcceleration() * h / (choice.dt * choice.dt);
      for (auto& a : particles_.acceleration) {
        const double norm = a.norm();
        if (norm > aLimit) {
          a *= aLimit / norm;
          ++counters_.clamped;
        }
      }
    }
    const double dt = choice.dt;
    viscosity_.apply(particles_, forcePass_.weightedVelocity(), forcePass_.weightSum(), dt);
    contact_.applyExternal(particles_, g, dt);
    if (dfsph) {
      contactNormal_.resize(particles_.velocity.size());
      for (std::size_t i = 0; i < contactNormal_.size(); ++i) {
        const int t = particles_.contact[i].triangle;
        contactNormal_[i] = t >= 0 ? collider_->faceNormal(t) : Eigen::Vector3d::Zero();
      }
      counters_.densityIterations += dfsph_.solveDensity(particles_, pairs_, dt, contactNormal_);
      counters_.solverCapped += dfsph_.stats().densityCapped;
      lastSubstep_ = dt;
      lastNetAcceleration_ = dfsph_.stats().maxNetAcceleration;
    }
    contact_.constrain(particles_, collider_->view(), g, dt);
    if (capped) {
      const double vLimit = stepper_.lambdaCfl() * h / dt;
      for (auto& v : particles_.velocity) {
        const double norm = v.norm();
        if (norm > vLimit) {
          v *= vLimit / norm;
          ++counters_.clamped;
        }
      }
    }
    previous_.assign(particles_.position.begin(), particles_.position.end());
    for (int i = 0; i < particles_.size(); ++i)
      particles_.position[static_cast<std::size_t>(i)] += dt * particles_.velocity[static_cast<std::size_t>(i)];
    times_.forces += msSince(start);

    start = Clock::now();
    collider_->resolve(particles_, previous_, collision);
    double lost[2] = {0, 0};
    massLoss_.apply(particles_, params_.restDensity, lost);
    trailVolume_[0] += lost[0];
    trailVolume_[1] += lost[1];
    for (auto& age : particles_.age) age += dt;
    recycleEscaped(sites, siteKnown);
    times_.collision += msSince(start);

    remaining -= dt;
    if (remaining < 1e-12 * frameDt) remaining = 0;
    ++counters_.substeps;
  }
  addCollisionCounters(counters_, collision);
  exposedGridStale_ = true;
}

}  // namespace lacrima::tears
