#pragma once
// Position-based fluids (PBF) of Macklin & Müller 2013 ("Position Based Fluids"): incompressibility
// as a constraint on the positions at the end of the sub-step, solved by a fixed number of Jacobi
// iterations, instead of a pressure force (WCSPH) or velocity solves (DFSPH).
//
// Per sub-step, once the non-pressure forces are in the velocities (correctVelocities), over the
// half pair list of DensitySolver (pairs within h at the start of the sub-step, rho0 = 1,
// V_j = m_j / rho0 the particle's volume):
//   d_i = dt v_i                                  predicted displacement, x*_i = x_i + d_i
//   r_ij = (x_i - x_j) + d_i - d_j                pair offset at the predicted positions
//   rho_i = m_i W(0) + sum_j m_j W_poly6(r_ij)     density at the predicted positions
//   C_i = max(0, rho_i / rho0 - 1)                 density constraint, compression only
//   g_ij = grad_i W_spiky(r_ij)
//   grad_i C_i = sum_j V_j g_ij,   grad_j C_i = -V_j g_ij
//   lambda_i = -C_i / (|grad_i C_i|^2 + sum_j |grad_j C_i|^2 + epsilon)
//   dp_i = sum_j V_j (lambda_i + lambda_j + s_corr,ij) g_ij,
//   dp_j = -V_i (lambda_i + lambda_j + s_corr,ij) g_ij            (momentum-conserving)
//   d_i += dp_i, repeated `iterations` times;
// then v_i = d_i / dt, so the integration x_i += dt v_i lands on the corrected positions.
// epsilon (the paper's constraint force mixing) is relaxation / h^2, against a denominator of
// about 1.5 / h^2 for a particle inside the fluid at rest spacing (26 neighbours at h / 2): it
// softens the particles with few neighbours, whose lambda would otherwise be huge. The default
// 1 under-relaxes each sweep; 0.1 leaves about as much compression (max rho/rho0 1.035 against
// 1.044 at 1,000 particles on the sheet, lacrima-bench tears --pbf-relaxation).
//
// As with the other solvers only compression is corrected: at the free surface (almost every
// particle of a tear) the density deficit is not an error, cohesion is surface tension's job.
// The artificial pressure of the paper,
//   s_corr,ij = -k h^2 (W_poly6(r_ij) / W_poly6(dq))^n,   k = 0.1, n = 4, dq = 0.2 h,
// (the paper's k = 0.1 is in its own units; lambda scales as h^2 here, since the denominator
// sum |grad C|^2 is about 1.5 / h^2, so s_corr at dq is what lambda is for a compression of 15%)
// pushes close pairs apart against the tensile instability. With compression-only constraints
// the clumping it fights does not show, and nothing pulls the pairs it pushes back (the
// constraint never acts on a stretched particle), so it spreads the drops (max rho/rho0 0.62 on
// the sheet, test_tears_pbf): optional and off by default
// (the "artificial-pressure" parameter).
//
// Skin contacts: a touching particle's correction loses its part into the skin (along the
// normal of the triangle it touches), as DFSPH's density solve does with its acceleration, so
// no correction pushes a particle through; the contact constraint runs afterwards as usual.
//
// The pairs are those within h at the start of the sub-step (Macklin & Müller also find the
// neighbours once per step); a pair that closes in from beyond h during the step is seen in
// the next sub-step. Coincident particles get a gradient along the pair's id direction
// (PairDirection.h), as in DFSPH and the pressure force.
//
// Time step: no speed of sound (soundSpeed() = 0) and, as DFSPH, the acceleration bound is the
// last sub-step's net acceleration a_i + dp_i / dt^2 (without what pushes into the skin), so
// the step is set by relative motion and by the balance of tension and the constraint, not by
// tension alone. A larger sub-step factor (lambda_c, lambda_a) gives PBF fewer sub-steps (x3:
// 8 a frame instead of 19 at 1,000 particles on the sheet), but then drops compress again (max
// rho/rho0 1.75), since pairs closing in from beyond h are not constrained within the step
// (docs/decisions/0016).
//
// Passes run in single precision over Float4 copies, serially in particle order: results are
// bitwise reproducible whatever the thread count.
#include "Kernels.h"
#include "PressureSolver.h"

#include <span>
#include <vector>

namespace lacrima::tears {

struct PositionBasedSettings {
  int iterations = 4;               // Jacobi sweeps per sub-step
  double relaxation = 1.0;          // epsilon h^2
  bool artificialPressure = false;  // the s_corr term
};

struct PositionBasedStats {
  // Largest |a_i + dp_i / dt^2| of the last solve, without what pushes a touching particle into
  // the skin (the step's acceleration bound, as DFSPH's).
  double maxNetAcceleration = 0;
};

class PressureSolver_PBF final : public PressureSolver {
 public:
  PressureSolver_PBF(double h, const PositionBasedSettings& settings);
  static MethodInfo info();
  static std::unique_ptr<PressureSolver> create(const MethodValues& values,
                                                const ScaledParameters& parameters,
                                                const TearSettings& settings);

  double soundSpeed() const override { return 0; }
  // Zero pressures: the constraint replaces the pressure force.
  void computePressures(ParticleSet& particles, const ActivePairs& pairs, double remaining,
                        TearCounters& counters) override;
  double accelerationBound(double largestFluidAcceleration) const override;
  // The position solve, with the skin normals under touching particles.
  void correctVelocities(ParticleSet& particles, const ActivePairs& pairs, double dt,
                         const SkinView& skin, TearCounters& counters) override;
  PressureHistory history() const override { return history_; }
  void restoreHistory(const PressureHistory& history) override { history_ = history; }

  // With the non-pressure forces (particles.acceleration, for dt) already in the velocities:
  // corrects them so the positions after dt satisfy the density constraints (to the iterations'
  // accuracy). `contactNormal[i]`: the skin normal under a touching particle (zero when free).
  void solve(ParticleSet& particles, const ActivePairs& pairs, double dt,
             std::span<const Eigen::Vector3d> contactNormal = {});

  const PositionBasedStats& stats() const { return stats_; }
  const PositionBasedSettings& settings() const { return settings_; }

 private:
  // Densities, pair gradients and lambda at the current predicted displacements.
  void constraints(const ActivePairs& pairs, std::span<const std::uint64_t> ids, int n);
  // dp from lambda (and s_corr), without its part into the skin, added to the displacements.
  void correct(const ActivePairs& pairs, std::span<const Eigen::Vector3d> contactNormal, int n);

  Poly6Kernel density_;
  SpikyKernel gradient_;
  PositionBasedSettings settings_;
  PositionBasedStats stats_;
  PressureHistory history_;
  float epsilon_ = 0, scorrScale_ = 0, scorrStrength_ = 0;
  std::vector<Eigen::Vector3d> contactNormal_;
  std::vector<float> g_, scorr_;  // per pair: 4 floats g_ij; s_corr,ij
  std::vector<float> m_, rho_, lambda_, diagonal_;
  std::vector<float> d_, start_, sum_, dp_;  // 4 per particle
};

}  // namespace lacrima::tears
