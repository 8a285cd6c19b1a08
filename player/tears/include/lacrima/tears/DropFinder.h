#pragma once
// Drops: connected components of the occupied grid cells (thesis 4.3.2, Algorithms 2 and 3),
// cells adjacent across a face, an edge or a corner belonging to one drop. With cells of edge h
// two particles closer than h always lie in adjacent cells, so a drop is never split; two drops
// closer than ~2 h may be reported as one, as in the thesis.
//
// Deterministic: seeds are taken in the grid's key order and the search is a stack walk over
// the 26 neighbours in a fixed order; a drop's particles are listed cell by cell.
#include <lacrima/tears/ParticleSet.h>
#include <lacrima/tears/UniformGrid.h>

#include <span>
#include <vector>

namespace lacrima::tears {

struct FoundDrop {
  Eigen::Vector3d centre{0, 0, 0};  // mean particle position
  int first = 0, count = 0;         // range in DropFinder::particleIndices()
  Eye eye = Eye::Left;              // the eye most of its particles came from
};

class DropFinder {
 public:
  // `grid` must be built over particles.position (any cell edge; the simulation's is h).
  void find(const ParticleSet& particles, const UniformGrid& grid);

  std::span<const FoundDrop> drops() const { return drops_; }
  // Every drop's particle indices, drop after drop.
  std::span<const int> particleIndices() const { return particles_; }
  std::span<const int> particlesOf(const FoundDrop& drop) const {
    return std::span<const int>(particles_)
        .subspan(static_cast<std::size_t>(drop.first), static_cast<std::size_t>(drop.count));
  }

 private:
  std::vector<FoundDrop> drops_;
  std::vector<int> particles_;         // particle indices, drop by drop
  std::vector<std::uint8_t> visited_;  // per occupied cell
  std::vector<std::size_t> stack_;
};

}  // namespace lacrima::tears
