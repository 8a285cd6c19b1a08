#pragma once
// Half neighbour lists for the solver: every pair once (i < j), forces applied to both ends.
//
// VerletPairs holds the candidate pairs closer than R = h + skin when it was built, and stays
// usable while the two largest displacements since then, d1 >= d2, sum to less than the skin:
// for any pair now closer than h,
//   |x_i0 - x_j0| <= |x_i - x_j| + |x_i - x_i0| + |x_j - x_j0| < h + d1 + d2 < R,
// so it was listed (Verlet 1967). Bounding d1 + d2 rather than 2 d1 lets a single fast particle
// (a drop falling off the chin) move up to a whole skin before everything is searched again. Each sub-step filters the candidates to the pairs within h
// (ActivePairs, with their distance), so every pass sees exactly the pairs a fresh search would.
//
// Built from a CellIndex over particles already in cell order (sorted position == particle
// index): the candidates of particle s are s+1 .. the end of its own z-row, plus the four
// "forward" rows (dx, dy) = (0, 1), (1, -1), (1, 0), (1, 1); their mirror images are the other
// particle's forward rows, so each pair is met exactly once.
#include <lacrima/tears/CellIndex.h>
#include <lacrima/tears/NeighbourSearch.h>

#include <cstdint>
#include <span>
#include <vector>

namespace lacrima::tears {

class VerletPairs {
public:
  // `index` was built over these positions, which are in its sorted order.
  void build(const CellIndex& index, double h, double skin);
  // From full lists (any structure): pairs i < j, no skin (valid for the current positions only).
  void fromFull(const NeighbourList& full, std::span<const Eigen::Vector3d> positions);

  // Whether the list still holds every pair within h (the two largest displacements since the
  // build sum to less than the skin).
  bool stillValid(std::span<const Eigen::Vector3d> positions) const;
  void invalidate() { valid_ = false; }
  bool valid() const { return valid_; }

  int particleCount() const { return static_cast<int>(start_.empty() ? 0 : start_.size() - 1); }
  std::size_t pairCount() const { return partner_.size(); }
  std::uint32_t begin(int i) const { return start_[static_cast<std::size_t>(i)]; }
  std::uint32_t end(int i) const { return start_[static_cast<std::size_t>(i) + 1]; }
  const std::uint32_t* partners() const { return partner_.data(); }

private:
  std::vector<std::uint32_t> start_;    // size n + 1
  std::vector<std::uint32_t> partner_;  // j > i
  std::vector<Eigen::Vector3d> anchor_; // positions at the build
  double skin_ = 0;
  bool valid_ = false;
};

// The pairs within h this sub-step, i < j, with their distance r = |x_i - x_j|.
// The float arrays are the pair geometry DensitySolver already computed (relative to one origin,
// single precision), kept so the force pass streams them instead of gathering positions again.
struct ActivePairs {
  std::vector<std::uint32_t> start;  // size n + 1
  std::vector<std::uint32_t> partner;
  std::vector<double> distance;      // r, written by FluidForcePass (Akinci reads it)
  std::vector<float> offset;         // 4 per pair: x_i - x_j, then 0 (one SSE register)
  std::vector<float> r2;             // |x_i - x_j|^2

  int particleCount() const { return static_cast<int>(start.empty() ? 0 : start.size() - 1); }
  std::size_t pairCount() const { return partner.size(); }
};

}  // namespace lacrima::tears
