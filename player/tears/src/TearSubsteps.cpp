#include "TearSimulationInternals.h"

#include <lacrima/tears/TearSimulation.h>

#include <algorithm>
#include <cmath>

namespace lacrima::tears {

void TearSimulation::recycleEscaped(EmissionSites& sites) {
  // Escaped particles are re-emitted in their own slots: compacting would renumber every
  // particle after them and void the pair list, a full neighbour search every sub-step while
  // drops keep falling off the chin. The chunks found them; gathered in chunk order, each
  // eye's list is in particle order.
  auto& escaped = internals_->escaped;
  for (auto& slots : escaped) slots.clear();
  const std::size_t chunks =
      ParallelChunks::chunkCount(particles_.position.size(), internals_->parallel.particleChunk());
  for (std::size_t c = 0; c < chunks; ++c)
    for (std::size_t e = 0; e < 2; ++e) {
      const std::vector<int>& found = internals_->chunkFindings[c].escaped[e];
      escaped[e].insert(escaped[e].end(), found.begin(), found.end());
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

void TearSimulation::simulate(double frameDt) {
  Internals& in = *internals_;
  PressureSolver& pressure = *in.pressure;
  const double h = params_.h;
  const Eigen::Vector3d g = gravity();
  const double minimumStep = frameDt / options_.maxSubsteps;
  const std::size_t chunk = in.parallel.particleChunk();
  EmissionSites sites;
  double remaining = frameDt;
  CollisionCounters collision;

  while (remaining > 0 && !particles_.empty()) {
    // The count is fixed for the whole sub-step (recycling re-emits in place).
    in.parallel.setParticleCount(particles_.size());
    auto start = SteadyClock::now();
    in.neighbours->update(particles_, in.cellIndex, in.candidates, in.parallel, counters_);
    times_.neighbours += millisecondsSince(start);

    start = SteadyClock::now();
    in.density.compute(particles_, in.candidates, in.pairs, &in.parallel);
    pressure.computePressures(particles_, in.pairs, remaining, counters_);
    times_.density += millisecondsSince(start);

    start = SteadyClock::now();
    in.tension->prepare(particles_, in.pairs);
    // Tension and the step limits' maxima per chunk, in the force pass's last loop; a maximum
    // is exact, so combining the chunks' in any order gives the one-thread value.
    const std::size_t chunks = ParallelChunks::chunkCount(particles_.position.size(), chunk);
    in.chunkMaxima.assign(chunks, {0.0, 0.0});
    const auto finishChunk = [&](int c, std::size_t begin, std::size_t end) {
      in.tension->addAccelerations(particles_, in.forcePass, begin, end);
      auto& [acceleration2, rate] = in.chunkMaxima[static_cast<std::size_t>(c)];
      for (std::size_t i = begin; i < end; ++i) {
        acceleration2 = std::max(acceleration2, particles_.acceleration[i].squaredNorm());
        rate = std::max(rate, particles_.viscosityRate[i]);
      }
    };
    const double relativeSpeed =
        in.forcePass.run(particles_, in.pairs, in.viscosity, in.tension->needsColourField(),
                         in.parallel, finishChunk);
    double maxAcceleration2 = 0, maxRate = 0;
    for (const auto& [acceleration2, rate] : in.chunkMaxima) {
      maxAcceleration2 = std::max(maxAcceleration2, acceleration2);
      maxRate = std::max(maxRate, rate);
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
    const std::size_t n = particles_.position.size();
    // More per-particle work shares a loop wherever nothing between needs other particles: every
    // shared loop costs a hand-over between threads, and the operations on each particle are
    // the same, in the same order, as in separate loops (so the same bits).
    in.parallel.forEachChunk(n, chunk, [&](int, std::size_t begin, std::size_t end) {
      in.viscosity.apply(particles_, in.forcePass.weightedVelocity(), in.forcePass.weightSum(), dt,
                         begin, end);
      in.contact.applyExternal(particles_, g, dt, begin, end);
    });
    pressure.correctVelocities(particles_, in.pairs, dt, in.collider->view(), counters_);
    if (in.detachment.update(particles_, in.pairs, in.collider->view(), g)) {
      ++counters_.pendantSubsteps;
      counters_.releasedContacts += in.detachment.releasedCount();
    }
    const double vLimit = capped ? in.stepper.lambdaCfl() * h / dt : 0.0;
    in.previous.resize(n);
    in.clampedPerChunk.assign(chunks, 0);
    in.parallel.forEachChunk(n, chunk, [&](int c, std::size_t begin, std::size_t end) {
      in.contact.constrain(particles_, in.collider->view(), g, dt, in.detachment.spare(), begin,
                           end);
      for (std::size_t i = begin; i < end; ++i) {
        if (capped) {
          Eigen::Vector3d& v = particles_.velocity[i];
          const double norm = v.norm();
          if (norm > vLimit) {
            v *= vLimit / norm;
            ++in.clampedPerChunk[static_cast<std::size_t>(c)];
          }
        }
        in.previous[i] = particles_.position[i];
        particles_.position[i] += dt * particles_.velocity[i];
      }
    });
    for (const long long clamped : in.clampedPerChunk) counters_.clamped += clamped;
    times_.forces += millisecondsSince(start);

    start = SteadyClock::now();
    in.collider->resolve(particles_, in.previous, collision, in.parallel);
    if (in.chunkFindings.size() < chunks) in.chunkFindings.resize(chunks);
    in.parallel.forEachChunk(n, chunk, [&](int c, std::size_t begin, std::size_t end) {
      Internals::ChunkFindings& found = in.chunkFindings[static_cast<std::size_t>(c)];
      found.lost.clear();
      for (auto& slots : found.escaped) slots.clear();
      in.massLoss.apply(particles_, params_.restDensity, begin, end, found.lost);
      for (std::size_t i = begin; i < end; ++i) {
        particles_.age[i] += dt;
        if (!box_.contains(particles_.position[i]))
          found.escaped[static_cast<std::size_t>(particles_.eye[i])].push_back(static_cast<int>(i));
      }
    });
    double lost[2] = {0, 0};
    for (std::size_t c = 0; c < chunks; ++c)
      for (const TrailMassLoss::Loss& loss : in.chunkFindings[c].lost)
        lost[static_cast<std::size_t>(loss.eye)] += loss.volume;
    trailVolume_[0] += lost[0];
    trailVolume_[1] += lost[1];
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
