#pragma once
// Drops lose water to the trail they leave (thesis 4.3.2): a particle's mass decays with the
// distance it slid over the skin, m = m0 max(floor, exp(-s / length)); the floor keeps every
// particle's mass (and so density and every force that divides by it) positive.
#include <lacrima/tears/ParticleSet.h>

#include <vector>

namespace lacrima::tears {

class TrailMassLoss {
 public:
  TrailMassLoss(double referenceMass, double decayLength, double floorFraction)
      : m0_(referenceMass), length_(decayLength), floor_(floorFraction) {}
  // What one particle left in the trail: the volume (mass / rho0) and the eye it came from.
  struct Loss {
    Eye eye;
    double volume;
  };
  // Updates the masses of particles [begin, end) and appends their losses to `losses` in
  // particle order (the caller sums them in that order: the same bits whoever ran the range).
  void apply(ParticleSet& particles, double restDensity, std::size_t begin, std::size_t end,
             std::vector<Loss>& losses) const;
  double floorMass() const { return m0_ * floor_; }

 private:
  double m0_, length_, floor_;
};

}  // namespace lacrima::tears
