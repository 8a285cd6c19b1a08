#include "TrailMassLoss.h"

#include <algorithm>
#include <cmath>

namespace lacrima::tears {

void TrailMassLoss::apply(ParticleSet& p, double rho0, double lostVolume[2]) const {
  const double floorMass = m0_ * floor_;
  for (int i = 0; i < p.size(); ++i) {
    const auto s = static_cast<std::size_t>(i);
    // No exp() where the result cannot lower the mass: a particle that never slid (target m0,
    // and no mass exceeds m0) or one already at the floor (no target is below it). Both skips
    // give exactly what the full test would.
    if (p.travelled[s] == 0 || p.mass[s] <= floorMass) continue;
    const double target = m0_ * std::max(floor_, std::exp(-p.travelled[s] / length_));
    if (target < p.mass[s]) {
      lostVolume[static_cast<int>(p.eye[s])] += (p.mass[s] - target) / rho0;
      p.mass[s] = target;
    }
  }
}

}  // namespace lacrima::tears
