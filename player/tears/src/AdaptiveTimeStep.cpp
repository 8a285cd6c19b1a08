#include "AdaptiveTimeStep.h"

#include <cmath>

namespace lacrima::tears {

StepChoice AdaptiveTimeStep::choose(double h, double c, double u, double a, double k,
                                    double remaining) const {
  StepChoice choice{remaining, StepLimit::Frame};
  auto consider = [&](double dt, StepLimit why) {
    if (dt < choice.dt) choice = {dt, why};
  };
  if (c + u > 0) consider(cfl_ * h / (c + u), StepLimit::Cfl);
  if (a > 0) consider(acceleration_ * std::sqrt(h / a), StepLimit::Acceleration);
  if (k > 0) consider(viscosity_ / k, StepLimit::Viscosity);
  // Even steps: ceil(remaining / dt) equal pieces, so the frame never ends with a sliver.
  if (choice.dt < remaining) {
    const double pieces = std::ceil(remaining / choice.dt * (1 - 1e-12));
    choice.dt = remaining / pieces;
  }
  return choice;
}

}  // namespace lacrima::tears
