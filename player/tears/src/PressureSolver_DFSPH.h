#pragma once
// Divergence-free SPH (DFSPH) of Bender & Koschier 2015 ("Divergence-free smoothed particle
// hydrodynamics") and 2017 ("Divergence-free SPH for incompressible and viscous fluids"):
// pressure as the solution of two constraints instead of the stiff equation of state
// p = k (rho - rho0), so the time step is no longer bound by the speed of sound (CFL h / c,
// 3 ms at c = 0.2 m/s) but only by how far the particles move relative to each other (h / u_rel)
// and by the other forces.
//
// Per sub-step, over the half pair list of DensitySolver (pairs within h, rho0 = 1):
//   g_ij = grad_i W_spiky(x_i - x_j)                                   (per pair, once)
//   alpha_i = 1 / (|sum_j m_j g_ij|^2 + sum_j m_i m_j |g_ij|^2)        (Jacobi diagonal)
// A velocity correction with per-particle stiffness kappa,
//   dv_i = - sum_j m_j (kappa_i + kappa_j) g_ij,   dv_j = + m_i (kappa_i + kappa_j) g_ij,
// is momentum-conserving (antisymmetric) and, for kappa_i = e_i alpha_i, removes the density
// error e_i of particle i to first order when its neighbours keep still (Jacobi iteration).
//  1. Divergence: e_i = max(0, D rho_i / Dt) = max(0, sum_j m_j (v_i - v_j) . g_ij) per unit
//     time, iterated until its mean times the step is below the tolerance (at least once).
//  2. Density: after the non-pressure forces, predicted rho*_i = rho_i + dt sum_j m_j (v_i -
//     v_j) . g_ij, e_i = max(0, rho*_i - 1) / dt, iterated until the mean relative compression
//     is below the tolerance (at least twice).
// Only compression is corrected (e_i >= 0): at the free surface (almost every particle of a
// tear) the density deficit is not an error, and cohesion is surface tension's job, as with the
// clamped pressure of the weakly compressible solver.
//
// The stiffness parameter of the 2009 table has no meaning here; create() maps it
// to the tolerance instead (stiffer = tighter), see create().
//
// Passes run in single precision over Float4 copies (as FluidForcePass.h); the velocity changes
// are summed in float and added to the double velocities once, in particle order, so results are
// bitwise reproducible. Coincident particles get a gradient along the pair's id direction
// (PairDirection.h), as in the pressure force, so they are pushed apart too.
#include "Kernels.h"
#include "PressureSolver.h"

#include <span>
#include <vector>

namespace lacrima::tears {

struct DivergenceFreeSettings {
  double densityTolerance = 0.01;     // mean relative compression left after a step
  double divergenceTolerance = 0.01;  // mean relative density change per step left in the velocity
  int maxIterations = 50;             // per solve; reaching it is counted, not an error
};

struct DivergenceFreeStats {
  int divergenceIterations = 0, densityIterations = 0;
  bool divergenceCapped = false, densityCapped = false;
  // Largest net fluid acceleration of the last density solve: the non-pressure forces plus the
  // pressure correction, |a_i + dv_i / dt|, without what pushes a touching particle into the
  // skin. Surface tension alone reaches several g on surface particles but is balanced by
  // pressure and the skin; the time step limit wants the balance.
  double maxNetAcceleration = 0;
};

class PressureSolver_DFSPH final : public PressureSolver {
 public:
  PressureSolver_DFSPH(double h, const DivergenceFreeSettings& settings);
  static MethodInfo info();
  // The pressure parameter sets how tight the solves are: ten times the default pressure, ten
  // times tighter than the "tolerance" parameter, within [1e-4, 0.1].
  static std::unique_ptr<PressureSolver> create(const MethodValues& values,
                                                const ScaledParameters& parameters,
                                                const TearSettings& settings);

  // No equation of state: no sound speed in the CFL condition.
  double soundSpeed() const override { return 0; }
  // Zero pressures (the solves replace them), the pair gradients and factors alpha, then the
  // divergence solve for the expected step (the last sub-step's, at most `remaining`).
  void computePressures(ParticleSet& particles, const ActivePairs& pairs, double remaining,
                        TearCounters& counters) override;
  // Pressure is not in the accelerations yet, and surface tension alone is several g on surface
  // particles; what moves them is the balance, known after the solve. The last sub-step's net
  // acceleration stands in for it (the force pass's before there is any).
  double accelerationBound(double largestFluidAcceleration) const override;
  // The density solve, with the skin normals under touching particles.
  void correctVelocities(ParticleSet& particles, const ActivePairs& pairs, double dt,
                         const SkinView& skin, TearCounters& counters) override;
  PressureHistory history() const override { return history_; }
  void restoreHistory(const PressureHistory& history) override { history_ = history; }

  // After DensitySolver::compute: the pair gradients and the factors alpha.
  void prepare(const ParticleSet& particles, const ActivePairs& pairs);
  // Removes the compressing part of the velocity divergence; `dt` is the expected step (it only
  // sets the stopping point). Returns the iterations taken.
  int solveDivergence(ParticleSet& particles, const ActivePairs& pairs, double dt);
  // With the non-pressure forces (particles.acceleration, for dt) already in the velocities:
  // corrects them so the densities predicted after dt stay within the tolerance of rest.
  // `contactNormal[i]`: the skin normal under a touching particle (zero when free), whose
  // inward part of the net acceleration the contact constraint removes. Returns the iterations.
  int solveDensity(ParticleSet& particles, const ActivePairs& pairs, double dt,
                   std::span<const Eigen::Vector3d> contactNormal = {});

  const DivergenceFreeStats& stats() const { return stats_; }
  const DivergenceFreeSettings& settings() const { return settings_; }

 private:
  // One Jacobi sweep: error[i] from the current float velocities (rate of density change).
  void densityRates(const ActivePairs& pairs, int n);
  // v_i -= sum_j m_j (kappa_i + kappa_j) g_ij over the pairs.
  void applyKappa(const ActivePairs& pairs, int n);
  void loadVelocities(const ParticleSet& particles);
  void storeVelocities(ParticleSet& particles) const;

  SpikyKernel w_;
  DivergenceFreeSettings settings_;
  DivergenceFreeStats stats_;
  PressureHistory history_;
  std::vector<Eigen::Vector3d> contactNormal_;
  std::vector<float> gradient_;  // 4 per pair: g_ij (x, y, z, 0)
  std::vector<float> m_, alpha_, rate_, kappa_;
  std::vector<float> velocity_, start_;  // 4 per particle; start_: velocity before the solve
};

}  // namespace lacrima::tears
