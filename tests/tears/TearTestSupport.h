#pragma once
// Shared scene and invariant checks for the tear-simulation suites: the generated cheek sheet,
// a runner that drives a simulation frame by frame, the checks every hard case must pass
// at every frame (finite state, particles inside a box around the sheet, the commanded count,
// and kinetic energy bounded by the potential energy released since each particle appeared),
// and what a frame shows, compared bit for bit (determinism and checkpoints).
#include <lacrima/tears/SyntheticSkin.h>
#include <lacrima/tears/TearSimulation.h>
#include <lacrima/tears/TrailBuilder.h>

#include <QtTest>

#include <cstring>
#include <functional>
#include <map>
#include <memory>
#include <string>

namespace lacrima::tears::testing {

inline constexpr double kFrameDt = 1.0 / 22.0;

inline std::unique_ptr<TearSimulation> makeSheetSimulation(const SyntheticSkin& sheet,
                                                           const TearSettings& settings = {},
                                                           SimulationOptions options = {}) {
  options.headHeight = 2.7;  // the sheet stands in for the default decimetre head
  auto sim = std::make_unique<TearSimulation>(sheet.positions, sheet.triangles, settings, options);
  sim->setSource(Eye::Left, sheet.leftSource);
  sim->setSource(Eye::Right, sheet.rightSource);
  return sim;
}

struct FrameReport {
  bool finite = true;
  bool inBox = true;
  bool countOk = true;
  double kinetic = 0;
  double released = 0;  // sum m g (y_first - y) + one frame of free fall per particle
  double maxSpeed = 0;
};

// Watches a simulation over many frames; remembers where each particle id was first seen.
class InvariantChecker {
 public:
  explicit InvariantChecker(const SyntheticSkin& sheet, double margin = 0.35) {
    for (Eigen::Index i = 0; i < sheet.positions.cols(); ++i)
      box_.extend(sheet.positions.col(i).cast<double>());
    box_.min().array() -= margin;
    box_.max().array() += margin;
  }
  void widen(const Eigen::Vector3d& by) {
    box_.min() -= by;
    box_.max() += by;
  }

  FrameReport check(const TearSimulation& sim, int left, int right) {
    FrameReport r;
    const ParticleSet& p = sim.particles();
    const double g = sim.parameters().gravity;
    r.countOk =
        sim.count(Eye::Left) == left && sim.count(Eye::Right) == right && p.size() == left + right;
    std::map<std::uint64_t, double> seen;
    for (int i = 0; i < p.size(); ++i) {
      const auto s = static_cast<std::size_t>(i);
      const Eigen::Vector3d& x = p.position[s];
      const Eigen::Vector3d& v = p.velocity[s];
      r.finite =
          r.finite && x.allFinite() && v.allFinite() && std::isfinite(p.mass[s]) && p.mass[s] > 0;
      r.inBox = r.inBox && box_.contains(x);
      auto it = firstHeight_.find(p.id[s]);
      const double first = it == firstHeight_.end() ? x.y() : it->second;
      seen[p.id[s]] = first;
      r.kinetic += 0.5 * p.mass[s] * v.squaredNorm();
      r.released += p.mass[s] * g * (first - x.y() + g * kFrameDt * kFrameDt);
      r.maxSpeed = std::max(r.maxSpeed, v.norm());
    }
    firstHeight_ = std::move(seen);
    return r;
  }

 private:
  Eigen::AlignedBox3d box_;
  std::map<std::uint64_t, double> firstHeight_;
};

// Runs `frames` frames with constant counts on a possibly moving sheet and checks every frame.
// `energyFactor` <= 0 skips the energy bound (moving surfaces do work on the fluid).
inline void runAndCheck(TearSimulation& sim, const SyntheticSkin& sheet, int left, int right,
                        int frames, double energyFactor = 1.05,
                        const std::function<Eigen::Matrix3Xf(int)>& surfaceAt = {},
                        InvariantChecker* customChecker = nullptr) {
  InvariantChecker defaultChecker(sheet);
  InvariantChecker& checker = customChecker ? *customChecker : defaultChecker;
  for (int f = 0; f < frames; ++f) {
    const Eigen::Matrix3Xf positions = surfaceAt ? surfaceAt(f) : sheet.positions;
    sim.step(positions, left, right, kFrameDt);
    const FrameReport r = checker.check(sim, left, right);
    const QByteArray where = QByteArray("frame ") + QByteArray::number(f);
    QVERIFY2(r.finite, where + ": non-finite particle state");
    QVERIFY2(r.inBox, where + ": a particle left the box around the sheet");
    QVERIFY2(r.countOk, where + ": particle count differs from the commanded count");
    if (energyFactor > 0) {
      // Tolerance: a particle's worth of free fall over the sheet's height, for pressure energy
      // stored at emission (particles appear in contact with their neighbours).
      const double tolerance =
          (left + right) * sim.parameters().particleMass * sim.parameters().gravity * 0.05;
      QVERIFY2(r.kinetic <= energyFactor * r.released + tolerance,
               where + ": kinetic energy " + QByteArray::number(r.kinetic) +
                   " exceeds what gravity released " + QByteArray::number(r.released));
    }
  }
}

template <typename T>
bool sameBits(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() &&
         (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

inline bool sameBits(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  return a.rows() == b.rows() && a.cols() == b.cols() &&
         (a.size() == 0 || std::memcmp(a.data(), b.data(),
                                       static_cast<std::size_t>(a.size()) * sizeof(double)) == 0);
}

// Everything a player sees of one frame: the particles, the trail mesh and the wetness.
struct FrameState {
  std::vector<Eigen::Vector3d> position, velocity;
  std::vector<double> mass;
  std::vector<std::uint64_t> id;
  std::vector<int> contact;
  Eigen::MatrixXd trail;
  double wetLeft = 0, wetRight = 0;
};

inline FrameState stateOf(const TearSimulation& sim, const TrailBuilder& trails) {
  FrameState s;
  const ParticleSet& p = sim.particles();
  s.position = p.position;
  s.velocity = p.velocity;
  s.mass = p.mass;
  s.id = p.id;
  for (const SkinContact& c : p.contact) s.contact.push_back(c.triangle);
  s.trail = trails.mesh().positions();
  s.wetLeft = sim.wetness(Eye::Left).trailVolume;
  s.wetRight = sim.wetness(Eye::Right).trailVolume;
  return s;
}

inline bool sameBits(const FrameState& a, const FrameState& b) {
  return sameBits(a.position, b.position) && sameBits(a.velocity, b.velocity) &&
         sameBits(a.mass, b.mass) && a.id == b.id && a.contact == b.contact &&
         sameBits(a.trail, b.trail) && std::memcmp(&a.wetLeft, &b.wetLeft, sizeof(double)) == 0 &&
         std::memcmp(&a.wetRight, &b.wetRight, sizeof(double)) == 0;
}

}  // namespace lacrima::tears::testing
