#pragma once
// Pair candidates from the cell sort (CellIndex.h) as Verlet lists (VerletPairs.h): listed within
// h + skin and reused, with strays searched afresh, until the particles have moved too far.
#include "NeighbourStructure.h"

namespace lacrima::tears {

class NeighbourStructure_VerletGrid final : public NeighbourStructure {
 public:
  NeighbourStructure_VerletGrid(double h, double skin) : h_(h), skin_(skin) {}
  static MethodInfo info();
  static std::unique_ptr<NeighbourStructure> create(const MethodValues& values,
                                                    const ScaledParameters& parameters,
                                                    double skin);

  void update(ParticleSet& particles, CellIndex& cells, VerletPairs& candidates,
              ParallelChunks& parallel, TearCounters& counters) override;

 private:
  double h_, skin_;
};

}  // namespace lacrima::tears
