#include <lacrima/tears/FluidForces.h>

#include <algorithm>

namespace lacrima::tears {

void DensitySolver::compute(ParticleSet& p, const VerletPairs& candidates, ActivePairs& active) const {
  const int n = p.size();
  const auto un = static_cast<std::size_t>(n);
  const double h2 = h_ * h_;
  const double w0 = w_.valueAtZero();
  const double wScale = w_.value(0.0) / (h2 * h2 * h2);  // W = wScale (h^2 - r^2)^3
  active.start.resize(un + 1);
  active.start[0] = 0;
  // Capacity grows to the candidate count once and is kept (no per-step allocation).
  if (active.partner.size() < candidates.pairCount()) {
    active.partner.resize(candidates.pairCount());
    active.distance.resize(candidates.pairCount());
  }
  for (std::size_t i = 0; i < un; ++i) p.density[i] = p.mass[i] * w0;

  const Eigen::Vector3d* x = p.position.data();
  const double* m = p.mass.data();
  double* rho = p.density.data();
  const std::uint32_t* partner = candidates.partners();
  std::uint32_t* outPartner = active.partner.data();
  double* outDistance = active.distance.data();
  std::uint32_t written = 0;
  for (int i = 0; i < n; ++i) {
    const auto si = static_cast<std::size_t>(i);
    const Eigen::Vector3d xi = x[si];
    const double mi = m[si];
    double rhoi = rho[si];
    // Branch-free: about half the candidates lie beyond h, unpredictably, so a branch would
    // mispredict often. Beyond h the weight is exactly 0 (adding 0 changes no sum) and the
    // pair is written but not kept (`written` does not advance).
    for (std::uint32_t k = candidates.begin(i); k < candidates.end(i); ++k) {
      const std::uint32_t j = partner[k];
      const double r2 = (xi - x[j]).squaredNorm();
      const double d = std::max(h2 - r2, 0.0);
      const double w = wScale * d * d * d;
      rhoi += m[j] * w;
      rho[j] += mi * w;
      outPartner[written] = j;
      outDistance[written] = r2;
      written += static_cast<std::uint32_t>(r2 < h2);
    }
    rho[si] = rhoi;
    active.start[si + 1] = written;
  }
}

}  // namespace lacrima::tears
