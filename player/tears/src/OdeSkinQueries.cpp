#include "OdeSkinQueries.h"

#include <cmath>

namespace lacrima::tears {
namespace {

constexpr int kEnvelopeVertices = 8;

bool finite(const dContactGeom& c) {
  return std::isfinite(c.depth) && std::isfinite(c.pos[0]) && std::isfinite(c.pos[1]) &&
         std::isfinite(c.pos[2]);
}

}  // namespace

OdeSkinQueries::OdeSkinQueries(const Eigen::Matrix3Xd& vertices,
                               std::span<const Eigen::Vector3i> triangles,
                               const Eigen::AlignedBox3d& envelope) {
  const auto n = static_cast<std::size_t>(vertices.cols());
  vertices_.assign(3 * (n + kEnvelopeVertices), 0.0);
  for (int c = 0; c < kEnvelopeVertices; ++c) {
    const Eigen::Vector3d corner = envelope.corner(static_cast<Eigen::AlignedBox3d::CornerType>(c));
    for (int a = 0; a < 3; ++a)
      vertices_[3 * (n + static_cast<std::size_t>(c)) + static_cast<std::size_t>(a)] = corner[a];
  }
  for (std::size_t v = 0; v < n; ++v)
    for (int a = 0; a < 3; ++a)
      vertices_[3 * v + static_cast<std::size_t>(a)] = vertices(a, static_cast<Eigen::Index>(v));
  indices_.reserve(3 * triangles.size());
  for (const auto& t : triangles)
    for (int a = 0; a < 3; ++a) indices_.push_back(static_cast<dTriIndex>(t[a]));

  const auto ode = lockOde();
  data_ = OdeTriMeshData(dGeomTriMeshDataCreate());
  dGeomTriMeshDataBuildDouble(data_.get(), vertices_.data(), 3 * sizeof(double),
                              static_cast<int>(n + kEnvelopeVertices), indices_.data(),
                              static_cast<int>(indices_.size()), 3 * sizeof(dTriIndex));
  mesh_ = OdeGeom(dCreateTriMesh(nullptr, data_.get(), nullptr, nullptr, nullptr));
  sphere_ = OdeGeom(dCreateSphere(nullptr, 1.0));
  ray_ = OdeGeom(dCreateRay(nullptr, 1.0));
  // Closest hit, front faces only: a ray that leaves the skin from behind is not a crossing.
  dGeomRaySetFirstContact(ray_.get(), 0);
  dGeomRaySetBackfaceCull(ray_.get(), 1);
  dGeomRaySetClosestHit(ray_.get(), 1);
  contacts_.resize(kMaxContacts);
  listed_.reserve(kMaxContacts);
}

void OdeSkinQueries::update(const Eigen::Matrix3Xd& v) {
  for (Eigen::Index c = 0; c < v.cols(); ++c)
    for (int a = 0; a < 3; ++a)
      vertices_[3 * static_cast<std::size_t>(c) + static_cast<std::size_t>(a)] = v(a, c);
  // Refit only: a rebuilt (or re-preprocessed) data object would assert in ODE.
  const auto ode = lockOde();
  dGeomTriMeshDataUpdate(data_.get());
}

std::span<const int> OdeSkinQueries::sphere(const Eigen::Vector3d& x, double radius,
                                            bool& complete) {
  const auto ode = lockOde();
  dGeomSphereSetRadius(sphere_.get(), radius);
  dGeomSetPosition(sphere_.get(), x.x(), x.y(), x.z());
  const int n =
      dCollide(sphere_.get(), mesh_.get(), kMaxContacts, contacts_.data(), sizeof(dContactGeom));
  listed_.clear();
  for (int c = 0; c < n; ++c) {
    const dContactGeom& contact = contacts_[static_cast<std::size_t>(c)];
    if (finite(contact)) listed_.push_back(contact.side2);
  }
  complete = n < kMaxContacts;
  return listed_;
}

bool OdeSkinQueries::ray(const Eigen::Vector3d& from, const Eigen::Vector3d& dir, double length,
                         int& triangle, Eigen::Vector3d& point, double& distance) {
  const auto ode = lockOde();
  dGeomRaySetLength(ray_.get(), length);
  dGeomRaySet(ray_.get(), from.x(), from.y(), from.z(), dir.x(), dir.y(), dir.z());
  if (dCollide(ray_.get(), mesh_.get(), 1, contacts_.data(), sizeof(dContactGeom)) < 1)
    return false;
  const dContactGeom& c = contacts_[0];
  if (!finite(c)) return false;
  triangle = c.side2;
  point = {c.pos[0], c.pos[1], c.pos[2]};
  distance = c.depth;
  return true;
}

}  // namespace lacrima::tears
