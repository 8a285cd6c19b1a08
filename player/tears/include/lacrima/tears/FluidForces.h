#pragma once
// The SPH terms of Müller et al. 2003. All write accelerations (force density divided by the
// particle's density) so the integrator adds them directly. Density is normalised: rho0 = 1, so
// k, nu and sigma below are per unit rest density.
//
// Every term is evaluated over the half pair list of the sub-step (ActivePairs, PairList.h):
// each pair i < j once, its contribution added to both particles (antisymmetric terms with
// opposite signs). Per sub-step there are three passes over the pairs:
//   A  DensitySolver        candidates -> pairs within h, with offset and r^2; density;
//   B  FluidForcePass       pressure, viscosity weights and weighted velocities and the Müller
//                           colour field, from one load of the pair's state;
//   C  (none)               the viscosity relaxation then needs per-particle work only.
// The iteration order is fixed (particle order, then partner order), so sums are reproducible.
//
// Passes A and B run in single precision on copies of the particle state: 3-vectors as 4 floats
// (x, y, z, 0), so each scattered vector update is one SSE2 load, add and store, and the force
// pass's per-particle scalars (m, p, 1 / rho, V) as 4 floats too, one load per partner
// (positions relative to the first particle, so float keeps ~1e-5 h of resolution anywhere on
// the head). Only baseline x86-64 instructions are used (no -march, no
// FMA contraction), so results are bitwise identical on every x86-64 machine. Per-particle
// results are converted back to the double ParticleSet.
#include <lacrima/tears/Kernels.h>
#include <lacrima/tears/PairList.h>
#include <lacrima/tears/ParticleSet.h>

#include <vector>

namespace lacrima::tears {

// rho_i = sum_j m_j W_poly6(x_i - x_j), the particle itself included.
class DensitySolver {
public:
  explicit DensitySolver(double h) : h_(h), w_(h) {}
  // Filters the candidates (with this sub-step's strays, PairList.h) to the pairs closer than h,
  // into `active` with their offset and r^2 (the force pass takes square roots for kept pairs
  // only), and sums the density over them.
  void compute(ParticleSet& particles, const VerletPairs& candidates, ActivePairs& active) const;

private:
  template <bool Strays>
  void accumulate(const VerletPairs& candidates, ActivePairs& active) const;

