#include "PressureSolver_DFSPH.h"
#include "Float4.h"
#include "PairDirection.h"

#include <algorithm>
#include <cmath>

namespace lacrima::tears {

MethodInfo PressureSolver_DFSPH::info() {
  const DivergenceFreeSettings defaults;
  return {"dfsph",
          "DFSPH",
          "Divergence-free SPH: two iterative velocity solves per sub-step; drops cling harder, "
          "about twice the cost per sub-step",
          {{"tolerance",
            "Mean compression left after a step at the default pressure (the pressure "
            "parameter scales it inversely)",
            defaults.densityTolerance, 1e-4, 0.1, false},
           {"max-iterations", "Iterations per solve before it stops (counted as capped)",
            static_cast<double>(defaults.maxIterations), 2, 1000, true}}};
}

std::unique_ptr<PressureSolver> PressureSolver_DFSPH::create(const MethodValues& values,
                                                             const ScaledParameters& p,
                                                             const TearSettings& settings) {
  const double stiffness =
      settings.pressure > 0 ? TearSettings{}.pressure / settings.pressure : 1e3;
  DivergenceFreeSettings dfsph;
  dfsph.densityTolerance = std::clamp(values.number("tolerance") * stiffness, 1e-4, 0.1);
  dfsph.divergenceTolerance = dfsph.densityTolerance;
  dfsph.maxIterations = values.wholeNumber("max-iterations");
  return std::make_unique<PressureSolver_DFSPH>(p.h, dfsph);
}

PressureSolver_DFSPH::PressureSolver_DFSPH(double h, const DivergenceFreeSettings& settings)
    : w_(h), settings_(settings) {}

void PressureSolver_DFSPH::prepare(const ParticleSet& p, const ActivePairs& pairs) {
  const int n = p.size();
  const auto un = static_cast<std::size_t>(n);
  if (gradient_.size() < 4 * pairs.indexLimit()) gradient_.resize(4 * pairs.indexLimit());
  m_.resize(un);
  for (std::size_t i = 0; i < un; ++i) m_[i] = static_cast<float>(p.mass[i]);
  const float h = static_cast<float>(w_.radius());
  const float coefficient = static_cast<float>(w_.gradientCoefficient());
  const float atZero = static_cast<float>(w_.gradientMagnitudeAtZero());
  // Gradients, per pair (offsets from DensitySolver's positions, r^2 as it measured it).
  const float* x = pairs.position.data();
  const float* r2s = pairs.r2.data();
  float* g = gradient_.data();
  for (std::size_t i = 0; i < un; ++i) {
    const Float4 xi = load4(x + 4 * i);
    for (std::uint32_t k = pairs.begin(i); k < pairs.end(i); ++k) {
      const float r = std::sqrt(r2s[k]);
      const float hr = h - r;
      const float divisor = r2s[k] > 1e-18f ? r : 1.0f;
      const Float4 d = xi - load4(x + 4 * std::size_t{pairs.partner[k]});
      store4(g + 4 * std::size_t{k}, (coefficient * hr * hr / divisor) * d);
    }
  }
  // Coincident pairs (rare): a fixed direction from the ids, pointing from j to i.
  for (int i = 0; i < n; ++i)
    for (std::uint32_t k = pairs.begin(static_cast<std::size_t>(i));
         k < pairs.end(static_cast<std::size_t>(i)); ++k)
      if (r2s[k] <= 1e-18f) [[unlikely]] {
        const Eigen::Vector3d e =
            pairDirection(p.id[static_cast<std::size_t>(i)], p.id[pairs.partner[k]]);
        store4(g + 4 * static_cast<std::size_t>(k), toFloat4(e) * atZero);
      }

  // alpha_i = 1 / (|S_i|^2 + Q_i), S_i = sum_j m_j g_ij, Q_i = sum_j m_i m_j |g_ij|^2.
  std::vector<float>& sum = velocity_;  // scratch: S per particle (4 floats)
  sum.assign(4 * un, 0.0f);
  rate_.assign(un, 0.0f);  // scratch: Q
  const float* m = m_.data();
  for (int i = 0; i < n; ++i) {
    const auto si = static_cast<std::size_t>(i);
    const float mi = m[si];
    Float4 si4{0, 0, 0, 0};
    float qi = 0;
    for (std::uint32_t k = pairs.begin(si); k < pairs.end(si); ++k) {
      const std::size_t j = pairs.partner[k];
      const Float4 gk = load4(g + 4 * static_cast<std::size_t>(k));
      const float q = mi * m[j] * dot3(gk, gk);
      si4 += m[j] * gk;
      qi += q;
      store4(&sum[4 * j], load4(&sum[4 * j]) - mi * gk);
      rate_[j] += q;
    }
    store4(&sum[4 * si], load4(&sum[4 * si]) + si4);
    rate_[si] += qi;
  }
  alpha_.resize(un);
  // Below this the particle has (next to) no neighbours: nothing to solve for.
  const float floor = 1e-6f / (h * h);
  for (std::size_t i = 0; i < un; ++i) {
    const Float4 s = load4(&sum[4 * i]);
    const float denominator = dot3(s, s) + rate_[i];
    alpha_[i] = denominator > floor ? 1.0f / denominator : 0.0f;
  }
}

void PressureSolver_DFSPH::loadVelocities(const ParticleSet& p) {
  const std::size_t un = p.velocity.size();
  velocity_.resize(4 * un);
  for (std::size_t i = 0; i < un; ++i) store4(&velocity_[4 * i], toFloat4(p.velocity[i]));
  start_ = velocity_;
}

void PressureSolver_DFSPH::storeVelocities(ParticleSet& p) const {
  // Only the change is in float: the velocities themselves keep double precision.
  for (std::size_t i = 0; i < p.velocity.size(); ++i) {
    const Float4 d = load4(&velocity_[4 * i]) - load4(&start_[4 * i]);
    p.velocity[i] += Eigen::Vector3d(d[0], d[1], d[2]);
  }
}

void PressureSolver_DFSPH::densityRates(const ActivePairs& pairs, int n) {
  const auto un = static_cast<std::size_t>(n);
  rate_.assign(un, 0.0f);
  const float* g = gradient_.data();
  const float* v = velocity_.data();
  const float* m = m_.data();
  float* rate = rate_.data();
  for (std::size_t i = 0; i < un; ++i) {
    const Float4 vi = load4(v + 4 * i);
    const float mi = m[i];
    float ri = 0;
    for (std::uint32_t k = pairs.begin(i); k < pairs.end(i); ++k) {
      const std::size_t j = pairs.partner[k];
      const float u = dot3(vi - load4(v + 4 * j), load4(g + 4 * static_cast<std::size_t>(k)));
      ri += m[j] * u;
      rate[j] += mi * u;  // grad_j W_ji = -g_ij and v_j - v_i = -(v_i - v_j): the same sign
    }
    rate[i] += ri;
  }
}

void PressureSolver_DFSPH::applyKappa(const ActivePairs& pairs, int n) {
  const auto un = static_cast<std::size_t>(n);
  const float* g = gradient_.data();
  const float* m = m_.data();
  const float* kappa = kappa_.data();
  float* v = velocity_.data();
  for (std::size_t i = 0; i < un; ++i) {
    const float ki = kappa[i], mi = m[i];
    Float4 dvi{0, 0, 0, 0};
    for (std::uint32_t k = pairs.begin(i); k < pairs.end(i); ++k) {
      const std::size_t j = pairs.partner[k];
      const float s = ki + kappa[j];
      // Both particles at rest density or stretched: no correction (frequent, unpredictable;
      // the update is then exactly zero anyway).
      const Float4 f = s * load4(g + 4 * static_cast<std::size_t>(k));
      dvi -= m[j] * f;
      store4(v + 4 * j, load4(v + 4 * j) + mi * f);
    }
    store4(v + 4 * i, load4(v + 4 * i) + dvi);
  }
}

int PressureSolver_DFSPH::solveDivergence(ParticleSet& p, const ActivePairs& pairs, double dt) {
  const int n = p.size();
  const auto un = static_cast<std::size_t>(n);
  stats_.divergenceIterations = 0;
  stats_.divergenceCapped = false;
  if (n == 0 || !(dt > 0)) return 0;
  loadVelocities(p);
  kappa_.resize(un);
  const double tolerance = settings_.divergenceTolerance / dt;  // on the mean rate
  int iteration = 0;
  for (;; ++iteration) {
    densityRates(pairs, n);
    double total = 0;
    for (std::size_t i = 0; i < un; ++i) {
      const float e = std::max(rate_[i], 0.0f);  // only compression
      total += e;
      kappa_[i] = e * alpha_[i];
    }
    if ((iteration >= 1 && total <= tolerance * n) || iteration >= settings_.maxIterations) {
      stats_.divergenceCapped = iteration >= settings_.maxIterations && total > tolerance * n;
      break;
    }
    applyKappa(pairs, n);
  }
  storeVelocities(p);
  stats_.divergenceIterations = iteration;
  return iteration;
}

int PressureSolver_DFSPH::solveDensity(ParticleSet& p, const ActivePairs& pairs, double dt,
                                       std::span<const Eigen::Vector3d> contactNormal) {
  const int n = p.size();
  const auto un = static_cast<std::size_t>(n);
  stats_.densityIterations = 0;
  stats_.densityCapped = false;
  if (n == 0 || !(dt > 0)) return 0;
  loadVelocities(p);
  kappa_.resize(un);
  const float fdt = static_cast<float>(dt), invDt = 1.0f / fdt;
  int iteration = 0;
  for (;; ++iteration) {
    densityRates(pairs, n);
    double total = 0;
    for (std::size_t i = 0; i < un; ++i) {
      // Predicted density after dt; its excess over rest, as a rate (the correction acts on
      // velocities, which act for dt).
      const float excess = std::max(static_cast<float>(p.density[i]) + fdt * rate_[i] - 1.0f, 0.0f);
      total += excess;
      kappa_[i] = excess * invDt * alpha_[i];
    }
    if ((iteration >= 2 && total <= settings_.densityTolerance * n) ||
        iteration >= settings_.maxIterations) {
      stats_.densityCapped =
          iteration >= settings_.maxIterations && total > settings_.densityTolerance * n;
      break;
    }
    applyKappa(pairs, n);
  }
  storeVelocities(p);
  double maxNet2 = 0;
  for (std::size_t i = 0; i < un; ++i) {
    const Float4 d = load4(&velocity_[4 * i]) - load4(&start_[4 * i]);
    Eigen::Vector3d net = p.acceleration[i] + Eigen::Vector3d(d[0], d[1], d[2]) / dt;
    if (i < contactNormal.size()) {
      const double into = net.dot(contactNormal[i]);
      if (into < 0) net -= into * contactNormal[i];  // the skin holds that part back
    }
    maxNet2 = std::max(maxNet2, net.squaredNorm());
  }
  stats_.maxNetAcceleration = std::sqrt(maxNet2);
  stats_.densityIterations = iteration;
  return iteration;
}

void PressureSolver_DFSPH::computePressures(ParticleSet& p, const ActivePairs& pairs,
                                            double remaining, TearCounters& counters) {
  std::fill(p.pressure.begin(), p.pressure.end(), 0.0);
  prepare(p, pairs);
  const double expected =
      history_.lastSubstep > 0 ? std::min(history_.lastSubstep, remaining) : remaining;
  counters.divergenceIterations += solveDivergence(p, pairs, expected);
  counters.solverCapped += stats_.divergenceCapped;
}

double PressureSolver_DFSPH::accelerationBound(double largestFluidAcceleration) const {
  return history_.lastNetAcceleration >= 0 ? history_.lastNetAcceleration
                                           : largestFluidAcceleration;
}

void PressureSolver_DFSPH::correctVelocities(ParticleSet& p, const ActivePairs& pairs, double dt,
                                             const SkinView& skin, TearCounters& counters) {
  contactNormals(p, skin, contactNormal_);
  counters.densityIterations += solveDensity(p, pairs, dt, contactNormal_);
  counters.solverCapped += stats_.densityCapped;
  history_.lastSubstep = dt;
  history_.lastNetAcceleration = stats_.maxNetAcceleration;
}

}  // namespace lacrima::tears
