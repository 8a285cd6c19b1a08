#include "SkinCollider.h"
#include "OdeSkinQueries.h"
#include "TriangleGeometry.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace lacrima::tears {
namespace {

// ODE: a full contact list makes nearest() narrow the sphere, kShrinkAttempts times at most,
// before scanning every triangle.
constexpr int kShrinkAttempts = 4;
// ODE queries a skin pose answers before the collider builds its grid to skip empty ones.
constexpr int kQueriesBeforeGrid = 1024;

}  // namespace

SkinCollider::SkinCollider(const Eigen::Matrix3Xd& vertices, std::vector<Eigen::Vector3i> triangles,
                           const Eigen::AlignedBox3d& envelope, double particleRadius,
                           double contactBand, double probeRadius, SkinQueryMethod method)
    : vertices_(vertices),
      triangles_(std::move(triangles)),
      radius_(particleRadius),
      band_(contactBand),
      probe_(probeRadius) {
  const auto n = static_cast<std::size_t>(vertices.cols());
  for (const auto& t : triangles_)
    if (t.minCoeff() < 0 || static_cast<std::size_t>(t.maxCoeff()) >= n)
      throw std::invalid_argument("skin triangle refers to a missing vertex");
  // A triangle whose area is below (1e-6 particle radius)^2 has no usable normal; such
  // triangles (collapsed by a pose, or modelled) never hold a contact.
  degenerateArea2_ = std::pow(1e-6 * radius_, 4);
  computeNormals(vertices_, normals_, degenerate_);
  refreshFaces();
  // Triangles around each vertex (CSR), then around each triangle without repeats: a
  // neighbour across an edge shares two vertices and the triangle itself three, so walking
  // the three vertex lists would test them twice and three times (18 tests for 13 triangles
  // on a regular mesh). The nearest of a set does not depend on its order or repeats
  // (consider() breaks ties by index), so the contact found is the same.
  std::vector<int> vertexStart(n + 1, 0);
  for (const auto& t : triangles_)
    for (int k = 0; k < 3; ++k) ++vertexStart[static_cast<std::size_t>(t[k]) + 1];
  for (std::size_t v = 0; v < n; ++v) vertexStart[v + 1] += vertexStart[v];
  std::vector<int> vertexTriangles(static_cast<std::size_t>(vertexStart[n]));
  std::vector<int> fill(vertexStart.begin(), vertexStart.end() - 1);
  for (std::size_t t = 0; t < triangles_.size(); ++t)
    for (int k = 0; k < 3; ++k)
      vertexTriangles[static_cast<std::size_t>(
          fill[static_cast<std::size_t>(triangles_[t][k])]++)] = static_cast<int>(t);
  ringStart_.assign(triangles_.size() + 1, 0);
  ringTriangles_.reserve(vertexTriangles.size() * 3);
  std::vector<int> ring;
  for (std::size_t t = 0; t < triangles_.size(); ++t) {
    ring.clear();
    for (int k = 0; k < 3; ++k) {
      const auto v = static_cast<std::size_t>(triangles_[t][k]);
      ring.insert(ring.end(), vertexTriangles.begin() + vertexStart[v],
                  vertexTriangles.begin() + vertexStart[v + 1]);
    }
    std::sort(ring.begin(), ring.end());
    ring.erase(std::unique(ring.begin(), ring.end()), ring.end());
    ringTriangles_.insert(ringTriangles_.end(), ring.begin(), ring.end());
    ringStart_[t + 1] = static_cast<int>(ringTriangles_.size());
  }
  if (method == SkinQueryMethod::Ode)
    ode_ = std::make_unique<OdeSkinQueries>(vertices_, triangles_, envelope);
}

SkinCollider::~SkinCollider() = default;

void SkinCollider::computeNormals(const Eigen::Matrix3Xd& v, std::vector<Eigen::Vector3d>& normals,
                                  std::vector<std::uint8_t>& degenerate) const {
  normals.resize(triangles_.size());
  degenerate.resize(triangles_.size());
  for (std::size_t t = 0; t < triangles_.size(); ++t) {
    const auto& tri = triangles_[t];
    const Eigen::Vector3d cross =
        (v.col(tri[1]) - v.col(tri[0])).cross(v.col(tri[2]) - v.col(tri[0]));
    const double area2 = cross.squaredNorm();
    degenerate[t] = !(area2 > degenerateArea2_);  // NaN counts as degenerate
    normals[t] =
        degenerate[t] ? Eigen::Vector3d::Zero() : Eigen::Vector3d(cross / std::sqrt(area2));
  }
}

