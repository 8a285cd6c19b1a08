#pragma once
// Closest point of triangle abc to p, with its barycentric coordinates (Ericson, Real-Time
// Collision Detection, 5.1.5): p is classified into the Voronoi region of a corner, an edge or
// the face, and projected onto that feature,
//   x = argmin_{x in abc} |x - p| = u a + v b + w c,   u + v + w = 1,   u, v, w >= 0.
// The face case solves v, w from the signed areas va, vb, vc of the projected sub-triangles
// (v = vb / (va + vb + vc), w = vc / (va + vb + vc)), so no normal and no square root is
// formed. A triangle of zero area has no face region to land in and may give non-finite
// coordinates there; callers that can meet one skip it (its edges belong to its neighbours).
//
// Shared by the tear collider (lacrima_tears, which forms the edges once per skin pose) and the
// rig builder's binding of attached cards to the skin (lacrima_rigging).
#include <Eigen/Core>

namespace lacrima::inline common {

struct TrianglePoint {
  Eigen::Vector3d point;
  Eigen::Vector3d barycentric;  // weights of a, b, c
  bool interior = false;        // the projection of p falls inside the face
};

// ab = b - a and ac = c - a, formed by the caller (or once per pose). Always inlined: out of
// line (GCC's choice at four call sites) the result goes through memory and the call costs
// about a fifth of the tear collider's test; inlined, its tracked-contact path keeps it in
// registers.
[[gnu::always_inline]] inline TrianglePoint closestPointWithEdges(
    const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
    const Eigen::Vector3d& c, const Eigen::Vector3d& ab, const Eigen::Vector3d& ac) {
  const Eigen::Vector3d ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return {a, {1, 0, 0}, false};
  const Eigen::Vector3d bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return {b, {0, 1, 0}, false};
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) {
    const double v = d1 / (d1 - d3);
    return {a + v * ab, {1 - v, v, 0}, false};
  }
  const Eigen::Vector3d cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return {c, {0, 0, 1}, false};
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) {
    const double w = d2 / (d2 - d6);
    return {a + w * ac, {1 - w, 0, w}, false};
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
    const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return {b + w * (c - b), {0, 1 - w, w}, false};
  }
  const double denom = 1.0 / (va + vb + vc);
  const double v = vb * denom, w = vc * denom;
  return {a + v * ab + w * ac, {1 - v - w, v, w}, true};
}

inline TrianglePoint closestPointOnTriangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                            const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  const Eigen::Vector3d ab = b - a, ac = c - a;
  return closestPointWithEdges(p, a, b, c, ab, ac);
}

}  // namespace lacrima::inline common
