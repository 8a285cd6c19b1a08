#include "FluidForcePass.h"
#include "Float4.h"
#include "PairDirection.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace lacrima::tears {

namespace {

// The largest closing speed -(v_i - v_j).(x_i - x_j) / r over the pairs, squared: Monaghan's
// signal velocity without its sound-speed part. Only closing pairs count (min(., 0)). Four pairs
// a step in SSE registers: GCC does not vectorise a float max reduction by itself (maxss is not
// associative for NaN), and the scalar loop was a chain of dependent divisions and maxima.
float largestClosingSpeed2(const float* approach, const float* r2s, std::size_t count) {
  const Float4 zero{0, 0, 0, 0}, tiny{1e-18f, 1e-18f, 1e-18f, 1e-18f};
  Float4 largest = zero;
  std::size_t k = 0;
  for (; k + 4 <= count; k += 4) {
    const Float4 a = load4(approach + k), r2 = load4(r2s + k);
    const Float4 closing = a < zero ? a : zero;
    const Float4 value = closing * closing / (r2 > tiny ? r2 : tiny);
    largest = value > largest ? value : largest;
  }
  float result = std::max(std::max(largest[0], largest[1]), std::max(largest[2], largest[3]));
  for (; k < count; ++k) {
    const float closing = std::min(approach[k], 0.0f);
    result = std::max(result, closing * closing / std::max(r2s[k], 1e-18f));
  }
  return result;
}

// Per-pair kernel factors from r alone: one flat loop over contiguous arrays, no gathers and no
// branches, which GCC vectorises with SSE2 (restrict: the arrays never overlap). Taking the
// square root and the division here, four pairs per instruction, saves about a tenth of the
// pair loop's instructions against doing them per pair inside it (callgrind).
void pairFactors(const float* __restrict r2s, std::size_t count, float h, float h2, float spiky,
                 float visc, float poly6, float* __restrict radial, float* __restrict lapVisc,
                 float* __restrict gradColour, float* __restrict lapColour) {
  for (std::size_t k = 0; k < count; ++k) {
    const float r2 = r2s[k];
    const float r = std::sqrt(r2);
    const float hr = h - r;
    const float q = h2 - r2;
    // Coincident pairs divide by infinity, giving exactly 0 (their force comes from the pair
    // direction instead). Selecting the divisor, not the quotient, keeps the loop branch-free
    // for GCC (it does not if-convert a division).
    const float divisor = r2 > 1e-18f ? r : std::numeric_limits<float>::infinity();
    radial[k] = spiky * hr * hr / divisor;
    lapVisc[k] = visc * hr;
    gradColour[k] = poly6 * q * q;
    lapColour[k] = poly6 * q * (3.0f * h2 - 7.0f * r2);
  }
}

}  // namespace

