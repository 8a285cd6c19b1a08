#pragma once
// Sub-step size for one SPH step, the smallest of:
//   CFL:           dt <= lambda_c h / (c + u_max)   u_max: largest neighbour relative speed,
//                  c: the pressure solver's speed of sound, 0 for DFSPH and PBF (no pressure
//                  waves to cross a kernel);
//   acceleration:  dt <= lambda_a sqrt(h / a_max)   a_max: largest fluid acceleration (pressure,
//                  tension), so no particle is thrown across a kernel radius by a force spike;
//   viscosity:     dt <= lambda_v / k_max           k_max: largest viscosity relaxation rate
//                  (explicit relaxation is non-overshooting iff k dt <= 1;
//                  Viscosity_Mueller2003.h).
// Gravity and adhesion are not in a_max: a uniform acceleration does not change relative motion,
// and adhesion is absorbed by the contact constraint (SkinContact.h). Absolute speed is not in
// the CFL term either: fast particles are protected from tunnelling by ray casts instead.
namespace lacrima::tears {

enum class StepLimit { Frame, Cfl, Acceleration, Viscosity };

struct StepChoice {
  double dt = 0;
  StepLimit limit = StepLimit::Frame;
};

class AdaptiveTimeStep {
 public:
  AdaptiveTimeStep(double lambdaCfl = 0.4, double lambdaAcceleration = 0.4,
                   double lambdaViscosity = 1.0)
      : cfl_(lambdaCfl), acceleration_(lambdaAcceleration), viscosity_(lambdaViscosity) {}

  StepChoice choose(double h, double soundSpeed, double maxRelativeSpeed, double maxAcceleration,
                    double maxViscosityRate, double remaining) const;

  double lambdaCfl() const { return cfl_; }
  double lambdaAcceleration() const { return acceleration_; }

 private:
  double cfl_, acceleration_, viscosity_;
};

}  // namespace lacrima::tears
