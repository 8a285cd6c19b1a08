#pragma once
// Re-snapping feature points whose index no longer leads to their stored position
// (FeaturePointFile.h, "position"): a vertex point goes to the nearest vertex of its sub-mesh,
// a triangle point to the closest point of its sub-mesh's surface (ClosestSurfacePoints.h).
#include <lacrima/common/HeadMesh.h>
#include <lacrima/rigging/FeaturePointFile.h>

#include <Eigen/Core>

#include <vector>

namespace lacrima::rigging::detail {

struct PositionTolerances {
  double match = 0;  // bound point to stored position: "where the file says"
  double lost = 0;   // stored position to the nearest of its sub-mesh: beyond, another mesh
};

// kPositionMatch x the bounding-box diagonal; kPositionLost x |3.5 - 3.6| from the stored
// positions when both have one, else kPositionLostDiagonal x the diagonal.
PositionTolerances positionTolerances(const FeaturePointFile& file, const HeadMesh& mesh);

struct Snap {
  SurfacePoint point;   // the new binding, its position set to where it now is
  double residual = 0;  // |new position - stored position|; +infinity when nothing to snap to
};

// For each of `points` (all on `submesh`, each with a position): the nearest vertex of the
// sub-mesh for a vertex point, the closest surface point for a triangle point. One pass over the
// sub-mesh for all of them.
std::vector<Snap> snapToSubmesh(const HeadMesh& mesh, const HeadSubmesh& submesh,
                                const std::vector<const SurfacePoint*>& points);

}  // namespace lacrima::rigging::detail
