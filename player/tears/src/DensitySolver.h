#pragma once
// SPH density summation (Müller et al. 2003), the first of the two passes over the pairs
// of a sub-step (FluidForcePass.h has the second):
//   rho_i = sum_j m_j W_poly6(x_i - x_j), the particle itself included,
// with density normalised (rho0 = 1). It also turns the Verlet candidates into the sub-step's
// pairs within h (ActivePairs.h) with their r^2 and the float positions they were
// measured with, from which every later pass recomputes the same offsets.
//
// Single precision on copies of the particle state (positions relative to the first particle,
// so float keeps ~1e-5 h of resolution anywhere on the head), baseline x86-64 only, fixed
// iteration order: results are bitwise reproducible (FluidForcePass.h has the argument).
//
// Shared between threads in fixed particle chunks (ParallelChunks.h). A chunk sums into a
// window of its own, one float for each particle from its first to the farthest partner its
// pairs reach (VerletPairs::reach), so no two threads write one float and the hot loop has no
// test for where a partner is. The windows hold about 1.5 n floats in all on the sheet and 1.7 n
// on the default head at 10,000 particles, 3-5 n on the head at 100,000 (a window spans about
// one x-slab of cells, which grows with the count); a window never exceeds n. Then each particle's
// density is its own chunk's sum plus the earlier chunks' sums for it, in chunk order: the same sum
// in the same order for any number of threads.
#include "ActivePairs.h"
#include "Kernels.h"
#include "ParallelChunks.h"
#include "VerletPairs.h"

#include <lacrima/tears/ParticleSet.h>

#include <vector>

namespace lacrima::tears {

class DensitySolver {
 public:
  explicit DensitySolver(double h) : h_(h), w_(h) {}
  // Filters the candidates (with this sub-step's strays, VerletPairs.h) to the pairs closer than h,
  // into `active` with their r^2 (the force pass takes square roots for kept pairs only) and
  // the positions, and sums the density over them. Without `parallel` the chunks run in order
  // on the calling thread (the same results).
  void compute(ParticleSet& particles, const VerletPairs& candidates, ActivePairs& active,
               ParallelChunks* parallel = nullptr) const;

 private:
  // One chunk's density sums for particles first, first + 1, ...
  struct Window {
    std::uint32_t first = 0;
    std::vector<float> sum;
  };
  // The candidates of particles [begin, end) into `active` from `slot` on (their stray pairs
  // start at strayPairs()[stray]), summed into `window`.
  template <bool Strays>
  void accumulate(const VerletPairs& candidates, ActivePairs& active, std::uint32_t begin,
                  std::uint32_t end, std::uint32_t slot, std::size_t stray, Window& window) const;

  double h_;
  Poly6Kernel w_;
  mutable float h2_ = 0, wScale_ = 0, w0_ = 0;
  // Single-precision copies of the particle state, refilled every call (capacity is kept); the
  // positions are written into ActivePairs.
  mutable std::vector<float> m_, rho_;
  mutable std::vector<Window> windows_;
};

}  // namespace lacrima::tears
