#include "SurfaceTension_Mueller2003.h"

namespace lacrima::tears {

void SurfaceTension_Mueller2003::addAccelerations(ParticleSet& p, const ActivePairs&,
                                                  const FluidForcePass& pass) {
  if (sigma_ <= 0) return;
  const auto gradient = pass.colourGradient();
  const auto laplacian = pass.colourLaplacian();
  const double threshold = 0.25 / h_;
  for (int i = 0; i < p.size(); ++i) {
    const auto si = static_cast<std::size_t>(i);
    const double length = gradient[si].norm();
    if (length < threshold) continue;
    p.acceleration[si] -= (sigma_ * laplacian[si] / (length * p.density[si])) * gradient[si];
  }
}

}  // namespace lacrima::tears
