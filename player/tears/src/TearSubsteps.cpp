#include "TearSimulationInternals.h"

#include <lacrima/tears/TearSimulation.h>

#include <algorithm>
#include <cmath>

namespace lacrima::tears {

void TearSimulation::recycleEscaped(EmissionSites& sites) {
  // Escaped particles are re-emitted in their own slots: compacting would renumber every
  // particle after them and void the pair list, a full neighbour search every sub-step while
  // drops keep falling off the chin.
  auto& escaped = internals_->escaped;
  for (auto& slots : escaped) slots.clear();
  for (int i = 0; i < particles_.size(); ++i) {
    const auto s = static_cast<std::size_t>(i);
    if (!box_.contains(particles_.position[s]))
      escaped[static_cast<std::size_t>(particles_.eye[s])].push_back(i);
  }
  for (int e = 0; e < 2; ++e) {
    const auto& slots = escaped[static_cast<std::size_t>(e)];
    if (slots.empty()) continue;
    if (!sites.known[static_cast<std::size_t>(e)]) {
      sites.site[static_cast<std::size_t>(e)] = siteFor(static_cast<Eye>(e));
      sites.known[static_cast<std::size_t>(e)] = true;
    }
    internals_->emitter.respawn(particles_, static_cast<Eye>(e), slots,
                                sites.site[static_cast<std::size_t>(e)]);
    counters_.recycled += static_cast<long long>(slots.size());
  }
}

void TearSimulation::updatePairs() {
  Internals& in = *internals_;
  const double h = params_.h;
  const double skin = std::max(0.0, options_.neighbourSkin) * h;
  if (options_.neighbours == NeighbourMethod::Octree) {
    // Comparison path: a fresh full search every sub-step, halved. The particles are still
    // sorted by the same cells as the grid path, so both methods keep the same particle order.
    if (!in.candidates.valid()) {
      in.cellIndex.build(particles_.position, h + skin);
      particles_.permute(in.cellIndex.order());
    }
    in.octree.find(particles_.position, h, in.fullList);
    in.candidates.fromFull(in.fullList, particles_.position);
    ++counters_.neighbourSearches;
    return;
  }
  if (in.candidates.refresh(in.cellIndex, particles_.position)) {
    if (in.candidates.hasStrays()) {
      ++counters_.straySubsteps;
      counters_.strays += in.candidates.strayCount();
    }
    return;
  }
  in.cellIndex.build(particles_.position, h + skin);
  particles_.permute(in.cellIndex.order());  // now sorted position == particle index
  in.candidates.build(in.cellIndex, h, skin, in.parallel);
  ++counters_.neighbourSearches;
}

void TearSimulation::simulate(double frameDt) {
  Internals& in = *internals_;
  PressureSolver& pressure = *in.pressure;
  const double h = params_.h;
  const Eigen::Vector3d g = gravity();
  const double minimumStep = frameDt / options_.maxSubsteps;
  EmissionSites sites;
  double remaining = frameDt;
  CollisionCounters collision;

  while (remaining > 0 && !particles_.empty()) {
    // The count is fixed for the whole sub-step (recycling re-emits in place).
    in.parallel.setParticleCount(particles_.size());
    auto start = SteadyClock::now();
    updatePairs();
    times_.neighbours += millisecondsSince(start);

    start = SteadyClock::now();
    in.density.compute(particles_, in.candidates, in.pairs, &in.parallel);
    pressure.computePressures(particles_, in.pairs, remaining, counters_);
    times_.density += millisecondsSince(start);

    start = SteadyClock::now();
    std::fill(particles_.acceleration.begin(), particles_.acceleration.end(),
              Eigen::Vector3d::Zero());
    const double relativeSpeed = in.forcePass.run(particles_, in.pairs, in.viscosity,
                                                  in.tension->needsColourField(), in.parallel);
    in.tension->addAccelerations(particles_, in.pairs, in.forcePass);
    double maxAcceleration2 = 0, maxRate = 0;
    for (int i = 0; i < particles_.size(); ++i) {
      maxAcceleration2 = std::max(
          maxAcceleration2, particles_.acceleration[static_cast<std::size_t>(i)].squaredNorm());
      maxRate = std::max(maxRate, particles_.viscosityRate[static_cast<std::size_t>(i)]);
    }
    const double longest = options_.maxSubstepSeconds > 0
                               ? std::min(remaining, options_.maxSubstepSeconds)
                               : remaining;
    StepChoice choice = in.stepper.choose(h, pressure.soundSpeed(), relativeSpeed,
                                          pressure.accelerationBound(std::sqrt(maxAcceleration2)),
                                          maxRate, longest);
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
      const double aLimit = in.stepper.lambdaAcceleration() * in.stepper.lambdaAcceleration() * h /
                            (choice.dt * choice.dt);
      for (auto& a : particles_.acceleration) {
        const double norm = a.norm();
        if (norm > aLimit) {
          a *= aLimit / norm;
          ++counters_.clamped;
        }
      }
    }
    const double dt = choice.dt;
    in.viscosity.apply(particles_, in.forcePass.weightedVelocity(), in.forcePass.weightSum(), dt);
    in.contact.applyExternal(particles_, g, dt, in.parallel);
    pressure.correctVelocities(particles_, in.pairs, dt, in.collider->view(), counters_);
    if (in.detachment.update(particles_, in.pairs, in.collider->view(), g)) {
      ++counters_.pendantSubsteps;
      counters_.releasedContacts += in.detachment.releasedCount();
    }
    in.contact.constrain(particles_, in.collider->view(), g, dt, in.detachment.spare(),
                         in.parallel);
    if (capped) {
      const double vLimit = in.stepper.lambdaCfl() * h / dt;
      for (auto& v : particles_.velocity) {
        const double norm = v.norm();
        if (norm > vLimit) {
          v *= vLimit / norm;
          ++counters_.clamped;
        }
      }
    }
    in.previous.resize(particles_.position.size());
    in.parallel.forEachChunk(particles_.position.size(), kParticleChunk,
                             [&](int, std::size_t begin, std::size_t end) {
                               for (std::size_t i = begin; i < end; ++i) {
                                 in.previous[i] = particles_.position[i];
                                 particles_.position[i] += dt * particles_.velocity[i];
                               }
                             });
    times_.forces += millisecondsSince(start);

    start = SteadyClock::now();
    in.collider->resolve(particles_, in.previous, collision, in.parallel);
    double lost[2] = {0, 0};
    in.massLoss.apply(particles_, params_.restDensity, lost);
    trailVolume_[0] += lost[0];
    trailVolume_[1] += lost[1];
    for (auto& age : particles_.age) age += dt;
    recycleEscaped(sites);
    times_.collision += millisecondsSince(start);

    remaining -= dt;
    if (remaining < 1e-12 * frameDt) remaining = 0;
    ++counters_.substeps;
  }
  addCollisionCounters(counters_, collision);
  exposedGridStale_ = true;
}

}  // namespace lacrima::tears
