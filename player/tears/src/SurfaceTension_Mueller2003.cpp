#include "SurfaceTension_Mueller2003.h"

namespace lacrima::tears {

MethodInfo SurfaceTension_Mueller2003::info() {
  return {"mueller",
          "Müller",
          "The colour-field curvature force of Müller et al. 2003 (2009's model)",
          {}};
}

std::unique_ptr<SurfaceTension> SurfaceTension_Mueller2003::create(const MethodValues&,
                                                                   const ScaledParameters& p) {
  return std::make_unique<SurfaceTension_Mueller2003>(p.h, p.tensionSigma);
}

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
