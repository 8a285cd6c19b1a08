#include "SkinCollider.h"

#include "TriangleGeometry.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace lacrima::tears {
namespace {

// Contacts ODE may report per query; a full buffer means the answer may be incomplete
// (nearest() then narrows the sphere, kShrinkAttempts times at most, before scanning).
constexpr int kMaxContacts = 32;
constexpr int kShrinkAttempts = 4;
constexpr int kEnvelopeVertices = 8;

bool finite(const dContactGeom& c) {
  return std::isfinite(c.depth) && std::isfinite(c.pos[0]) && std::isfinite(c.pos[1]) && std::isfinite(c.pos[2]);
}

}  // namespace

SkinCollider::SkinCollider(const Eigen::Matrix3Xd& vertices, std::vector<Eigen::Vector3i> triangles,
                           const Eigen::AlignedBox3d& envelope, double particleRadius,
                           double contactBand, double probeRadius)
    : vertices_(vertices), triangles_(std::move(triangles)), radius_(particleRadius),
      band_(contactBand), probe_(probeRadius) {
  const auto n = static_cast<std::size_t>(vertices.cols());
  for (const auto& t : triangles_)
    if (t.minCoeff() < 0 || static_cast<std::size_t>(t.maxCoeff()) >= n)
      throw std::invalid_argument("skin triangle refers to a missing vertex");
  // A triangle whose area is below (1e-6 particle radius)^2 has no usable normal; such
  // triangles (collapsed by a pose, or modelled) never hold a contact.
  degenerateArea2_ = std::pow(1e-6 * radius_, 4);
  computeNormals(vertices_, normals_, degenerate_);
  // Triangles around each vertex (CSR), for contacts that slide onto a neighbouring triangle.
  vertexStart_.assign(n + 1, 0);
  for (const auto& t : triangles_)
    for (int k = 0; k < 3; ++k) ++vertexStart_[static_cast<std::size_t>(t[k]) + 1];
  for (std::size_t v = 0; v < n; ++v) vertexStart_[v + 1] += vertexStart_[v];
  vertexTriangles_.resize(static_cast<std::size_t>(vertexStart_[n]));
  std::vector<int> fill(vertexStart_.begin(), vertexStart_.end() - 1);
  for (std::size_t t = 0; t < triangles_.size(); ++t)
    for (int k = 0; k < 3; ++k)
      vertexTriangles_[static_cast<std::size_t>(fill[static_cast<std::size_t>(triangles_[t][k])]++)] = static_cast<int>(t);

  odeVertices_.assign(3 * (n + kEnvelopeVertices), 0.0);
  for (int c = 0; c < kEnvelopeVertices; ++c) {
    const Eigen::Vector3d corner = envelope.corner(static_cast<Eigen::AlignedBox3d::CornerType>(c));
    for (int a = 0; a < 3; ++a) odeVertices_[3 * (n + static_cast<std::size_t>(c)) + static_cast<std::size_t>(a)] = corner[a];
  }
  for (std::size_t v = 0; v < n; ++v)
    for (int a = 0; a < 3; ++a) odeVertices_[3 * v + static_cast<std::size_t>(a)] = vertices(a, static_cast<Eigen::Index>(v));
  odeIndices_.reserve(3 * triangles_.size());
  for (const auto& t : triangles_)
    for (int a = 0; a < 3; ++a) odeIndices_.push_back(static_cast<dTriIndex>(t[a]));

  data_ = OdeTriMeshData(dGeomTriMeshDataCreate());
  dGeomTriMeshDataBuildDouble(data_.get(), odeVertices_.data(), 3 * sizeof(double),
                              static_cast<int>(n + kEnvelopeVertices), odeIndices_.data(),
                              static_cast<int>(odeIndices_.size()), 3 * sizeof(dTriIndex));
  mesh_ = OdeGeom(dCreateTriMesh(nullptr, data_.get(), nullptr, nullptr, nullptr));
  sphere_ = OdeGeom(dCreateSphere(nullptr, radius_));
  ray_ = OdeGeom(dCreateRay(nullptr, 1.0));
  // Closest hit, front faces only: a ray that leaves the skin from behind is not a crossing.
  dGeomRaySetFirstContact(ray_.get(), 0);
  dGeomRaySetBackfaceCull(ray_.get(), 1);
  dGeomRaySetClosestHit(ray_.get(), 1);
  contacts_.resize(kMaxContacts);
}

void SkinCollider::computeNormals(const Eigen::Matrix3Xd& v, std::vector<Eigen::Vector3d>& normals,
                                  std::vector<std::uint8_t>& degenerate) const {
  normals.resize(triangles_.size());
  degenerate.resize(triangles_.size());
  for (std::size_t t = 0; t < triangles_.size(); ++t) {
    const auto& tri = triangles_[t];
    const Eigen::Vector3d cross = (v.col(tri[1]) - v.col(tri[0])).cross(v.col(tri[2]) - v.col(tri[0]));
    const double area2 = cross.squaredNorm();
    degenerate[t] = !(area2 > degenerateArea2_);  // NaN counts as degenerate
    normals[t] = degenerate[t] ? Eigen::Vector3d::Zero() : Eigen::Vector3d(cross / std::sqrt(area2));
  }
}

