#pragma once
// The closest point of a triangle mesh to each query point.
//
//   x_j = argmin over triangles t and points x in t of |x - p_j|,
//   x_j = b_j0 V(t_j, 0) + b_j1 V(t_j, 1) + b_j2 V(t_j, 2),   b_j >= 0,   sum b_j = 1,
// with closestPointOnTriangle (lacrima/common/ClosestPointOnTriangle.h) on each candidate
// triangle and a bounding-volume hierarchy over the triangles (Eigen's KdBVH, best-first
// BVMinimize) to visit only those whose box is nearer than the best point so far.
//
// Anything given per vertex of the mesh (weights, displacements) blended with b_j is the value
// at x_j, linear over the triangle and continuous across its edges: a point between vertices
// gets what the surface under it has, not what its nearest vertex has. Triangles of zero area
// are skipped (their edges belong to their neighbours); on a tie the answer is one of the
// nearest triangles.
#include <Eigen/Core>

#include <vector>

namespace lacrima::rigging {

struct SurfacePoints {
  Eigen::VectorXi triangle;      // per query: index into `triangles`; -1 when no triangle has area
  Eigen::Matrix3Xd barycentric;  // per query: b_j, the weights of the triangle's corners in order
  Eigen::VectorXd distance;      // per query: |x_j - p_j| (+infinity when triangle is -1)
};

// `triangles` index columns of `vertices`. Throws std::invalid_argument for an index out of
// range.
SurfacePoints closestSurfacePoints(const Eigen::Matrix3Xd& vertices,
                                   const std::vector<Eigen::Vector3i>& triangles,
                                   const Eigen::Matrix3Xd& queries);

}  // namespace lacrima::rigging
