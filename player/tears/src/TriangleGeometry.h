#pragma once
// Closest point on a skin triangle (lacrima/common/ClosestPointOnTriangle.h: Ericson's Voronoi
// regions of vertices, edges and face), from the corners or from a SkinFace.
//
// Two entry points share one body: from the corners (edges formed there), and from a SkinFace
// whose edges were formed once per skin pose. The edges are the same differences either way,
// so both give bitwise-identical answers (tests/tears/TriangleGeometryTest.cpp checks it).
#include "SkinContact.h"

#include <lacrima/common/ClosestPointOnTriangle.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace lacrima::tears {

using common::closestPointOnTriangle;
using common::closestPointWithEdges;
using common::TrianglePoint;

[[gnu::always_inline]] inline TrianglePoint closestPointOnFace(const Eigen::Vector3d& p,
                                                               const SkinFace& f) {
  return closestPointWithEdges(p, f.a, f.b, f.c, f.ab, f.ac);
}

// The per-pose record of triangle (a, b, c) with the given normal and degeneracy.
inline SkinFace makeSkinFace(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                             const Eigen::Vector3d& c, const Eigen::Vector3d& normal,
                             bool degenerate) {
  return {normal, a, b - a, c - a, b, c, degenerate};
}

}  // namespace lacrima::tears

namespace lacrima::tears {

// Where the segment from `from` along unit `dir` enters the front of `face` within `length`
// (Möller & Trumbore 1997, with the edges formed once per pose): the distance along the
// segment, or a negative value when it does not. Front only: the segment must run against the
// normal (det = dir . (ac x ab) > 0), as a particle crossing the skin from outside does. The
// barycentric bounds are widened by 1e-9 so that a segment through a shared edge or vertex is
// caught by both triangles rather than slipping between them through rounding (the collider
// keeps the nearer crossing, ties to the lower index).
inline double segmentEntersFace(const Eigen::Vector3d& from, const Eigen::Vector3d& dir,
                                double length, const SkinFace& face) {
  constexpr double kEdgeSlack = 1e-9;
  if (face.degenerate) return -1;
  const Eigen::Vector3d p = dir.cross(face.ac);
  const double det = face.ab.dot(p);
  if (!(det > 0)) return -1;
  const double inverse = 1.0 / det;
  const Eigen::Vector3d s = from - face.a;
  const double u = s.dot(p) * inverse;
  if (!(u >= -kEdgeSlack && u <= 1 + kEdgeSlack)) return -1;
  const Eigen::Vector3d q = s.cross(face.ab);
  const double v = dir.dot(q) * inverse;
  if (!(v >= -kEdgeSlack && u + v <= 1 + kEdgeSlack)) return -1;
  const double distance = face.ac.dot(q) * inverse;
  return distance >= 0 && distance <= length ? distance : -1;
}

}  // namespace lacrima::tears
