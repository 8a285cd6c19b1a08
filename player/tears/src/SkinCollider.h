#pragma once
// Collision of tear particles with the deforming skin, by CONTACT QUERIES ONLY (no rigid bodies,
// no world step): the particles are integrated by the SPH solver, and the collider asks which
// skin triangle a particle's sphere touches or which triangle a moving particle's path crosses.
// Two methods answer (SkinQueryMethod): a uniform grid over the pose's triangles, the default,
// which any number of threads may ask at once; or ODE (dCollide sphere/ray vs trimesh), the
// reference the grid is tested against, which every query must ask under one process-wide lock
// (OdeSkinQueries.h), so collision with ODE runs on one thread.
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
// With the grid, a sphere query takes the nearest of every triangle the grid lists near the
// sphere (consider(), the same test applied to ODE's list), and a ray query the nearest front
// crossing among the triangles whose boxes meet the segment's (segmentEntersFace). With ODE,
// ODE is asked only when it could answer something: once a pose has had a thousand queries (a
// few thousand particles) the grid proves most queries of particles away from the skin empty
// without ODE, with the same arithmetic, so every answer is unchanged (fewer dCollide calls).
//
// Contacts are tracked on their triangle by barycentric coordinates: while the particle's
// projection stays inside that triangle, no query is made, and when it slides onto one of the
// triangles around it (sharing a vertex), that one is found from the mesh's adjacency, also
// without a query (one is made only when the particle ends up over none of them). When the face
// deforms between frames, a tracked particle is carried with its triangle (same barycentric point,
// same height along the new normal); a free particle near the skin is anchored to the nearest point
// of the OLD surface, that anchor is moved with the surface, and a ray from the moved anchor to the
// particle finds any triangle that swept through it (the jaw snapping open in one frame), which
// then pushes the particle out along its normal. Free particles keep a conservative clearance
// (lower bound on their distance to the skin) and are only queried once it is used up.
//
// The skin is one-sided: outside is the side the counter-clockwise triangles face (HeadMesh's
// convention), which is also how ODE's sphere-trimesh test behaves.
#include "ParallelChunks.h"
#include "SkinContact.h"
#include "TriangleGrid.h"

#include <lacrima/tears/ParticleSet.h>
#include <lacrima/tears/SimulationOptions.h>

#include <Eigen/Geometry>

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

namespace lacrima::tears {

class OdeSkinQueries;

struct CollisionCounters {
  long long gridQueries = 0;      // sphere and ray queries answered by the grid alone
  long long odeQueries = 0;       // dCollide calls (sphere and ray)
  long long trimeshUpdates = 0;   // dGeomTriMeshDataUpdate calls
  long long sweptParticles = 0;   // free particles the moving skin swept through, pushed out
  long long contactsTracked = 0;  // contact tests answered from the cached triangle alone
  long long bruteForceQueries =
      0;  // nearest() answered by scanning every triangle (ODE's list was full)

  CollisionCounters& operator+=(const CollisionCounters& c) {
    gridQueries += c.gridQueries;
    odeQueries += c.odeQueries;
    trimeshUpdates += c.trimeshUpdates;
    sweptParticles += c.sweptParticles;
    contactsTracked += c.contactsTracked;
    bruteForceQueries += c.bruteForceQueries;
    return *this;
  }
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
  // envelope: the largest region the skin can ever occupy (OdeSkinQueries.h; ODE only).
  SkinCollider(const Eigen::Matrix3Xd& vertices, std::vector<Eigen::Vector3i> triangles,
               const Eigen::AlignedBox3d& envelope, double particleRadius, double contactBand,
               double probeRadius, SkinQueryMethod method = SkinQueryMethod::Grid);
  ~SkinCollider();

  int triangleCount() const { return static_cast<int>(triangles_.size()); }
  const Eigen::Vector3d& faceNormal(int t) const { return normals_[static_cast<std::size_t>(t)]; }
  bool degenerate(int t) const { return degenerate_[static_cast<std::size_t>(t)] != 0; }
  const Eigen::Matrix3Xd& vertices() const { return vertices_; }
  SkinView view() const { return {faces_}; }

  // Moves the skin to `vertices`, carrying tracked particles and pushing out free particles the
  // skin swept through. Returns the largest vertex displacement. The per-particle work is
  // shared in `parallel`'s fixed chunks when the grid answers the queries (ODE's cannot be).
  double moveSurface(const Eigen::Matrix3Xd& vertices, ParticleSet& particles,
                     CollisionCounters& counters, ParallelChunks& parallel);
  // Moves the skin without touching particles (first frame, or after the simulation was idle
  // and has no particles).
  void resetSurface(const Eigen::Matrix3Xd& vertices, CollisionCounters& counters);

