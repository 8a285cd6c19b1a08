#include "PairDirection.h"

#include <lacrima/tears/FluidForces.h>

#include <algorithm>
#include <cmath>

namespace lacrima::tears {

double FluidForcePass::run(ParticleSet& p, ActivePairs& pairs, const PressureForce& pressure,
                           const ViscosityForce& viscosity, const MuellerSurfaceTension* tension) {
  const int n = p.size();
  const auto un = static_cast<std::size_t>(n);
  const bool colour = tension && tension->active();
  weightSum_.assign(un, 0.0);
  weighted_.assign(un, Eigen::Vector3d::Zero());
  volume_.resize(un);
  inverseDensity_.resize(un);
  for (std::size_t i = 0; i < un; ++i) {
    inverseDensity_[i] = 1.0 / p.density[i];
    volume_[i] = p.mass[i] * inverseDensity_[i];
  }
  gradient_.assign(colour ? un : 0, Eigen::Vector3d::Zero());
  laplacian_.resize(colour ? un : 0);
  if (colour) {
    const double selfLaplacian = tension->kernel().laplacian(0.0);
    for (std::size_t i = 0; i < un; ++i) laplacian_[i] = volume_[i] * selfLaplacian;
  }

  // Kernel coefficients, so the loop only multiplies (Kernels.h):
  //   grad W_spiky = spiky (h - r)^2 / r r_vec,  lap W_visc = visc (h - r),
  //   grad W_poly6 = poly6 (h^2 - r^2)^2 r_vec,  lap W_poly6 = poly6 (h^2 - r^2)(3 h^2 - 7 r^2).
  const double h = pressure.kernel().radius(), h2 = h * h;
  const double spiky = pressure.kernel().gradientCoefficient();
  const double atZero = pressure.kernel().gradientMagnitudeAtZero();
  const double visc = viscosity.kernel().laplacianCoefficient();
  const double poly6 = colour ? tension->kernel().gradientCoefficient() : 0.0;
  const double coincident2 = 1e-18;

  const Eigen::Vector3d* x = p.position.data();
  const Eigen::Vector3d* v = p.velocity.data();
  Eigen::Vector3d* a = p.acceleration.data();
  const double* m = p.mass.data();
  const double* invRho = inverseDensity_.data();
  double* distance = pairs.distance.data();
  const double* pr = p.pressure.data();
  const double* vol = volume_.data();
  double* wsum = weightSum_.data();
  Eigen::Vector3d* wv = weighted_.data();
  Eigen::Vector3d* grad = gradient_.data();
  double* lap = laplacian_.data();
  double maxRelativeSpeed2 = 0;

  for (int i = 0; i < n; ++i) {
    const auto si = static_cast<std::size_t>(i);
    const Eigen::Vector3d xi = x[si], vi = v[si];
    const double mi = m[si], pi = pr[si], voli = vol[si];
    const double halfOverRhoi = 0.5 * invRho[si];
    Eigen::Vector3d ai = Eigen::Vector3d::Zero(), gi = Eigen::Vector3d::Zero(), wvi = Eigen::Vector3d::Zero();
    double wi = 0, li = 0;
    for (std::uint32_t k = pairs.start[si]; k < pairs.start[si + 1]; ++k) {
      const std::uint32_t j = pairs.partner[k];
      const double r2 = distance[k];
      const double r = std::sqrt(r2);
      distance[k] = r;  // for ViscosityForce::apply
      const Eigen::Vector3d d = xi - x[j];
      maxRelativeSpeed2 = std::max(maxRelativeSpeed2, (vi - v[j]).squaredNorm());
      const double hr = h - r;
      // Pressure: a_i -= m_j P d, a_j += m_i P d with P = (p_i + p_j) / (2 rho_i rho_j) g(r).
      // No test for p_i + p_j == 0 (frequent at the surface, where pressure is clamped, and
      // unpredictable): the force is then exactly zero.
      const double shared = (pi + pr[j]) * halfOverRhoi * invRho[j];
      if (r2 > coincident2) [[likely]] {
        const Eigen::Vector3d f = (shared * spiky * hr * hr / r) * d;
        ai -= m[j] * f;
        a[j] += mi * f;
      } else if (shared != 0.0) {
        // Coincident: a fixed, antisymmetric direction from the ids (PairDirection.h).
        const Eigen::Vector3d f = (shared * atZero) * pairDirection(p.id[si], p.id[j]);
        ai += m[j] * f;
        a[j] -= mi * f;
      }
      // Viscosity: sum_j V_j lap W and sum_j V_j lap W v_j (symmetric kernel).
      const double lw = visc * hr;
      const double wj = vol[j] * lw, wi_ = voli * lw;
      wi += wj;
      wsum[j] += wi_;
      wvi += wj * v[j];
      wv[j] += wi_ * vi;
      if (colour) {
        const double q = h2 - r2;
        const double g = poly6 * q * q;
        gi += (vol[j] * g) * d;
        grad[j] -= (voli * g) * d;
        const double l = poly6 * q * (3.0 * h2 - 7.0 * r2);
        li += vol[j] * l;
        lap[j] += voli * l;
      }
    }
    a[si] += ai;
    wsum[si] += wi;
    wv[si] += wvi;
    if (colour) {
      grad[si] += gi;
      lap[si] += li;
    }
  }

  const double nu = viscosity.nu();
  for (std::size_t i = 0; i < un; ++i) p.viscosityRate[i] = nu * wsum[i] * invRho[i];
  if (colour) tension->addAccelerations(p, gradient_, laplacian_);
  return std::sqrt(maxRelativeSpeed2);
}

}  // namespace lacrima::tears
