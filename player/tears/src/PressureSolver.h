#pragma once
// Pressure: what keeps the fluid from compressing, chosen by SimulationOptions::pressureSolver
// (a key of the registry below, TearMethods.h). Each method is its own class named after it,
// listed once in PressureSolverRegistration.cpp:
//   PressureSolver_WCSPH.h  a stiff equation of state (weakly compressible SPH, the default);
//   PressureSolver_DFSPH.h  divergence-free SPH, two iterative velocity solves;
//   PressureSolver_PBF.h    position-based fluids, density constraints on the predicted positions.
// A sub-step of TearSimulation calls the solver at two points:
//   1. computePressures(), after the densities (DensitySolver.h) and before the force pass:
//      leaves in particles.pressure what the force pass turns into the symmetric pressure force
//      (FluidForcePass.h), and may correct the velocities (DFSPH's divergence solve);
//   2. correctVelocities(), once the non-pressure forces are in the velocities and before the
//      skin contact constraint (DFSPH's density solve, PBF's position solve).
// Between them the sub-step's length is chosen (AdaptiveTimeStep.h) with the solver's speed of
// sound and the acceleration it says bounds the step.
#include "ActivePairs.h"
#include "MethodRegistry.h"
#include "SkinContact.h"

#include <lacrima/tears/ParticleSet.h>
#include <lacrima/tears/SimulationOptions.h>
#include <lacrima/tears/TearCounters.h>
#include <lacrima/tears/TearSettings.h>

#include <memory>
#include <vector>

namespace lacrima::tears {

// What a pressure solver carries from one sub-step to the next (saved in checkpoints).
struct PressureHistory {
  double lastSubstep = 0;           // DFSPH: the divergence solve's expected step (0: none yet)
  double lastNetAcceleration = -1;  // DFSPH, PBF: of the last sub-step (-1: none yet)
};

class PressureSolver {
 public:
  virtual ~PressureSolver() = default;

  // The speed of sound of the CFL condition (0: the method has no equation of state).
  virtual double soundSpeed() const = 0;
  // `remaining`: what is left of the frame, the longest the coming sub-step can be.
  virtual void computePressures(ParticleSet& particles, const ActivePairs& pairs, double remaining,
                                TearCounters& counters) = 0;
  // The acceleration that bounds the sub-step, given the largest one of the force pass.
  virtual double accelerationBound(double largestFluidAcceleration) const = 0;
  // `skin`: the collision surface, whose normals say which way a touching particle cannot go.
  virtual void correctVelocities(ParticleSet& particles, const ActivePairs& pairs, double dt,
                                 const SkinView& skin, TearCounters& counters) = 0;

  virtual PressureHistory history() const { return {}; }
  virtual void restoreHistory(const PressureHistory&) {}
};

// Every pressure solver, made from its values, the scaled parameters and the tear settings.
using PressureSolverRegistry =
    MethodRegistry<PressureSolver, const ScaledParameters&, const TearSettings&>;
PressureSolverRegistry& pressureSolverRegistry();

// The skin normal under each touching particle, zero under a free one: the incompressible
// solvers (DFSPH, PBF) drop the part of a correction that would push a particle into the skin.
void contactNormals(const ParticleSet& particles, const SkinView& skin,
                    std::vector<Eigen::Vector3d>& normals);

}  // namespace lacrima::tears