  // After a sub-step moved the particles from `previous`: keeps every particle outside the skin,
  // updates contacts (triangle, barycentric) and clearances, zeroes velocity into the skin, and
  // adds the distance slid along the skin to `travelled`. Each particle's answer depends on
  // that particle alone, so sharing the chunks between threads changes no bit.
  void resolve(ParticleSet& particles, std::span<const Eigen::Vector3d> previous,
               CollisionCounters& counters, ParallelChunks& parallel);

  // The surface state (vertices, normals), for checkpoints: restoring it rebuilds the grid from
  // (or refits ODE's trimesh to) those vertices, which makes every later query answer exactly
  // as it did after the save (both depend on the vertices alone).
  struct Surface {
    Eigen::Matrix3Xd vertices;
    std::vector<Eigen::Vector3d> normals;
    std::vector<std::uint8_t> degenerate;
  };
  Surface surface() const { return {vertices_, normals_, degenerate_}; }
  void restoreSurface(const Surface& surface, CollisionCounters& counters);

  // Nearest skin point within `radius` of x (front side only). Builds the grid if the pose has
  // none yet, so it may be called from several threads only once shareQueries() ran.
  bool nearest(const Eigen::Vector3d& x, double radius, SkinHit& hit, CollisionCounters& counters);

 private:
  void computeNormals(const Eigen::Matrix3Xd& v, std::vector<Eigen::Vector3d>& normals,
                      std::vector<std::uint8_t>& degenerate) const;
  void writeOdeVertices(const Eigen::Matrix3Xd& v, CollisionCounters& counters);
  // Whether this pass's per-particle loop may be shared: only with the grid, which it builds
  // first so that the threads only read it.
  bool shareQueries(const ParallelChunks& parallel);
  // Calls body(chunk, begin, end) over [0, count): in `parallel`'s fixed chunks, on its threads,
  // when shareQueries() allows, else as one range on this thread (each item's answer is the
  // same either way); then adds the chunks' counters to `counters`.
  template <class Body>
  void forEachParticleChunk(ParallelChunks& parallel, std::size_t count, Body&& body,
                            CollisionCounters& counters) {
    if (count == 0) return;
    const bool shared = shareQueries(parallel);
    const std::size_t chunks =
        shared ? ParallelChunks::chunkCount(count, parallel.particleChunk()) : 1;
    chunkCounters_.assign(chunks, {});
    if (shared)
      parallel.forEachChunk(count, parallel.particleChunk(), body);
    else
      body(0, 0, count);
    for (const CollisionCounters& c : chunkCounters_) counters += c;
  }
  void resolveRange(ParticleSet& particles, std::span<const Eigen::Vector3d> previous,
                    std::size_t begin, std::size_t end, CollisionCounters& counters);
  // The grid's answers (TriangleGrid.h): every candidate near the sphere, every crossing of the
  // segment; the nearest wins, ties to the lower triangle index.
  bool nearestOnGrid(const Eigen::Vector3d& x, double radius, SkinHit& hit);
  bool rayOnGrid(const Eigen::Vector3d& from, const Eigen::Vector3d& to, SkinHit& hit);
  void buildGrid();
  // Rebuilds faces_ from vertices_, normals_ and degenerate_ (after every change of pose).
  void refreshFaces();
  // Takes triangle t as the hit if its closest point to x is within radius, in front, and nearer
  // than `hit` (when `found`); ties go to the lower index, so the answer is order-independent.
  bool consider(const Eigen::Vector3d& x, int t, double radius, SkinHit& hit, bool found) const;
  // Whether consider() accepts any triangle for x and radius: when not, a sphere query cannot
  // find anything and ODE is not asked (TriangleGrid.h has the argument).
  bool anyWithin(const Eigen::Vector3d& x, double radius) const;
  // ODE only: counts a query against the current pose; true once grid_ holds that pose (it is
  // built when the pose has had enough queries to pay for it).
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
  TriangleGrid grid_;  // of faces_: the answers, or (ODE) the queries that cannot find one
  bool gridBuilt_ = false;
  int queriesThisPose_ = 0;
  double radius_, band_, probe_, degenerateArea2_;

  std::unique_ptr<OdeSkinQueries> ode_;  // SkinQueryMethod::Ode only
  // Per-chunk scratch of the shared passes: counters, and moveSurface's anchors.
  std::vector<CollisionCounters> chunkCounters_;
  struct Anchor {
    int particle;
    Eigen::Vector3d from;
  };
  std::vector<std::vector<Anchor>> chunkAnchors_;
  std::vector<Anchor> anchors_;
};

}  // namespace lacrima::tears
