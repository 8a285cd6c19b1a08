#include <lacrima/rigging/ClosestSurfacePoints.h>

#include <lacrima/common/ClosestPointOnTriangle.h>

#include <Eigen/Geometry>
#include <unsupported/Eigen/BVH>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace lacrima::rigging {
namespace {

using Tree = Eigen::KdBVH<double, 3, int>;

// BVMinimize's query object: boxes are bounded below by their squared distance to p, so the
// search opens a box only while it could hold something nearer than the best triangle so far.
class NearestTriangle {
 public:
  using Scalar = double;

  NearestTriangle(const Eigen::Matrix3Xd& vertices, const std::vector<Eigen::Vector3i>& triangles,
                  const Eigen::Vector3d& p)
      : vertices_(vertices), triangles_(triangles), p_(p) {}

  double minimumOnVolume(const Tree::Volume& box) const { return box.squaredExteriorDistance(p_); }

  double minimumOnObject(int t) {
    const Eigen::Vector3i& f = triangles_[static_cast<std::size_t>(t)];
    const TrianglePoint x =
        closestPointOnTriangle(p_, vertices_.col(f[0]), vertices_.col(f[1]), vertices_.col(f[2]));
    const double d2 = (x.point - p_).squaredNorm();
    if (d2 < best) best = d2, triangle = t, barycentric = x.barycentric;
    return d2;
  }

  double best = std::numeric_limits<double>::infinity();
  int triangle = -1;
  Eigen::Vector3d barycentric = Eigen::Vector3d::Zero();

 private:
  const Eigen::Matrix3Xd& vertices_;
  const std::vector<Eigen::Vector3i>& triangles_;
  Eigen::Vector3d p_;
};

}  // namespace

SurfacePoints closestSurfacePoints(const Eigen::Matrix3Xd& vertices,
                                   const std::vector<Eigen::Vector3i>& triangles,
                                   const Eigen::Matrix3Xd& queries) {
  std::vector<int> faces;
  std::vector<Tree::Volume> boxes;
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    const Eigen::Vector3i& f = triangles[t];
    if ((f.array() < 0).any() || (f.array() >= vertices.cols()).any())
      throw std::invalid_argument("closestSurfacePoints: triangle " + std::to_string(t) +
                                  " names a vertex outside the " + std::to_string(vertices.cols()) +
                                  " given");
    const Eigen::Vector3d a = vertices.col(f[0]), b = vertices.col(f[1]), c = vertices.col(f[2]);
    if (!((b - a).cross(c - a).squaredNorm() > 0)) continue;
    faces.push_back(static_cast<int>(t));
    boxes.emplace_back(a);
    boxes.back().extend(b).extend(c);
  }
  const Tree tree(faces.begin(), faces.end(), boxes.begin(), boxes.end());

  SurfacePoints out;
  out.triangle.setConstant(queries.cols(), -1);
  out.barycentric.setZero(3, queries.cols());
  out.distance.setConstant(queries.cols(), std::numeric_limits<double>::infinity());
  if (faces.empty()) return out;
  for (Eigen::Index j = 0; j < queries.cols(); ++j) {
    NearestTriangle nearest(vertices, triangles, queries.col(j));
    Eigen::BVMinimize(tree, nearest);
    out.triangle[j] = nearest.triangle;
    out.barycentric.col(j) = nearest.barycentric;
    out.distance[j] = std::sqrt(nearest.best);
  }
  return out;
}

}  // namespace lacrima::rigging
