#include "CellIndex.h"

#include <lacrima/tears/UniformGrid.h>

#include <algorithm>
#include <array>

namespace lacrima::tears {

UniformGrid::UniformGrid() : index_(std::make_unique<CellIndex>()) {}
UniformGrid::~UniformGrid() = default;
UniformGrid::UniformGrid(const UniformGrid& other)
    : index_(std::make_unique<CellIndex>(*other.index_)),
      found_(other.found_),
      start_(other.start_),
      rank_(other.rank_) {}

UniformGrid& UniformGrid::operator=(const UniformGrid& other) {
  *index_ = *other.index_;
  found_ = other.found_;
  start_ = other.start_;
  rank_ = other.rank_;
  return *this;
}

void UniformGrid::build(std::span<const Eigen::Vector3d> x, double h) { index_->build(x, h); }

Eigen::Vector3i UniformGrid::cellOf(const Eigen::Vector3d& x) const { return index_->cellOf(x); }

void UniformGrid::find(std::span<const Eigen::Vector3d> x, double h, NeighbourList& out) {
  build(x, h);
  const std::size_t n = x.size();
  const double h2 = h * h;
  const auto order = index_->order();
  const double* sx = index_->sortedX().data();
  const double* sy = index_->sortedY().data();
  const double* sz = index_->sortedZ().data();
  start_.resize(n + 1);
  start_[0] = 0;
  if (found_.size() < 64) found_.resize(64);
  std::size_t written = 0;

  // Cell by cell: the nine row ranges (CellIndex::row) are shared by all particles of a cell.
  std::array<CellIndex::Range, 9> rows;
  for (std::size_t c = 0; c < index_->cellCount(); ++c) {
    const Eigen::Vector3i cell = index_->cellCoordinates(c);
    int rowCount = 0;
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy) {
        const CellIndex::Range r = index_->row(cell.x() + dx, cell.y() + dy, cell.z());
        if (r.end > r.begin) rows[static_cast<std::size_t>(rowCount++)] = r;
      }
    for (std::uint32_t s = index_->cellStart(c); s < index_->cellStart(c + 1); ++s) {
      const double xi = sx[s], yi = sy[s], zi = sz[s];
      for (int r = 0; r < rowCount; ++r) {
        const auto [begin, end] = rows[static_cast<std::size_t>(r)];
        if (found_.size() < written + (end - begin)) found_.resize(2 * (written + (end - begin)));
        int* dst = found_.data();
        // Branch-free append: the test fails for most candidates, unpredictably.
        for (std::uint32_t t = begin; t < end; ++t) {
          const double dx = sx[t] - xi, dy = sy[t] - yi, dz = sz[t] - zi;
          dst[written] = order[t];
          written += static_cast<std::size_t>((dx * dx + dy * dy + dz * dz < h2) & (t != s));
        }
      }
      start_[s + 1] = static_cast<std::uint32_t>(written);  // cells cover s = 0..n-1 in order
    }
  }

  // Back to particle order.
  rank_.resize(n);
  for (std::size_t s = 0; s < n; ++s)
    rank_[static_cast<std::size_t>(order[s])] = static_cast<int>(s);
  out.offsets.resize(n + 1);
  out.indices.resize(written);
  out.offsets[0] = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const auto s = static_cast<std::size_t>(rank_[i]);
    const int begin = out.offsets[i];
    std::copy(found_.begin() + start_[s], found_.begin() + start_[s + 1],
              out.indices.begin() + begin);
    out.offsets[i + 1] = begin + static_cast<int>(start_[s + 1] - start_[s]);
  }
}

std::vector<Eigen::Vector3i> UniformGrid::occupiedCells() const {
  std::vector<Eigen::Vector3i> cells;
  cells.reserve(index_->cellCount());
  // Key order is (x, y, z) lexicographic order of the integer coordinates.
  for (std::size_t c = 0; c < index_->cellCount(); ++c) cells.push_back(index_->cellCoordinates(c));
  return cells;
}

std::vector<int> UniformGrid::particlesInCell(const Eigen::Vector3i& cell) const {
  std::vector<int> result;
  const std::int64_t c = index_->findCell(cell);
  if (c < 0) return result;
  const auto order = index_->order();
  for (std::uint32_t s = index_->cellStart(static_cast<std::size_t>(c));
       s < index_->cellStart(static_cast<std::size_t>(c) + 1); ++s)
    result.push_back(order[s]);
  return result;  // the radix sort is stable: particle order within a cell
}

}  // namespace lacrima::tears
