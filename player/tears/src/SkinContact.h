#pragma once
// External forces and the skin contact response (thesis ch. 4.2, Eq. 4.9, made stable).
//
// Gravity acts on every particle. A particle touching the skin (tracked on triangle t with unit
// outward normal n) also gets the adhesion force f = -alpha n_s / rho of the thesis, written
// as an acceleration relative to a fresh particle at rest density:
//   a_adh = -A (rho0 / rho_i) (m0 / m_i) n,     A = adhesion in head units / s^2,
// so thin (low-density) and trail-depleted (light) particles cling harder, as in 2009. Where
// the skin faces down, a drop heavier than its contact can hold lets go
// (DropDetachment_Tate1864.h): its contacts get no adhesion, and gravity pulls it off; a drop
// still held is pressed on by the share of adhesion its weight leaves spare.
//
// The contact is a velocity constraint, not a penalty spring: after the velocity update the
// normal component may not exceed the gap closing speed, v.n >= -gap / dt, so a particle never
// ends a step inside its triangle and adhesion of any strength injects no energy (it only
// presses the particle against the skin). This is why adhesion needs no time-step limit: the
// derivation for an explicit spring-like treatment would give dt < sqrt(band / A), 0.6 ms at
// adhesion 1000; the constraint removes it.
//
// Friction is viscous drag on the tangential velocity, proportional to the normal load per
// unit mass (the spare adhesion plus the pressing part of gravity and fluid forces), integrated
// implicitly so it can stop a particle but never reverse it, for any friction and dt:
//   v_t <- v_t / (1 + dt mu N / m)   with mu = friction / (0.3 m/s).

#include <lacrima/tears/ParticleSet.h>

#include <span>

namespace lacrima::tears {

// One skin triangle as every per-sub-step test reads it, made once per skin pose (the skin
// only moves between frames): the corners copied out of the vertex array, the two edges from
// a as closestPointOnTriangle computes them (b - a, c - a: the same bits), and the unit outward
// normal. A contact test reads one record instead of an index triple, three vertex columns
// and a normal from four arrays; the arithmetic done on it is unchanged, so results are
// bitwise identical to working from the vertices.
struct SkinFace {
  Eigen::Vector3d normal;  // unit, outward; zero when degenerate
  Eigen::Vector3d a;       // first corner: the plane's origin for gaps
  Eigen::Vector3d ab, ac;  // b - a, c - a
  Eigen::Vector3d b, c;
  bool degenerate = true;  // too little area for a normal: never holds a contact
};

// Read-only view of the skin's current geometry.
struct SkinView {
  std::span<const SkinFace> faces;
};

class SkinContactForces {
 public:
  SkinContactForces(double adhesion, double friction, double restDensity, double referenceMass,
                    double particleRadius)
      : adhesion_(adhesion),
        friction_(friction),
        rho0_(restDensity),
        m0_(referenceMass),
        radius_(particleRadius) {}

  // Adhesion acceleration magnitude for particle i (0 when not touching).
  double adhesionOf(const ParticleSet& particles, int i) const;

  // v += dt (a + g) for particles [begin, end) (a: the fluid forces of this sub-step). Both
  // passes work per particle, so the sub-step runs them on its chunks, fused with the other
  // per-particle work next to them (one shared loop instead of several).
  void applyExternal(ParticleSet& particles, const Eigen::Vector3d& gravity, double dt,
                     std::size_t begin, std::size_t end) const;

  // For particles touching the skin: adhesion (it needs the contact normal), then the normal
  // velocity constraint, then friction. `spare`: empty (all 1), or per particle the share of
  // its drop's holding capacity not in use (DropDetachment_Tate1864::spare()): 0 = the drop
  // let go, no adhesion; otherwise adhesion holds and that share of it loads friction.
  // Particles [begin, end).
  void constrain(ParticleSet& particles, const SkinView& skin, const Eigen::Vector3d& gravity,
                 double dt, std::span<const double> spare, std::size_t begin,
                 std::size_t end) const;

 private:
  void constrainOne(ParticleSet& particles, const SkinView& skin, const Eigen::Vector3d& gravity,
                    double dt, std::span<const double> spare, std::size_t s) const;

  double adhesion_, friction_, rho0_, m0_, radius_;
};

}  // namespace lacrima::tears
