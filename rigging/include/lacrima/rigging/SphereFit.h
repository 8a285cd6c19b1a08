#pragma once
// Least-squares sphere through points: the eyeball's centre of rotation when a feature-point
// file does not give one.
//
// Algebraic fit: |p|^2 = 2 c.p + k for all points, linear in (c, k), solved in the least-squares
// sense (column-pivoting QR on points centred on their mean, so large offsets cost no
// precision); the radius is sqrt(k + |c|^2). For points on a sphere this is exact; for an
// eyeball with a bulging cornea it leans slightly forward, well under a millimetre here.
#include <lacrima/common/HeadMesh.h>

#include <Eigen/Core>

#include <optional>
#include <string>
#include <vector>

namespace lacrima::rigging {

struct Sphere {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  double radius = 0;
};

// nullopt for fewer than 4 points or points that do not span 3-D space (coplanar).
std::optional<Sphere> fitSphere(const Eigen::Matrix3Xd& points);

// The sphere through every vertex of the sub-meshes `names` of `mesh` (an eye's); nullopt as
// above. Precondition: every name is a sub-mesh of `mesh`.
std::optional<Sphere> fitSphere(const HeadMesh& mesh, const std::vector<std::string>& names);

}  // namespace lacrima::rigging
