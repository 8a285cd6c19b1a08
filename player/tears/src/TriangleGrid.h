#pragma once
// A uniform grid over the skin's triangles, rebuilt with every skin pose, that answers one
// question exactly enough to skip ODE: which triangles could touch a box? A triangle is listed
// in every cell its bounding box (widened by `margin`) overlaps; a query visits the cells the
// box overlaps and reports each listed triangle whose widened box overlaps it (a triangle
// spanning several cells may be reported more than once).
//
// Why it leaves every answer unchanged: the collider only skips a dCollide call when the grid
// proves the call could not change the outcome. A sphere query keeps only triangles that
// consider() accepts, so when consider() accepts none of the candidates, ODE's list (a subset
// of the triangles near the sphere) could not give one either. A ray only counts when it
// crosses a triangle, and no triangle whose box misses the segment's box can be crossed. The
// margin covers rounding: ODE (OPCODE) tests in single precision, so a hit may lie a few float
// ulps outside the double triangle; the margin is 1e-4 of the skin's extent, ten thousand
// times more than that, and far below a particle radius (it only adds candidates).
//
// Cell size: the mean triangle's largest box side or the given floor (the common query's
// radius), whichever is larger, grown if needed so the grid has at most ~4 cells per triangle.
// Degenerate triangles are left out: they never hold a contact and ODE's hits on them are
// discarded.
#include "SkinContact.h"

#include <Eigen/Core>

#include <cmath>
#include <span>
#include <vector>

namespace lacrima::tears {

class TriangleGrid {
 public:
  void build(std::span<const SkinFace> faces, double minimumCell);

  // Calls visit(t) for candidate triangles until visit returns true; returns whether one did.
  // Candidates of a box [lo, hi]: triangles whose widened box overlaps it. Candidates of a
  // sphere: triangles whose plane lies within radius + margin of the centre and whose widened
  // box overlaps the sphere's box (the distance to a triangle is at least the distance to its
  // plane, and rounding in either is far below the margin). Non-finite
  // queries visit every triangle (no proof is possible).
  template <class Visit>
  bool any(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi, Visit&& visit) const {
    return walk(
        lo, hi,
        [&](std::size_t t) {
          return (lo_[t].array() <= hi.array()).all() && (lo.array() <= hi_[t].array()).all();
        },
        visit);
  }
  template <class Visit>
  bool anyNear(const Eigen::Vector3d& centre, double radius, Visit&& visit) const {
    const Eigen::Vector3d r = Eigen::Vector3d::Constant(radius);
    const double reach = radius + margin_;
    return walk(
        centre - r, centre + r,
        [&](std::size_t t) {
          // The plane first: on smooth skin it rejects nearly every triangle near a particle
          // that is not touching. Then the widened box, which holds the triangle.
          if (!(std::abs(normal_[t].dot(centre) - offset_[t]) <= reach)) return false;
          return (lo_[t].array() <= centre.array() + radius).all() &&
                 (centre.array() - radius <= hi_[t].array()).all();
        },
        visit);
  }

 private:
  // Cell coordinate of a point's offset along one axis, clamped to the grid (no floor(): on
  // baseline x86-64 it is a library call; offsets below zero clamp before the cast).
  int clampedCell(double offset, int axis) const {
    const double c = offset * inverseCell_;
    if (!(c >= 0)) return 0;
    return c >= dims_[axis] ? dims_[axis] - 1 : static_cast<int>(c);
  }
  bool cellRange(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi, Eigen::Array3i& first,
                 Eigen::Array3i& last) const;
  // Calls f(cell) for the cells of [first, last] in x-fastest order until f returns true;
  // returns whether it did.
  template <class F>
  bool anyCell(const Eigen::Array3i& first, const Eigen::Array3i& last, F&& f) const {
    for (int z = first.z(); z <= last.z(); ++z)
      for (int y = first.y(); y <= last.y(); ++y)
        for (int x = first.x(); x <= last.x(); ++x)
          if (f(static_cast<std::size_t>((z * dims_.y() + y) * dims_.x() + x))) return true;
    return false;
  }
  template <class Overlaps, class Visit>
  bool walk(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi, Overlaps&& overlaps,
            Visit&& visit) const;

  Eigen::Vector3d origin_ = Eigen::Vector3d::Zero(), extent_ = Eigen::Vector3d::Zero();
  double inverseCell_ = 0;
  bool exhaustive_ = false;  // no grid (a non-finite skin): walk every triangle
  Eigen::Array3i dims_ = Eigen::Array3i::Zero();
  std::vector<Eigen::Vector3d> lo_, hi_;  // widened triangle boxes
  std::vector<Eigen::Vector3d> normal_;   // unit normals, and offsets n.a of the planes
  std::vector<double> offset_;
  double margin_ = 0;
  std::vector<int> cellStart_, cellTriangles_;  // CSR
  std::vector<int> all_;                        // every listed triangle (non-finite queries)
  std::vector<Eigen::Array3i> first_, last_;    // build scratch: each triangle's cell range
  std::vector<int> fill_;                       // build scratch: next free slot per cell
};

inline bool TriangleGrid::cellRange(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi,
                                    Eigen::Array3i& first, Eigen::Array3i& last) const {
  if (dims_.minCoeff() <= 0) return false;
  const Eigen::Vector3d from = lo - origin_, to = hi - origin_;
  for (int a = 0; a < 3; ++a)
    if (to[a] < 0 || from[a] > extent_[a]) return false;  // misses the grid: no triangle there
  for (int a = 0; a < 3; ++a) {
    first[a] = clampedCell(from[a], a);
    last[a] = clampedCell(to[a], a);
  }
  return true;
}

template <class Overlaps, class Visit>
bool TriangleGrid::walk(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi, Overlaps&& overlaps,
                        Visit&& visit) const {
  if (exhaustive_ || !lo.allFinite() || !hi.allFinite()) {
    for (int t : all_)
      if (visit(t)) return true;
    return false;
  }
  Eigen::Array3i first, last;
  if (!cellRange(lo, hi, first, last)) return false;
  return anyCell(first, last, [&](std::size_t cell) {
    for (int a = cellStart_[cell]; a < cellStart_[cell + 1]; ++a) {
      const int t = cellTriangles_[static_cast<std::size_t>(a)];
      if (overlaps(static_cast<std::size_t>(t)) && visit(t)) return true;
    }
    return false;
  });
}

}  // namespace lacrima::tears
