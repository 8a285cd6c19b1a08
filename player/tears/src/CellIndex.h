#pragma once
// Particles bucketed into cubic cells of a chosen edge, sorted by cell so that each cell and each
// run of cells along z is one contiguous range of the sorted order.
//
// Cell (cx, cy, cz) = floor(x / edge). Cells are numbered relative to the particles' bounding
// box, key = ((cx - x0) * ny + (cy - y0)) * nz + (cz - z0), and the particles are sorted by key
// with a stable LSD radix sort (O(n), ties keep particle order, so the result is a pure function
// of the input). Key order is x-major, z-minor: the three cells (cx, cy, cz-1 .. cz+1) are
// adjacent in key order, so the particles of such a "row" are one contiguous range, and the 27
// cells around a particle are nine ranges instead of 27.
//
// Occupied cells are found through an open-addressing hash of their keys (linear probing,
// 2^k >= 2 x cells slots), so memory is O(n) however far the particles spread.
#include <lacrima/tears/Scratch.h>

#include <Eigen/Core>

#include <cstdint>
#include <span>
#include <vector>

namespace lacrima::tears {

class CellIndex {
 public:
  // Sorts `positions` into cells of edge `edge`.
  void build(std::span<const Eigen::Vector3d> positions, double edge);

  double edge() const { return edge_; }
  std::size_t particleCount() const { return order_.size(); }
  std::size_t cellCount() const { return cellKey_.size(); }

  // order()[s] = the particle at sorted position s.
  std::span<const int> order() const { return order_; }
  // Sorted-order copies of the positions, one array per axis (the search loops stream them).
  std::span<const double> sortedX() const { return sx_; }
  std::span<const double> sortedY() const { return sy_; }
  std::span<const double> sortedZ() const { return sz_; }

  // Integer cell of a point (the same floor as the build used).
  Eigen::Vector3i cellOf(const Eigen::Vector3d& x) const;
  // Occupied cell c (0 <= c < cellCount(), in key order): its integer coordinates and its
  // sorted range [cellStart(c), cellStart(c + 1)).
  Eigen::Vector3i cellCoordinates(std::size_t c) const;
  std::uint32_t cellStart(std::size_t c) const { return cellStart_[c]; }
  // Index of the occupied cell with these coordinates, or -1.
  std::int64_t findCell(const Eigen::Vector3i& cell) const;

  // Sorted range of the particles in cells (cx, cy, cz-1 .. cz+1); empty when none.
  struct Range {
    std::uint32_t begin = 0, end = 0;
  };
  Range row(int cx, int cy, int cz) const;
  // The same row as occupied cell indices [begin, end), in key order (z ascending).
  Range rowCells(int cx, int cy, int cz) const;

 private:
  bool inBox(int cx, int cy, int cz) const;
  std::uint64_t keyOf(int cx, int cy, int cz) const;
  std::int64_t findKey(std::uint64_t key) const;

  double edge_ = 1.0, inverse_ = 1.0;
  Eigen::Vector3i low_{0, 0, 0}, dims_{0, 0, 0};

  std::vector<int> order_;
  std::vector<double> sx_, sy_, sz_;
  std::vector<std::uint64_t> cellKey_;    // per occupied cell, increasing
  std::vector<std::uint32_t> cellStart_;  // size cells + 1
  std::vector<std::uint64_t> slotKey_;    // hash table: key + 1 (0 = empty)
  std::vector<std::uint32_t> slotCell_;
  int slotBits_ = 0;

  // Buffers of the radix sort, kept between builds (no per-step allocation; Scratch.h).
  struct SortBuffers {
    std::vector<std::uint64_t> key, keyScratch;
    std::vector<int> orderScratch;
    std::vector<Eigen::Vector3i> cell;
  };
  Scratch<SortBuffers> sort_;
};

}  // namespace lacrima::tears
