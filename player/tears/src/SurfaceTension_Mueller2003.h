#pragma once
// Surface tension of Müller, Charypar & Gross 2003 ("Particle-based fluid simulation for
// interactive applications"): the colour field
//   c_i = sum_j m_j / rho_j W_poly6(x_i - x_j),
// its gradient n_i = grad c_i (pointing into the fluid) and the surface curvature
// kappa_i = -lap c_i / |n_i| give the force density sigma kappa n_i / |n_i|, as an acceleration
//   a_i = -sigma lap c_i n_i / (|n_i| rho_i),
// applied where |n_i| exceeds 0.25 / h (near the surface; inside, n is noise). The sums grad c
// and lap c come from the force pass (FluidForcePass.h); this class turns them into forces.
#include "SurfaceTension.h"

namespace lacrima::tears {

class SurfaceTension_Mueller2003 final : public SurfaceTension {
 public:
  SurfaceTension_Mueller2003(double h, double sigma) : h_(h), sigma_(sigma) {}
  static MethodInfo info();
  static std::unique_ptr<SurfaceTension> create(const MethodValues& values,
                                                const ScaledParameters& parameters);

  bool needsColourField() const override { return sigma_ > 0; }
  void addAccelerations(ParticleSet& particles, const FluidForcePass& pass, std::size_t begin,
                        std::size_t end) override;

 private:
  double h_;
  double sigma_;
};

}  // namespace lacrima::tears
