#pragma once
// Tear emission driven by the absolute particle counts of FAP 69 / 70 (thesis 5.2).
// A higher count spawns particles at the eye's source; a lower count removes that eye's oldest
// particles first (tears drying up, not the newest drop vanishing).
//
// New particles are placed on a cubic lattice at the rest spacing, nearest lattice points first,
// in the half-space in front of the skin at the source, skipping points already occupied: a
// burst of thousands starts as a block of fluid at rest density instead of thousands of
// coincident points (which would store enormous pressure energy). A tiny jitter derived from the
// particle id (never from time or a global random generator) breaks the lattice's symmetry
// identically on every run.
#include <lacrima/tears/Scratch.h>

#include <lacrima/tears/ParticleSet.h>

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace lacrima::tears {

// Where an eye's particles appear this frame.
struct EmissionSite {
  Eigen::Vector3d base;    // the first particle's position
  Eigen::Vector3d normal;  // skin normal at the source (unit), or zero when no skin is near
};

class Emitter {
 public:
  Emitter(double spacing, double mass) : spacing_(spacing), mass_(mass) {}

  // Removes the `count` oldest particles of `eye` (smallest ids). Returns how many were removed.
  int removeOldest(ParticleSet& particles, Eye eye, int count) const;
  // Appends `count` particles for `eye` at `site`.
  void spawn(ParticleSet& particles, Eye eye, int count, const EmissionSite& site);
  // Re-emits the particles in `slots` (escaped ones) as new particles of `eye` at `site`, in
  // place: no other particle changes index, so the solver's pair list stays usable (the moved
  // ones become strays, VerletPairs.h).
  void respawn(ParticleSet& particles, Eye eye, std::span<const int> slots,
               const EmissionSite& site);

  std::uint64_t nextId() const { return nextId_; }

 private:
  const std::vector<Eigen::Vector3d>& latticeWithin(double radius);
  // Where `count` new particles go and their ids, chosen against the particles as they are.
  struct Placement {
    Eigen::Vector3d position;
    std::uint64_t id;
  };
  std::vector<Placement> place(const ParticleSet& particles, int count, const EmissionSite& site);

  double spacing_, mass_;
  std::uint64_t nextId_ = 1;
  // Lattice offsets in units of spacing within `radius`, nearest first: a cache that a copy (a
  // checkpoint) does not take (Scratch.h). Any cached radius gives the same placements: the
  // order of the points is the same, a larger cache only spares a rescan.
  struct Lattice {
    std::vector<Eigen::Vector3d> offsets;
    double radius = 0;
  };
  Scratch<Lattice> lattice_;
};

}  // namespace lacrima::tears