// The pair loop proper: sums over the half list in fixed order (particle, then partner), each
// pair added to both ends. A pair's offset is recomputed from DensitySolver's float positions
// (the same subtraction, so the same bits) and the kernel factors come from pairFactors, so per
// pair only the state of j is gathered. 3-vectors are Float4 lanes 0..2, so each vector update
// is one SSE2 operation. `Colour` removes the Müller sums from the loop at compile time instead
// of testing a flag per pair. A partner at or past `end`
// belongs to a later chunk, which another thread may be summing: its share goes to `spill`.
template <bool Colour, bool Pressure>
void FluidForcePass::accumulate(const ActivePairs& pairs, std::uint32_t begin, std::uint32_t end,
                                std::uint64_t const* ids, Spill& spill) {
  const std::uint32_t* partner = pairs.partner.data();
  const float* x = pairs.position.data();
  const float* r2s = pairs.r2.data();
  const float* velocity = velocity_.data();
  const float* scalars = scalars_.data();  // per particle: m, p, 1 / rho, V (one SSE load)
  float* acc = acc_.data();                // acceleration, then the viscosity weight sum in lane 3
  float* weighted = weighted4_.data();     // weighted velocity, then the colour Laplacian in lane 3
  float* gradient = gradient4_.data();
  float* approach = approach_.data();
  const float* radial = radial_.data();
  const float* lapVisc = lapVisc_.data();
  const float* gradColour = gradColour_.data();
  const float* lapColour = lapColour_.data();
  // At most every pair of the chunk spills: room for that, so that the loop writes through
  // plain pointers with no test. The room is never zeroed (it was, as it grew: about 10 MB at
  // 10,000 particles).
  const std::size_t most = pairs.end(end - 1) - pairs.begin(begin);
  if (spill.partner.size() < most) {
    spill.partner.resize(most);
    spill.share.resize(12 * most);
  }
  std::uint32_t* spillPartner = spill.partner.data();
  float* spillShare = spill.share.data();
  std::size_t spilled = 0;

  for (std::uint32_t i = begin; i < end; ++i) {
    const auto si = static_cast<std::size_t>(i);
    const Float4 xi = load4(x + 4 * si);
    const Float4 vi = load4(velocity + 4 * si);
    const Float4 own = load4(scalars + 4 * si);
    const float mi = own[0], pi = own[1], voli = own[3];
    (void)mi;
    (void)pi;
    const float halfOverRhoi = 0.5f * own[2];
    Float4 ai{0, 0, 0, 0}, gi{0, 0, 0, 0}, wvi{0, 0, 0, 0};
    float wi = 0, li = 0;
    // The bound is read once: the float stores below could alias it as far as GCC knows.
    const std::uint32_t last = pairs.end(si);
    for (std::uint32_t k = pairs.begin(si); k < last; ++k) {
      const std::uint32_t j = partner[k];
      const std::size_t j4 = 4 * static_cast<std::size_t>(j);
      const Float4 d = xi - load4(x + j4);
      const Float4 vj = load4(velocity + j4);
      const Float4 sj = load4(scalars + j4);
      const float mj = sj[0], pj = sj[1], invRhoj = sj[2], volj = sj[3];
      const Float4 u = vi - vj;
      approach[k] = dot3(u, d);
      // Pressure: a_i -= m_j P d, a_j += m_i P d with P = (p_i + p_j) / (2 rho_i rho_j) g(r).
      // No test for p_i + p_j == 0 (frequent at the surface, where pressure is clamped, and
      // unpredictable): the force is then exactly zero.
      // Viscosity: sum_j V_j lap W and sum_j V_j lap W v_j (symmetric kernel); the weight sum
      // rides in lane 3 of the acceleration (d and so f have 0 there).
      const float lw = lapVisc[k];
      const float wj = volj * lw, wiPart = voli * lw;
      wi += wj;
      Float4 toJ{0, 0, 0, wiPart};  // j's acceleration share, weight sum in lane 3
      if constexpr (Pressure) {
        const float shared = (pi + pj) * halfOverRhoi * invRhoj;
        Float4 f = (shared * radial[k]) * d;
        if (r2s[k] <= 1e-18f && shared != 0.0f) [[unlikely]] {
          // Coincident (radial is 0 there): a fixed, antisymmetric direction from the ids.
          const Eigen::Vector3d e = pairDirection(ids[si], ids[j]);
          const float a = -shared * atZero_;
          f = Float4{a * static_cast<float>(e.x()), a * static_cast<float>(e.y()),
                     a * static_cast<float>(e.z()), 0.0f};
        }
        ai -= mj * f;
        toJ = mi * f + toJ;
      }
      wvi += wj * vj;
      Float4 wvj = wiPart * vi;
      Float4 gj{0, 0, 0, 0};
      if constexpr (Colour) {
        const float g = gradColour[k];
        gi += (volj * g) * d;
        gj = (voli * g) * d;
        const float l = lapColour[k];
        li += volj * l;
        wvj[3] = voli * l;
      }
      if (j < end) [[likely]] {
        if constexpr (Pressure)
          store4(acc + j4, load4(acc + j4) + toJ);
        else
          acc[j4 + 3] += wiPart;
        store4(weighted + j4, load4(weighted + j4) + wvj);
        if constexpr (Colour) store4(gradient + j4, load4(gradient + j4) - gj);
      } else {
        spillPartner[spilled] = j;
        float* share = spillShare + 12 * spilled;
        store4(share, toJ);
        store4(share + 4, wvj);
        store4(share + 8, gj);
        ++spilled;
      }
    }
    const std::size_t i4 = 4 * si;
    ai[3] = wi;
    store4(acc + i4, load4(acc + i4) + ai);
    wvi[3] = li;
    store4(weighted + i4, load4(weighted + i4) + wvi);
    if constexpr (Colour) store4(gradient + i4, load4(gradient + i4) + gi);
  }
  spill.count = spilled;
  // After the loop, not in it: tracked per spill, the range cost the pair loop 3.6 % more
  // instructions (callgrind); minmax_element here costs it about 1.5 %, and saves addSpills
  // from reading the lists that cannot reach a chunk.
  const auto [lowest, highest] = std::minmax_element(spillPartner, spillPartner + spilled);
  spill.lowest = spilled > 0 ? *lowest : 0;
  spill.highest = spilled > 0 ? *highest : 0;
}

