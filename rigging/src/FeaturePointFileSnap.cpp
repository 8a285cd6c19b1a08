// Re-snapping moved feature points (FeaturePointFileSnap.h).
#include "FeaturePointFileSnap.h"

#include <lacrima/rigging/ClosestSurfacePoints.h>

#include <cmath>
#include <limits>

namespace lacrima::rigging::detail {

PositionTolerances positionTolerances(const FeaturePointFile& file, const HeadMesh& mesh) {
  double diagonal = 0;
  if (mesh.vertexCount() > 0)
    diagonal = (mesh.boundsMax() - mesh.boundsMin()).cast<double>().norm();
  if (!std::isfinite(diagonal)) diagonal = 0;
  PositionTolerances t;
  t.match = kPositionMatch * diagonal;
  t.lost = kPositionLostDiagonal * diagonal;
  const auto left = file.points.find("3.5"), right = file.points.find("3.6");
  if (left != file.points.end() && right != file.points.end() && left->second.at.position &&
      right->second.at.position) {
    const double es0 = (*left->second.at.position - *right->second.at.position).norm();
    if (std::isfinite(es0) && es0 > 0) t.lost = kPositionLost * es0;
  }
  return t;
}

std::vector<Snap> snapToSubmesh(const HeadMesh& mesh, const HeadSubmesh& submesh,
                                const std::vector<const SurfacePoint*>& points) {
  std::vector<Snap> snaps(points.size());
  std::vector<std::size_t> onTriangles;  // triangle points, answered together below
  for (std::size_t k = 0; k < points.size(); ++k) {
    const SurfacePoint& p = *points[k];
    Snap& snap = snaps[k];
    snap.point = p;
    snap.residual = std::numeric_limits<double>::infinity();
    if (p.vertex < 0) {
      onTriangles.push_back(k);
      continue;
    }
    // Nearest vertex; on a tie (uv-seam copies at one position) the lowest index.
    const Eigen::Vector3f target = p.position->cast<float>();
    float best = std::numeric_limits<float>::infinity();
    for (int v = 0; v < submesh.vertexCount; ++v) {
      const float d = (mesh.positions.col(submesh.firstVertex + v) - target).squaredNorm();
      if (d < best) {
        best = d;
        snap.point.vertex = v;
      }
    }
    if (best < std::numeric_limits<float>::infinity()) {
      const Eigen::Vector3d at =
          mesh.positions.col(submesh.firstVertex + snap.point.vertex).cast<double>();
      snap.residual = (at - *p.position).norm();
      snap.point.position = at;
    }
  }
  if (onTriangles.empty() || submesh.triangles.empty()) return snaps;

  Eigen::Matrix3Xd queries(3, static_cast<Eigen::Index>(onTriangles.size()));
  for (std::size_t q = 0; q < onTriangles.size(); ++q)
    queries.col(static_cast<Eigen::Index>(q)) = *points[onTriangles[q]]->position;
  const Eigen::Matrix3Xd vertices = mesh.positions.cast<double>();
  const SurfacePoints closest = closestSurfacePoints(vertices, submesh.triangles, queries);
  for (std::size_t q = 0; q < onTriangles.size(); ++q) {
    const auto j = static_cast<Eigen::Index>(q);
    if (closest.triangle[j] < 0) continue;  // every triangle degenerate: nothing to snap to
    Snap& snap = snaps[onTriangles[q]];
    snap.point.triangle = closest.triangle[j];
    snap.point.barycentric = closest.barycentric.col(j);
    const Eigen::Vector3i t = submesh.triangles[static_cast<std::size_t>(snap.point.triangle)];
    const Eigen::Vector3d at = snap.point.barycentric[0] * vertices.col(t[0]) +
                               snap.point.barycentric[1] * vertices.col(t[1]) +
                               snap.point.barycentric[2] * vertices.col(t[2]);
    snap.residual = (at - *snap.point.position).norm();
    snap.point.position = at;
  }
  return snaps;
}

}  // namespace lacrima::rigging::detail
