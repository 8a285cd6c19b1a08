#include "Float4.h"

#include <lacrima/tears/FluidForces.h>

#include <algorithm>
#include <cmath>

namespace lacrima::tears {

// The candidate loop. With strays (PairList.h), listed pairs that involve one are weighted and
// kept by 0 (branch-free, as for pairs beyond h), and each particle's stray pairs follow its
// listed ones, so the pair order stays a pure function of the list.
template <bool Strays>
void DensitySolver::accumulate(const VerletPairs& candidates, ActivePairs& active) const {
  const int n = candidates.particleCount();
  const float h2 = h2_, wScale = wScale_;
  const float* x = position_.data();
  const float* m = m_.data();
  float* rho = rho_.data();
  const std::uint32_t* partner = candidates.partners();
  const std::uint8_t* stray = Strays ? candidates.strayFlags().data() : nullptr;
  const auto& strayPairs = candidates.strayPairs();
  std::size_t nextStray = 0;
  std::uint32_t* outPartner = active.partner.data();
  float* outOffset = active.offset.data();
  float* outR2 = active.r2.data();
  std::uint32_t written = 0;
  auto visit = [&](const Float4& xi, float mi, float& rhoi, std::uint32_t j, bool keep) {
    const Float4 d = xi - load4(x + 4 * static_cast<std::size_t>(j));
    const float r2 = dot3(d, d);
    // max(h^2 - r^2, 0) without a branch (GCC compiles std::max here to a mispredicted
    // jump): (q + |q|) / 2 is exactly q for q > 0 and exactly 0 otherwise.
    const float q0 = h2 - r2;
    const float q = (q0 + std::fabs(q0)) * 0.5f;
    const float w = keep ? wScale * q * q * q : 0.0f;
    rhoi += m[j] * w;
    rho[j] += mi * w;
    outPartner[written] = j;
    store4(outOffset + 4 * static_cast<std::size_t>(written), d);
    outR2[written] = r2;
    written += static_cast<std::uint32_t>(keep & (r2 < h2));
  };
  for (int i = 0; i < n; ++i) {
    const auto si = static_cast<std::size_t>(i);
    const Float4 xi = load4(x + 4 * si);
    const float mi = m[si];
    float rhoi = rho[si];
    // Branch-free: about half the candidates lie beyond h, unpredictably, so a branch would
    // mispredict often. Beyond h the weight is exactly 0 (adding 0 changes no sum) and the
    // pair is written but not kept (`written` does not advance).
    // The bound is read once: the uint32 output stores could alias it as far as GCC knows.
    const std::uint32_t end = candidates.end(i);
    if constexpr (Strays) {
      const bool strayI = stray[si] != 0;
      for (std::uint32_t k = candidates.begin(i); k < end; ++k) visit(xi, mi, rhoi, partner[k], !(strayI | (stray[partner[k]] != 0)));
      for (; nextStray < strayPairs.size() && strayPairs[nextStray].lower == static_cast<std::uint32_t>(i); ++nextStray)
        visit(xi, mi, rhoi, strayPairs[nextStray].higher, true);
    } else {
      for (std::uint32_t k = candidates.begin(i); k < end; ++k) visit(xi, mi, rhoi, partner[k], true);
    }
    rho[si] = rhoi;
    active.start[si + 1] = written;
  }
}

void DensitySolver::compute(ParticleSet& p, const VerletPairs& candidates, ActivePairs& active) const {
  const int n = p.size();
  const auto un = static_cast<std::size_t>(n);
  const double h2d = h_ * h_;
  h2_ = static_cast<float>(h2d);
  const float w0 = static_cast<float>(w_.valueAtZero());
  wScale_ = static_cast<float>(w_.value(0.0) / (h2d * h2d * h2d));  // W = wScale (h^2 - r^2)^3
  active.start.resize(un + 1);
  active.start[0] = 0;
  // Capacity grows to the candidate count once and is kept (no per-step allocation).
  const std::size_t capacity = candidates.pairCount() + candidates.strayPairs().size();
  if (active.partner.size() < capacity) {
    const std::size_t c = capacity;
    active.partner.resize(c);
    active.offset.resize(4 * c);
    active.r2.resize(c);
  }
  position_.resize(4 * un);
  m_.resize(un);
  rho_.resize(un);
  if (n == 0) return;
  // Relative to one particle: the float copies then resolve differences within a drop far
  // better than absolute head coordinates would.
  const Eigen::Vector3d origin = p.position[0];
  for (std::size_t i = 0; i < un; ++i) {
    const Eigen::Vector3d r = p.position[i] - origin;
    store4(&position_[4 * i], Float4{static_cast<float>(r.x()), static_cast<float>(r.y()), static_cast<float>(r.z()), 0.0f});
    m_[i] = static_cast<float>(p.mass[i]);
    rho_[i] = m_[i] * w0;
  }

  if (candidates.hasStrays())
    accumulate<true>(candidates, active);
  else
    accumulate<false>(candidates, active);
  for (std::size_t i = 0; i < un; ++i) p.density[i] = rho_[i];
}

}  // namespace lacrima::tears
