#include <lacrima/tears/FluidForces.h>

namespace lacrima::tears {

void MuellerSurfaceTension::addAccelerations(ParticleSet& p, std::span<const Eigen::Vector3d> gradient,
                                             std::span<const double> laplacian) const {
  if (sigma_ <= 0) return;
  const double threshold = 0.25 / h_;
  for (int i = 0; i < p.size(); ++i) {
    const auto si = static_cast<std::size_t>(i);
    const double length = gradient[si].norm();
    if (length < threshold) continue;
    p.acceleration[si] -= (sigma_ * laplacian[si] / (length * p.density[si])) * gradient[si];
  }
}

}  // namespace lacrima::tears
