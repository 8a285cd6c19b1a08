#include "PressureSolver_WCSPH.h"

#include <algorithm>

namespace lacrima::tears {

void PressureSolver_WCSPH::computePressures(ParticleSet& p, const ActivePairs&, double,
                                            TearCounters&) {
  for (int i = 0; i < p.size(); ++i) {
    const auto s = static_cast<std::size_t>(i);
    const double pressure = k_ * (p.density[s] - rho0_);
    p.pressure[s] = clampNegative_ ? std::max(0.0, pressure) : pressure;
  }
}

}  // namespace lacrima::tears
