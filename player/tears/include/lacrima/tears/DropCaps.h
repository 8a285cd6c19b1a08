#pragma once
// Small drops on the skin drawn as what they are: spherical caps sitting on it.
//
// A drop of a few SPH particles is water a millimetre or two across. Meshed from its particles'
// colour field (SurfaceMesher.h) it becomes a ball with a silhouette all round; a stream of such
// drops reads as glass beads on a string. Drops that small are shaped by surface tension alone
// (far below the capillary length), so each is drawn as the cap DropFootprint.h gives for its
// volume at the skin's contact angle: a lens, flat against the skin, steepest at its rim, with
// its highlight on top. Larger drops (and all drops in the air) are left to the mesher, which
// can show them hanging and stretching.
//
// Which drops get a cap. A stream of tears on the simulated skin is a chain of small drops
// running one behind the other (a few particles across cannot hold a continuous rivulet); drawn
// as caps they read as beads on a string. On a real tear track the water behind the front runs
// on the wet film the front left, and what the eye sees is a rivulet with a rounded bead at its
// head. So a small drop gets a cap when it LEADS: it is at rest (slower than `minimumSpeed`
// kernel radii per second), or no other drop on the skin lies ahead of it, within
// `followDistance` kernel radii along its velocity and `trackWidth` across. The drops that
// follow are skipped by the mesher too and drawn by the trails, whose film is as wide as each
// drop's footprint (TrailBuilder.h): the rivulet.
//
// For each drop (DropFinder.h) with fewer than `maxParticles` particles, at least one of them in
// contact with the skin, that leads:
//   volume V = particle count x parcelVolume (DropFootprint.h); cap radius a, height H, sphere
//   radius R = a / sin(theta) from DropFootprint.h;
//   base b = the skin point closest to the drop's mean position (TrailSkin.h, seeded with the
//   contact triangles), n = that triangle's outward normal;
//   sphere centre o = b + (H - R) n; vertices o + R (cos(phi) n + sin(phi) (cos(psi) e1 +
//   sin(psi) e2)) on `rings` rings phi = theta k / rings and `segments` angles psi, the normal
//   at each the sphere's, (x - o) / R. The rim is lifted off the skin by a small fraction of a
//   so a curved cheek does not cut it.
// Their particles are flagged (skipped()) for SurfaceMesher::update, so no water is drawn twice.
#include <lacrima/tears/DropFinder.h>
#include <lacrima/tears/SurfaceMesher.h>
#include <lacrima/tears/TrailSkin.h>

#include <Eigen/Core>

#include <cstdint>
#include <span>
#include <vector>

namespace lacrima::tears {

struct DropCapSettings {
  int maxParticles = 10;                       // drops this size and larger are meshed
  double contactAngleDegrees = 70;             // as TrailSettings::contactAngleDegrees
  double minimumSpeed = 1;                     // kernel radii per second; slower drops are at rest
  double followDistance = 10, trackWidth = 2;  // kernel radii
  int rings = 3, segments = 14;
  double rimLift = 0.04;  // of the contact radius
  // At most this many caps a frame (43 vertices each at the default rings and segments), so the
  // work and the mesh stay bounded when thousands of particles scatter as single drops; past it
  // the remaining small drops are left to the mesher, as larger drops are.
  int maxCaps = 1024;
};

class DropCaps {
 public:
  // `skinTriangles`: as TrailBuilder's, the skin's triangles in the simulation's order; contacts
  // past them (the eyes) are not skin and make no cap.
  explicit DropCaps(std::vector<Eigen::Vector3i> skinTriangles,
                    const DropCapSettings& settings = {});

  // The caps of the simulation's current particles on the skin at `headPositions`.
  const TearSurface& update(const TearSimulation& simulation,
                            const Eigen::Matrix3Xf& headPositions);
  const TearSurface& update(const ParticleSet& particles, const UniformGrid& grid, double h,
                            double particleRadius, const Eigen::Matrix3Xf& headPositions);

  const TearSurface& mesh() const { return mesh_; }
  // One flag per particle of the last update: 1 for those drawn as a cap.
  std::span<const std::uint8_t> skipped() const { return skipped_; }
  int capCount() const { return caps_; }
  const DropCapSettings& settings() const { return settings_; }

 private:
  struct SkinDrop {
    int index = 0;                                       // in the finder's drops
    Eigen::Vector3d velocity = Eigen::Vector3d::Zero();  // mean
  };
  bool gatherSeeds(const ParticleSet& particles, const FoundDrop& drop);
  // The drops on the skin binned by cells of edge followDistance x h, sorted by cell, so the
  // drops ahead of one are looked for in the 27 cells around it, not among all of them.
  struct Binned {
    std::int64_t cell = 0;
    int drop = 0;  // in onSkin_
    bool operator<(const Binned& o) const {
      return cell < o.cell || (cell == o.cell && drop < o.drop);
    }
  };
  std::int64_t cellKey(const Eigen::Vector3d& x) const;
  void binDrops(double h);
  bool leads(const SkinDrop& drop, double h) const;
  void addCap(const Eigen::Vector3d& base, const Eigen::Vector3d& normal, double volume);

  TrailSkin skin_;
  DropCapSettings settings_;
  DropFinder finder_;
  TearSurface mesh_;
  std::vector<std::uint8_t> skipped_;
  std::vector<int> seeds_;
  std::vector<SkinDrop> onSkin_;
  std::vector<Binned> bins_;
  double binSize_ = 1;
  int caps_ = 0;
};

}  // namespace lacrima::tears
