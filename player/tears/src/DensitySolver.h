#pragma once
// SPH density summation (Müller et al. 2003), the first of the two passes over the pairs
// of a sub-step (FluidForcePass.h has the second):
//   rho_i = sum_j m_j W_poly6(x_i - x_j), the particle itself included,
// with density normalised (rho0 = 1). It also turns the Verlet candidates into the sub-step's
// pairs within h (ActivePairs, PairList.h) with their r^2 and the float positions they were
// measured with, from which every later pass recomputes the same offsets.
//
// Single precision on copies of the particle state (positions relative to the first particle,
// so float keeps ~1e-5 h of resolution anywhere on the head), baseline x86-64 only, fixed
// iteration order: results are bitwise reproducible (FluidForcePass.h has the argument).
#include "Kernels.h"
#include "PairList.h"

#include <lacrima/tears/ParticleSet.h>

#include <vector>

namespace lacrima::tears {

class DensitySolver {
 public:
  explicit DensitySolver(double h) : h_(h), w_(h) {}
  // Filters the candidates (with this sub-step's strays, PairList.h) to the pairs closer than h,
  // into `active` with their r^2 (the force pass takes square roots for kept pairs only) and
  // the positions, and sums the density over them.
  void compute(ParticleSet& particles, const VerletPairs& candidates, ActivePairs& active) const;

 private:
  template <bool Strays>
  void accumulate(const VerletPairs& candidates, ActivePairs& active) const;

  double h_;
  Poly6Kernel w_;
  mutable float h2_ = 0, wScale_ = 0;
  // Single-precision copies of the particle state, refilled every call (capacity is kept); the
  // positions are written into ActivePairs.
  mutable std::vector<float> m_, rho_;
};

}  // namespace lacrima::tears
