#pragma once
// What a ray meets on a head: the triangle (numbered over all sub-meshes in HeadMesh order: the
// triangles of sub-mesh 0, then those of sub-mesh 1, ...), where on it, and which sub-mesh.
// The viewport's pick() is this on the ray through a pixel; engine-free, so the workspace and
// tests can pick without a display. Sub-meshes can be left out (ignored parts, eyelash cards in
// front of the eye corners). New positions for a deformed frame refit the hierarchy (RayMesh.h).
#include <lacrima/common/HeadMesh.h>
#include <lacrima/common/RayMesh.h>

#include <Eigen/Core>

#include <optional>
#include <vector>

namespace lacrima::viewport {

using Ray = lacrima::Ray;

struct SurfaceHit {
  int triangle = -1;                                      // global: HeadMesh order over sub-meshes
  Eigen::Vector3d barycentric = Eigen::Vector3d::Zero();  // weights of the triangle's corners
  Eigen::Vector3d position = Eigen::Vector3d::Zero();     // head frame
  int submesh = -1;
  int submeshTriangle = -1;  // the same triangle within its sub-mesh (FeaturePointFile's index)
  int vertex = -1;           // global index of the corner with the largest weight
  double distance = 0;       // along the ray
};

// The global index of a sub-mesh's first triangle (sum of the triangle counts before it).
int firstTriangleOf(const HeadMesh& head, int submesh);

class HeadPicker {
 public:
  // `pickable` per sub-mesh (false leaves it out); empty or shorter: the rest are pickable.
  // Copies what it needs: `head` may go away afterwards.
  explicit HeadPicker(const HeadMesh& head, const std::vector<bool>& pickable = {});

  // The positions shown (a deformed frame, or the neutral ones again): same vertex count as the
  // head, else std::invalid_argument.
  void setPositions(const Eigen::Matrix3Xf& positions);

  std::optional<SurfaceHit> pick(const Ray& ray) const;

 private:
  // Declared before mesh_: the constructor fills them while building mesh_'s triangle list.
  std::vector<int> global_;   // RayMesh triangle -> global triangle
  std::vector<int> submesh_;  // RayMesh triangle -> sub-mesh
  std::vector<int> local_;    // RayMesh triangle -> index within its sub-mesh
  RayMesh mesh_;
};

}  // namespace lacrima::viewport
