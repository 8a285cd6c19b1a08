#pragma once
// Viscosity of Müller, Charypar & Gross 2003 ("Particle-based fluid simulation for interactive
// applications"), with rho0 = 1:
//   a_i = nu sum_j m_j (v_j - v_i) / (rho_i rho_j) lap W_visc(x_i - x_j),
//   lap W_visc(r) = 45 / (pi h^6) (h - r),
// written as a relaxation towards the weighted neighbour mean:
//   a_i = k_i (vbar_i - v_i),  k_i = nu sum_j m_j lap W / (rho_i rho_j),  vbar_i = weighted mean.
// Explicit Euler is stable (and non-overshooting: the new v_i stays between v_i and vbar_i)
// iff k_i dt <= 1: that is the viscosity limit given to the time stepper (AdaptiveTimeStep.h).
// The update used is the exact solution of the frozen relaxation,
//   v_i += (1 - exp(-k_i dt)) (vbar_i - v_i),
// equal to Euler to first order and still a convex combination if a step is ever longer than
// 1 / k_i. The relaxation acts on the velocities at the start of the sub-step, before the other
// forces are added (operator splitting: relax, then accelerate). That differs from relaxing
// after the forces by (1 - exp(-k dt)) dt (abar_i - a_i) = O(k dt^2), second order, and lets the
// weighted means be summed in the force pass (FluidForcePass.h) instead of a pass of their own.
#include <lacrima/tears/ParticleSet.h>

#include <span>

namespace lacrima::tears {

class Viscosity_Mueller2003 {
 public:
  explicit Viscosity_Mueller2003(double kinematicViscosity) : nu_(kinematicViscosity) {}
  double nu() const { return nu_; }
  // Relaxes the velocities of particles [begin, end) over dt, Jacobi-style (every particle sees
  // the velocities before the update, so the result does not depend on particle order or on
  // how the range is cut), from what FluidForcePass summed: particles.viscosityRate,
  // weightSum_i = sum_j m_j / rho_j lap W and weighted_i = sum_j m_j / rho_j lap W v_j (so
  // vbar_i = weighted_i / weightSum_i).
  void apply(ParticleSet& particles, std::span<const Eigen::Vector3d> weighted,
             std::span<const double> weightSum, double dt, std::size_t begin,
             std::size_t end) const;

 private:
  double nu_;
};

}  // namespace lacrima::tears
