#include "PressureSolver_PBF.h"
#include "Float4.h"
#include "PairDirection.h"

#include <algorithm>
#include <cmath>

namespace lacrima::tears {

MethodInfo PressureSolver_PBF::info() {
  const PositionBasedSettings defaults;
  return {"pbf",
          "PBF",
          "Position-based fluids: density constraints on the predicted positions, a fixed number "
          "of iterations per sub-step",
          {{"iterations", "Constraint iterations per sub-step",
            static_cast<double>(defaults.iterations), 1, 100, true},
           {"relaxation", "Constraint force mixing epsilon, in 1/h^2", defaults.relaxation, 0, 100,
            false},
           {"artificial-pressure",
            "The paper's s_corr term against the tensile instability (1) "
            "or none (0)",
            defaults.artificialPressure ? 1.0 : 0.0, 0, 1, true}}};
}

std::unique_ptr<PressureSolver> PressureSolver_PBF::create(const MethodValues& values,
                                                           const ScaledParameters& p,
                                                           const TearSettings&) {
  PositionBasedSettings pbf;
  pbf.iterations = values.wholeNumber("iterations");
  pbf.relaxation = values.number("relaxation");
  pbf.artificialPressure = values.flag("artificial-pressure");
  return std::make_unique<PressureSolver_PBF>(p.h, pbf);
}

namespace {

// The paper's artificial pressure: k = 0.1 (times h^2, lambda's scale), n = 4, at dq = 0.2 h.
constexpr double kScorrStrength = 0.1;
constexpr double kScorrDistance = 0.2;

}  // namespace

PressureSolver_PBF::PressureSolver_PBF(double h, const PositionBasedSettings& settings)
    : density_(h), gradient_(h), settings_(settings) {
  epsilon_ = static_cast<float>(std::max(0.0, settings.relaxation) / (h * h));
  const double dq = kScorrDistance * h;
  scorrScale_ = static_cast<float>(1.0 / density_.value(dq * dq));
  scorrStrength_ = static_cast<float>(kScorrStrength * h * h);
}

void PressureSolver_PBF::computePressures(ParticleSet& p, const ActivePairs&, double,
                                          TearCounters&) {
  std::fill(p.pressure.begin(), p.pressure.end(), 0.0);
}

double PressureSolver_PBF::accelerationBound(double largestFluidAcceleration) const {
  return history_.lastNetAcceleration >= 0 ? history_.lastNetAcceleration
                                           : largestFluidAcceleration;
}

void PressureSolver_PBF::constraints(const ActivePairs& pairs, std::span<const std::uint64_t> ids,
                                     int n) {
  const auto un = static_cast<std::size_t>(n);
  const float h = static_cast<float>(gradient_.radius()), h2 = h * h;
  const float wCoefficient = static_cast<float>(density_.valueCoefficient());
  const float gCoefficient = static_cast<float>(gradient_.gradientCoefficient());
  const float atZero = static_cast<float>(gradient_.gradientMagnitudeAtZero());
  const float w0 = static_cast<float>(density_.valueAtZero());
  const bool scorr = settings_.artificialPressure;
  const float* m = m_.data();
  const float* d = d_.data();
  const float* x = pairs.position.data();
  for (std::size_t i = 0; i < un; ++i) rho_[i] = m[i] * w0;
  std::fill(sum_.begin(), sum_.end(), 0.0f);
  std::fill(diagonal_.begin(), diagonal_.end(), 0.0f);
  for (std::size_t i = 0; i < un; ++i) {
    const Float4 xi = load4(x + 4 * i), di = load4(d + 4 * i);
    const float mi = m[i];
    Float4 sumI{0, 0, 0, 0};
    float rhoI = 0, diagonalI = 0;
    for (std::uint32_t k = pairs.begin(i); k < pairs.end(i); ++k) {
      const std::size_t j = pairs.partner[k];
      const Float4 r = (xi - load4(x + 4 * j)) + di - load4(d + 4 * j);
      const float r2 = dot3(r, r);
      float* gk = &g_[4 * static_cast<std::size_t>(k)];
      if (r2 >= h2) {  // moved apart beyond the kernel during the solve
        store4(gk, Float4{0, 0, 0, 0});
        if (scorr) scorr_[k] = 0;
        continue;
      }
      const float q = h2 - r2, w = wCoefficient * q * q * q;
      Float4 g;
      if (r2 > 1e-18f) [[likely]] {
        const float rl = std::sqrt(r2), hr = h - rl;
        g = (gCoefficient * hr * hr / rl) * r;
      } else {
        g = atZero * toFloat4(pairDirection(ids[i], ids[j]));
      }
      store4(gk, g);
      const float mj = m[j], gg = dot3(g, g);
      rhoI += mj * w;
      rho_[j] += mi * w;
      sumI += mj * g;                                      // grad_i C_i: V_j g_ij
      store4(&sum_[4 * j], load4(&sum_[4 * j]) - mi * g);  // grad_j C_j: V_i g_ji = -V_i g_ij
      diagonalI += mj * mj * gg;                           // |grad_j C_i|^2
      diagonal_[j] += mi * mi * gg;
      if (scorr) {
        const float ratio = w * scorrScale_, ratio2 = ratio * ratio;
        scorr_[k] = -scorrStrength_ * ratio2 * ratio2;
      }
    }
    rho_[i] += rhoI;
    store4(&sum_[4 * i], load4(&sum_[4 * i]) + sumI);
    diagonal_[i] += diagonalI;
  }
  for (std::size_t i = 0; i < un; ++i) {
    const float c = std::max(rho_[i] - 1.0f, 0.0f);  // rho0 = 1
    const Float4 s = load4(&sum_[4 * i]);
    lambda_[i] = c > 0 ? -c / (dot3(s, s) + diagonal_[i] + epsilon_) : 0.0f;
  }
}

void PressureSolver_PBF::correct(const ActivePairs& pairs,
                                 std::span<const Eigen::Vector3d> contactNormal, int n) {
  const auto un = static_cast<std::size_t>(n);
  const bool scorr = settings_.artificialPressure;
  const float* m = m_.data();
  const float* lambda = lambda_.data();
  const float* g = g_.data();
  float* dp = dp_.data();
  std::fill(dp_.begin(), dp_.end(), 0.0f);
  for (std::size_t i = 0; i < un; ++i) {
    const float li = lambda[i], mi = m[i];
    Float4 dpi{0, 0, 0, 0};
    for (std::uint32_t k = pairs.begin(i); k < pairs.end(i); ++k) {
      const std::size_t j = pairs.partner[k];
      const float s = li + lambda[j] + (scorr ? scorr_[k] : 0.0f);
      const Float4 f = s * load4(g + 4 * static_cast<std::size_t>(k));
      dpi += m[j] * f;
      store4(dp + 4 * j, load4(dp + 4 * j) - mi * f);
    }
    store4(dp + 4 * i, load4(dp + 4 * i) + dpi);
  }
  for (std::size_t i = 0; i < un; ++i) {
    Float4 dpi = load4(dp + 4 * i);
    if (i < contactNormal.size()) {
      const Float4 normal = toFloat4(contactNormal[i]);
      const float into = dot3(dpi, normal);
      if (into < 0) dpi -= into * normal;  // the skin holds that part back
    }
    store4(&d_[4 * i], load4(&d_[4 * i]) + dpi);
  }
}

void PressureSolver_PBF::solve(ParticleSet& p, const ActivePairs& pairs, double dt,
                               std::span<const Eigen::Vector3d> contactNormal) {
  const int n = p.size();
  const auto un = static_cast<std::size_t>(n);
  stats_ = {};
  if (n == 0 || !(dt > 0)) return;
  if (g_.size() < 4 * pairs.indexLimit()) g_.resize(4 * pairs.indexLimit());
  if (settings_.artificialPressure && scorr_.size() < pairs.indexLimit())
    scorr_.resize(pairs.indexLimit());
  m_.resize(un);
  rho_.resize(un);
  lambda_.resize(un);
  diagonal_.resize(un);
  sum_.resize(4 * un);
  dp_.resize(4 * un);
  d_.resize(4 * un);
  for (std::size_t i = 0; i < un; ++i) {
    m_[i] = static_cast<float>(p.mass[i]);  // V_i = m_i / rho0, rho0 = 1
    store4(&d_[4 * i], toFloat4(dt * p.velocity[i]));
  }
  start_ = d_;
  for (int iteration = 0; iteration < settings_.iterations; ++iteration) {
    constraints(pairs, p.id, n);
    correct(pairs, contactNormal, n);
  }

  // v_i = d_i / dt: only the correction is in float, the velocities keep double precision.
  double maxNet2 = 0;
  for (std::size_t i = 0; i < un; ++i) {
    const Float4 c = load4(&d_[4 * i]) - load4(&start_[4 * i]);
    const Eigen::Vector3d correction(c[0], c[1], c[2]);
    p.velocity[i] += correction / dt;
    Eigen::Vector3d net = p.acceleration[i] + correction / (dt * dt);
    if (i < contactNormal.size()) {
      const double into = net.dot(contactNormal[i]);
      if (into < 0) net -= into * contactNormal[i];
    }
    maxNet2 = std::max(maxNet2, net.squaredNorm());
  }
  stats_.maxNetAcceleration = std::sqrt(maxNet2);
}

void PressureSolver_PBF::correctVelocities(ParticleSet& p, const ActivePairs& pairs, double dt,
                                           const SkinView& skin, TearCounters& counters) {
  contactNormals(p, skin, contactNormal_);
  solve(p, pairs, dt, contactNormal_);
  counters.densityIterations += settings_.iterations;
  history_.lastNetAcceleration = stats_.maxNetAcceleration;
}

}  // namespace lacrima::tears