void SkinCollider::writeOdeVertices(const Eigen::Matrix3Xd& v, CollisionCounters& counters) {
  for (Eigen::Index c = 0; c < v.cols(); ++c)
    for (int a = 0; a < 3; ++a) odeVertices_[3 * static_cast<std::size_t>(c) + static_cast<std::size_t>(a)] = v(a, c);
  // Refit only: a rebuilt (or re-preprocessed) data object would assert in ODE.
  dGeomTriMeshDataUpdate(data_.get());
  ++counters.trimeshUpdates;
}

void SkinCollider::resetSurface(const Eigen::Matrix3Xd& v, CollisionCounters& counters) {
  vertices_ = v;
  computeNormals(vertices_, normals_, degenerate_);
  writeOdeVertices(vertices_, counters);
}

void SkinCollider::restoreSurface(const Surface& surface, CollisionCounters& counters) {
  if (surface.vertices.cols() != vertices_.cols() || surface.normals.size() != triangles_.size())
    throw std::invalid_argument("the saved skin does not match this collider");
  vertices_ = surface.vertices;
  normals_ = surface.normals;
  degenerate_ = surface.degenerate;
  writeOdeVertices(vertices_, counters);
}

Eigen::Vector3d SkinCollider::pointAt(int t, const Eigen::Vector3d& b, const Eigen::Matrix3Xd& v) const {
  const auto& tri = triangles_[static_cast<std::size_t>(t)];
  return b[0] * v.col(tri[0]) + b[1] * v.col(tri[1]) + b[2] * v.col(tri[2]);
}

bool SkinCollider::consider(const Eigen::Vector3d& x, int t, double radius, SkinHit& hit, bool found) const {
  if (t < 0 || t >= triangleCount() || degenerate(t)) return false;
  const auto& tri = triangles_[static_cast<std::size_t>(t)];
  const TrianglePoint cp = closestPointOnTriangle(x, vertices_.col(tri[0]), vertices_.col(tri[1]), vertices_.col(tri[2]));
  if ((x - cp.point).dot(normals_[static_cast<std::size_t>(t)]) < 0) return false;  // behind: not ours
  const double distance = (x - cp.point).norm();
  if (!(distance <= radius)) return false;
  if (found && !(distance < hit.distance || (distance == hit.distance && t < hit.triangle))) return false;
  hit = {t, cp.point, cp.barycentric, cp.interior, distance};
  return true;
}

bool SkinCollider::contactAround(const Eigen::Vector3d& x, int from, SkinHit& hit) const {
  bool found = false;
  const auto& tri = triangles_[static_cast<std::size_t>(from)];
  for (int k = 0; k < 3; ++k) {
    const auto v = static_cast<std::size_t>(tri[k]);
    for (int a = vertexStart_[v]; a < vertexStart_[v + 1]; ++a)
      if (consider(x, vertexTriangles_[static_cast<std::size_t>(a)], radius_ + band_, hit, found)) found = true;
  }
  // Over a face, not at a rim of the ring: a contact as good as the global search's. At an edge
  // or vertex of the ring, a triangle further out might be closer: leave it to ODE.
  return found && hit.interior;
}

