#include <lacrima/tears/PairList.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace lacrima::tears {

void VerletPairs::build(const CellIndex& index, double h, double skin) {
  const std::size_t n = index.particleCount();
  const double radius = h + skin, r2max = radius * radius;
  const double* sx = index.sortedX().data();
  const double* sy = index.sortedY().data();
  const double* sz = index.sortedZ().data();
  skin_ = skin;
  start_.resize(n + 1);
  start_[0] = 0;
  if (partner_.size() < 64) partner_.resize(64);
  std::size_t written = 0;

  constexpr std::array<std::array<int, 2>, 4> kForward{{{0, 1}, {1, -1}, {1, 0}, {1, 1}}};
  std::array<CellIndex::Range, 4> rows;
  for (std::size_t c = 0; c < index.cellCount(); ++c) {
    const Eigen::Vector3i cell = index.cellCoordinates(c);
    const std::uint32_t ownEnd = index.row(cell.x(), cell.y(), cell.z()).end;
    int rowCount = 0;
    for (const auto& [dx, dy] : kForward) {
      const CellIndex::Range r = index.row(cell.x() + dx, cell.y() + dy, cell.z());
      if (r.end > r.begin) rows[static_cast<std::size_t>(rowCount++)] = r;
    }
    for (std::uint32_t s = index.cellStart(c); s < index.cellStart(c + 1); ++s) {
      const double xi = sx[s], yi = sy[s], zi = sz[s];
      auto scan = [&](std::uint32_t begin, std::uint32_t end) {
        if (partner_.size() < written + (end - begin)) partner_.resize(2 * (written + (end - begin)));
        std::uint32_t* dst = partner_.data();
        // Branch-free append: most candidates fail the test, unpredictably.
        for (std::uint32_t t = begin; t < end; ++t) {
          const double dx = sx[t] - xi, dy = sy[t] - yi, dz = sz[t] - zi;
          dst[written] = t;
          written += static_cast<std::size_t>(dx * dx + dy * dy + dz * dz < r2max);
        }
      };
      scan(s + 1, ownEnd);
      for (int r = 0; r < rowCount; ++r) scan(rows[static_cast<std::size_t>(r)].begin, rows[static_cast<std::size_t>(r)].end);
      start_[s + 1] = static_cast<std::uint32_t>(written);
    }
  }
  partner_.resize(written);
  anchor_.resize(n);
  for (std::size_t s = 0; s < n; ++s) anchor_[s] = {sx[s], sy[s], sz[s]};
  valid_ = true;
}

void VerletPairs::fromFull(const NeighbourList& full, std::span<const Eigen::Vector3d> x) {
  const int n = full.particleCount();
  start_.resize(static_cast<std::size_t>(n) + 1);
  start_[0] = 0;
  partner_.clear();
  for (int i = 0; i < n; ++i) {
    for (int j : full.of(i))
      if (j > i) partner_.push_back(static_cast<std::uint32_t>(j));
    start_[static_cast<std::size_t>(i) + 1] = static_cast<std::uint32_t>(partner_.size());
  }
  anchor_.assign(x.begin(), x.end());
  skin_ = 0;
  valid_ = false;  // no skin: good for this step only
}

bool VerletPairs::stillValid(std::span<const Eigen::Vector3d> x) const {
  if (!valid_ || x.size() != anchor_.size()) return false;
  // The two largest displacements: no pair can have closed by more than their sum.
  double first = 0, second = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double d2 = (x[i] - anchor_[i]).squaredNorm();
    if (!(d2 <= first)) {  // NaN lands here too, and fails below
      second = first;
      first = d2;
    } else if (d2 > second) {
      second = d2;
    }
  }
  return std::sqrt(first) + std::sqrt(second) < skin_;
}

}  // namespace lacrima::tears
