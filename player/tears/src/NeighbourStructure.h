#pragma once
// Where a sub-step's pair candidates come from, chosen by SimulationOptions::neighbours (a key
// of the registry below, TearMethods.h). Each structure is its own class, listed once in
// NeighbourStructureRegistration.cpp:
//   NeighbourStructure_VerletGrid.h  cell-sorted Verlet lists reused while the particles move
//                                    less than the skin (the default);
//   NeighbourStructure_Octree2009.h  the 2009 thesis's octree, a full search every sub-step,
//                                    kept to measure the grid against.
// Both keep the particles in the same cell order, so either gives the same particle numbering
// and the same pairs within h.
#include "CellIndex.h"
#include "MethodRegistry.h"
#include "ParallelChunks.h"
#include "VerletPairs.h"

#include <lacrima/tears/ParticleSet.h>
#include <lacrima/tears/TearCounters.h>
#include <lacrima/tears/TearSettings.h>

namespace lacrima::tears {

class NeighbourStructure {
 public:
  virtual ~NeighbourStructure() = default;
  // Brings `candidates` up to date with the particles' positions. A structure that rebuilds
  // `cells` (cell edge h + skin) sorts the particles into its order first; searches and stray
  // sub-steps are counted in `counters`.
  virtual void update(ParticleSet& particles, CellIndex& cells, VerletPairs& candidates,
                      ParallelChunks& parallel, TearCounters& counters) = 0;
};

// Every neighbour structure, made from its values, the scaled parameters and the Verlet skin
// (SimulationOptions::neighbourSkin, in head units).
using NeighbourStructureRegistry =
    MethodRegistry<NeighbourStructure, const ScaledParameters&, double>;
NeighbourStructureRegistry& neighbourStructureRegistry();

}  // namespace lacrima::tears
