#include <lacrima/scene/OrbitView.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace lacrima::scene {
namespace {

constexpr double kDegree = std::numbers::pi / 180.0;
constexpr double kPitchLimit = 85.0;

Eigen::AlignedBox3d boundsOf(const HeadMesh& head, const HeadSubmesh& sub) {
  Eigen::AlignedBox3d box;
  for (int v = sub.firstVertex; v < sub.firstVertex + sub.vertexCount; ++v)
    box.extend(head.positions.col(v).cast<double>());
  return box;
}

}  // namespace

OrbitView OrbitView::framing(const HeadMesh& head) {
  OrbitView view;
  Eigen::AlignedBox3d all;
  for (int v = 0; v < head.vertexCount(); ++v) all.extend(head.positions.col(v).cast<double>());
  if (all.isEmpty()) return view;
  const double height = all.sizes().y();
  const HeadSubmesh* left = head.findSubmesh("eye_l");
  const HeadSubmesh* right = head.findSubmesh("eye_r");
  double visibleHeight = 0;
  if (left && right && left->vertexCount > 0 && right->vertexCount > 0) {
    const Eigen::Vector3d eyes =
        0.5 * (boundsOf(head, *left).center() + boundsOf(head, *right).center());
    // Brows to chin: the eyes sit about 0.09 head heights above the middle of the face.
    view.target =
        Eigen::Vector3d(eyes.x(), eyes.y() - 0.03 * height, 0.5 * (eyes.z() + all.center().z()));
    visibleHeight = 0.92 * height;
  } else {
    view.target = all.center();
    visibleHeight = 1.1 * height;
  }
  view.fovYDegrees = 28;
  view.yawDegrees = 16;
  view.pitchDegrees = 4;
  view.distance =
      0.5 * visibleHeight / std::tan(0.5 * view.fovYDegrees * kDegree) + 0.25 * all.sizes().z();
  view.minDistance = 0.12 * view.distance;
  view.maxDistance = 8.0 * view.distance;
  return view;
}

void OrbitView::orbit(double yawDelta, double pitchDelta) {
  yawDegrees = std::remainder(yawDegrees + yawDelta, 360.0);
  pitchDegrees = std::clamp(pitchDegrees + pitchDelta, -kPitchLimit, kPitchLimit);
}

void OrbitView::zoom(double factor) {
  if (!(factor > 0) || !std::isfinite(factor)) return;
  distance = std::clamp(distance * factor, minDistance, maxDistance);
}

void OrbitView::pan(double right, double up) {
  if (!std::isfinite(right) || !std::isfinite(up)) return;
  const double viewHeight = 2.0 * distance * std::tan(0.5 * fovYDegrees * kDegree);
  const Eigen::Matrix3d axes = orientation().toRotationMatrix();
  target += viewHeight * (right * axes.col(0) + up * axes.col(1));
}

Eigen::Vector3d OrbitView::eye() const {
  const double yaw = yawDegrees * kDegree, pitch = pitchDegrees * kDegree;
  return target + distance * Eigen::Vector3d(std::sin(yaw) * std::cos(pitch), std::sin(pitch),
                                             std::cos(yaw) * std::cos(pitch));
}

Eigen::Quaterniond OrbitView::orientation() const {
  return Eigen::Quaterniond(Eigen::AngleAxisd(yawDegrees * kDegree, Eigen::Vector3d::UnitY()) *
                            Eigen::AngleAxisd(-pitchDegrees * kDegree, Eigen::Vector3d::UnitX()));
}

}  // namespace lacrima::scene