  double h_;
  Poly6Kernel w_;
  mutable float h2_ = 0, wScale_ = 0;
  // Single-precision copies of the particle state, refilled every call (capacity is kept).
  mutable std::vector<float> position_, m_, rho_;  // position: 4 floats per particle (x, y, z, 0)
};

// Equation of state p = k (rho - rho0) and the symmetric pressure force
//   a_i = - sum_j m_j (p_i + p_j) / (2 rho_i rho_j) grad W_spiky(x_i - x_j),
// which is antisymmetric in (i, j) and so conserves momentum.
// Negative pressures are clamped to 0 by default: with tens of particles nearly all of them sit
// at the free surface, where the density deficit would otherwise pull them into clumps (tensile
// instability); cohesion is the surface-tension term's job.
class PressureForce {
public:
  PressureForce(double h, double stiffness, double restDensity, bool clampNegative)
      : w_(h), k_(stiffness), rho0_(restDensity), clampNegative_(clampNegative) {}
  void computePressures(ParticleSet& particles) const;
  const SpikyKernel& kernel() const { return w_; }

private:
  SpikyKernel w_;
  double k_, rho0_;
  bool clampNegative_;
};

// Müller's viscosity a_i = nu sum_j m_j (v_j - v_i) / (rho_i rho_j) lap W_visc(x_i - x_j) (rho0=1)
// written as a relaxation towards the weighted neighbour mean:
//   a_i = k_i (vbar_i - v_i), k_i = nu sum_j m_j lap W / (rho_i rho_j), vbar_i = weighted mean.
// Explicit Euler is stable (and non-overshooting: the new v_i stays between v_i and vbar_i)
// iff k_i dt <= 1: that is the viscosity limit given to the time stepper. The update used is the
// exact solution of the frozen relaxation, v_i += (1 - exp(-k_i dt)) (vbar_i - v_i), equal to
// Euler to first order and still a convex combination if a step is ever longer than 1 / k_i.
// The relaxation acts on the velocities at the start of the sub-step, before the other forces
// are added (operator splitting: relax, then accelerate). That differs from relaxing after the
// forces by (1 - exp(-k dt)) dt (abar_i - a_i) = O(k dt^2), second order, and lets the weighted
// means be summed in the force pass instead of a third pass over the pairs.
class ViscosityForce {
public:
  ViscosityForce(double h, double kinematicViscosity) : h_(h), w_(h), nu_(kinematicViscosity) {}
  double nu() const { return nu_; }
  // lap W_visc(r) = 45 / (pi h^6) (h - r)
  const ViscosityKernel& kernel() const { return w_; }
  // Relaxes velocities over dt, Jacobi-style (every particle sees the velocities before the
  // update, so the result does not depend on particle order), from what FluidForcePass summed:
  // particles.viscosityRate, weightSum_i = sum_j m_j / rho_j lap W and
  // weighted_i = sum_j m_j / rho_j lap W v_j (so vbar_i = weighted_i / weightSum_i).
  void apply(ParticleSet& particles, std::span<const Eigen::Vector3d> weighted, std::span<const double> weightSum,
             double dt) const;

private:
  double h_;
  ViscosityKernel w_;
  double nu_;
};

enum class SurfaceTensionModel { Mueller, Akinci };

// Müller colour field: c_i = sum_j m_j / rho_j W_poly6, n_i = grad c, kappa = -lap c / |n|,
//   a_i = sigma kappa n_i / |n_i| / rho_i = -sigma lap c_i n_i / (|n_i| rho_i),
// applied where |n_i| exceeds 0.25 / h (near the surface; inside, n is noise).
// The sums grad c and lap c are accumulated by FluidForcePass; this class turns them into forces.
class MuellerSurfaceTension {
public:
  MuellerSurfaceTension(double h, double sigma) : h_(h), w_(h), sigma_(sigma) {}
  bool active() const { return sigma_ > 0; }
  const Poly6Kernel& kernel() const { return w_; }
  void addAccelerations(ParticleSet& particles, std::span<const Eigen::Vector3d> gradient,
                        std::span<const double> laplacian) const;

private:
  double h_;
  Poly6Kernel w_;
  double sigma_;
};

// Akinci 2013: cohesion plus curvature minimisation,
//   F_ij = K_ij (-gamma m_i m_j C(r) r_hat - gamma m_i (n_i - n_j)),  K_ij = 2 rho0 / (rho_i + rho_j)
//   n_i = h sum_j m_j / rho_j grad W_poly6(x_i - x_j)
// a_i = sum_j F_ij / m_i. (Its two passes run after pass B; it is not the default model.)
class AkinciSurfaceTension {
public:
  AkinciSurfaceTension(double h, double gamma, double restDensity)
      : h_(h), w_(h), c_(h), gamma_(gamma), rho0_(restDensity) {}
  void addAccelerations(ParticleSet& particles, const ActivePairs& pairs);

private:
  double h_;
  Poly6Kernel w_;
  CohesionKernel c_;
  double gamma_, rho0_;
  std::vector<Eigen::Vector3d> normal_, force_;
};

// Pass B: for every pair within h, the pressure force, the viscosity weight sums and (Müller
// model) the colour-field gradient and Laplacian, from one load of the pair's state.
class FluidForcePass {
public:
  // Adds pressure (and Müller tension) to particles.acceleration, fills particles.viscosityRate
  // and weightSum(). Returns the largest closing speed -(v_i - v_j).(x_i - x_j) / r over pairs
  // within h, the velocity part of Monaghan's signal velocity in the CFL condition: SPH is
  // Galilean invariant (a drop sliding as a whole at any speed is as stable as one at rest),
  // and pairs that slide past or separate compress nothing.
  // Reads the velocities: call it before they change in this sub-step.
  double run(ParticleSet& particles, ActivePairs& pairs, const PressureForce& pressure,
             const ViscosityForce& viscosity, const MuellerSurfaceTension* tension);
  std::span<const double> weightSum() const { return weightSum_; }
  std::span<const Eigen::Vector3d> weightedVelocity() const { return weighted_; }

private:
  template <bool Colour, bool Pressure>
  void accumulate(const ActivePairs& pairs, int n, std::uint64_t const* ids);

  std::vector<double> weightSum_, laplacian_;
  std::vector<Eigen::Vector3d> gradient_, weighted_;
  // Float state per particle: velocity (x, y, z, 0 as 4 floats) and m, p, 1 / rho, V (4 floats:
  // one load per partner); sums per particle: acceleration (x, y, z, viscosity weight sum), weighted velocity
  // (x, y, z, colour Laplacian) and colour gradient (x, y, z, 0). Groups of 4 floats are one
  // SSE register, so a scattered vector update is one load, one add and one store.
  std::vector<float> velocity_, scalars_;
  std::vector<float> acc_, weighted4_, gradient4_;
  // Per-pair kernel factors, from r alone (one flat, vectorised loop over the pairs), and
  // (v_i - v_j).(x_i - x_j), reduced to the closing speed after the pair loop.
  std::vector<float> radial_, lapVisc_, gradColour_, lapColour_, approach_;
  float h_ = 0, h2_ = 0, spiky_ = 0, atZero_ = 0, visc_ = 0, poly6_ = 0;
};

}  // namespace lacrima::tears
