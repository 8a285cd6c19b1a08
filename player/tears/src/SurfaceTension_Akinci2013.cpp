#include "SurfaceTension_Akinci2013.h"

namespace lacrima::tears {

MethodInfo SurfaceTension_Akinci2013::info() {
  return {"akinci",
          "Akinci",
          "Cohesion and curvature minimisation of Akinci et al. 2013: rounder drops, two more "
          "passes over the pairs",
          {}};
}

std::unique_ptr<SurfaceTension> SurfaceTension_Akinci2013::create(const MethodValues&,
                                                                  const ScaledParameters& p) {
  return std::make_unique<SurfaceTension_Akinci2013>(p.h, p.tensionGamma, p.restDensity);
}

void SurfaceTension_Akinci2013::prepare(const ParticleSet& p, const ActivePairs& pairs) {
  if (gamma_ <= 0) return;
  const auto n = static_cast<std::size_t>(p.size());
  normal_.assign(n, Eigen::Vector3d::Zero());
  // n_i = h sum_j V_j grad W(x_i - x_j); grad W is odd, so j gets the opposite sign.
  for (std::size_t i = 0; i < n; ++i) {
    for (std::uint32_t k = pairs.begin(i); k < pairs.end(i); ++k) {
      const std::uint32_t j = pairs.partner[k];
      const Eigen::Vector3d r = p.position[i] - p.position[j];
      const Eigen::Vector3d g = w_.gradient(r, r.squaredNorm());
      normal_[i] += (p.mass[j] / p.density[j]) * g;
      normal_[j] -= (p.mass[i] / p.density[i]) * g;
    }
  }
  for (auto& normal : normal_) normal *= h_;
  // F_ij / (gamma m_i) = K_ij (-(n_i - n_j) - m_j C(r) / r r_vec); for j, r_vec and n swap sign.
  force_.assign(n, Eigen::Vector3d::Zero());
  for (std::size_t i = 0; i < n; ++i) {
    for (std::uint32_t k = pairs.begin(i); k < pairs.end(i); ++k) {
      const std::uint32_t j = pairs.partner[k];
      const Eigen::Vector3d r = p.position[i] - p.position[j];
      const double distance = r.norm();
      const double correction = 2.0 * rho0_ / (p.density[i] + p.density[j]);
      const Eigen::Vector3d curvature = normal_[i] - normal_[j];
      const double c = distance > 1e-9 * h_ ? c_.value(distance) / distance : 0.0;
      force_[i] -= correction * (curvature + (p.mass[j] * c) * r);
      force_[j] += correction * (curvature + (p.mass[i] * c) * r);
    }
  }
}

void SurfaceTension_Akinci2013::addAccelerations(ParticleSet& p, const FluidForcePass&,
                                                 std::size_t begin, std::size_t end) {
  if (gamma_ <= 0) return;
  for (std::size_t i = begin; i < end; ++i) p.acceleration[i] += gamma_ * force_[i];
}

}  // namespace lacrima::tears
