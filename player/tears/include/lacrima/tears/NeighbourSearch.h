#pragma once
// Fixed-radius neighbour search: full neighbour lists (every j != i with |x_i - x_j| < h) from
// the uniform grid (UniformGrid.h) or, inside the library, the 2009 octree; both give the same
// sets. The solver's own half pair lists come from the grid's cell sort or, for comparison,
// from the octree's lists (SimulationOptions::neighbours).
#include <Eigen/Core>

#include <span>
#include <vector>

namespace lacrima::tears {

// Neighbours of every particle in compressed-row form: neighbours of i are
// indices[offsets[i] .. offsets[i+1]), excluding i itself.
struct NeighbourList {
  std::vector<int> offsets;  // size n + 1
  std::vector<int> indices;

  int particleCount() const { return offsets.empty() ? 0 : static_cast<int>(offsets.size()) - 1; }
  std::span<const int> of(int i) const {
    return {indices.data() + offsets[static_cast<std::size_t>(i)],
            static_cast<std::size_t>(offsets[static_cast<std::size_t>(i) + 1] -
                                     offsets[static_cast<std::size_t>(i)])};
  }
};

class NeighbourSearch {
 public:
  virtual ~NeighbourSearch() = default;
  // Rebuilds the structure for these positions and fills `out` with all pairs closer than h.
  virtual void find(std::span<const Eigen::Vector3d> positions, double h, NeighbourList& out) = 0;
};

}  // namespace lacrima::tears
