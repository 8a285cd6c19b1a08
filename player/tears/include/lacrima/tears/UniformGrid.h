#pragma once
// Compact uniform grid (cell edge h) for fixed-radius neighbour queries and for the surface
// mesher. Particles are sorted by cell with a counting (radix) sort (CellIndex.h), so the
// candidates of a query are nine contiguous runs of a sorted, axis-split copy of the positions;
// memory is O(n) however far the particles spread (a dense grid over the head box at
// h = 1.6 mm would need 10^7 cells).
//
// The occupied cells (integer coordinates floor(x / h)) are exposed for the surface mesher.
#include <lacrima/tears/NeighbourSearch.h>

#include <cstdint>
#include <memory>

namespace lacrima::tears {

class CellIndex;

class UniformGrid final : public NeighbourSearch {
 public:
  UniformGrid();
  ~UniformGrid() override;
  UniformGrid(const UniformGrid& other);  // copies the cells (trail checkpoints hold a grid)
  UniformGrid& operator=(const UniformGrid& other);

  // Full lists: every j != i with |x_i - x_j| < h, for every i, in particle order.
  void find(std::span<const Eigen::Vector3d> positions, double h, NeighbourList& out) override;

  // Sorts `positions` into the grid only (no neighbour lists).
  void build(std::span<const Eigen::Vector3d> positions, double h);

  Eigen::Vector3i cellOf(const Eigen::Vector3d& x) const;
  // Distinct occupied cells, sorted (x, then y, then z) so consumers iterate deterministically.
  std::vector<Eigen::Vector3i> occupiedCells() const;
  // Indices of the particles in one cell, in particle order.
  std::vector<int> particlesInCell(const Eigen::Vector3i& cell) const;
  // The sorted structure itself (cells in key order, particle ranges), for the library's own
  // allocation-free consumers (surface mesher, drop finder).
  const CellIndex& index() const { return *index_; }

 private:
  std::unique_ptr<CellIndex> index_;
  std::vector<int> found_;            // neighbours in sorted order of the query particle
  std::vector<std::uint32_t> start_;  // per sorted particle: its run in found_
  std::vector<int> rank_;             // sorted position of each particle
};

}  // namespace lacrima::tears
