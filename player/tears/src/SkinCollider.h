#pragma once
// Collision of tear particles with the deforming skin, through ODE used for CONTACT QUERIES ONLY
// (no ODE bodies, no world step): the particles are integrated by the SPH solver, ODE finds which
// skin triangle a particle's sphere touches (dCollide sphere vs trimesh) or which triangle a
// moving particle's path crosses (dCollide ray vs trimesh).
//
// Why not ODE bodies (the 2009 design)? Measured on this machine class (docs/decisions/0001, 9k
// triangles, 2 sub-steps per frame, one core): ODE bodies cost 0.54 / 5.6 / 79 ms per frame for
// 100 / 1,000 / 10,000 particles in collision alone (+~40 ms solver at 10k), while contact-only
// queries with a cached contact triangle cost 0.02 / 0.18 / 1.7 ms; our own measurement
// (lacrima-bench tears, "collision" stage) agrees in magnitude. Bodies also cannot be carried by
// a moving skin (contact joints do not know the surface moves) and the 2009 system broke down
// at adhesion 100 because a large constant force fights ODE's penalty/LCP contact. Here adhesion
// is absorbed by a velocity constraint, so it needs no time-step limit at all.
//
// ODE is asked only when it could answer something: once a pose has had a thousand queries (a
// few thousand particles), a grid over its triangles (TriangleGrid.h) proves most sphere and
// ray queries of particles away from the skin empty without ODE, with the same arithmetic
// nearest() applies to ODE's list, so every answer is unchanged (fewer dCollide calls only).
//
// Contacts are tracked on their triangle by barycentric coordinates: while the particle's
// projection stays inside that triangle, no ODE call is made, and when it slides onto one of the
// triangles around it (sharing a vertex), that one is found from the mesh's adjacency, also
// without ODE (ODE answers only when the particle ends up over none of them). When the face deforms
// between frames, a tracked particle is carried with its triangle (same barycentric point, same
// height along the new normal); a free particle near the skin is anchored to the nearest point of
// the OLD surface, that anchor is moved with the surface, and a ray from the moved anchor to the
// particle finds any triangle that swept through it (the jaw snapping open in one frame), which
// then pushes the particle out along its normal. Free particles keep a conservative clearance
// (lower bound on their distance to the skin) and are only queried once it is used up.
//
// The skin is one-sided: outside is the side the counter-clockwise triangles face (HeadMesh's
// convention), which is also how ODE's sphere-trimesh test behaves.
#include "OdeHandles.h"
#include "SkinContact.h"
#include "TriangleGrid.h"

#include <lacrima/tears/ParticleSet.h>

#include <Eigen/Geometry>

#include <cstdint>
#include <span>
#include <vector>

namespace lacrima::tears {

struct CollisionCounters {
  long long odeQueries = 0;       // dCollide calls (sphere and ray)
  long long trimeshUpdates = 0;   // dGeomTriMeshDataUpdate calls
  long long sweptParticles = 0;   // free particles the moving skin swept through, pushed out
  long long contactsTracked = 0;  // contact tests answered from the cached triangle alone
  long long bruteForceQueries =
      0;  // nearest() answered by scanning every triangle (ODE's list was full)
};

struct SkinHit {
  int triangle = -1;
  Eigen::Vector3d point;  // closest point on the triangle
  Eigen::Vector3d barycentric;
  bool interior = false;
  double distance = 0;  // from the query point to `point`
};

class SkinCollider {
 public:
  // vertices: 3 x n in the head frame; triangles index them (counter-clockwise outside).
  // envelope: the largest region the skin can ever occupy (ODE keeps the geom's bounding box
  // from build time, so it is built with unreferenced vertices at the envelope's corners).
  SkinCollider(const Eigen::Matrix3Xd& vertices, std::vector<Eigen::Vector3i> triangles,
               const Eigen::AlignedBox3d& envelope, double particleRadius, double contactBand,
               double probeRadius);

  int triangleCount() const { return static_cast<int>(triangles_.size()); }
  const Eigen::Vector3d& faceNormal(int t) const { return normals_[static_cast<std::size_t>(t)]; }
  bool degenerate(int t) const { return degenerate_[static_cast<std::size_t>(t)] != 0; }
  const Eigen::Matrix3Xd& vertices() const { return vertices_; }
  SkinView view() const { return {faces_}; }

