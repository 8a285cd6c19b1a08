#pragma once
// Drops of resting particles placed on the cheek sheet (makeCheekSheet), for the tests of what
// is drawn on the skin: trails (TearTrailsTest) and drop caps (DropCapsTest).
#include "TearTestSupport.h"

#include <lacrima/tears/ParticleSet.h>
#include <lacrima/tears/SyntheticSkin.h>
#include <lacrima/tears/TrailBuilder.h>
#include <lacrima/tears/TrailSkin.h>
#include <lacrima/tears/UniformGrid.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>
#include <vector>

namespace lacrima::tears::testing {

inline constexpr double kH = 0.016, kRadius = kH / 4;  // the default kernel and particle radius, dm

// The sheet's analytic surface (SyntheticSkin.cpp's construction, default options): a vertical
// cylinder of radius 1 leaning back 20 degrees about x. Used as an independent reference.
inline const Eigen::AngleAxisd kLean(-20 * std::numbers::pi / 180, Eigen::Vector3d::UnitX());
inline Eigen::Vector3d sheetPoint(double u, double v) {
  return kLean * Eigen::Vector3d(std::sin(u), v, std::cos(u) - 1);
}
inline Eigen::Vector3d sheetNormal(double u) {
  return kLean * Eigen::Vector3d(std::sin(u), 0, std::cos(u));
}
// Distance from x to the (unmoved) cylinder.
inline double distanceToSheet(const Eigen::Vector3d& x) {
  const Eigen::Vector3d p = kLean.inverse() * x;
  return std::abs(std::hypot(p.x(), p.z() + 1) - 1);
}

// A rigid motion of the sheet about its centre, as movedSheet applies it.
struct Motion {
  Eigen::Vector3d centre, translation;
  Eigen::Matrix3d rotation;
  Eigen::Vector3d apply(const Eigen::Vector3d& x) const {
    return centre + rotation * (x - centre) + translation;
  }
  Eigen::Vector3d undo(const Eigen::Vector3d& x) const {
    return centre + rotation.transpose() * (x - translation - centre);
  }
};

// A drop of resting particles on the sheet at (u, v): a half-ball lattice of spacing h/2 over
// the skin, ids from firstId, each touching particle given its contact triangle. A drop lifted
// off the sheet (in the air) touches nothing.
struct DropSpec {
  double u, v;
  int count;
  std::uint64_t firstId;
  Eye eye = Eye::Left;
  double lift = 0;  // along the normal
};

inline void addDrop(ParticleSet& particles, const TrailSkin& skin, const DropSpec& d,
                    const Motion* motion = nullptr) {
  const Eigen::Vector3d c = sheetPoint(d.u, d.v), n = sheetNormal(d.u);
  const Eigen::Vector3d e1 = Eigen::Vector3d::UnitY().cross(n).normalized(), e2 = n.cross(e1);
  const double spacing = kH / 2;
  std::vector<Eigen::Vector3d> offsets;
  for (int i = -4; i <= 4; ++i)
    for (int j = -4; j <= 4; ++j)
      for (int k = 0; k <= 4; ++k) offsets.emplace_back(i * spacing, j * spacing, k * spacing);
  std::stable_sort(offsets.begin(), offsets.end(),
                   [](const auto& a, const auto& b) { return a.squaredNorm() < b.squaredNorm(); });
  std::vector<int> all(static_cast<std::size_t>(skin.triangleCount()));
  std::iota(all.begin(), all.end(), 0);
  for (int p = 0; p < d.count; ++p) {
    const Eigen::Vector3d& o = offsets[static_cast<std::size_t>(p)];
    Eigen::Vector3d x = c + o.x() * e1 + o.y() * e2 + (o.z() + kRadius + d.lift) * n;
    const SkinAnchor nearest = skin.closest(x, all);  // set-up only: brute force over the sheet
    if (motion) x = motion->apply(x);
    const int i = particles.add(x, 1.0, d.firstId + static_cast<std::uint64_t>(p), d.eye);
    if (o.z() == 0 && d.lift == 0)
      particles.contact[static_cast<std::size_t>(i)].triangle = nearest.triangle;
  }
}

struct Scene {
  SyntheticSkin sheet = makeCheekSheet();
  TrailSkin probe{sheet.triangles};  // for setting up contacts
  ParticleSet particles;
  UniformGrid grid;
  Scene() { probe.bind(sheet.positions); }

  const TrailMesh& step(TrailBuilder& trails, const std::vector<DropSpec>& drops,
                        double dt = kFrameDt, const Eigen::Matrix3Xf* moved = nullptr,
                        const Motion* motion = nullptr) {
    particles.clear();
    for (const DropSpec& d : drops) addDrop(particles, probe, d, motion);
    grid.build(particles.position, kH);
    return trails.update(particles, grid, kH, kRadius, moved ? *moved : sheet.positions, dt);
  }
};

}  // namespace lacrima::tears::testing
