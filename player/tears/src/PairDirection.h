#pragma once
// A direction for two particles at the same position, where r_hat is undefined. Derived from
// the pair's ids only, and antisymmetric (swapping i and j flips it), so forces along it still
// cancel pairwise and every run separates the pair the same way.
#include <Eigen/Core>

#include <cstdint>

namespace lacrima::tears {

inline std::uint64_t mix64(std::uint64_t z) {
  z += 0x9E3779B97F4A7C15ull;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

// Uniform in [-1, 1) from 53 bits of a hash.
inline double unitFromHash(std::uint64_t z) {
  return static_cast<double>(z >> 11) * (2.0 / 9007199254740992.0) - 1.0;
}

inline Eigen::Vector3d pairDirection(std::uint64_t idI, std::uint64_t idJ) {
  const std::uint64_t lo = idI < idJ ? idI : idJ, hi = idI < idJ ? idJ : idI;
  const std::uint64_t seed = mix64(lo * 0x100000001B3ull ^ mix64(hi));
  Eigen::Vector3d d(unitFromHash(mix64(seed)), unitFromHash(mix64(seed + 1)),
                    unitFromHash(mix64(seed + 2)));
  if (d.squaredNorm() < 1e-12) d = Eigen::Vector3d::UnitY();
  d.normalize();
  return idI < idJ ? d : Eigen::Vector3d(-d);
}

}  // namespace lacrima::tears
