#include "PressureSolver_WCSPH.h"

#include <algorithm>

namespace lacrima::tears {

MethodInfo PressureSolver_WCSPH::info() {
  return {"wcsph",
          "WCSPH",
          "Weakly compressible SPH (2009): pressure from a stiff equation of state; sub-steps "
          "bound by the speed of sound",
          {{"clamp-negative",
            "Clamp negative pressures to 0 (1) against clumping at the free "
            "surface, or keep them (0)",
            1, 0, 1, true}}};
}

std::unique_ptr<PressureSolver> PressureSolver_WCSPH::create(const MethodValues& values,
                                                             const ScaledParameters& p,
                                                             const TearSettings&) {
  return std::make_unique<PressureSolver_WCSPH>(p.stiffness, p.restDensity, p.soundSpeed,
                                                values.flag("clamp-negative"));
}

void PressureSolver_WCSPH::computePressures(ParticleSet& p, const ActivePairs&, double,
                                            TearCounters&) {
  for (int i = 0; i < p.size(); ++i) {
    const auto s = static_cast<std::size_t>(i);
    const double pressure = k_ * (p.density[s] - rho0_);
    p.pressure[s] = clampNegative_ ? std::max(0.0, pressure) : pressure;
  }
}

}  // namespace lacrima::tears
