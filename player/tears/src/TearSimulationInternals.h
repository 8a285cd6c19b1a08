#pragma once
// The parts of a TearSimulation that its header names only through a pointer: the neighbour
// search, the SPH terms, the pressure and surface-tension methods the options chose, skin
// contact and collision, emission and the adaptive time step.
#include "ActivePairs.h"
#include "AdaptiveTimeStep.h"
#include "CellIndex.h"
#include "DensitySolver.h"
#include "DropDetachment_Tate1864.h"
#include "Emitter.h"
#include "FluidForcePass.h"
#include "NeighbourStructure.h"
#include "ParallelChunks.h"
#include "PressureSolver.h"
#include "SkinCollider.h"
#include "SkinContact.h"
#include "SurfaceTension.h"
#include "TrailMassLoss.h"
#include "VerletPairs.h"
#include "Viscosity_Mueller2003.h"

#include <lacrima/common/Milliseconds.h>
#include <lacrima/tears/TearSimulation.h>

#include <array>
#include <memory>
#include <vector>

namespace lacrima::tears {

struct TearSimulation::Internals {
  Internals(const ScaledParameters& parameters, const TearSettings& settings,
            const SimulationOptions& options, const UnitScale& scale);
  // Makes the neighbour structure, the pressure solver and the surface tension the options name
  // (their registries throw std::invalid_argument for an unknown key).
  void chooseMethods(const ScaledParameters& parameters, const TearSettings& settings,
                     const SimulationOptions& options);

  ParallelChunks parallel;                 // the sub-steps' threads (ParallelChunks.h)
  std::unique_ptr<SkinCollider> collider;  // made once the simulation box is known
  CellIndex cellIndex;                     // cell edge h (1 + skin), orders the particles
  VerletPairs candidates;
  ActivePairs pairs;
  std::unique_ptr<NeighbourStructure> neighbours;

  DensitySolver density;
  std::unique_ptr<PressureSolver> pressure;
  Viscosity_Mueller2003 viscosity;
  std::unique_ptr<SurfaceTension> tension;
  FluidForcePass forcePass;
  SkinContactForces contact;
  DropDetachment_Tate1864 detachment;
  TrailMassLoss massLoss;
  Emitter emitter;
  AdaptiveTimeStep stepper;

  std::vector<Eigen::Vector3d> previous;    // positions before the sub-step's move (scratch)
  std::array<std::vector<int>, 2> escaped;  // per eye, this sub-step (scratch)
  // Per particle chunk (scratch): what the sub-step's last shared loop found, in particle order.
  struct ChunkFindings {
    std::vector<TrailMassLoss::Loss> lost;    // water left in the trail
    std::array<std::vector<int>, 2> escaped;  // per eye, particles out of the box
  };
  std::vector<ChunkFindings> chunkFindings;
  // Per particle chunk (scratch): the largest |a|^2 and viscosity rate, and the speed clamps of
  // a capped sub-step.
  std::vector<std::pair<double, double>> chunkMaxima;
  std::vector<long long> clampedPerChunk;
};

struct TearSimulation::EmissionSites {
  std::array<EmissionSite, 2> site;
  std::array<bool, 2> known{false, false};
};

inline void addCollisionCounters(TearCounters& total, const CollisionCounters& c) {
  total.gridQueries += c.gridQueries;
  total.odeQueries += c.odeQueries;
  total.trimeshUpdates += c.trimeshUpdates;
  total.sweptParticles += c.sweptParticles;
  total.contactsTracked += c.contactsTracked;
  total.bruteForceQueries += c.bruteForceQueries;
}

}  // namespace lacrima::tears
