#include "DropDetachment_Tate1864.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace lacrima::tears {
namespace {

enum Role : std::uint8_t { kHeld = 0, kPendant = 1, kFree = 2 };

}  // namespace

bool DropDetachment_Tate1864::update(const ParticleSet& p, const ActivePairs& pairs,
                                     const SkinView& skin, const Eigen::Vector3d& g) {
  releasedCount_ = 0;
  spare_.clear();
  const auto n = static_cast<std::size_t>(p.size());
  role_.assign(n, kHeld);
  bool anyPendant = false;
  for (std::size_t s = 0; s < n; ++s) {
    const int t = p.contact[s].triangle;
    if (t < 0) {
      role_[s] = kFree;
    } else if (g.dot(skin.faces[static_cast<std::size_t>(t)].normal) > 0) {
      role_[s] = kPendant;
      anyPendant = true;
    }
  }
  if (!anyPendant) return false;

  // Components of pendant contacts and free particles, each root its lowest index.
  parent_.resize(n);
  for (std::size_t s = 0; s < n; ++s) parent_[s] = static_cast<int>(s);
  for (int i = 0; i < pairs.particleCount(); ++i) {
    if (role_[static_cast<std::size_t>(i)] == kHeld) continue;
    int a = root(i);  // stays the root of i's set: a link only ever lowers it
    for (std::uint32_t k = pairs.begin(static_cast<std::size_t>(i));
         k < pairs.end(static_cast<std::size_t>(i)); ++k) {
      const auto j = static_cast<std::size_t>(pairs.partner[k]);
      // Most partners hang right under i's root already (its last links): skip the walk. A
      // held particle is never linked (its parent is itself, above i), so this test comes first.
      if (parent_[j] == a || role_[j] == kHeld) continue;
      const int b = root(static_cast<int>(j));
      if (a < b) {
        parent_[static_cast<std::size_t>(b)] = a;
      } else if (b < a) {
        parent_[static_cast<std::size_t>(a)] = b;
        a = b;
      }
    }
  }

  mass_.assign(n, 0.0);
  contactMass_.assign(n, 0.0);
  area_.assign(n, 0.0);
  normal_.assign(n, Eigen::Vector3d::Zero());
  for (int i = 0; i < static_cast<int>(n); ++i) {
    const auto s = static_cast<std::size_t>(i);
    if (role_[s] == kHeld) continue;
    const auto r = static_cast<std::size_t>(root(i));
    mass_[r] += p.mass[s];
    if (role_[s] == kPendant) {
      contactMass_[r] += p.mass[s];
      area_[r] += 1;  // counts the contacts until the footprints are known
      normal_[r] += skin.faces[static_cast<std::size_t>(p.contact[s].triangle)].normal;
    }
  }
  // Tate: a drop lets go when its weight off the skin reaches 2 pi r gamma, r = sqrt(A / pi).
  // The share of the capacity in use is found at the root (which may be a free particle), then
  // handed to the contacts.
  usage_.assign(n, 0.0);
  for (std::size_t s = 0; s < n; ++s) {
    if (static_cast<std::size_t>(parent_[s]) != s || !(area_[s] > 0)) continue;
    // N contacts of the mean contact volume V each cover V^(2/3).
    const double side = std::cbrt(contactMass_[s] / (rho0_ * area_[s]));
    area_[s] *= side * side;
    const double weight = mass_[s] * g.dot(normal_[s].normalized());
    const double capacity = 2 * std::sqrt(std::numbers::pi * area_[s]) * gamma_;
    usage_[s] = capacity > 0 ? weight / capacity : 1.0;
  }
  spare_.assign(n, 1.0);
  for (int i = 0; i < static_cast<int>(n); ++i) {
    const auto s = static_cast<std::size_t>(i);
    if (role_[s] != kPendant) continue;
    spare_[s] = std::max(0.0, 1.0 - usage_[static_cast<std::size_t>(root(i))]);
    releasedCount_ += spare_[s] == 0;
  }
  return true;
}

}  // namespace lacrima::tears
