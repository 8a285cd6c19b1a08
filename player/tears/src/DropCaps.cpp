#include <lacrima/tears/DropCaps.h>
#include <lacrima/tears/DropFootprint.h>
#include <lacrima/tears/TearSimulation.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace lacrima::tears {
namespace {}  // namespace

DropCaps::DropCaps(std::vector<Eigen::Vector3i> skinTriangles, const DropCapSettings& settings)
    : skin_(std::move(skinTriangles)), settings_(settings) {
  if (settings_.maxParticles < 1 || settings_.rings < 1 || settings_.segments < 3 ||
      !(settings_.minimumSpeed >= 0) || !(settings_.followDistance >= 0) ||
      !(settings_.trackWidth >= 0) || settings_.maxCaps < 0 ||
      !(settings_.contactAngleDegrees > 0 && settings_.contactAngleDegrees <= 180) ||
      !(settings_.rimLift >= 0 && settings_.rimLift < 1))
    throw std::invalid_argument(
        "drop caps: at least one particle, ring and three segments, distances, a speed and a "
        "number of caps of at least 0, a contact angle in (0, 180] degrees and a rim lift in "
        "[0, 1)");
}

const TearSurface& DropCaps::update(const TearSimulation& simulation,
                                    const Eigen::Matrix3Xf& headPositions) {
  if (simulation.particles().empty()) {  // the grid is built on demand: do not ask for it
    mesh_.clear();
    skipped_.clear();
    caps_ = 0;
    return mesh_;
  }
  return update(simulation.particles(), simulation.grid(), simulation.kernelRadius(),
                simulation.particleRadius(), headPositions);
}

const TearSurface& DropCaps::update(const ParticleSet& particles, const UniformGrid& grid, double h,
                                    double particleRadius, const Eigen::Matrix3Xf& headPositions) {
  mesh_.clear();
  caps_ = 0;
  skipped_.assign(particles.position.size(), 0);
  if (particles.empty()) return mesh_;
  if (headPositions.cols() <= skin_.maxVertex())
    throw std::invalid_argument("drop caps: fewer head positions than the skin uses");
  skin_.bind(headPositions);
  finder_.find(particles, grid);
  // Every drop touching the skin, with its volume and velocity; any size, since a large drop
  // ahead also means the small one behind runs on its track.
  onSkin_.clear();
  const auto all = finder_.drops();
  for (std::size_t d = 0; d < all.size(); ++d) {
    if (!gatherSeeds(particles, all[d])) continue;  // in the air or only on an eye: the mesher's
    SkinDrop drop;
    drop.index = static_cast<int>(d);
    for (int i : finder_.particlesOf(all[d]))
      drop.velocity += particles.velocity[static_cast<std::size_t>(i)];
    drop.velocity /= all[d].count;
    onSkin_.push_back(drop);
  }
  binDrops(h);
  for (const SkinDrop& drop : onSkin_) {
    const FoundDrop& found = all[static_cast<std::size_t>(drop.index)];
    if (found.count >= settings_.maxParticles) continue;
    const bool cap = leads(drop, h);
    if (cap && caps_ >= settings_.maxCaps) continue;  // over the bound: the mesher's
    for (int i : finder_.particlesOf(found)) skipped_[static_cast<std::size_t>(i)] = 1;
    if (!cap) continue;
    // The skin point under the drop only for the drops drawn: a walk over the skin each.
    gatherSeeds(particles, found);
    const SkinAnchor base = skin_.closest(found.centre, seeds_);
    if (base.triangle < 0) continue;
    const Eigen::Vector3d normal = skin_.normal(base.triangle);
    if (normal.isZero()) continue;  // a degenerate triangle has no side to sit on
    addCap(skin_.point(base), normal, found.count * parcelVolume(particleRadius));
  }
  skin_.unbind();
  return mesh_;
}

std::int64_t DropCaps::cellKey(const Eigen::Vector3d& x) const {
  // 21 bits an axis: two million cells of at least h (1.6 mm at the defaults) is 3 km. A
  // non-finite centre lands in some cell; nothing near it passes the distance tests.
  std::int64_t key = 0;
  for (int a = 0; a < 3; ++a) {
    double c = std::floor(x[a] / binSize_);
    c = std::isfinite(c) ? std::clamp(c, -1048575.0, 1048575.0) : 0.0;
    key = (key << 21) | ((static_cast<std::int64_t>(c) + 1048576) & 0x1fffff);
  }
  return key;
}