  // Moves the skin to `vertices`, carrying tracked particles and pushing out free particles the
  // skin swept through. Returns the largest vertex displacement.
  double moveSurface(const Eigen::Matrix3Xd& vertices, ParticleSet& particles,
                     CollisionCounters& counters);
  // Moves the skin without touching particles (first frame, or after the simulation was idle
  // and has no particles).
  void resetSurface(const Eigen::Matrix3Xd& vertices, CollisionCounters& counters);

  // After a sub-step moved the particles from `previous`: keeps every particle outside the skin,
  // updates contacts (triangle, barycentric) and clearances, zeroes velocity into the skin, and
  // adds the distance slid along the skin to `travelled`.
  void resolve(ParticleSet& particles, std::span<const Eigen::Vector3d> previous,
               CollisionCounters& counters);

  // The surface state (vertices, normals), for checkpoints: restoring it refits ODE's trimesh to
  // those vertices, which makes every later query answer exactly as it did after the save (the
  // mesh's bounding-volume tree has a fixed topology; a refit depends on the vertices alone).
  struct Surface {
    Eigen::Matrix3Xd vertices;
    std::vector<Eigen::Vector3d> normals;
    std::vector<std::uint8_t> degenerate;
  };
  Surface surface() const { return {vertices_, normals_, degenerate_}; }
  void restoreSurface(const Surface& surface, CollisionCounters& counters);

  // Nearest skin point within `radius` of x (front side only).
  bool nearest(const Eigen::Vector3d& x, double radius, SkinHit& hit, CollisionCounters& counters);

 private:
  void computeNormals(const Eigen::Matrix3Xd& v, std::vector<Eigen::Vector3d>& normals,
                      std::vector<std::uint8_t>& degenerate) const;
  void writeOdeVertices(const Eigen::Matrix3Xd& v, CollisionCounters& counters);
  // Rebuilds faces_ from vertices_, normals_ and degenerate_ (after every change of pose).
  void refreshFaces();
  // Takes triangle t as the hit if its closest point to x is within radius, in front, and nearer
  // than `hit` (when `found`); ties go to the lower index, so the answer is order-independent.
  bool consider(const Eigen::Vector3d& x, int t, double radius, SkinHit& hit, bool found) const;
  // Whether consider() accepts any triangle for x and radius: when not, a sphere query cannot
  // find anything and ODE is not asked (TriangleGrid.h has the argument).
  bool anyWithin(const Eigen::Vector3d& x, double radius) const;
  // Counts a query against the current pose; true once grid_ holds that pose (it is built
  // when the pose has had enough queries to pay for it).
  bool gridReady();
  // A contact for x among the triangles sharing a vertex with `from` (no ODE call): true when
  // the nearest of them within radius + band lies under x (interior), as after a slide onto a
  // neighbouring triangle.
  bool contactAround(const Eigen::Vector3d& x, int from, SkinHit& hit) const;
  bool rayFirstHit(const Eigen::Vector3d& from, const Eigen::Vector3d& to, SkinHit& hit,
                   CollisionCounters& counters);
  Eigen::Vector3d pointAt(int t, const Eigen::Vector3d& barycentric,
                          const Eigen::Matrix3Xd& v) const;
  void makeContact(int i, ParticleSet& particles, const SkinHit& hit);

  Eigen::Matrix3Xd vertices_;
  std::vector<Eigen::Vector3i> triangles_;
  std::vector<Eigen::Vector3d> normals_;
  std::vector<std::uint8_t> degenerate_;
  // The current pose, one packed record per triangle: what every per-sub-step test reads.
  std::vector<SkinFace> faces_;
  // Triangles sharing at least one vertex with each triangle, itself included, each listed
  // once (CSR): the candidates of a contact that slid off its triangle.
  std::vector<int> ringStart_, ringTriangles_;
  TriangleGrid grid_;  // of faces_, to skip ODE queries that cannot find a triangle
  bool gridBuilt_ = false;
  int queriesThisPose_ = 0;
  double radius_, band_, probe_, degenerateArea2_;

  // ODE keeps pointers into these two arrays: they are sized once and never reallocated.
  std::vector<double> odeVertices_;
  std::vector<dTriIndex> odeIndices_;
  OdeLibrary library_;
  OdeTriMeshData data_;
  OdeGeom mesh_, sphere_, ray_;
  std::vector<dContactGeom> contacts_;
};

}  // namespace lacrima::tears
