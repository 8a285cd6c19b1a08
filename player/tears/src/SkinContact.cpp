#include "SkinContact.h"

#include <algorithm>
#include <cmath>

namespace lacrima::tears {

double SkinContactForces::adhesionOf(const ParticleSet& p, int i) const {
  const auto s = static_cast<std::size_t>(i);
  if (p.contact[s].triangle < 0 || adhesion_ <= 0) return 0.0;
  // A lone particle has a fraction of the rest density; capping the ratio at 10 keeps the
  // factor finite for any isolated particle without changing the thesis's trend.
  const double densityRatio = std::min(10.0, rho0_ / std::max(p.density[s], 1e-12 * rho0_));
  return adhesion_ * densityRatio * (m0_ / p.mass[s]);
}

void SkinContactForces::applyExternal(ParticleSet& p, const Eigen::Vector3d& g, double dt,
                                      std::size_t begin, std::size_t end) const {
  for (std::size_t s = begin; s < end; ++s) p.velocity[s] += dt * (p.acceleration[s] + g);
}

void SkinContactForces::constrain(ParticleSet& p, const SkinView& skin, const Eigen::Vector3d& g,
                                  double dt, std::span<const double> spare, std::size_t begin,
                                  std::size_t end) const {
  if (dt <= 0) return;
  for (std::size_t s = begin; s < end; ++s) constrainOne(p, skin, g, dt, spare, s);
}

void SkinContactForces::constrainOne(ParticleSet& p, const SkinView& skin, const Eigen::Vector3d& g,
                                     double dt, std::span<const double> spare,
                                     std::size_t s) const {
  const int i = static_cast<int>(s);
  const int t = p.contact[s].triangle;
  if (t < 0) return;
  const SkinFace& face = skin.faces[static_cast<std::size_t>(t)];
  const Eigen::Vector3d n = face.normal;
  if (n.squaredNorm() == 0) return;  // degenerate triangle: the collider drops the contact
  const double share = spare.empty() ? 1.0 : spare[s];
  const double adhesion = share > 0 ? adhesionOf(p, i) : 0.0;
  Eigen::Vector3d v = p.velocity[s] - dt * adhesion * n;
  // Gap between the particle's surface and the triangle's plane.
  const double gap = std::max(0.0, (p.position[s] - face.a).dot(n) - radius_);
  const double vn = v.dot(n);
  const double minimum = -gap / dt;
  if (vn < minimum) v += (minimum - vn) * n;
  // Normal load per unit mass: the adhesion not spent holding the drop up, plus whatever of
  // gravity and the fluid forces pushes the particle into the skin.
  const double load = share * adhesion + std::max(0.0, -(p.acceleration[s] + g).dot(n));
  const double vnAfter = v.dot(n);
  const Eigen::Vector3d tangential = v - vnAfter * n;
  v = vnAfter * n + tangential / (1.0 + dt * friction_ * load);
  p.velocity[s] = v;
}

}  // namespace lacrima::tears
