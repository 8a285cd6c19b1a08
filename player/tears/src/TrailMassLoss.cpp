#include "TrailMassLoss.h"

#include <algorithm>
#include <cmath>

namespace lacrima::tears {

void TrailMassLoss::apply(ParticleSet& p, double rho0, std::size_t begin, std::size_t end,
                          std::vector<Loss>& losses) const {
  const double floorMass = m0_ * floor_;
  for (std::size_t s = begin; s < end; ++s) {
    // No exp() where the result cannot lower the mass: a particle that never slid (target m0,
    // and no mass exceeds m0) or one already at the floor (no target is below it). Both skips
    // give exactly what the full test would.
    if (p.travelled[s] == 0 || p.mass[s] <= floorMass) continue;
    const double target = m0_ * std::max(floor_, std::exp(-p.travelled[s] / length_));
    if (target < p.mass[s]) {
      losses.push_back({p.eye[s], (p.mass[s] - target) / rho0});
      p.mass[s] = target;
    }
  }
}

}  // namespace lacrima::tears
