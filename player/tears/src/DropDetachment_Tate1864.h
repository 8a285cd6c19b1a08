#pragma once
// Pendant drops: where the skin faces away from gravity (under the jaw, the chin, the nose
// tip), water hangs from its contact with the skin, and the contact can carry only so much.
// Tate's law (T. Tate 1864, "On the magnitude of a drop of liquid formed under different
// circumstances") gives the weight a drop hanging from a contact of radius r can have before
// it falls:
//   m g = 2 pi r gamma.
// The holding force grows with the contact line (its length 2 pi r), the weight with the
// volume, so a small drop hangs and a large one falls. Per-particle adhesion cannot express
// this: every touching particle is held at ~2 g however much water hangs from it, so a film
// under the chin clung there forever.
//
// Each sub-step:
//  * pendant contacts are touching particles whose triangle faces down, g . n > 0;
//  * a pendant drop is a connected component, through this sub-step's pairs within h, of
//    pendant contacts and free particles (contacts on skin that does not face down hold by
//    their own adhesion and are not part of it);
//  * its weight pulling it off the skin is W = M g . n_bar, M the drop's mass and n_bar the
//    mean normal of its pendant contacts;
//  * its contact is a disc of the area A of its contacts' footprints: N contacts of mean
//    volume V = sum m_k / (rho0 N), each covering the cross-section V^(2/3) (a monolayer of
//    those particles at rest spacing), so r = sqrt(A / pi) and it holds F = 2 pi r gamma;
//  * when W >= F the drop lets go: its contacts get no adhesion (SkinContact.h), and gravity
//    pulls it off the skin as a whole. A drop under its capacity keeps the adhesion of the
//    2009 model, so it hangs and grows as more water arrives;
//  * the capacity a drop uses to carry its weight does not press it onto the skin: friction
//    (SkinContact.h) sees the adhesion scaled by the spare share 1 - W / F. A small drop
//    sticks where it is; one near its limit slides down the overhang to the lowest point,
//    where the water gathers (on the chin it would otherwise stall in puddles too small to
//    fall, each pressed on by the full adhesion). Where the skin is vertical W = 0 and the
//    share is 1, so friction does not jump where a drop crosses onto the overhang.
// No state is carried between sub-steps: a drop that let go stays let go while it still
// touches, because losing contacts only lowers F while W stays. What is left on the skin after
// the drop fell hangs again when its own weight is under its capacity (the residue of a real
// pendant drop).
//
// gamma is an effective holding tension (TearSettings.h): the SPH film under the chin is one or
// two particles thick, so its contact patch is several times wider than the neck a real drop
// hangs from, and gamma is scaled so drops let go at the 20-30 uL water drops on skin hold
// (docs/tears.md, "Drops that fall").
//
// Deterministic: components are joined towards the lower particle index, and every sum runs in
// particle order.
#include "ActivePairs.h"
#include "SkinContact.h"

#include <lacrima/tears/ParticleSet.h>

#include <cstdint>
#include <span>
#include <vector>

namespace lacrima::tears {

class DropDetachment_Tate1864 {
 public:
  // holdingTension: gamma / rho0 in head units^3 / s^2.
  DropDetachment_Tate1864(double holdingTension, double restDensity)
      : gamma_(holdingTension), rho0_(restDensity) {}

  // Weighs every pendant drop; afterwards spare() tells each contact its drop's verdict.
  // Returns whether any contact faced down (false: nothing was weighed, at the cost of one
  // scan).
  bool update(const ParticleSet& particles, const ActivePairs& pairs, const SkinView& skin,
              const Eigen::Vector3d& gravity);

  // Per particle, the share of its drop's holding capacity not in use, 1 - W / F in [0, 1]:
  // 1 for particles in no pendant drop, 0 where the drop let go. Empty when update() found no
  // contact facing down.
  std::span<const double> spare() const { return spare_; }
  int releasedCount() const { return releasedCount_; }  // contacts whose drop let go

 private:
  // The root of i's set, halving the path on the way (the root does not depend on the path).
  int root(int i) {
    while (parent_[static_cast<std::size_t>(i)] != i) {
      const auto s = static_cast<std::size_t>(i);
      parent_[s] = parent_[static_cast<std::size_t>(parent_[s])];
      i = parent_[s];
    }
    return i;
  }

  double gamma_, rho0_;
  // Scratch, sized per call: role of each particle, union-find parents, per-root sums.
  std::vector<std::uint8_t> role_;
  std::vector<int> parent_;
  std::vector<double> mass_, contactMass_, area_, usage_;  // per root; usage W / F
  std::vector<Eigen::Vector3d> normal_;
  std::vector<double> spare_;  // per particle
  int releasedCount_ = 0;
};

}  // namespace lacrima::tears