bool SkinCollider::nearest(const Eigen::Vector3d& x, double radius, SkinHit& hit, CollisionCounters& counters) {
  bool found = false;
  double r = radius;
  for (int attempt = 0; attempt < kShrinkAttempts; ++attempt) {
    dGeomSphereSetRadius(sphere_.get(), r);
    dGeomSetPosition(sphere_.get(), x.x(), x.y(), x.z());
    ++counters.odeQueries;
    const int n = dCollide(sphere_.get(), mesh_.get(), kMaxContacts, contacts_.data(), sizeof(dContactGeom));
    for (int c = 0; c < n; ++c) {
      const dContactGeom& contact = contacts_[static_cast<std::size_t>(c)];
      if (finite(contact) && consider(x, contact.side2, radius, hit, found)) found = true;
    }
    if (n < kMaxContacts) return found;  // complete: every triangle reaching into the sphere was listed
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
  const Eigen::Vector3d d = to - from;
  const double length = d.norm();
  if (!(length > 0)) return false;
  const Eigen::Vector3d dir = d / length;
  dGeomRaySetLength(ray_.get(), length);
  dGeomRaySet(ray_.get(), from.x(), from.y(), from.z(), dir.x(), dir.y(), dir.z());
  ++counters.odeQueries;
  const int n = dCollide(ray_.get(), mesh_.get(), 1, contacts_.data(), sizeof(dContactGeom));
  if (n < 1) return false;
  const dContactGeom& c = contacts_[0];
  const int t = c.side2;
  if (!finite(c) || t < 0 || t >= triangleCount() || degenerate(t)) return false;
  if (dir.dot(normals_[static_cast<std::size_t>(t)]) >= 0) return false;  // leaving, not entering
  const Eigen::Vector3d p(c.pos[0], c.pos[1], c.pos[2]);
  const auto& tri = triangles_[static_cast<std::size_t>(t)];
  const TrianglePoint cp = closestPointOnTriangle(p, vertices_.col(tri[0]), vertices_.col(tri[1]), vertices_.col(tri[2]));
  hit = {t, cp.point, cp.barycentric, cp.interior, c.depth};
  return true;
}

void SkinCollider::makeContact(int i, ParticleSet& p, const SkinHit& hit) {
  const auto s = static_cast<std::size_t>(i);
  const Eigen::Vector3d n = normals_[static_cast<std::size_t>(hit.triangle)];
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

double SkinCollider::moveSurface(const Eigen::Matrix3Xd& next, ParticleSet& p, CollisionCounters& counters) {
  double maxDisplacement = 0;
  for (Eigen::Index c = 0; c < next.cols(); ++c)
    maxDisplacement = std::max(maxDisplacement, (next.col(c) - vertices_.col(c)).norm());
  if (!std::isfinite(maxDisplacement)) throw std::invalid_argument("skin positions are not finite");
  if (maxDisplacement == 0) return 0;  // nothing moved: no refit, no carrying

  std::vector<Eigen::Vector3d> nextNormals;
  std::vector<std::uint8_t> nextDegenerate;
  computeNormals(next, nextNormals, nextDegenerate);

  // Free particles the skin could reach this frame: anchor them on the OLD surface (ODE still
  // holds it), to cast their rays once the new one is in place.
  struct Anchor {
    int particle;
    Eigen::Vector3d from;
  };
  std::vector<Anchor> anchors;
  const bool sweeping = maxDisplacement > 0.25 * radius_;
  for (int i = 0; i < p.size(); ++i) {
    const auto s = static_cast<std::size_t>(i);
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
      p.position[s] = pointAt(t, p.contact[s].barycentric, next) + (o - height * normals_[st]) + height * nextNormals[st];
      continue;
    }
    if (sweeping && p.clearance[s] < maxDisplacement) {
      SkinHit hit;
      if (nearest(p.position[s], radius_ + maxDisplacement + radius_, hit, counters)) {
        const auto st = static_cast<std::size_t>(hit.triangle);
        if (!nextDegenerate[st]) {
          const Eigen::Vector3d o = p.position[s] - hit.point;
          const double height = o.dot(normals_[st]);
          const Eigen::Vector3d from = pointAt(hit.triangle, hit.barycentric, next) + (o - height * normals_[st]) + height * nextNormals[st];
          anchors.push_back({i, from});
        }
      }
    }
    p.clearance[s] = std::max(0.0, p.clearance[s] - maxDisplacement);
  }

  vertices_ = next;
  normals_ = std::move(nextNormals);
  degenerate_ = std::move(nextDegenerate);
  writeOdeVertices(vertices_, counters);

  for (const Anchor& anchor : anchors) {
    const auto s = static_cast<std::size_t>(anchor.particle);
    // The anchor moved with the skin; if the segment to the particle enters the skin, the
    // surface passed through the particle's path: put it back on the side it came from.
    const Eigen::Vector3d to = p.position[s];
    const Eigen::Vector3d dir = to - anchor.from;
    const double length = dir.norm();
    if (!(length > 1e-12 * radius_)) continue;
    SkinHit hit;
    if (rayFirstHit(anchor.from, to + dir / length * radius_, hit, counters)) {
      p.position[s] = hit.point;  // on the surface; makeContact lifts it to one radius
      makeContact(anchor.particle, p, hit);
      ++counters.sweptParticles;
    }
  }
  return maxDisplacement;
}

void SkinCollider::resolve(ParticleSet& p, std::span<const Eigen::Vector3d> previous, CollisionCounters& counters) {
  for (int i = 0; i < p.size(); ++i) {
    const auto s = static_cast<std::size_t>(i);
    SkinContact& contact = p.contact[s];
    const Eigen::Vector3d moved = p.position[s] - previous[s];
    if (contact.triangle >= 0 && !degenerate(contact.triangle)) {
      const auto& tri = triangles_[static_cast<std::size_t>(contact.triangle)];
      const TrianglePoint cp = closestPointOnTriangle(p.position[s], vertices_.col(tri[0]), vertices_.col(tri[1]), vertices_.col(tri[2]));
      if (cp.interior) {
        ++counters.contactsTracked;
        const Eigen::Vector3d n = normals_[static_cast<std::size_t>(contact.triangle)];
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
      // the triangles around the old one first, then through ODE.
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