void DropCaps::binDrops(double h) {
  binSize_ = std::max(std::max(settings_.followDistance, settings_.trackWidth) * h, 1e-12);
  bins_.clear();
  for (std::size_t i = 0; i < onSkin_.size(); ++i)
    bins_.push_back({cellKey(finder_.drops()[static_cast<std::size_t>(onSkin_[i].index)].centre),
                     static_cast<int>(i)});
  std::sort(bins_.begin(), bins_.end());
}

// The skin triangles a drop's particles touch, into seeds_; false when none.
bool DropCaps::gatherSeeds(const ParticleSet& particles, const FoundDrop& drop) {
  skin_.contactSeeds(particles.contact, finder_.particlesOf(drop), seeds_);
  return !seeds_.empty();
}

// A sliding drop leads unless another drop on the skin lies ahead of it, within
// `followDistance` along its motion and `trackWidth` across it.
bool DropCaps::leads(const SkinDrop& drop, double h) const {
  const double speed = drop.velocity.norm();
  if (speed < settings_.minimumSpeed * h) return true;  // a drop at rest sits on its own
  const Eigen::Vector3d direction = drop.velocity / speed;
  const Eigen::Vector3d centre = finder_.drops()[static_cast<std::size_t>(drop.index)].centre;
  for (int dx = -1; dx <= 1; ++dx)
    for (int dy = -1; dy <= 1; ++dy)
      for (int dz = -1; dz <= 1; ++dz) {
        const std::int64_t cell = cellKey(centre + binSize_ * Eigen::Vector3d(dx, dy, dz));
        for (auto it = std::lower_bound(bins_.begin(), bins_.end(), Binned{cell, 0});
             it != bins_.end() && it->cell == cell; ++it) {
          const SkinDrop& other = onSkin_[static_cast<std::size_t>(it->drop)];
          if (other.index == drop.index) continue;
          const Eigen::Vector3d d =
              finder_.drops()[static_cast<std::size_t>(other.index)].centre - centre;
          const double along = d.dot(direction);
          if (along > 0 && along < settings_.followDistance * h &&
              (d - along * direction).norm() < settings_.trackWidth * h)
            return false;
        }
      }
  return true;
}

void DropCaps::addCap(const Eigen::Vector3d& base, const Eigen::Vector3d& n, double volume) {
  const double theta = settings_.contactAngleDegrees * std::numbers::pi / 180;
  const CapShape cap = sphericalCap(volume, theta);
  if (!(cap.contactRadius > 0) || !std::isfinite(cap.contactRadius)) return;
  const double R = cap.contactRadius / std::sin(theta);
  const Eigen::Vector3d centre =
      base + (cap.height - R + settings_.rimLift * cap.contactRadius) * n;
  // Any two directions across the normal.
  const Eigen::Vector3d helper =
      std::abs(n.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  const Eigen::Vector3d e1 = n.cross(helper).normalized(), e2 = n.cross(e1);

  const int rings = settings_.rings, segments = settings_.segments;
  const int top = mesh_.vertexCount();
  auto addVertex = [&](const Eigen::Vector3d& direction) {
    mesh_.position_.push_back(centre + R * direction);
    mesh_.normal_.push_back(direction);
  };
  addVertex(n);
  for (int k = 1; k <= rings; ++k) {
    const double phi = theta * k / rings;
    for (int j = 0; j < segments; ++j) {
      const double psi = 2 * std::numbers::pi * j / segments;
      addVertex(std::cos(phi) * n + std::sin(phi) * (std::cos(psi) * e1 + std::sin(psi) * e2));
    }
  }
  // Counter-clockwise seen from outside (along +n): e1, e2, n is right-handed.
  auto ring = [&](int k, int j) { return top + 1 + (k - 1) * segments + (j % segments); };
  for (int j = 0; j < segments; ++j) mesh_.triangle_.emplace_back(top, ring(1, j), ring(1, j + 1));
  for (int k = 1; k < rings; ++k)
    for (int j = 0; j < segments; ++j) {
      mesh_.triangle_.emplace_back(ring(k, j), ring(k + 1, j), ring(k + 1, j + 1));
      mesh_.triangle_.emplace_back(ring(k, j), ring(k + 1, j + 1), ring(k, j + 1));
    }
  ++caps_;
}

}  // namespace lacrima::tears
