#include "Viscosity_Mueller2003.h"

#include <cmath>

namespace lacrima::tears {

void Viscosity_Mueller2003::apply(ParticleSet& p, std::span<const Eigen::Vector3d> weighted,
                                  std::span<const double> weightSum, double dt, std::size_t begin,
                                  std::size_t end) const {
  if (nu_ <= 0 || dt <= 0) return;
  for (std::size_t i = begin; i < end; ++i) {
    const double k = p.viscosityRate[i];
    if (k <= 0 || weightSum[i] <= 0) continue;
    const Eigen::Vector3d mean = weighted[i] / weightSum[i];
    p.velocity[i] += (1.0 - std::exp(-k * dt)) * (mean - p.velocity[i]);
  }
}

}  // namespace lacrima::tears
