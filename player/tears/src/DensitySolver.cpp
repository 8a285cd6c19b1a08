#include "DensitySolver.h"
#include "Float4.h"

#include <xmmintrin.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

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
// Beyond h the weight is exactly 0 (adding 0 changes no sum). With strays (VerletPairs.h), listed
// pairs that involve one are weighted by 0 and not kept, and each particle's stray pairs follow
// its listed ones, so the pair order stays a pure function of the list. rho_i sums its
// candidates in four lanes, then the lanes, the tail and the strays, in that fixed order, onto
// what the chunk's earlier particles gave it.
template <bool Strays>
void DensitySolver::accumulate(const VerletPairs& candidates, ActivePairs& active,
                               std::uint32_t begin, std::uint32_t end, std::uint32_t slot,
                               std::size_t stray, Window& window) const {
  const float h2 = h2_, wScale = wScale_;
  const Float4 h2v = {h2, h2, h2, h2}, wScalev = {wScale, wScale, wScale, wScale};
  const float* x = active.position.data();
  const float* m = m_.data();
  const std::uint32_t* partner = candidates.partners();
  const std::uint8_t* strayFlag = Strays ? candidates.strayFlags().data() : nullptr;
  const auto& strayPairs = candidates.strayPairs();
  std::size_t nextStray = stray;

  // The window: from the chunk's first particle to the farthest partner, the chunk's own
  // particles starting from their own term m_i W(0).
  std::uint32_t reach = end - 1;
  for (std::uint32_t i = begin; i < end; ++i)
    reach = std::max(reach, candidates.reach(static_cast<int>(i)));
  for (std::size_t s = stray; s < strayPairs.size() && strayPairs[s].lower < end; ++s)
    reach = std::max(reach, strayPairs[s].higher);
  window.first = begin;
  window.sum.assign(reach + 1 - begin, 0.0f);
  for (std::uint32_t i = begin; i < end; ++i) window.sum[i - begin] = m[i] * w0_;
  // Indexed by particle, rho[j] for j in [begin, reach]. The base is shifted through an integer
  // (GCC defines the conversions as keeping the address), not by pointer arithmetic before the
  // array; indexing sum[j - begin] instead costs a subtraction per pair (5 % more instructions).
  float* const rho = reinterpret_cast<float*>(reinterpret_cast<std::uintptr_t>(window.sum.data()) -
                                              std::uintptr_t{begin} * sizeof(float));

  std::uint32_t* outPartner = active.partner.data();
  float* outR2 = active.r2.data();
  std::uint32_t* first = active.first.data();
  std::uint32_t* last = active.last.data();
  std::uint32_t written = slot;
  auto emit = [&](std::uint32_t j, float r2, int kept) {
    outPartner[written] = j;
    outR2[written] = r2;
    written += static_cast<std::uint32_t>(kept);
  };
  auto visit = [&](const Float4& xi, float mi, float& rhoi, std::uint32_t j, bool listed) {
    const Float4 d = xi - load4(x + 4 * static_cast<std::size_t>(j));
    const float r2 = dot3(d, d);
    const float q = positivePart(h2 - r2);
    const float w = listed ? wScale * q * q * q : 0.0f;
    rhoi += m[j] * w;
    rho[j] += mi * w;
    emit(j, r2, listed & (r2 < h2));
  };
  for (std::uint32_t i = begin; i < end; ++i) {
    const auto si = static_cast<std::size_t>(i);
    const Float4 xi = load4(x + 4 * si);
    const float mi = m[si];
    const Float4 miv = {mi, mi, mi, mi};
    const bool strayI = Strays && strayFlag[si] != 0;
    Float4 rhoLanes = {0, 0, 0, 0};
    first[si] = written;
    // The bounds are read once: the uint32 output stores could alias them as far as GCC knows.
    std::uint32_t k = candidates.begin(static_cast<int>(i));
    const std::uint32_t stop = candidates.end(static_cast<int>(i));
    for (; k + 4 <= stop; k += 4) {
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
        const Int4 void4 = {strayFlag[j0], strayFlag[j1], strayFlag[j2], strayFlag[j3]};
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
    for (; k < stop; ++k)
      visit(xi, mi, rhoi, partner[k], !(strayI || (Strays && strayFlag[partner[k]] != 0)));
    if constexpr (Strays)
      for (; nextStray < strayPairs.size() && strayPairs[nextStray].lower == i; ++nextStray)
        visit(xi, mi, rhoi, strayPairs[nextStray].higher, true);
    rho[si] = rhoi;
    last[si] = written;
  }
}

void DensitySolver::compute(ParticleSet& p, const VerletPairs& candidates, ActivePairs& active,
                            ParallelChunks* parallel) const {
  const int n = p.size();
  const auto un = static_cast<std::size_t>(n);
  const double h2d = h_ * h_;
  h2_ = static_cast<float>(h2d);
  w0_ = static_cast<float>(w_.valueAtZero());
  wScale_ = static_cast<float>(w_.value(0.0) / (h2d * h2d * h2d));  // W = wScale (h^2 - r^2)^3
  active.first.resize(un);
  active.last.resize(un);
  // Capacity follows the candidate count and is kept, growing by a quarter more than asked:
  // a film that spreads adds a few candidates at every rebuild, and growing to the exact count
  // moved megabytes to freshly mapped pages each time (10,000 more page faults in 44 frames of
  // the sheet at 10,000 particles).
  const auto& strayPairs = candidates.strayPairs();
  const std::size_t capacity = candidates.pairCount() + strayPairs.size();
  if (active.partner.size() < capacity) {
    const std::size_t c = capacity + capacity / 4;
    active.partner.resize(c);
    active.r2.resize(c);
  }
  active.position.resize(4 * un);
  active.kept = 0;
  m_.resize(un);
  rho_.resize(un);
  if (n == 0) return;
  // Relative to one particle: the float copies then resolve differences within a drop far
  // better than absolute head coordinates would.
  const Eigen::Vector3d origin = p.position[0];
  const std::size_t chunk = parallel ? parallel->particleChunk() : kParticleChunk;
  forEachChunkOn(parallel, un, chunk, [&](int, std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) {
      store4(&active.position[4 * i], toFloat4(Eigen::Vector3d(p.position[i] - origin)));
      m_[i] = static_cast<float>(p.mass[i]);
    }
  });

  // A chunk's pairs start where its candidates do, after the stray pairs of earlier particles.
  const std::size_t chunks = ParallelChunks::chunkCount(un, chunk);
  if (windows_.size() < chunks) windows_.resize(chunks);
  forEachChunkOn(parallel, un, chunk, [&](int c, std::size_t begin, std::size_t end) {
    const auto b = static_cast<std::uint32_t>(begin), e = static_cast<std::uint32_t>(end);
    const std::size_t stray = static_cast<std::size_t>(
        std::lower_bound(strayPairs.begin(), strayPairs.end(), VerletPairs::Pair{b, 0}) -
        strayPairs.begin());
    const auto slot = static_cast<std::uint32_t>(candidates.begin(static_cast<int>(b)) + stray);
    Window& window = windows_[static_cast<std::size_t>(c)];
    if (candidates.hasStrays())
      accumulate<true>(candidates, active, b, e, slot, stray, window);
    else
      accumulate<false>(candidates, active, b, e, slot, stray, window);
  });
  // A chunk's kept pairs lie together from its first particle's first pair.
  for (std::size_t begin = 0; begin < un; begin += chunk)
    active.kept += active.last[std::min(un, begin + chunk) - 1] - active.first[begin];
  // Each density: its own chunk's sum, then the earlier chunks' sums for it, in chunk order.
  forEachChunkOn(parallel, un, chunk, [&](int c, std::size_t begin, std::size_t end) {
    const Window& own = windows_[static_cast<std::size_t>(c)];
    for (std::size_t i = begin; i < end; ++i) rho_[i] = own.sum[i - begin];
    for (std::size_t earlier = 0; earlier < static_cast<std::size_t>(c); ++earlier) {
      const Window& w = windows_[earlier];
      const std::size_t from = std::max<std::size_t>(begin, w.first),
                        to = std::min(end, w.first + w.sum.size());
      for (std::size_t i = from; i < to; ++i) rho_[i] += w.sum[i - w.first];
    }
    for (std::size_t i = begin; i < end; ++i) p.density[i] = rho_[i];
  });
}

}  // namespace lacrima::tears
