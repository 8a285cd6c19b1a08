#pragma once
// Surface tension of Akinci, Akinci & Teschner 2013 ("Versatile surface tension and adhesion for
// SPH fluids"): cohesion between neighbours plus a term that minimises the surface's curvature,
//   F_ij = K_ij (-gamma m_i m_j C(r) r_hat - gamma m_i (n_i - n_j)),  K_ij = 2 rho0 / (rho_i +
//   rho_j), n_i = h sum_j m_j / rho_j grad W_poly6(x_i - x_j)      (scaled surface normal),
// a_i = sum_j F_ij / m_i, with the cohesion spline C (Kernels.h: repulsive below h / 2,
// attractive beyond, so cohesion does not clump particles). K_ij strengthens the force where
// the neighbourhood is thin, the surface. Its two passes over the pairs run after the force pass.
#include "Kernels.h"
#include "SurfaceTension.h"

#include <vector>

namespace lacrima::tears {

class SurfaceTension_Akinci2013 final : public SurfaceTension {
 public:
  SurfaceTension_Akinci2013(double h, double gamma, double restDensity)
      : h_(h), w_(h), c_(h), gamma_(gamma), rho0_(restDensity) {}
  static MethodInfo info();
  static std::unique_ptr<SurfaceTension> create(const MethodValues& values,
                                                const ScaledParameters& parameters);

  bool needsColourField() const override { return false; }
  // The normals and the pair forces (two passes over the pairs, on one thread).
  void prepare(const ParticleSet& particles, const ActivePairs& pairs) override;
  void addAccelerations(ParticleSet& particles, const FluidForcePass& pass, std::size_t begin,
                        std::size_t end) override;

 private:
  double h_;
  Poly6Kernel w_;
  CohesionKernel c_;
  double gamma_, rho0_;
  std::vector<Eigen::Vector3d> normal_, force_;
};

}  // namespace lacrima::tears
