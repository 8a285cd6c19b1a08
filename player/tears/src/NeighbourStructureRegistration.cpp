// The neighbour structures users can choose, in the order the apps and the bench list them; the
// default (SimulationOptions::neighbours) is the first, measured faster (lacrima-bench tears).
#include "NeighbourStructure.h"
#include "NeighbourStructure_Octree2009.h"
#include "NeighbourStructure_VerletGrid.h"

namespace lacrima::tears {

NeighbourStructureRegistry& neighbourStructureRegistry() {
  static NeighbourStructureRegistry registry(
      MethodFamily::NeighbourStructure,
      {
          {NeighbourStructure_VerletGrid::info(), &NeighbourStructure_VerletGrid::create},
          {NeighbourStructure_Octree2009::info(), &NeighbourStructure_Octree2009::create},
      });
  return registry;
}

}  // namespace lacrima::tears
