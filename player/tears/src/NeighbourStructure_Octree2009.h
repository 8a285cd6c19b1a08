#pragma once
// The 2009 thesis's neighbour search for comparison: a fresh octree search every sub-step
// (Octree.h), halved into pairs. The particles are still sorted by the grid's cells, so both
// structures number the particles alike.
#include "NeighbourStructure.h"
#include "Octree.h"

namespace lacrima::tears {

class NeighbourStructure_Octree2009 final : public NeighbourStructure {
 public:
  NeighbourStructure_Octree2009(double h, double skin, double nodeSize)
      : h_(h), skin_(skin), octree_(nodeSize) {}
  static MethodInfo info();
  static std::unique_ptr<NeighbourStructure> create(const MethodValues& values,
                                                    const ScaledParameters& parameters,
                                                    double skin);

  void update(ParticleSet& particles, CellIndex& cells, VerletPairs& candidates,
              ParallelChunks& parallel, TearCounters& counters) override;

 private:
  double h_, skin_;
  Octree octree_;
  NeighbourList full_;
};

}  // namespace lacrima::tears
