#pragma once
// The first surface a ray meets on a triangle mesh: what a click on a picture of the mesh
// points at.
//
// Ray o + t d (t > 0, |d| = 1) against triangle abc by Moller-Trumbore: with e1 = b - a,
// e2 = c - a, s = o - a, p = d x e2, q = s x e1 and det = e1 . p,
//   u = (s . p) / det,   v = (d . q) / det,   t = (e2 . q) / det,
// the hit is a + u e1 + v e2 = (1 - u - v) a + u b + v c when u, v >= 0 and u + v <= 1. det is
// the volume spanned by d, e1, e2: near zero the ray runs parallel to the face or the triangle
// has no area, and the triangle is skipped (its edges belong to its neighbours). The inside test
// allows a hair's breadth (1e-9 of the barycentric range) so a ray through a shared edge or
// corner is not lost between two triangles.
//
// A bounding-volume hierarchy over the triangles (median split of centroids along the longest
// axis, four triangles a leaf) visits only boxes the ray enters before the best hit so far,
// nearer child first: a pick on a 56k-triangle head costs microseconds. refit() takes new
// positions for the same triangles (a deformed frame) and only recomputes the boxes.
// Engine-free (Eigen only), like ClosestPointOnTriangle.h.
#include <Eigen/Core>
#include <Eigen/Geometry>

#include <optional>
#include <vector>

namespace lacrima::inline common {

struct Ray {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  Eigen::Vector3d direction = -Eigen::Vector3d::UnitZ();  // unit length
};

struct RayHit {
  int triangle = -1;                                      // index into the mesh's triangles
  Eigen::Vector3d barycentric = Eigen::Vector3d::Zero();  // weights of the corners, in order
  Eigen::Vector3d point = Eigen::Vector3d::Zero();        // origin + distance * direction
  double distance = 0;                                    // t along the (unit) direction
};

// The hit of `ray` on triangle abc (Moller-Trumbore, above): nullopt when the ray misses,
// runs parallel to the face, starts on or beyond it, or the triangle has no area. `triangle`
// of the result is -1.
std::optional<RayHit> intersectRayTriangle(const Ray& ray, const Eigen::Vector3d& a,
                                           const Eigen::Vector3d& b, const Eigen::Vector3d& c);

class RayMesh {
 public:
  RayMesh() = default;
  // `triangles` index columns of `vertices`. Throws std::invalid_argument for an index out of
  // range. Non-finite vertices make their triangles unhittable, nothing worse.
  RayMesh(const Eigen::Matrix3Xf& vertices, std::vector<Eigen::Vector3i> triangles);

  // New positions for the same triangles (same vertex count, else std::invalid_argument):
  // the boxes are recomputed bottom-up, the tree's shape kept (linear time).
  void refit(const Eigen::Matrix3Xf& vertices);

  // The nearest hit with distance > 0, or nullopt. A direction of zero or non-finite length
  // hits nothing; any other direction is normalised first.
  std::optional<RayHit> closestHit(const Ray& ray) const;

  int triangleCount() const { return static_cast<int>(triangles_.size()); }
  const std::vector<Eigen::Vector3i>& triangles() const { return triangles_; }

 private:
  struct Node {
    Eigen::AlignedBox3f box;
    int first = 0, count = 0;  // leaf: order_[first, first + count); inner: count == 0
    int left = -1, right = -1;
  };
  int build(int first, int count, const std::vector<Eigen::Vector3f>& centroids);
  Eigen::AlignedBox3f refitNode(int node);

  Eigen::Matrix3Xf vertices_;
  std::vector<Eigen::Vector3i> triangles_;
  std::vector<int> order_;  // triangle indices, grouped by leaf
  std::vector<Node> nodes_;
};

}  // namespace lacrima::inline common
