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
