#pragma once
// The skin as an ODE trimesh, asked the collider's two questions through dCollide: which
// triangles touch a sphere, and where a segment first enters the skin from the front. ODE is
// used for contact queries only (no bodies, no world step; docs/decisions/0001).
//
// This is the reference the collider's own triangle grid is checked against
// (SkinQueryMethod::Ode; tests/tears/SkinColliderGridTest.cpp): every call holds the
// process-wide ODE lock (OdeHandles.h), so these queries can never be shared between threads.
#include "OdeHandles.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <span>
#include <vector>

namespace lacrima::tears {

class OdeSkinQueries {
 public:
  // Contacts ODE may list per sphere query; a full list may be missing some triangles.
  static constexpr int kMaxContacts = 32;

  // vertices: 3 x n; triangles index them. ODE keeps the geom's bounding box from build time,
  // so the mesh is built with unreferenced vertices at the envelope's corners: the largest
  // region the skin can ever occupy.
  OdeSkinQueries(const Eigen::Matrix3Xd& vertices, std::span<const Eigen::Vector3i> triangles,
                 const Eigen::AlignedBox3d& envelope);

  // Moves the mesh to `vertices` (same count): a refit of ODE's tree, which depends on the
  // vertices alone, so a restored pose answers exactly as before.
  void update(const Eigen::Matrix3Xd& vertices);

  // Triangles ODE lists as reaching into the sphere (finite contacts only), in its tree's
  // order; `complete` is false when the list was full, so a closer triangle may be missing.
  std::span<const int> sphere(const Eigen::Vector3d& centre, double radius, bool& complete);

  // The front-facing triangle the segment from `from` along unit `direction` first enters
  // within `length`: its index, the crossing point and the distance to it; false when none.
  bool ray(const Eigen::Vector3d& from, const Eigen::Vector3d& direction, double length,
           int& triangle, Eigen::Vector3d& point, double& distance);

 private:
  // ODE keeps pointers into these two arrays: they are sized once and never reallocated.
  std::vector<double> vertices_;
  std::vector<dTriIndex> indices_;
  OdeLibrary library_;
  OdeTriMeshData data_;
  OdeGeom mesh_, sphere_, ray_;
  std::vector<dContactGeom> contacts_;
  std::vector<int> listed_;  // the last sphere query's triangles
};

}  // namespace lacrima::tears
