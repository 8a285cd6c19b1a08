#include "NeighbourStructure_Octree2009.h"

namespace lacrima::tears {

MethodInfo NeighbourStructure_Octree2009::info() {
  return {"octree",
          "octree",
          "The 2009 octree: the same pairs from a full search every sub-step (slower; for "
          "comparison)",
          {}};
}

std::unique_ptr<NeighbourStructure> NeighbourStructure_Octree2009::create(const MethodValues&,
                                                                          const ScaledParameters& p,
                                                                          double skin) {
  return std::make_unique<NeighbourStructure_Octree2009>(p.h, skin, p.nodeSize);
}

void NeighbourStructure_Octree2009::update(ParticleSet& particles, CellIndex& cells,
                                           VerletPairs& candidates, ParallelChunks&,
                                           TearCounters& counters) {
  if (!candidates.valid()) {
    cells.build(particles.position, h_ + skin_);
    particles.permute(cells.order());
  }
  octree_.find(particles.position, h_, full_);
  candidates.fromFull(full_, particles.position);
  ++counters.neighbourSearches;
}

}  // namespace lacrima::tears
