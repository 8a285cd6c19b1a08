#include "CellIndex.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>

namespace lacrima::tears {
namespace {

// Cells beyond +-2^20 would make the key wider than 63 bits; positions are confined to the head
// box (< 10^5 cells per axis at the smallest kernel), so the clamp only guards non-finite input.
constexpr double kCellLimit = double((1 << 20) - 2);

std::uint64_t hashSlot(std::uint64_t key, int bits) {
  // Fibonacci hashing: the top bits of key * 2^64 / phi spread consecutive keys well.
  return (key * 0x9E3779B97F4A7C15ull) >> (64 - bits);
}

}  // namespace

Eigen::Vector3i CellIndex::cellOf(const Eigen::Vector3d& x) const {
  const auto axis = [&](double v) {
    const double c = std::floor(v * inverse_);
    // std::clamp passes NaN through and casting NaN to int is undefined: such a coordinate
    // goes to cell 0 (a non-finite particle is never within h of anything anyway).
    if (!(c == c)) return 0;
    return static_cast<int>(std::clamp(c, -kCellLimit, kCellLimit));
  };
  return {axis(x.x()), axis(x.y()), axis(x.z())};
}

bool CellIndex::inBox(int cx, int cy, int cz) const {
  return cx >= low_.x() && cy >= low_.y() && cz >= low_.z() && cx < low_.x() + dims_.x() &&
         cy < low_.y() + dims_.y() && cz < low_.z() + dims_.z();
}

std::uint64_t CellIndex::keyOf(int cx, int cy, int cz) const {
  return (static_cast<std::uint64_t>(cx - low_.x()) * static_cast<std::uint64_t>(dims_.y()) +
          static_cast<std::uint64_t>(cy - low_.y())) *
             static_cast<std::uint64_t>(dims_.z()) +
         static_cast<std::uint64_t>(cz - low_.z());
}

void CellIndex::build(std::span<const Eigen::Vector3d> x, double edge) {
  SortBuffers& scratch = *sort_;
  const std::size_t n = x.size();
  edge_ = edge;
  inverse_ = 1.0 / edge;
  order_.resize(n);
  sx_.resize(n);
  sy_.resize(n);
  sz_.resize(n);
  cellKey_.clear();
  cellStart_.clear();
  if (n == 0) {
    dims_.setZero();
    cellStart_.push_back(0);
    slotBits_ = 0;
    slotKey_.clear();
    slotCell_.clear();
    return;
  }

  scratch.cell.resize(n);
  Eigen::Vector3i lo = Eigen::Vector3i::Constant(std::numeric_limits<int>::max());
  Eigen::Vector3i hi = Eigen::Vector3i::Constant(std::numeric_limits<int>::min());
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector3i c = cellOf(x[i]);
    scratch.cell[i] = c;
    lo = lo.cwiseMin(c);
    hi = hi.cwiseMax(c);
  }
  low_ = lo;
  dims_ = hi - lo + Eigen::Vector3i::Ones();
  scratch.key.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    scratch.key[i] = keyOf(scratch.cell[i].x(), scratch.cell[i].y(), scratch.cell[i].z());
    order_[i] = static_cast<int>(i);
  }
  const std::uint64_t maxKey = keyOf(hi.x(), hi.y(), hi.z());

  // Stable LSD radix sort of (key, particle) by key.
  const int digitBits = n < 2048 ? 8 : 11;
  const std::size_t radix = std::size_t{1} << digitBits;
  const int keyBits = std::max(1, static_cast<int>(std::bit_width(maxKey)));
  scratch.keyScratch.resize(n);
  scratch.orderScratch.resize(n);
  std::vector<std::uint32_t>& count = cellStart_;  // borrowed as the histogram until the end
  for (int shift = 0; shift < keyBits; shift += digitBits) {
    count.assign(radix + 1, 0);
    for (std::size_t i = 0; i < n; ++i) ++count[((scratch.key[i] >> shift) & (radix - 1)) + 1];
    if (count[1 + ((scratch.key[0] >> shift) & (radix - 1))] == n)
      continue;  // one digit value: no-op pass
    for (std::size_t d = 0; d < radix; ++d) count[d + 1] += count[d];
    for (std::size_t i = 0; i < n; ++i) {
      const std::uint32_t slot = count[(scratch.key[i] >> shift) & (radix - 1)]++;
      scratch.keyScratch[slot] = scratch.key[i];
      scratch.orderScratch[slot] = order_[i];
    }
    scratch.key.swap(scratch.keyScratch);
    order_.swap(scratch.orderScratch);
  }

  cellStart_.clear();
  for (std::size_t s = 0; s < n; ++s) {
    if (s == 0 || scratch.key[s] != scratch.key[s - 1]) {
      cellKey_.push_back(scratch.key[s]);
      cellStart_.push_back(static_cast<std::uint32_t>(s));
    }
    const Eigen::Vector3d& p = x[static_cast<std::size_t>(order_[s])];
    sx_[s] = p.x();
    sy_[s] = p.y();
    sz_[s] = p.z();
  }
  cellStart_.push_back(static_cast<std::uint32_t>(n));

  const std::size_t cells = cellKey_.size();
  slotBits_ = std::max(4, static_cast<int>(std::bit_width(2 * cells - 1)));
  const std::size_t slots = std::size_t{1} << slotBits_;
  slotKey_.assign(slots, 0);
  slotCell_.resize(slots);
  for (std::size_t c = 0; c < cells; ++c) {
    std::uint64_t s = hashSlot(cellKey_[c], slotBits_);
    while (slotKey_[s] != 0) s = (s + 1) & (slots - 1);
    slotKey_[s] = cellKey_[c] + 1;
    slotCell_[s] = static_cast<std::uint32_t>(c);
  }
}