// The spilled shares, chunk by chunk in order, each list in pair order: one fixed order of
// additions per particle, whichever thread ran which chunk. A list mostly reaches the next
// chunk or two only, so its partner range rules most lists out without a look at their entries.
// Lanes that a pass without pressure leaves untouched get a share of exactly 0 there (x + 0 = x).
void FluidForcePass::addSpills(std::size_t chunk, std::size_t begin, std::size_t end, bool colour) {
  float* acc = acc_.data();
  float* weighted = weighted4_.data();
  float* gradient = gradient4_.data();
  for (std::size_t c = 0; c < chunk; ++c) {
    const Spill& spill = spills_[c];
    if (spill.count == 0 || spill.highest < begin || spill.lowest >= end) continue;
    for (std::size_t e = 0; e < spill.count; ++e) {
      const std::size_t j = spill.partner[e];
      if (j < begin || j >= end) continue;
      const std::size_t j4 = 4 * j;
      const float* share = &spill.share[12 * e];
      store4(acc + j4, load4(acc + j4) + load4(share));
      store4(weighted + j4, load4(weighted + j4) + load4(share + 4));
      if (colour) store4(gradient + j4, load4(gradient + j4) - load4(share + 8));
    }
  }
}

double FluidForcePass::run(ParticleSet& p, ActivePairs& pairs,
                           const Viscosity_Mueller2003& viscosity, bool colour,
                           ParallelChunks& parallel, const ChunkWork& afterChunk) {
  const int n = p.size();
  const auto un = static_cast<std::size_t>(n);
  velocity_.resize(4 * un);
  scalars_.resize(4 * un);
  // Zeroed chunk by chunk below, by the thread that will sum into them.
  for (auto* v : {&acc_, &weighted4_, &gradient4_}) v->resize(4 * un);
  // Kernel coefficients, so the loops only multiply (Kernels.h):
  //   grad W_spiky = spiky (h - r)^2 / r r_vec,  lap W_visc = visc (h - r),
  //   grad W_poly6 = poly6 (h^2 - r^2)^2 r_vec,  lap W_poly6 = poly6 (h^2 - r^2)(3 h^2 - 7 r^2).
  const double hd = spikyKernel_.radius();
  h_ = static_cast<float>(hd);
  h2_ = static_cast<float>(hd * hd);
  spiky_ = static_cast<float>(spikyKernel_.gradientCoefficient());
  atZero_ = static_cast<float>(spikyKernel_.gradientMagnitudeAtZero());
  visc_ = static_cast<float>(viscosityKernel_.laplacianCoefficient());
  poly6_ = colour ? static_cast<float>(poly6Kernel_.gradientCoefficient()) : 0.0f;
  const float selfLaplacian = colour ? static_cast<float>(poly6Kernel_.laplacian(0.0)) : 0.0f;
  parallel.setParticleCount(n);
  // No pressure anywhere (DFSPH, whose solves replace it, or a fluid nowhere compressed): the
  // pressure terms are left out of the loop rather than added as zeros.
  const std::size_t chunk = parallel.particleChunk();
  const std::size_t particleChunks = ParallelChunks::chunkCount(un, chunk);
  anyPressureChunk_.assign(particleChunks, 0);
  parallel.forEachChunk(un, chunk, [&](int c, std::size_t begin, std::size_t end) {
    bool any = false;
    for (auto* v : {&acc_, &weighted4_, &gradient4_})
      std::fill(v->begin() + static_cast<std::ptrdiff_t>(4 * begin),
                v->begin() + static_cast<std::ptrdiff_t>(4 * end), 0.0f);
    for (std::size_t i = begin; i < end; ++i) {
      store4(&velocity_[4 * i], toFloat4(p.velocity[i]));
      const float m = static_cast<float>(p.mass[i]), pi = static_cast<float>(p.pressure[i]);
      const float invRho = 1.0f / static_cast<float>(p.density[i]), volume = m * invRho;
      weighted4_[4 * i + 3] = volume * selfLaplacian;
      store4(&scalars_[4 * i], Float4{m, pi, invRho, volume});
      any = any || pi != 0.0f;
    }
    anyPressureChunk_[static_cast<std::size_t>(c)] = any;
  });
  const bool anyPressure =
      std::find(anyPressureChunk_.begin(), anyPressureChunk_.end(), 1) != anyPressureChunk_.end();
  for (auto* v : {&approach_, &radial_, &lapVisc_, &gradColour_, &lapColour_})
    if (v->size() < pairs.indexLimit()) v->resize(pairs.indexLimit());

  // One job per particle chunk does its pairs from start to end: their kernel factors, the pair
  // loop, their largest closing speed. The per-pair arrays are then written and read back by
  // one thread while they are in its cache (about 0.4 MB for a chunk of the sheet), and never
  // cross to another core, which on a virtual machine costs more than the arithmetic.
  if (spills_.size() < particleChunks) spills_.resize(particleChunks);
  closing_.assign(particleChunks, 0.0f);
  parallel.forEachChunk(un, chunk, [&](int c, std::size_t begin, std::size_t end) {
    const std::size_t first = pairs.begin(begin), count = pairs.end(end - 1) - first;
    pairFactors(pairs.r2.data() + first, count, h_, h2_, spiky_, visc_, poly6_,
                radial_.data() + first, lapVisc_.data() + first, gradColour_.data() + first,
                lapColour_.data() + first);
    const auto b = static_cast<std::uint32_t>(begin), e = static_cast<std::uint32_t>(end);
    Spill& spill = spills_[static_cast<std::size_t>(c)];
    const std::uint64_t* ids = p.id.data();
    if (colour)
      anyPressure ? accumulate<true, true>(pairs, b, e, ids, spill)
                  : accumulate<true, false>(pairs, b, e, ids, spill);
    else
      anyPressure ? accumulate<false, true>(pairs, b, e, ids, spill)
                  : accumulate<false, false>(pairs, b, e, ids, spill);
    closing_[static_cast<std::size_t>(c)] =
        largestClosingSpeed2(approach_.data() + first, pairs.r2.data() + first, count);
  });
  // The largest closing speed: a maximum per chunk, then over the chunks (a maximum is exact,
  // so this is the serial value too).
  float closing2 = 0;
  for (float c : closing_) closing2 = std::max(closing2, c);

  weightSum_.resize(un);
  weighted_.resize(un);
  gradient_.resize(colour ? un : 0);
  laplacian_.resize(colour ? un : 0);
  const double nu = viscosity.nu();
  parallel.forEachChunk(un, chunk, [&](int c, std::size_t begin, std::size_t end) {
    addSpills(static_cast<std::size_t>(c), begin, end, colour);
    for (std::size_t i = begin; i < end; ++i) {
      const float* a = &acc_[4 * i];
      const float* w = &weighted4_[4 * i];
      p.acceleration[i] = Eigen::Vector3d(a[0], a[1], a[2]);
      weightSum_[i] = a[3];
      weighted_[i] = Eigen::Vector3d(w[0], w[1], w[2]);
      p.viscosityRate[i] = nu * weightSum_[i] * scalars_[4 * i + 2];
      if (colour) {
        const float* g = &gradient4_[4 * i];
        gradient_[i] = Eigen::Vector3d(g[0], g[1], g[2]);
        laplacian_[i] = weighted4_[4 * i + 3];
      }
    }
    if (afterChunk) afterChunk(c, begin, end);
  });
  return std::sqrt(static_cast<double>(closing2));
}

}  // namespace lacrima::tears
