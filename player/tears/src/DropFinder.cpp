#include "CellIndex.h"

#include <lacrima/tears/DropFinder.h>

namespace lacrima::tears {

void DropFinder::find(const ParticleSet& particles, const UniformGrid& grid) {
  drops_.clear();
  particles_.clear();
  const CellIndex& index = grid.index();
  const auto order = index.order();
  visited_.assign(index.cellCount(), 0);
  for (std::size_t seed = 0; seed < index.cellCount(); ++seed) {
    if (visited_[seed]) continue;
    FoundDrop drop;
    drop.first = static_cast<int>(particles_.size());
    visited_[seed] = 1;
    stack_.assign(1, seed);
    while (!stack_.empty()) {
      const std::size_t c = stack_.back();
      stack_.pop_back();
      for (std::uint32_t s = index.cellStart(c); s < index.cellStart(c + 1); ++s)
        particles_.push_back(order[s]);
      // The 26 neighbours as nine runs along z (CellIndex::rowCells), in (dx, dy, dz) order.
      const Eigen::Vector3i cell = index.cellCoordinates(c);
      for (int dx = -1; dx <= 1; ++dx)
        for (int dy = -1; dy <= 1; ++dy) {
          const CellIndex::Range run = index.rowCells(cell.x() + dx, cell.y() + dy, cell.z());
          for (std::size_t n = run.begin; n < run.end; ++n) {
            if (visited_[n]) continue;
            visited_[n] = 1;
            stack_.push_back(n);
          }
        }
    }
    drop.count = static_cast<int>(particles_.size()) - drop.first;
    int left = 0;
    for (int i : particlesOf(drop)) {
      drop.centre += particles.position[static_cast<std::size_t>(i)];
      left += particles.eye[static_cast<std::size_t>(i)] == Eye::Left;
    }
    drop.centre /= static_cast<double>(drop.count);
    drop.eye = 2 * left >= drop.count ? Eye::Left : Eye::Right;
    drops_.push_back(drop);
  }
}

}  // namespace lacrima::tears
