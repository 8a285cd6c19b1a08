#pragma once
// The SPH colour field of a particle set (Müller et al. 2003), the scalar field whose iso
// surface is the tear's surface:
//   c(x)      = sum_j V_j W_poly6(x - x_j, h),          V_j = m_j / rho_j,
//   grad c(x) = sum_j V_j grad W_poly6(x - x_j, h)
//             = -945 / (32 pi h^9) sum_j V_j (h^2 - r_j^2)^2 (x - x_j),
//   rho_j     = sum_k m_k W_poly6(x_j - x_k, h)          (self included).
// c is ~1 inside the fluid (the V_j W are a partition of unity) and falls to 0 at distance h
// from the outermost particles; a lone particle has c(x_j) = 1 and c = (1 - r^2/h^2)^3.
//
// The densities are recomputed here from the positions given, not taken from the simulation:
// the solver's densities are one position update old at the end of a frame, and a particle
// spawned in a frame without a sub-step has none. Recomputing costs one density pass and makes
// the field a pure function of the positions (the tests evaluate exactly the mesher's field).
//
// Queries scan the 27 grid cells around x as nine contiguous runs of the grid's sorted copy of
// the positions (CellIndex::row), so nothing is allocated per query.
//
// The density pass of bind() runs cell by cell: the nine runs are looked up once per occupied
// cell (not per particle), and the pairs are summed four at a time in single precision
// (Float4.h) on positions in kernel units relative to the particles' bounding box, where
// rho_j / (w h^6) = sum_k m_k (1 - r_jk^2 / h^2)^3 is a sum of O(m) terms: float keeps ~7
// digits of the volumes, far below what the linear interpolation of marching cubes resolves.
// Each cell writes only its own particles' volumes, so the cells are shared between threads in
// fixed chunks (ParallelChunks.h) and the result does not depend on the thread count.
#include "CellIndex.h"
#include "ParallelChunks.h"

#include <lacrima/tears/UniformGrid.h>

#include <Eigen/Core>

#include <span>
#include <vector>

namespace lacrima::tears {

class SurfaceMesherField {
 public:
  // `grid` must be built over `positions` with cell edge h and must outlive the queries.
  // Throws std::invalid_argument if it was not (other edge, other particle count). `parallel`:
  // the threads to share the density pass with, or none.
  void bind(std::span<const Eigen::Vector3d> positions, std::span<const double> masses,
            const UniformGrid& grid, double h, ParallelChunks* parallel = nullptr);

  double kernelRadius() const { return h_; }
  double value(const Eigen::Vector3d& x) const;
  Eigen::Vector3d gradient(const Eigen::Vector3d& x) const;

  // Per sorted particle s (the grid's order): position and volume V = m / rho.
  const CellIndex& index() const { return *index_; }
  std::span<const double> sortedVolumes() const { return volume_; }
  // Per sorted particle: V w h^6, the dimensionless weight with c(x) = sum_j a_j (1 - r_j^2/h^2)^3
  // (0 for a particle that contributes nothing: non-positive mass, non-finite position).
  std::span<const float> sortedSplatWeights() const { return splat_; }

 private:
  template <typename Visit>
  void forNeighbours(const Eigen::Vector3d& x, Visit&& visit) const;

  const CellIndex* index_ = nullptr;
  double h_ = 0, h2_ = 0, w_ = 0, grad_ = 0;
  std::vector<double> volume_;  // sorted order
  std::vector<float> splat_;
  // Density-pass scratch, sorted order, padded by 3 for four-wide loads: positions in kernel
  // units relative to the bounding box, masses relative to the largest.
  std::vector<float> fx_, fy_, fz_, fm_;
};

}  // namespace lacrima::tears
