#include "NeighbourStructure_VerletGrid.h"

namespace lacrima::tears {

MethodInfo NeighbourStructure_VerletGrid::info() {
  return {"grid",
          "grid",
          "Verlet lists on a uniform grid, reused while the particles move less than the skin "
          "(faster)",
          {}};
}

std::unique_ptr<NeighbourStructure> NeighbourStructure_VerletGrid::create(const MethodValues&,
                                                                          const ScaledParameters& p,
                                                                          double skin) {
  return std::make_unique<NeighbourStructure_VerletGrid>(p.h, skin);
}

void NeighbourStructure_VerletGrid::update(ParticleSet& particles, CellIndex& cells,
                                           VerletPairs& candidates, ParallelChunks& parallel,
                                           TearCounters& counters) {
  if (candidates.refresh(cells, particles.position)) {
    if (candidates.hasStrays()) {
      ++counters.straySubsteps;
      counters.strays += candidates.strayCount();
    }
    return;
  }
  cells.build(particles.position, h_ + skin_);
  particles.permute(cells.order());  // now sorted position == particle index
  candidates.build(cells, h_, skin_, parallel);
  ++counters.neighbourSearches;
}

}  // namespace lacrima::tears
