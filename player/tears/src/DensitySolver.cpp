#include "DensitySolver.h"
#include "Float4.h"

#include <xmmintrin.h>

#include <algorithm>
#include <cmath>

namespace lacrima::tears {

namespace {

// |d|^2 of four offsets held as rows (x, y, z, 0). The transpose puts each coordinate of the four
// pairs in one register, and the squares are added in dot3's order, so each lane is bitwise the
// scalar r^2.
Float4 squaredNorms(Float4 d0, Float4 d1, Float4 d2, Float4 d3) {
  const __m128 xy01 = _mm_unpacklo_ps(d0, d1), xy23 = _mm_unpacklo_ps(d2, d3);
  const __m128 zw01 = _mm_unpackhi_ps(d0, d1), zw23 = _mm_unpackhi_ps(d2, d3);
  const Float4 x = _mm_movelh_ps(xy01, xy23), y = _mm_movehl_ps(xy23, xy01),
               z = _mm_movelh_ps(zw01, zw23);
  return x * x + y * y + z * z;
}

// max(q, 0) without a branch: (q + |q|) / 2 is exactly q for q > 0 and exactly 0 otherwise
// (GCC compiles std::max to a mispredicted jump in the scalar tail).
float positivePart(float q) { return (q + std::fabs(q)) * 0.5f; }
Float4 positivePart(Float4 q) {
  const Int4 magnitude = {0x7fffffff, 0x7fffffff, 0x7fffffff, 0x7fffffff};
  const Float4 half = {0.5f, 0.5f, 0.5f, 0.5f};
  return (q + reinterpret_cast<Float4>(reinterpret_cast<Int4>(q) & magnitude)) * half;
}

}  // namespace

// The candidate loop, four candidates of particle i at a time. Every candidate is written out
// (partner, r^2) and the write position advances only for a kept pair within h, so the
// output is compact without a branch: about half the candidates lie beyond h, unpredictably.
// Beyond h the weight is exactly 0 (adding 0 changes no sum). With strays (PairList.h), listed
// pairs that involve one are weighted by 0 and not kept, and each particle's stray pairs follow
// its listed ones, so the pair order stays a pure function of the list. rho_i sums its
// candidates in four lanes, then the lanes, the tail and the strays, in that fixed order.
template <bool Strays>
void DensitySolver::accumulate(const VerletPairs& candidates, ActivePairs& active) const {
  const int n = candidates.particleCount();
  const float h2 = h2_, wScale = wScale_;
  const Float4 h2v = {h2, h2, h2, h2}, wScalev = {wScale, wScale, wScale, wScale};
  const float* x = active.position.data();
  const float* m = m_.data();
  float* rho = rho_.data();
  const std::uint32_t* partner = candidates.partners();
  const std::uint8_t* stray = Strays ? candidates.strayFlags().data() : nullptr;
  const auto& strayPairs = candidates.strayPairs();
  std::size_t nextStray = 0;
  std::uint32_t* outPartner = active.partner.data();
  float* outR2 = active.r2.data();
  std::uint32_t written = 0;
  auto emit = [&](std::uint32_t j, float r2, int kept) {
    outPartner[written] = j;
    outR2[written] = r2;
    written += static_cast<std::uint32_t>(kept);
  };
  auto visit = [&](const Float4& xi, float mi, float& rhoi, std::uint32_t j, bool keep) {
    const Float4 d = xi - load4(x + 4 * static_cast<std::size_t>(j));
    const float r2 = dot3(d, d);
    const float q = positivePart(h2 - r2);
    const float w = keep ? wScale * q * q * q : 0.0f;
    rhoi += m[j] * w;
    rho[j] += mi * w;
    emit(j, r2, keep & (r2 < h2));
  };
  for (int i = 0; i < n; ++i) {
    const auto si = static_cast<std::size_t>(i);
    const Float4 xi = load4(x + 4 * si);
    const float mi = m[si];
    const Float4 miv = {mi, mi, mi, mi};
    const bool strayI = Strays && stray[si] != 0;
    Float4 rhoLanes = {0, 0, 0, 0};
    // The bounds are read once: the uint32 output stores could alias them as far as GCC knows.
    std::uint32_t k = candidates.begin(i);
    const std::uint32_t end = candidates.end(i);
    for (; k + 4 <= end; k += 4) {
      const std::uint32_t j0 = partner[k], j1 = partner[k + 1], j2 = partner[k + 2],
                          j3 = partner[k + 3];
      const Float4 d0 = xi - load4(x + 4 * std::size_t{j0}),
                   d1 = xi - load4(x + 4 * std::size_t{j1});
      const Float4 d2 = xi - load4(x + 4 * std::size_t{j2}),
                   d3 = xi - load4(x + 4 * std::size_t{j3});
      const Float4 r2 = squaredNorms(d0, d1, d2, d3);
      const Float4 q = positivePart(h2v - r2);
      Float4 w = wScalev * q * q * q;
      int kept = _mm_movemask_ps(reinterpret_cast<Float4>(r2 < h2v));
      if constexpr (Strays) {
        const Int4 void4 = {stray[j0], stray[j1], stray[j2], stray[j3]};
        const Int4 listed = strayI ? Int4{0, 0, 0, 0} : (void4 == 0);
        w = reinterpret_cast<Float4>(reinterpret_cast<Int4>(w) & listed);
        kept &= _mm_movemask_ps(reinterpret_cast<Float4>(listed));
      }
      const Float4 mj = {m[j0], m[j1], m[j2], m[j3]};
      rhoLanes += mj * w;
      const Float4 toJ = miv * w;
      rho[j0] += toJ[0];
      rho[j1] += toJ[1];
      rho[j2] += toJ[2];
      rho[j3] += toJ[3];
      emit(j0, r2[0], kept & 1);
      emit(j1, r2[1], (kept >> 1) & 1);
      emit(j2, r2[2], (kept >> 2) & 1);
      emit(j3, r2[3], (kept >> 3) & 1);
    }
    float rhoi = rho[si] + ((rhoLanes[0] + rhoLanes[1]) + (rhoLanes[2] + rhoLanes[3]));
    for (; k < end; ++k)
      visit(xi, mi, rhoi, partner[k], !(strayI || (Strays && stray[partner[k]] != 0)));
    if constexpr (Strays)
      for (; nextStray < strayPairs.size() &&
             strayPairs[nextStray].lower == static_cast<std::uint32_t>(i);
           ++nextStray)
        visit(xi, mi, rhoi, strayPairs[nextStray].higher, true);
    rho[si] = rhoi;
    active.start[si + 1] = written;
  }
}

void DensitySolver::compute(ParticleSet& p, const VerletPairs& candidates,
                            ActivePairs& active) const {
  const int n = p.size();
  const auto un = static_cast<std::size_t>(n);
  const double h2d = h_ * h_;
  h2_ = static_cast<float>(h2d);
  const float w0 = static_cast<float>(w_.valueAtZero());
  wScale_ = static_cast<float>(w_.value(0.0) / (h2d * h2d * h2d));  // W = wScale (h^2 - r^2)^3
  active.start.resize(un + 1);
  active.start[0] = 0;
  // Capacity follows the candidate count and is kept, growing by a quarter more than asked:
  // a film that spreads adds a few candidates at every rebuild, and growing to the exact count
  // moved megabytes to freshly mapped pages each time (10,000 more page faults in 44 frames of
  // the sheet at 10,000 particles).
  const std::size_t capacity = candidates.pairCount() + candidates.strayPairs().size();
  if (active.partner.size() < capacity) {
    const std::size_t c = capacity + capacity / 4;
    active.partner.resize(c);
    active.r2.resize(c);
  }
  active.position.resize(4 * un);
  m_.resize(un);
  rho_.resize(un);
  if (n == 0) return;
  // Relative to one particle: the float copies then resolve differences within a drop far
  // better than absolute head coordinates would.
  const Eigen::Vector3d origin = p.position[0];
  for (std::size_t i = 0; i < un; ++i) {
    store4(&active.position[4 * i], toFloat4(Eigen::Vector3d(p.position[i] - origin)));
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
