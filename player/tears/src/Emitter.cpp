#include "Emitter.h"
#include "PairDirection.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace lacrima::tears {

int Emitter::removeOldest(ParticleSet& p, Eye eye, int count) const {
  if (count <= 0) return 0;
  std::vector<std::uint64_t> ids;
  for (int i = 0; i < p.size(); ++i)
    if (p.eye[static_cast<std::size_t>(i)] == eye) ids.push_back(p.id[static_cast<std::size_t>(i)]);
  count = std::min<int>(count, static_cast<int>(ids.size()));
  if (count == 0) return 0;
  std::nth_element(ids.begin(), ids.begin() + (count - 1), ids.end());
  const std::uint64_t newestRemoved = ids[static_cast<std::size_t>(count - 1)];
  std::vector<std::uint8_t> keep(static_cast<std::size_t>(p.size()), 1);
  for (int i = 0; i < p.size(); ++i) {
    const auto s = static_cast<std::size_t>(i);
    if (p.eye[s] == eye && p.id[s] <= newestRemoved) keep[s] = 0;
  }
  p.compact(keep);
  return count;
}

const std::vector<Eigen::Vector3d>& Emitter::latticeWithin(double radius) {
  Lattice& lattice = *lattice_;
  if (radius <= lattice.radius) return lattice.offsets;
  lattice.radius = std::max(radius, 2 * lattice.radius);
  const int n = static_cast<int>(std::ceil(lattice.radius));
  lattice.offsets.clear();
  for (int i = -n; i <= n; ++i)
    for (int j = -n; j <= n; ++j)
      for (int k = -n; k <= n; ++k)
        if (i * i + j * j + k * k <= lattice.radius * lattice.radius)
          lattice.offsets.emplace_back(i, j, k);
  // Nearest first; ties in a fixed lexicographic order, so the sequence is reproducible.
  std::sort(lattice.offsets.begin(), lattice.offsets.end(),
            [](const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
              const double na = a.squaredNorm(), nb = b.squaredNorm();
              if (na != nb) return na < nb;
              return std::lexicographical_compare(a.data(), a.data() + 3, b.data(), b.data() + 3);
            });
  return lattice.offsets;
}

std::vector<Emitter::Placement> Emitter::place(const ParticleSet& p, int count,
                                               const EmissionSite& site) {
  std::vector<Placement> placements;
  const bool halfSpace = site.normal.squaredNorm() > 0;
  // Lattice points needed if the source region were empty, plus room for what is already there.
  const double occupiedMinimum = 0.75 * spacing_;
  std::vector<Eigen::Vector3d> nearby;
  auto radiusFor = [&](std::size_t points) {
    return std::cbrt(3.0 * static_cast<double>(points) /
                     ((halfSpace ? 2.0 : 4.0) * std::numbers::pi)) +
           2.0;
  };
  double searchRadius = radiusFor(static_cast<std::size_t>(count));
  for (const auto& x : p.position)
    if ((x - site.base).norm() < (searchRadius + 1) * spacing_) nearby.push_back(x);
  searchRadius = radiusFor(static_cast<std::size_t>(count) + nearby.size());

  int placed = 0;
  while (placed < count) {
    const auto& offsets = latticeWithin(searchRadius);
    for (const Eigen::Vector3d& unit : offsets) {
      if (placed == count) break;
      const Eigen::Vector3d offset = unit * spacing_;
      if (halfSpace && offset.dot(site.normal) < -1e-9 * spacing_) continue;
      const Eigen::Vector3d x = site.base + offset;
      bool free = true;
      for (const auto& y : nearby)
        if ((x - y).squaredNorm() < occupiedMinimum * occupiedMinimum) {
          free = false;
          break;
        }
      if (!free) continue;
      const std::uint64_t id = nextId_++;
      const Eigen::Vector3d jitter(unitFromHash(mix64(3 * id)), unitFromHash(mix64(3 * id + 1)),
                                   unitFromHash(mix64(3 * id + 2)));
      placements.push_back({x + 0.02 * spacing_ * jitter, id});
      nearby.push_back(x);
      ++placed;
    }
    searchRadius *= 1.5;  // the region was crowded: look further out
  }
  return placements;
}

void Emitter::spawn(ParticleSet& p, Eye eye, int count, const EmissionSite& site) {
  if (count <= 0) return;
  for (const Placement& a : place(p, count, site)) p.add(a.position, mass_, a.id, eye);
}

void Emitter::respawn(ParticleSet& p, Eye eye, std::span<const int> slots,
                      const EmissionSite& site) {
  if (slots.empty()) return;
  const std::vector<Placement> placements = place(p, static_cast<int>(slots.size()), site);
  for (std::size_t k = 0; k < slots.size(); ++k)
    p.reset(slots[k], placements[k].position, mass_, placements[k].id, eye);
}

}  // namespace lacrima::tears
