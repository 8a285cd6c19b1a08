#include "SurfaceTension_Mueller2003.h"

namespace lacrima::tears {

void SurfaceTension_Mueller2003::addAccelerations(ParticleSet& p, const FluidForcePass& pass,
                                                  std::size_t begin, std::size_t end) {
  if (sigma_ <= 0) return;
  const auto gradient = pass.colourGradient();
  const auto laplacian = pass.colourLaplacian();
  const double threshold = 0.25 / h_;
  for (std::size_t si = begin; si < end; ++si) {
    const double length = gradient[si].norm();
    if (length < threshold) continue;
    p.acceleration[si] -= (sigma_ * laplacian[si] / (length * p.density[si])) * gradient[si];
  }
}

}  // namespace lacrima::tears