void SkinCollider::refreshFaces() {
  faces_.resize(triangles_.size());
  for (std::size_t t = 0; t < triangles_.size(); ++t) {
    const auto& tri = triangles_[t];
    faces_[t] = makeSkinFace(vertices_.col(tri[0]), vertices_.col(tri[1]), vertices_.col(tri[2]),
                             normals_[t], degenerate_[t] != 0);
  }
  gridBuilt_ = false;  // built on demand, for this pose
  queriesThisPose_ = 0;
}

void SkinCollider::buildGrid() {
  // Cells about one free particle's query across (or a triangle, if larger).
  grid_.build(faces_, radius_ + probe_);
  gridBuilt_ = true;
}

bool SkinCollider::gridReady() {
  if (gridBuilt_) return true;
  // A grid costs about as much as a thousand ODE queries to build: only worth it for a pose
  // that sees many (thousands of particles), not for a drop or two on a moving face.
  if (++queriesThisPose_ <= kQueriesBeforeGrid) return false;
  buildGrid();
  return true;
}

bool SkinCollider::shareQueries(const ParallelChunks& parallel) {
  if (ode_ || !parallel.shared()) return false;
  if (!gridBuilt_) buildGrid();
  return true;
}

void SkinCollider::writeOdeVertices(const Eigen::Matrix3Xd& v, CollisionCounters& counters) {
  if (!ode_) return;  // the grid is rebuilt from faces_ on demand
  ode_->update(v);
  ++counters.trimeshUpdates;
}

void SkinCollider::resetSurface(const Eigen::Matrix3Xd& v, CollisionCounters& counters) {
  vertices_ = v;
  computeNormals(vertices_, normals_, degenerate_);
  refreshFaces();
  writeOdeVertices(vertices_, counters);
}

void SkinCollider::restoreSurface(const Surface& surface, CollisionCounters& counters) {
  if (surface.vertices.cols() != vertices_.cols() || surface.normals.size() != triangles_.size())
    throw std::invalid_argument("the saved skin does not match this collider");
  vertices_ = surface.vertices;
  normals_ = surface.normals;
  degenerate_ = surface.degenerate;
  refreshFaces();
  writeOdeVertices(vertices_, counters);
}

Eigen::Vector3d SkinCollider::pointAt(int t, const Eigen::Vector3d& b,
                                      const Eigen::Matrix3Xd& v) const {
  const auto& tri = triangles_[static_cast<std::size_t>(t)];
  return b[0] * v.col(tri[0]) + b[1] * v.col(tri[1]) + b[2] * v.col(tri[2]);
}

bool SkinCollider::consider(const Eigen::Vector3d& x, int t, double radius, SkinHit& hit,
                            bool found) const {
  if (t < 0 || t >= triangleCount()) return false;
  const SkinFace& face = faces_[static_cast<std::size_t>(t)];
  if (face.degenerate) return false;
  const TrianglePoint cp = closestPointOnFace(x, face);
  if ((x - cp.point).dot(face.normal) < 0) return false;  // behind: not ours
  const double distance = (x - cp.point).norm();
  if (!(distance <= radius)) return false;
  if (found && !(distance < hit.distance || (distance == hit.distance && t < hit.triangle)))
    return false;
  hit = {t, cp.point, cp.barycentric, cp.interior, distance};
  return true;
}

bool SkinCollider::anyWithin(const Eigen::Vector3d& x, double radius) const {
  SkinHit scratch;
  return grid_.anyNear(x, radius, [&](int t) { return consider(x, t, radius, scratch, false); });
}

bool SkinCollider::contactAround(const Eigen::Vector3d& x, int from, SkinHit& hit) const {
  bool found = false;
  const auto f = static_cast<std::size_t>(from);
  for (int a = ringStart_[f]; a < ringStart_[f + 1]; ++a)
    if (consider(x, ringTriangles_[static_cast<std::size_t>(a)], radius_ + band_, hit, found))
      found = true;
  // Over a face, not at a rim of the ring: a contact as good as the global search's. At an edge
  // or vertex of the ring, a triangle further out might be closer: leave it to ODE.
  return found && hit.interior;
}

