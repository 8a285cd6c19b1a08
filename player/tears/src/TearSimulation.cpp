#include "TearSimulationInternals.h"
#include "VectorState.h"

#include <lacrima/tears/TearSimulation.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <stdexcept>

namespace lacrima::tears {
namespace {

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

TearSimulation::Internals::Internals(const ScaledParameters& p, const TearSettings& settings,
                                     const SimulationOptions& options, const UnitScale& scale)
    : parallel(resolveThreadCount(options.threads),
               static_cast<std::size_t>(std::max(1, options.chunkParticles)),
               options.shareFromParticles),
      density(p.h),
      viscosity(p.kinematicViscosity),
      forcePass(p.h),
      contact(p.adhesion, p.friction, p.restDensity, p.particleMass, p.particleRadius),
      detachment(p.holdingTension, p.restDensity),
      massLoss(p.particleMass, options.trailDecayMetres * scale.headUnitsPerMetre,
               options.massFloor),
      emitter(p.spacing, p.particleMass),
      stepper(options.lambdaCfl, options.lambdaAcceleration, options.lambdaViscosity) {
  chooseMethods(p, settings, options);
}

int TearSimulation::threads() const { return internals_->parallel.threads(); }
ParallelChunks& TearSimulation::parallelChunks() { return internals_->parallel; }

void TearSimulation::Internals::chooseMethods(const ScaledParameters& p,
                                              const TearSettings& settings,
                                              const SimulationOptions& options) {
  neighbours = neighbourStructureRegistry().create(options.neighbours, p,
                                                   std::max(0.0, options.neighbourSkin) * p.h);
  pressure = pressureSolverRegistry().create(options.pressureSolver, p, settings);
  tension = surfaceTensionRegistry().create(options.surfaceTension, p);
}

TearSimulation::TearSimulation(const Eigen::Matrix3Xf& rest,
                               const std::vector<Eigen::Vector3i>& triangles,
                               const TearSettings& settings, const SimulationOptions& options)
    : instance_(nextInstance()), settings_(settings), options_(options) {
  if (triangles.empty()) throw std::invalid_argument("the skin has no triangles");
  if (!rest.allFinite()) throw std::invalid_argument("skin positions are not finite");
  // Compact the skin: only vertices on skin triangles, in first-use order (deterministic).
  std::map<int, int> compact;
  for (const auto& t : triangles) {
    for (int a = 0; a < 3; ++a) {
      if (t[a] < 0 || t[a] >= rest.cols())
        throw std::invalid_argument("skin triangle refers to a missing vertex");
      if (compact.emplace(t[a], static_cast<int>(skinVertices_.size())).second)
        skinVertices_.push_back(t[a]);
    }
  }
  for (const auto& t : triangles)
    skinTriangles_.emplace_back(compact[t[0]], compact[t[1]], compact[t[2]]);
  skinPositions_.resize(3, static_cast<Eigen::Index>(skinVertices_.size()));
  for (std::size_t v = 0; v < skinVertices_.size(); ++v)
    skinPositions_.col(static_cast<Eigen::Index>(v)) = rest.col(skinVertices_[v]).cast<double>();

  scale_ = UnitScale::fromHeadHeight(options_.headHeight > 0 ? options_.headHeight
                                                             : heightOf(rest, skinVertices_));
  params_ = ScaledParameters::from(settings_, scale_);
  internals_ = std::make_unique<Internals>(params_, settings_, options_, scale_);

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
  internals_->collider = std::make_unique<SkinCollider>(
      skinPositions_, skinTriangles_, envelope, params_.particleRadius, params_.contactBand,
      std::max(0.0, options_.collisionProbeKernels) * params_.h, options_.skinQueries);
}

TearSimulation::~TearSimulation() = default;

std::unique_ptr<TearSimulation> TearSimulation::forHead(const HeadMesh& head,
                                                        const TearSettings& settings,
                                                        const SimulationOptions& options,
                                                        const HeadTearOptions& headOptions) {
  const HeadSubmesh* skin = head.findSubmesh("skin");
  if (!skin) throw std::invalid_argument("the head has no 'skin' sub-mesh");
  std::vector<Eigen::Vector3i> surface = skin->triangles;
  if (headOptions.eyesCollide)
    for (const char* name : {"eye_l", "eye_r", "cornea_l", "cornea_r"})
      if (const HeadSubmesh* eye = head.findSubmesh(name))
        surface.insert(surface.end(), eye->triangles.begin(), eye->triangles.end());
  auto simulation = std::make_unique<TearSimulation>(head.positions, surface, settings, options);
  // The unit scale is the height of all collision vertices: the eyes lie inside the skin's.
  for (auto [eye, given] : {std::pair{Eye::Left, &headOptions.leftSource},
                            std::pair{Eye::Right, &headOptions.rightSource}})
    simulation->setSource(eye, *given ? **given : defaultTearSource(head, eye));
  return simulation;
}

Eigen::Vector3d TearSimulation::defaultTearSource(const HeadMesh& head, Eye eye) {
  const HeadSubmesh* skin = head.findSubmesh("skin");
  if (!skin || skin->triangles.empty())
    throw std::invalid_argument("the head has no 'skin' sub-mesh");
  const HeadSubmesh* ball = head.findSubmesh(eye == Eye::Left ? "eye_l" : "eye_r");
  if (!ball || ball->vertexCount == 0) {
    // No eye to go by: the constructor's rule for a head of this skin's size.
    Eigen::AlignedBox3d bounds;
    for (const auto& t : skin->triangles)
      for (int a = 0; a < 3; ++a) bounds.extend(head.positions.col(t[a]).cast<double>());
    const double height = bounds.sizes().y(), side = eye == Eye::Left ? 1 : -1;
    return {bounds.center().x() + side * 0.11 * height, bounds.max().y() - 0.35 * height,
            bounds.max().z()};
  }
  // The eyeball: its mesh may be the front cap only, so the radius comes from the width and the
  // centre lies one radius behind the front-most point.
  Eigen::AlignedBox3d box;
  for (int v = ball->firstVertex; v < ball->firstVertex + ball->vertexCount; ++v)
    box.extend(head.positions.col(v).cast<double>());
  const double radius = 0.5 * std::max(box.sizes().x(), box.sizes().y());
  const Eigen::Vector3d centre(box.center().x(), box.center().y(), box.max().z() - radius);
  const double below = 25 * std::numbers::pi / 180;
  const Eigen::Vector3d target =
      centre + 1.1 * radius * Eigen::Vector3d(0, -std::sin(below), std::cos(below));
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
  const double referenceVolume =
      options_.wetnessReferenceParticles * params_.particleMass / params_.restDensity;
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
    skinPositions_.col(static_cast<Eigen::Index>(v)) =
        positions.col(skinVertices_[v]).cast<double>();
  CollisionCounters c;
  if (skinStale_) {
    internals_->collider->resetSurface(skinPositions_, c);
    skinStale_ = false;
  } else {
    internals_->parallel.setParticleCount(particles_.size());
    internals_->collider->moveSurface(skinPositions_, particles_, c, internals_->parallel);
  }
  addCollisionCounters(counters_, c);
}

SkinPoint TearSimulation::nearestSkinPoint(const Eigen::Vector3d& x, double radius) {
  SkinPoint result;
  SkinHit hit;
  CollisionCounters c;
  if (x.allFinite() && radius > 0 && internals_->collider->nearest(x, radius, hit, c))
    result = {hit.triangle, hit.point, internals_->collider->faceNormal(hit.triangle),
              hit.distance};
  addCollisionCounters(counters_, c);
  return result;
}

EmissionSite TearSimulation::siteFor(Eye eye) {
  const Eigen::Vector3d source = sources_[static_cast<std::size_t>(eye)];
  SkinHit hit;
  CollisionCounters c;
  EmissionSite site{source, Eigen::Vector3d::Zero()};
  // The skin within a few kernel radii of the source: emit on it, in front of it.
  if (internals_->collider->nearest(source, 8 * params_.h, hit, c)) {
    const Eigen::Vector3d n = internals_->collider->faceNormal(hit.triangle);
    site.normal = n;
    site.base = hit.point + 1.01 * params_.particleRadius * n;
  }
  addCollisionCounters(counters_, c);
  return site;
}

void TearSimulation::step(const Eigen::Matrix3Xf& positions, int leftCount, int rightCount,
                          double dt) {
  clearUpperVectorState();
  ++counters_.frames;
  times_ = {};
  const std::array<int, 2> target{clampCount(leftCount), clampCount(rightCount)};
  if (positions.cols() <
      static_cast<Eigen::Index>(
          skinVertices_.empty()
              ? 0
              : *std::max_element(skinVertices_.begin(), skinVertices_.end()) + 1))
    throw std::invalid_argument("fewer head positions than the skin refers to");

  if (target[0] == 0 && target[1] == 0 && particles_.empty()) {
    skinStale_ = true;  // on resume, take the skin as it is then, without carrying anything
    return;             // effects on demand: no skin update, no ODE, no grid
  }
  const auto emissionStart = SteadyClock::now();
  // Count down first: it needs no geometry, and may leave nothing to simulate.
  for (int e = 0; e < 2; ++e) {
    const Eye eye = static_cast<Eye>(e);
    const int excess = count(eye) - target[static_cast<std::size_t>(e)];
    if (excess > 0) {
      double before = 0, after = 0;
      for (int i = 0; i < particles_.size(); ++i)
        if (particles_.eye[static_cast<std::size_t>(i)] == eye)
          before += particles_.mass[static_cast<std::size_t>(i)];
      counters_.removed += internals_->emitter.removeOldest(particles_, eye, excess);
      internals_->candidates.invalidate();
      for (int i = 0; i < particles_.size(); ++i)
        if (particles_.eye[static_cast<std::size_t>(i)] == eye)
          after += particles_.mass[static_cast<std::size_t>(i)];
      trailVolume_[static_cast<std::size_t>(e)] +=
          (before - after) / params_.restDensity;  // dried on the skin
    }
  }
  exposedGridStale_ = true;
  if (target[0] == 0 && target[1] == 0) {
    skinStale_ = true;
    times_.emission = millisecondsSince(emissionStart);
    return;
  }
  times_.emission = millisecondsSince(emissionStart);

  const auto skinStart = SteadyClock::now();
  updateSkin(positions);
  times_.collision += millisecondsSince(skinStart);

  const auto spawnStart = SteadyClock::now();
  for (int e = 0; e < 2; ++e) {
    const Eye eye = static_cast<Eye>(e);
    const int missing = target[static_cast<std::size_t>(e)] - count(eye);
    if (missing > 0) {
      internals_->emitter.spawn(particles_, eye, missing, siteFor(eye));
      internals_->candidates.invalidate();
      counters_.spawned += missing;
    }
  }
  times_.emission += millisecondsSince(spawnStart);

  if (dt > 0 && std::isfinite(dt) && !particles_.empty()) {
    ++counters_.sphSteps;
    simulate(dt);
  }
}

}  // namespace lacrima::tears
