#pragma once
// Half neighbour lists for the solver: every pair once (i < j), forces applied to both ends.
//
// VerletPairs holds the candidate pairs closer than R = h + skin when it was built, and stays
// usable while the two largest displacements since then, d1 >= d2, sum to less than the skin:
// for any pair now closer than h,
//   |x_i0 - x_j0| <= |x_i - x_j| + |x_i - x_i0| + |x_j - x_j0| < h + d1 + d2 < R,
// so it was listed (Verlet 1967). Bounding d1 + d2 rather than 2 d1 lets a single fast particle
// move up to a whole skin before anything is searched again. Each sub-step filters the
// candidates to the pairs within h (ActivePairs, with their offsets), so every pass sees
// exactly the pairs a fresh search would.
//
// Built from a CellIndex over particles already in cell order (sorted position == particle
// index): the candidates of particle s are s+1 .. the end of its own z-row, plus the four
// "forward" rows (dx, dy) = (0, 1), (1, -1), (1, 0), (1, 1); their mirror images are the other
// particle's forward rows, so each pair is met exactly once. Cell keys are x-major, so those rows
// come in sorted order and each particle's candidates ascend.
//
// Drift. A displacement v common to every particle changes no distance, so d_i above may be
// measured as x_i - x_i0 - v for any one v: the test uses the middle of the displacements'
// bounding box, and a film sliding down the cheek as a whole keeps its list however far it
// slides.
//
// Strays. One fast particle (a drop falling off the chin past still ones, or one re-emitted at
// its source) would otherwise force a full rebuild every sub-step. When the test fails, v
// becomes the median displacement (per axis, of a strided sample: a few outliers do not move
// it; any v keeps the argument exact) and the particles
// with |d_i - v| >= skin / 2 become strays. Any pair of two others still has d_i + d_j < skin,
// so the list stays exact for them; each stray's pairs are searched afresh every sub-step in
// the build's cells around x_f - v (a partner within h of it now has its anchor within
// h + skin / 2 < cell edge of that point, so the 27 cells around it hold every one). The
// density pass skips listed pairs that involve a stray and adds the stray pairs instead.
// Beyond n / 32 strays a rebuild is cheaper, and refresh() asks for one.
#include <lacrima/tears/Scratch.h>
#include "CellIndex.h"
#include "ParallelChunks.h"
#include "UninitialisedAllocator.h"

#include <lacrima/tears/NeighbourSearch.h>

#include <cstdint>
#include <span>
#include <vector>

namespace lacrima::tears {

class VerletPairs {
 public:
  // `index` was built over these positions, which are in its sorted order.
  void build(const CellIndex& index, double h, double skin);
  // The same list, the particles' search shared in `parallel`'s fixed chunks.
  void build(const CellIndex& index, double h, double skin, ParallelChunks& parallel);
  // From full lists (any structure): pairs i < j, no skin (valid for the current positions only).
  void fromFull(const NeighbourList& full, std::span<const Eigen::Vector3d> positions);

  // Whether the list (with its strays) still holds every pair within h of `positions`; false
  // means rebuild. `index` is the one the list was built from. Finds this sub-step's strays and
  // their pairs.
  bool refresh(const CellIndex& index, std::span<const Eigen::Vector3d> positions);
  void invalidate() { valid_ = false; }
  bool valid() const { return valid_; }

  int particleCount() const { return static_cast<int>(start_.empty() ? 0 : start_.size() - 1); }
  std::size_t pairCount() const { return partner_.size(); }
  std::uint32_t begin(int i) const { return start_[static_cast<std::size_t>(i)]; }
  std::uint32_t end(int i) const { return start_[static_cast<std::size_t>(i) + 1]; }
  const std::uint32_t* partners() const { return partner_.data(); }
  // The largest candidate partner of particle i (i itself when it has none): how far the
  // density pass's scatter from i reaches.
  std::uint32_t reach(int i) const { return reach_[static_cast<std::size_t>(i)]; }

  // This sub-step's strays (refresh()): empty flags when there are none, else one per particle
  // (1 = its listed pairs are void), and the pairs of every stray within h + skin of it now, as
  // (lower, higher) index, sorted.
  bool hasStrays() const { return strayCount_ > 0; }
  const std::vector<std::uint8_t>& strayFlags() const { return stray_; }
  struct Pair {
    std::uint32_t lower, higher;
    auto operator<=>(const Pair&) const = default;
  };
  const std::vector<Pair>& strayPairs() const { return strayPairs_; }
  int strayCount() const { return strayCount_; }

 private:
  void clearStrays();
  std::size_t scan(const CellIndex& index, std::uint32_t first, std::uint32_t last, float r2max,
                   UninitialisedVector<std::uint32_t>& out, std::size_t written);

  std::vector<std::uint32_t> start_;            // size n + 1
  UninitialisedVector<std::uint32_t> partner_;  // j > i
  std::vector<std::uint32_t> reach_;            // size n
  std::vector<Eigen::Vector3d> anchor_;         // positions at the build
  double h_ = 0, skin_ = 0;
  bool valid_ = false;
  std::vector<std::uint8_t> stray_;
  std::vector<Pair> strayPairs_;
  int strayCount_ = 0;
  // Working buffers of build() and refresh(), kept for their capacity (Scratch.h).
  struct Buffers {
    std::vector<float> fx, fy, fz;      // build: sorted positions in float
    std::vector<double> median;         // refresh: drifts along one axis
    std::vector<std::uint32_t> strays;  // refresh: this sub-step's strays
    // Shared builds: each chunk's candidates, their count and place in partner_.
    std::vector<UninitialisedVector<std::uint32_t>> chunkPartner;
    std::vector<std::size_t> chunkCount, chunkOffset;
  };
  Scratch<Buffers> buffers_;
};

}  // namespace lacrima::tears