std::int64_t CellIndex::findKey(std::uint64_t key) const {
  if (slotKey_.empty()) return -1;
  const std::size_t mask = slotKey_.size() - 1;
  for (std::uint64_t s = hashSlot(key, slotBits_);; s = (s + 1) & mask) {
    if (slotKey_[s] == key + 1) return slotCell_[s];
    if (slotKey_[s] == 0) return -1;
  }
}

std::int64_t CellIndex::findCell(const Eigen::Vector3i& c) const {
  if (!inBox(c.x(), c.y(), c.z())) return -1;
  return findKey(keyOf(c.x(), c.y(), c.z()));
}

Eigen::Vector3i CellIndex::cellCoordinates(std::size_t c) const {
  std::uint64_t key = cellKey_[c];
  const auto nz = static_cast<std::uint64_t>(dims_.z()), ny = static_cast<std::uint64_t>(dims_.y());
  const int z = static_cast<int>(key % nz);
  key /= nz;
  const int y = static_cast<int>(key % ny);
  const int xx = static_cast<int>(key / ny);
  return {xx + low_.x(), y + low_.y(), z + low_.z()};
}

CellIndex::Range CellIndex::rowCells(int cx, int cy, int cz) const {
  if (cx < low_.x() || cy < low_.y() || cx >= low_.x() + dims_.x() || cy >= low_.y() + dims_.y())
    return {};
  const int z0 = std::max(cz - 1, low_.z()), z1 = std::min(cz + 1, low_.z() + dims_.z() - 1);
  if (z0 > z1) return {};
  // The cells z0..z1 are consecutive keys: find the first occupied one, then extend over the
  // following occupied cells while their keys stay within the row.
  const std::uint64_t first = keyOf(cx, cy, z0), last = keyOf(cx, cy, z1);
  for (std::uint64_t k = first; k <= last; ++k) {
    const std::int64_t c = findKey(k);
    if (c < 0) continue;
    auto end = static_cast<std::size_t>(c) + 1;
    while (end < cellKey_.size() && cellKey_[end] <= last) ++end;
    return {static_cast<std::uint32_t>(c), static_cast<std::uint32_t>(end)};
  }
  return {};
}

CellIndex::Range CellIndex::row(int cx, int cy, int cz) const {
  const Range cells = rowCells(cx, cy, cz);
  if (cells.begin == cells.end) return {};
  return {cellStart_[cells.begin], cellStart_[cells.end]};
}

}  // namespace lacrima::tears