bool SkinCollider::nearestOnGrid(const Eigen::Vector3d& x, double radius, SkinHit& hit) {
  if (!gridBuilt_) buildGrid();
  bool found = false;
  grid_.anyNear(x, radius, [&](int t) {
    if (consider(x, t, radius, hit, found)) found = true;
    return false;  // every candidate: the nearest wins
  });
  return found;
}

bool SkinCollider::rayOnGrid(const Eigen::Vector3d& from, const Eigen::Vector3d& to, SkinHit& hit) {
  if (!gridBuilt_) buildGrid();
  const Eigen::Vector3d d = to - from;
  const double length = d.norm();
  if (!(length > 0)) return false;
  const Eigen::Vector3d dir = d / length;
  int best = -1;
  double bestDistance = 0;
  grid_.any(from.cwiseMin(to), from.cwiseMax(to), [&](int t) {
    const double distance =
        segmentEntersFace(from, dir, length, faces_[static_cast<std::size_t>(t)]);
    if (distance >= 0 &&
        (best < 0 || distance < bestDistance || (distance == bestDistance && t < best))) {
      best = t;
      bestDistance = distance;
    }
    return false;
  });
  if (best < 0) return false;
  const TrianglePoint cp =
      closestPointOnFace(from + bestDistance * dir, faces_[static_cast<std::size_t>(best)]);
  hit = {best, cp.point, cp.barycentric, cp.interior, bestDistance};
  return true;
}

bool SkinCollider::nearest(const Eigen::Vector3d& x, double radius, SkinHit& hit,
                           CollisionCounters& counters) {
  if (!ode_) {
    ++counters.gridQueries;
    return nearestOnGrid(x, radius, hit);
  }
  // Nothing consider() accepts within the radius: ODE's list could not hold one either.
  if (gridReady() && !anyWithin(x, radius)) return false;
  bool found = false;
  double r = radius;
  for (int attempt = 0; attempt < kShrinkAttempts; ++attempt) {
    ++counters.odeQueries;
    bool complete = false;
    for (int t : ode_->sphere(x, r, complete))
      if (consider(x, t, radius, hit, found)) found = true;
    if (complete) return found;  // every triangle reaching into the sphere was listed
    // Saturated: ODE stops at the buffer's size, listing triangles in its tree's order, not by
    // distance, so a closer one may be missing. Anything closer than the best so far lies in
    // the sphere of that radius: ask again with it.
    if (!found || !(hit.distance < r)) break;
    r = hit.distance;
  }
  // Still saturated (a very dense patch of mesh): scan every triangle. Counted; rare.
  ++counters.bruteForceQueries;
  for (int t = 0; t < triangleCount(); ++t)
    if (consider(x, t, radius, hit, found)) found = true;
  return found;
}

bool SkinCollider::rayFirstHit(const Eigen::Vector3d& from, const Eigen::Vector3d& to, SkinHit& hit,
                               CollisionCounters& counters) {
  if (!ode_) {
    ++counters.gridQueries;
    return rayOnGrid(from, to, hit);
  }
  const Eigen::Vector3d d = to - from;
  const double length = d.norm();
  if (!(length > 0)) return false;
  // No triangle's box meets the segment's: no crossing for ODE to find.
  if (gridReady() && !grid_.any(from.cwiseMin(to), from.cwiseMax(to), [](int) { return true; }))
    return false;
  const Eigen::Vector3d dir = d / length;
  ++counters.odeQueries;
  int t = -1;
  Eigen::Vector3d p;
  double depth = 0;
  if (!ode_->ray(from, dir, length, t, p, depth)) return false;
  if (t < 0 || t >= triangleCount()) return false;
  const SkinFace& face = faces_[static_cast<std::size_t>(t)];
  if (face.degenerate) return false;
  if (dir.dot(face.normal) >= 0) return false;  // leaving, not entering
  const TrianglePoint cp = closestPointOnFace(p, face);
  hit = {t, cp.point, cp.barycentric, cp.interior, depth};
  return true;
}

void SkinCollider::makeContact(int i, ParticleSet& p, const SkinHit& hit) {
  const auto s = static_cast<std::size_t>(i);
  const Eigen::Vector3d n = faces_[static_cast<std::size_t>(hit.triangle)].normal;
  // Push out along the face normal inside the face; at an edge or vertex, away from it.
  const Eigen::Vector3d offset = p.position[s] - hit.point;
  const double along = offset.dot(n);
  Eigen::Vector3d outward = n;
  if (!hit.interior && offset.norm() > 1e-9 * radius_) outward = offset.normalized();
  const double height = hit.interior ? along : offset.norm();
  if (height < radius_) p.position[s] += (radius_ - height) * outward;
  const double vn = p.velocity[s].dot(n);
  if (vn < 0) p.velocity[s] -= vn * n;  // inelastic: liquid does not bounce off skin
  p.contact[s] = {hit.triangle, hit.barycentric};
  p.clearance[s] = 0;
}

