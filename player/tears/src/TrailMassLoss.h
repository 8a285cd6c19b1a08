#pragma once
// Drops lose water to the trail they leave (thesis 4.3.2): a particle's mass decays with the
// distance it slid over the skin, m = m0 max(floor, exp(-s / length)); the floor keeps every
// particle's mass (and so density and every force that divides by it) positive.
#include <lacrima/tears/ParticleSet.h>

namespace lacrima::tears {

class TrailMassLoss {
 public:
  TrailMassLoss(double referenceMass, double decayLength, double floorFraction)
      : m0_(referenceMass), length_(decayLength), floor_(floorFraction) {}
  // Updates masses; returns the volume (mass / rho0) left in the trail per eye this call.
  void apply(ParticleSet& particles, double restDensity, double lostVolume[2]) const;
  double floorMass() const { return m0_ * floor_; }

 private:
  double m0_, length_, floor_;
};

}  // namespace lacrima::tears
