#include "VerletPairs.h"
#include "Float4.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <limits>

namespace lacrima::tears {
namespace {

// The two largest of a stream of squared lengths, and the sum of their square roots.
struct LargestTwo {
  double first = 0, second = 0;
  void add(double d2) {
    if (d2 > first) {
      second = first;
      first = d2;
    } else if (d2 > second) {
      second = d2;
    }
  }
  double sum() const { return std::sqrt(first) + std::sqrt(second); }
};

}  // namespace

// The candidates of the sorted particles [first, last) (cells in key order), appended to `out`
// from `written` on; start_[s + 1] gets each particle's end, relative to `out`, and reach_[s]
// its largest partner.
std::size_t VerletPairs::scan(const CellIndex& index, std::uint32_t first, std::uint32_t last,
                              float r2max, UninitialisedVector<std::uint32_t>& out,
                              std::size_t written) {
  Buffers& work = *buffers_;
  const float* fx = work.fx.data();
  const float* fy = work.fy.data();
  const float* fz = work.fz.data();
  constexpr std::array<std::array<int, 2>, 4> kForward{{{0, 1}, {1, -1}, {1, 0}, {1, 1}}};
  std::array<CellIndex::Range, 4> rows;
  // The occupied cell holding `first`: the last one starting at or before it.
  std::size_t c = 0, cells = index.cellCount();
  for (std::size_t step = std::bit_floor(std::max<std::size_t>(cells, 1)); step > 0; step /= 2)
    if (c + step < cells && index.cellStart(c + step) <= first) c += step;
  for (; c < cells && index.cellStart(c) < last; ++c) {
    const Eigen::Vector3i cell = index.cellCoordinates(c);
    const std::uint32_t ownEnd = index.row(cell.x(), cell.y(), cell.z()).end;
    int rowCount = 0;
    for (const auto& [dx, dy] : kForward) {
      const CellIndex::Range r = index.row(cell.x() + dx, cell.y() + dy, cell.z());
      if (r.end > r.begin) rows[static_cast<std::size_t>(rowCount++)] = r;
    }
    const std::uint32_t begin = std::max(first, index.cellStart(c)),
                        end = std::min(last, index.cellStart(c + 1));
    for (std::uint32_t s = begin; s < end; ++s) {
      const float xi = fx[s], yi = fy[s], zi = fz[s];
      const Float4 x4{xi, xi, xi, xi}, y4{yi, yi, yi, yi}, z4{zi, zi, zi, zi},
          r4{r2max, r2max, r2max, r2max};
      auto scanRow = [&](std::uint32_t rowBegin, std::uint32_t rowEnd) {
        if (out.size() < written + (rowEnd - rowBegin))
          out.resize(2 * (written + (rowEnd - rowBegin)));
        std::uint32_t* dst = out.data();
        // Four distances at a time, then a branch-free append of each: most candidates fail
        // the test, unpredictably.
        std::uint32_t t = rowBegin;
        for (; t + 4 <= rowEnd; t += 4) {
          const Float4 dx = load4(fx + t) - x4, dy = load4(fy + t) - y4, dz = load4(fz + t) - z4;
          const Int4 inside = dx * dx + dy * dy + dz * dz < r4;  // -1 where true
          dst[written] = t;
          written -= static_cast<std::size_t>(static_cast<std::ptrdiff_t>(inside[0]));
          dst[written] = t + 1;
          written -= static_cast<std::size_t>(static_cast<std::ptrdiff_t>(inside[1]));
          dst[written] = t + 2;
          written -= static_cast<std::size_t>(static_cast<std::ptrdiff_t>(inside[2]));
          dst[written] = t + 3;
          written -= static_cast<std::size_t>(static_cast<std::ptrdiff_t>(inside[3]));
        }
        for (; t < rowEnd; ++t) {
          const float dx = fx[t] - xi, dy = fy[t] - yi, dz = fz[t] - zi;
          dst[written] = t;
          written += static_cast<std::size_t>(dx * dx + dy * dy + dz * dz < r2max);
        }
      };
      const std::size_t before = written;
      scanRow(s + 1, ownEnd);
      for (int r = 0; r < rowCount; ++r)
        scanRow(rows[static_cast<std::size_t>(r)].begin, rows[static_cast<std::size_t>(r)].end);
      // The rows follow key order, so the candidates ascend and the last is the largest.
      reach_[s] = written > before ? out[written - 1] : s;
      start_[s + 1] = static_cast<std::uint32_t>(written);
    }
  }
  return written;
}

void VerletPairs::build(const CellIndex& index, double h, double skin) {
  ParallelChunks serial(1);
  build(index, h, skin, serial);
}

// Each particle's candidates depend on its own cell and rows only, so the list is the same
// integers however it is cut. On one thread the particles are scanned straight into the list;
// shared, each chunk of particles scans into a buffer of its own and the buffers are then
// copied into place (each at the total of the chunks before it), which costs a copy of the
// list that one thread need not pay.
void VerletPairs::build(const CellIndex& index, double h, double skin, ParallelChunks& parallel) {
  Buffers& work = *buffers_;
  const std::size_t n = index.particleCount();
  const std::size_t chunk = parallel.particleChunk();
  const double radius = h + skin;
  // The test runs in single precision on positions relative to the first particle; the bound
  // is widened by 1e-5 so float rounding can only add candidates, never drop one within R.
  const float r2max = static_cast<float>(radius * radius * (1 + 1e-5));
  h_ = h;
  skin_ = skin;
  clearStrays();
  start_.resize(n + 1);
  start_[0] = 0;
  reach_.resize(n);
  // The list was cut to its count at the end of the last build; its whole capacity is usable
  // again (growing an UninitialisedVector within capacity costs nothing). Measured against the
  // count instead, a list a few pairs longer than the last one reallocated at almost every
  // rebuild, each time onto freshly mapped pages.
  partner_.resize(std::max<std::size_t>(partner_.capacity(), 64));
  const double* sx = index.sortedX().data();
  const double* sy = index.sortedY().data();
  const double* sz = index.sortedZ().data();
  work.fx.resize(n);
  work.fy.resize(n);
  work.fz.resize(n);
  anchor_.resize(n);
  parallel.forEachChunk(n, chunk, [&](int, std::size_t begin, std::size_t end) {
    for (std::size_t s = begin; s < end; ++s) {
      work.fx[s] = static_cast<float>(sx[s] - sx[0]);
      work.fy[s] = static_cast<float>(sy[s] - sy[0]);
      work.fz[s] = static_cast<float>(sz[s] - sz[0]);
      anchor_[s] = {sx[s], sy[s], sz[s]};
    }
  });

  std::size_t written = 0;
  const std::size_t chunks = ParallelChunks::chunkCount(n, chunk);
  if (!parallel.shared() || chunks < 2) {
    written = scan(index, 0, static_cast<std::uint32_t>(n), r2max, partner_, 0);
  } else {
    if (work.chunkPartner.size() < chunks) work.chunkPartner.resize(chunks);
    work.chunkCount.resize(chunks);
    parallel.forEachChunk(n, chunk, [&](int c, std::size_t begin, std::size_t end) {
      UninitialisedVector<std::uint32_t>& out = work.chunkPartner[static_cast<std::size_t>(c)];
      if (out.size() < 64) out.resize(64);
      work.chunkCount[static_cast<std::size_t>(c)] = scan(
          index, static_cast<std::uint32_t>(begin), static_cast<std::uint32_t>(end), r2max, out, 0);
    });
    work.chunkOffset.resize(chunks);
    for (std::size_t c = 0; c < chunks; ++c) {
      work.chunkOffset[c] = written;
      written += work.chunkCount[c];
    }
    if (partner_.size() < written) partner_.resize(written);
    parallel.forEachChunk(n, chunk, [&](int c, std::size_t begin, std::size_t end) {
      const auto cs = static_cast<std::size_t>(c);
      const auto offset = static_cast<std::uint32_t>(work.chunkOffset[cs]);
      std::copy_n(work.chunkPartner[cs].begin(), work.chunkCount[cs],
                  partner_.begin() + static_cast<std::ptrdiff_t>(offset));
      for (std::size_t s = begin; s < end; ++s) start_[s + 1] += offset;
    });
  }
  partner_.resize(written);
  valid_ = true;
}

void VerletPairs::fromFull(const NeighbourList& full, std::span<const Eigen::Vector3d> x) {
  const int n = full.particleCount();
  start_.resize(static_cast<std::size_t>(n) + 1);
  start_[0] = 0;
  reach_.resize(static_cast<std::size_t>(n));
  partner_.clear();
  for (int i = 0; i < n; ++i) {
    auto& reach = reach_[static_cast<std::size_t>(i)];
    reach = static_cast<std::uint32_t>(i);
    for (int j : full.of(i))
      if (j > i) {
        partner_.push_back(static_cast<std::uint32_t>(j));
        reach = std::max(reach, static_cast<std::uint32_t>(j));
      }
    start_[static_cast<std::size_t>(i) + 1] = static_cast<std::uint32_t>(partner_.size());
  }
  anchor_.assign(x.begin(), x.end());
  h_ = 0;
  skin_ = 0;
  clearStrays();
  valid_ = false;  // no skin: good for this step only
}

void VerletPairs::clearStrays() {
  stray_.clear();
  strayPairs_.clear();
  strayCount_ = 0;
}

bool VerletPairs::refresh(const CellIndex& index, std::span<const Eigen::Vector3d> x) {
  Buffers& work = *buffers_;
  clearStrays();
  if (!valid_ || x.size() != anchor_.size() || index.particleCount() != x.size()) return false;
  // The two largest displacements: no pair can have closed by more than their sum. Measured
  // as they are first (one pass, the common case), then less the drift v (VerletPairs.h), the
  // middle of the displacements' bounding box: either passing proves the list.
  const std::size_t n = x.size();
  LargestTwo still;
  bool finite = true;
  Eigen::Vector3d low = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity()),
                  high = -low;
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector3d d = x[i] - anchor_[i];
    const double d2 = d.squaredNorm();
    finite = finite && d2 <= std::numeric_limits<double>::max();  // false for NaN and inf
    still.add(d2);
    low = low.cwiseMin(d);
    high = high.cwiseMax(d);
  }
  if (!finite) return false;
  if (still.sum() < skin_) return true;
  const Eigen::Vector3d drift = 0.5 * (low + high);
  LargestTwo drifting;
  for (std::size_t i = 0; i < n; ++i) drifting.add((x[i] - anchor_[i] - drift).squaredNorm());
  if (drifting.sum() < skin_) return true;
  if (!(skin_ > 0)) return false;

  // Some moved too far. Strays are measured from the median displacement (per axis) instead:
  // a few teleported or falling particles stretch the bounding box, not the median. The proof
  // holds for any v, so the median of an evenly strided sample of at most 1024 particles does
  // (deterministic, and three selections over 10,000 particles cost more than the rest of this).
  const std::size_t stride = (n + 1023) / 1024;
  Eigen::Vector3d median;
  for (int axis = 0; axis < 3; ++axis) {
    work.median.clear();
    for (std::size_t i = 0; i < n; i += stride)
      work.median.push_back(x[i][axis] - anchor_[i][axis]);
    const auto middle = work.median.begin() + static_cast<std::ptrdiff_t>(work.median.size() / 2);
    std::nth_element(work.median.begin(), middle, work.median.end());
    median[axis] = *middle;
  }
  const std::size_t limit = n / 32;
  const double half2 = 0.25 * skin_ * skin_;
  work.strays.clear();
  for (std::size_t i = 0; i < n; ++i)
    if (!((x[i] - anchor_[i] - median).squaredNorm() < half2)) {
      work.strays.push_back(static_cast<std::uint32_t>(i));
      if (work.strays.size() > limit) return false;
    }
  stray_.assign(n, 0);
  for (std::uint32_t f : work.strays) stray_[f] = 1;
  strayCount_ = static_cast<int>(work.strays.size());
  const double reach = h_ + skin_, reach2 = reach * reach;
  for (std::uint32_t f : work.strays) {
    // Partner j now within h: its anchor x_j - median - e_j lies within h + skin / 2 of
    // x_f - median, inside the 27 cells around that point.
    const Eigen::Vector3i c = index.cellOf(x[f] - median);
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy) {
        const CellIndex::Range r = index.row(c.x() + dx, c.y() + dy, c.z());
        for (std::uint32_t j = r.begin; j < r.end; ++j)  // sorted position == particle index
          if (!stray_[j] && (x[j] - x[f]).squaredNorm() < reach2)
            strayPairs_.push_back({std::min(f, j), std::max(f, j)});
      }
  }
  for (std::size_t a = 0; a < work.strays.size(); ++a)
    for (std::size_t b = a + 1; b < work.strays.size(); ++b)
      if ((x[work.strays[a]] - x[work.strays[b]]).squaredNorm() < reach2)
        strayPairs_.push_back({work.strays[a], work.strays[b]});
  std::sort(strayPairs_.begin(), strayPairs_.end());
  return true;
}

}  // namespace lacrima::tears