double SkinCollider::moveSurface(const Eigen::Matrix3Xd& next, ParticleSet& p,
                                 CollisionCounters& counters, ParallelChunks& parallel) {
  double maxDisplacement = 0;
  for (Eigen::Index c = 0; c < next.cols(); ++c)
    maxDisplacement = std::max(maxDisplacement, (next.col(c) - vertices_.col(c)).norm());
  if (!std::isfinite(maxDisplacement)) throw std::invalid_argument("skin positions are not finite");
  if (maxDisplacement == 0) return 0;  // nothing moved: no refit, no carrying

  std::vector<Eigen::Vector3d> nextNormals;
  std::vector<std::uint8_t> nextDegenerate;
  computeNormals(next, nextNormals, nextDegenerate);

  // Free particles the skin could reach this frame: anchor them on the OLD surface (the grid
  // or ODE still holds it), to cast their rays once the new one is in place. Each chunk lists
  // its anchors in particle order, and the lists are joined in chunk order: the anchors are in
  // particle order whatever the threads.
  const bool sweeping = maxDisplacement > 0.25 * radius_;
  chunkAnchors_.resize(
      ParallelChunks::chunkCount(static_cast<std::size_t>(p.size()), parallel.particleChunk()));
  for (auto& anchors : chunkAnchors_) anchors.clear();
  const auto carry = [&](int chunk, std::size_t begin, std::size_t end) {
    std::vector<Anchor>& anchors = chunkAnchors_[static_cast<std::size_t>(chunk)];
    CollisionCounters& chunkCounters = chunkCounters_[static_cast<std::size_t>(chunk)];
    for (std::size_t s = begin; s < end; ++s) {
      const int t = p.contact[s].triangle;
      if (t >= 0) {
        const auto st = static_cast<std::size_t>(t);
        if (nextDegenerate[st]) {
          p.contact[s].triangle = -1;
          p.clearance[s] = 0;
          continue;
        }
        // Carried: same barycentric point, same height along the (rotated) normal.
        const Eigen::Vector3d q0 = pointAt(t, p.contact[s].barycentric, vertices_);
        const Eigen::Vector3d o = p.position[s] - q0;
        const double height = o.dot(normals_[st]);
        p.position[s] = pointAt(t, p.contact[s].barycentric, next) + (o - height * normals_[st]) +
                        height * nextNormals[st];
        continue;
      }
      if (sweeping && p.clearance[s] < maxDisplacement) {
        SkinHit hit;
        if (nearest(p.position[s], radius_ + maxDisplacement + radius_, hit, chunkCounters)) {
          const auto st = static_cast<std::size_t>(hit.triangle);
          if (!nextDegenerate[st]) {
            const Eigen::Vector3d o = p.position[s] - hit.point;
            const double height = o.dot(normals_[st]);
            const Eigen::Vector3d from = pointAt(hit.triangle, hit.barycentric, next) +
                                         (o - height * normals_[st]) + height * nextNormals[st];
            anchors.push_back({static_cast<int>(s), from});
          }
        }
      }
      p.clearance[s] = std::max(0.0, p.clearance[s] - maxDisplacement);
    }
  };
  forEachParticleChunk(parallel, static_cast<std::size_t>(p.size()), carry, counters);
  anchors_.clear();
  for (const auto& anchors : chunkAnchors_)
    anchors_.insert(anchors_.end(), anchors.begin(), anchors.end());

  vertices_ = next;
  normals_ = std::move(nextNormals);
  degenerate_ = std::move(nextDegenerate);
  refreshFaces();
  writeOdeVertices(vertices_, counters);

  const auto push = [&](int chunk, std::size_t begin, std::size_t end) {
    CollisionCounters& chunkCounters = chunkCounters_[static_cast<std::size_t>(chunk)];
    for (std::size_t a = begin; a < end; ++a) {
      const Anchor& anchor = anchors_[a];
      const auto s = static_cast<std::size_t>(anchor.particle);
      // The anchor moved with the skin; if the segment to the particle enters the skin, the
      // surface passed through the particle's path: put it back on the side it came from.
      const Eigen::Vector3d to = p.position[s];
      const Eigen::Vector3d dir = to - anchor.from;
      const double length = dir.norm();
      if (!(length > 1e-12 * radius_)) continue;
      SkinHit hit;
      if (rayFirstHit(anchor.from, to + dir / length * radius_, hit, chunkCounters)) {
        p.position[s] = hit.point;  // on the surface; makeContact lifts it to one radius
        makeContact(anchor.particle, p, hit);
        ++chunkCounters.sweptParticles;
      }
    }
  };
  forEachParticleChunk(parallel, anchors_.size(), push, counters);
  return maxDisplacement;
}

