#pragma once
// The second pass over the pairs of a sub-step (DensitySolver.h has the first): for every pair
// within h, from one load of the pair's state,
//   * the symmetric pressure force of Müller et al. 2003, from particles.pressure
//     (PressureSolver.h fills it):
//       a_i = - sum_j m_j (p_i + p_j) / (2 rho_i rho_j) grad W_spiky(x_i - x_j),
//     antisymmetric in (i, j), so momentum is conserved;
//   * the viscosity weight sums of Viscosity_Mueller2003.h (the relaxation itself then needs
//     per-particle work only);
//   * when the surface-tension model asks for it (SurfaceTension_Mueller2003.h), the colour
//     field's gradient and Laplacian, c_i = sum_j m_j / rho_j W_poly6.
// All terms are accelerations (force density over the particle's density); density is
// normalised (rho0 = 1).
//
// Every term is evaluated over the half pair list (ActivePairs.h): each pair i < j
// once, its contribution added to both particles (antisymmetric terms with opposite signs). The
// iteration order is fixed (particle order, then partner order), so sums are reproducible.
//
// Threads (ParallelChunks.h): the particles are cut into fixed chunks of kParticleChunk. A
// chunk sums its own particles' terms and adds the partner's share directly when the partner is
// in the chunk too; a partner beyond the chunk gets its share through the chunk's spill list
// (partner, share). Once all chunks have run, each chunk adds the spills aimed at its particles,
// from the earlier chunks' lists in chunk order, each list in its own order. Every particle's
// sums thus take the same additions in the same order for any thread count.
//
// Both pair passes run in single precision on copies of the particle state: 3-vectors as 4
// floats (x, y, z, 0), so each scattered vector update is one SSE2 load, add and store, and the
// per-particle scalars (m, p, 1 / rho, V) as 4 floats too, one load per partner (positions
// relative to the first particle, so float keeps ~1e-5 h of resolution anywhere on the head).
// Only baseline x86-64 instructions are used (no -march, no FMA contraction), so results are
// bitwise identical on every x86-64 machine. Per-particle results are converted back to the
// double ParticleSet.
#include "ActivePairs.h"
#include "Kernels.h"
#include "ParallelChunks.h"
#include "UninitialisedAllocator.h"
#include "Viscosity_Mueller2003.h"

#include <lacrima/tears/ParticleSet.h>

#include <cstdint>
#include <functional>
#include <span>
#include <vector>

namespace lacrima::tears {

class FluidForcePass {
 public:
  explicit FluidForcePass(double h) : spikyKernel_(h), viscosityKernel_(h), poly6Kernel_(h) {}

  // Per-particle work that needs the pass's results: afterChunk(c, begin, end) runs in the
  // pass's last shared loop once particles [begin, end) have them (one hand-over between the
  // threads fewer than a loop of its own).
  using ChunkWork = std::function<void(int chunk, std::size_t begin, std::size_t end)>;

  // Sets particles.acceleration to the pressure acceleration, fills particles.viscosityRate,
  // weightSum() and weightedVelocity(), and with `colourField` colourGradient() and
  // colourLaplacian(); then calls afterChunk, if any, on every chunk. Returns
  // the largest closing speed -(v_i - v_j).(x_i - x_j) / r over pairs within h, the velocity
  // part of Monaghan's signal velocity in the CFL condition: SPH is Galilean invariant (a drop
  // sliding as a whole at any speed is as stable as one at rest), and pairs that slide past or
  // separate compress nothing.
  // Reads the velocities: call it before they change in this sub-step.
  double run(ParticleSet& particles, ActivePairs& pairs, const Viscosity_Mueller2003& viscosity,
             bool colourField, ParallelChunks& parallel, const ChunkWork& afterChunk = {});
  std::span<const double> weightSum() const { return weightSum_; }
  std::span<const Eigen::Vector3d> weightedVelocity() const { return weighted_; }
  // grad c_i and lap c_i of the last run with colourField (empty otherwise).
  std::span<const Eigen::Vector3d> colourGradient() const { return gradient_; }
  std::span<const double> colourLaplacian() const { return laplacian_; }

 private:
  // A chunk's shares for partners beyond it: the partner's index and its 12 floats
  // (acceleration, weighted velocity, colour gradient; lane 3 as in acc_ and weighted4_).
  // Never zeroed: every entry in use is written first.
  struct Spill {
    UninitialisedVector<std::uint32_t> partner;
    UninitialisedVector<float> share;
    std::size_t count = 0;                  // entries in use
    std::uint32_t lowest = 0, highest = 0;  // of the partners in use, when count > 0
  };
  // The pair loop over the particles [begin, end).
  template <bool Colour, bool Pressure>
  void accumulate(const ActivePairs& pairs, std::uint32_t begin, std::uint32_t end,
                  std::uint64_t const* ids, Spill& spill);
  // Adds the shares that chunks before `chunk` spilled onto particles [begin, end).
  void addSpills(std::size_t chunk, std::size_t begin, std::size_t end, bool colour);

  SpikyKernel spikyKernel_;  // pressure
  ViscosityKernel viscosityKernel_;
  Poly6Kernel poly6Kernel_;  // colour field
  std::vector<double> weightSum_, laplacian_;
  std::vector<Eigen::Vector3d> gradient_, weighted_;
  // Float state per particle: velocity (x, y, z, 0 as 4 floats) and m, p, 1 / rho, V (4 floats:
  // one load per partner); sums per particle: acceleration (x, y, z, viscosity weight sum),
  // weighted velocity (x, y, z, colour Laplacian) and colour gradient (x, y, z, 0). Groups of 4
  // floats are one SSE register, so a scattered vector update is one load, one add and one store.
  std::vector<float> velocity_, scalars_;
  std::vector<float> acc_, weighted4_, gradient4_;
  // Per-pair kernel factors, from r alone (a flat, vectorised loop over a chunk's pairs before
  // its pair loop), and (v_i - v_j).(x_i - x_j), reduced to the chunk's closing speed after it.
  std::vector<float> radial_, lapVisc_, gradColour_, lapColour_, approach_;
  std::vector<Spill> spills_;                    // per particle chunk, capacity kept
  std::vector<float> closing_;                   // per particle chunk: largest closing speed^2
  std::vector<unsigned char> anyPressureChunk_;  // per particle chunk
  float h_ = 0, h2_ = 0, spiky_ = 0, atZero_ = 0, visc_ = 0, poly6_ = 0;
};

}  // namespace lacrima::tears
