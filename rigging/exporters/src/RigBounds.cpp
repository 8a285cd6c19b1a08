#include "RigBounds.h"

#include <lacrima/common/FapTable.h>

#include <algorithm>

namespace lacrima::exporters {
namespace {

// Distance from `centre` to the farthest corner of the box [lo, hi].
float farthestCorner(const Eigen::Vector3f& lo, const Eigen::Vector3f& hi,
                     const Eigen::Vector3f& centre) {
  return (lo - centre).cwiseAbs().cwiseMax((hi - centre).cwiseAbs()).norm();
}

// Every member of `group` may end up anywhere on the sphere it sweeps about the centre: widen
// each member's box to the sphere's box (radius of the farthest member).
void sweepRotation(const RotationGroup& group, Eigen::Matrix3Xf& lo, Eigen::Matrix3Xf& hi) {
  float radius = 0.0f;
  for (int v : group.vertices)
    radius = std::max(radius, farthestCorner(lo.col(v), hi.col(v), group.centre));
  const Eigen::Vector3f reach = Eigen::Vector3f::Constant(radius);
  for (int v : group.vertices) {
    lo.col(v) = lo.col(v).cwiseMin(group.centre - reach);
    hi.col(v) = hi.col(v).cwiseMax(group.centre + reach);
  }
}

}  // namespace

Eigen::AlignedBox3f reachableBounds(const HeadMesh& head, const PoseSet& poses,
                                    const std::vector<ExportedPose>& exported, float rangeFactor) {
  Eigen::Matrix3Xf lo = head.positions;
  Eigen::Matrix3Xf hi = head.positions;
  for (const ExportedPose& pose : exported) {
    const FapInfo& info = fapInfo(pose.fap);
    // Exported offsets are for a value of kExportedPoseValue; scale the value range instead.
    const float low =
        std::min(0.0f, rangeFactor * static_cast<float>(info.sliderMin)) / kExportedPoseValue;
    const float high =
        std::max(0.0f, rangeFactor * static_cast<float>(info.sliderMax)) / kExportedPoseValue;
    for (std::size_t k = 0; k < pose.vertices.size(); ++k) {
      const Eigen::Vector3f d = pose.offsets.col(static_cast<Eigen::Index>(k));
      const Eigen::Vector3f a = low * d;
      const Eigen::Vector3f b = high * d;
      lo.col(pose.vertices[k]) += a.cwiseMin(b);
      hi.col(pose.vertices[k]) += a.cwiseMax(b);
    }
  }
  // Eyes turn inside the head's rotation (p = R_head(E_v(...))), so they are swept first.
  sweepRotation(poses.eyeLeft, lo, hi);
  sweepRotation(poses.eyeRight, lo, hi);
  sweepRotation(poses.head, lo, hi);
  return Eigen::AlignedBox3f(lo.rowwise().minCoeff(), hi.rowwise().maxCoeff());
}

}  // namespace lacrima::exporters