void SkinCollider::resolve(ParticleSet& p, std::span<const Eigen::Vector3d> previous,
                           CollisionCounters& counters, ParallelChunks& parallel) {
  forEachParticleChunk(
      parallel, static_cast<std::size_t>(p.size()),
      [&](int chunk, std::size_t begin, std::size_t end) {
        resolveRange(p, previous, begin, end, chunkCounters_[static_cast<std::size_t>(chunk)]);
      },
      counters);
}

void SkinCollider::resolveRange(ParticleSet& p, std::span<const Eigen::Vector3d> previous,
                                std::size_t begin, std::size_t end, CollisionCounters& counters) {
  for (std::size_t s = begin; s < end; ++s) {
    const int i = static_cast<int>(s);
    SkinContact& contact = p.contact[s];
    const Eigen::Vector3d moved = p.position[s] - previous[s];
    const SkinFace* face =
        contact.triangle >= 0 ? &faces_[static_cast<std::size_t>(contact.triangle)] : nullptr;
    if (face && !face->degenerate) {
      const TrianglePoint cp = closestPointOnFace(p.position[s], *face);
      if (cp.interior) {
        ++counters.contactsTracked;
        const Eigen::Vector3d n = face->normal;
        const double height = (p.position[s] - cp.point).dot(n);
        // The tracked side is known, so even a particle pulled far below the plane (huge
        // adhesion, huge step) comes back out on the front: no tunnelling through its triangle.
        if (height < radius_) {
          p.position[s] += (radius_ - height) * n;
          const double vn = p.velocity[s].dot(n);
          if (vn < 0) p.velocity[s] -= vn * n;
        }
        p.travelled[s] += (moved - moved.dot(n) * n).norm();
        if (height > radius_ + band_) {
          contact.triangle = -1;  // lifted off
          p.clearance[s] = 0;
        } else {
          contact.barycentric = cp.barycentric;
        }
        continue;
      }
    }
    if (contact.triangle >= 0) {
      // Slid off its triangle (or the triangle collapsed): find the one it is on now, among
      // the triangles around the old one first, then by a query.
      SkinHit hit;
      if (contactAround(p.position[s], contact.triangle, hit)) {
        ++counters.contactsTracked;
        p.travelled[s] += moved.norm();
        makeContact(i, p, hit);
      } else if (nearest(p.position[s], radius_ + band_, hit, counters)) {
        p.travelled[s] += moved.norm();
        makeContact(i, p, hit);
      } else {
        contact.triangle = -1;
        p.clearance[s] = band_;
      }
      continue;
    }
    // Free particle.
    const double travel = moved.norm();
    const double before = p.clearance[s];
    p.clearance[s] -= travel;
    if (p.clearance[s] > 0) continue;
    SkinHit hit;
    // A free particle's centre starts at least radius + clearance from the skin (clearance >= 0),
    // so a shorter path cannot have crossed it and ends in front, where the sphere test below
    // finds the skin. Half a radius of margin.
    if (travel > before + 0.5 * radius_) {
      // Fast: the sphere test at the end point could miss a crossing, so test the path, one
      // radius beyond the end point (ending within a radius of the skin is a contact too).
      if (rayFirstHit(previous[s], p.position[s] + moved / travel * radius_, hit, counters)) {
        p.position[s] = hit.point;
        makeContact(i, p, hit);
        continue;
      }
    }
    if (nearest(p.position[s], radius_ + probe_, hit, counters)) {
      if (hit.distance <= radius_ + band_) {
        makeContact(i, p, hit);
      } else {
        p.clearance[s] = hit.distance - radius_;
      }
    } else {
      p.clearance[s] = probe_;
    }
  }
}

}  // namespace lacrima::tears
