#pragma once
// Weakly compressible SPH: pressure from a stiff equation of state, here the linear one of
// Müller, Charypar & Gross 2003 ("Particle-based fluid simulation for interactive
// applications"),
//   p_i = k (rho_i - rho0),   speed of sound c = sqrt(k),
// in the regime Monaghan 1994 ("Simulating free surface flows with SPH") set out: c about ten
// times the fastest flow, so density varies by about a per cent and the fluid passes for
// incompressible. (Becker & Teschner 2007 use Tait's stiffer equation instead; the tears do not
// need it.) The price is the CFL limit h / c on the sub-step (TearSettings.h picks c).
// The force pass applies the symmetric pressure force (FluidForcePass.h).
//
// Negative pressures are clamped to 0 by default (the "clamp-negative" parameter): with tens of
// particles nearly all of them sit at the free surface, where the density deficit would
// otherwise pull them into clumps (tensile instability); cohesion is the surface-tension term's
// job.
#include "PressureSolver.h"

namespace lacrima::tears {

class PressureSolver_WCSPH final : public PressureSolver {
 public:
  PressureSolver_WCSPH(double stiffness, double restDensity, double soundSpeed, bool clampNegative)
      : k_(stiffness), rho0_(restDensity), c_(soundSpeed), clampNegative_(clampNegative) {}
  static MethodInfo info();
  static std::unique_ptr<PressureSolver> create(const MethodValues& values,
                                                const ScaledParameters& parameters,
                                                const TearSettings& settings);

  double soundSpeed() const override { return c_; }
  void computePressures(ParticleSet& particles, const ActivePairs& pairs, double remaining,
                        TearCounters& counters) override;
  double accelerationBound(double largestFluidAcceleration) const override {
    return largestFluidAcceleration;
  }
  // Nothing to correct: the pressure force is in the accelerations already.
  void correctVelocities(ParticleSet&, const ActivePairs&, double, const SkinView&,
                         TearCounters&) override {}

 private:
  double k_, rho0_, c_;
  bool clampNegative_;
};

}  // namespace lacrima::tears
