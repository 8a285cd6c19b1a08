#include <lacrima/scene/OrbitView.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <utility>

namespace lacrima::scene {
namespace {

constexpr double kDegree = std::numbers::pi / 180.0;
constexpr double kPitchLimit = 85.0;

// Bounds of a vertex range in the face frame: the head's positions seen through F^T.
Eigen::AlignedBox3d boundsOf(const HeadMesh& head, int first, int count,
                             const Eigen::Matrix3d& toFace) {
  Eigen::AlignedBox3d box;
  for (int v = first; v < first + count; ++v)
    box.extend(toFace * head.positions.col(v).cast<double>());
  return box;
}

// Whether the eyes are where a face in this frame has them: apart mostly across (x), level,
// in the upper half. False for a head in another axis convention seen through the identity.
bool eyesFitTheFrame(const Eigen::Vector3d& left, const Eigen::Vector3d& right,
                     const Eigen::AlignedBox3d& all) {
  const Eigen::Vector3d apart = left - right;
  return std::abs(apart.x()) > 0.8 * apart.norm() &&
         0.5 * (left.y() + right.y()) > all.center().y();
}

}  // namespace

Eigen::Matrix3d faceFrameRotation(const Eigen::Matrix3d& frame) {
  // Gram-Schmidt from the axes that matter most: up kept, forward made perpendicular to it,
  // the side axis completing a right-handed frame (x = y cross z).
  const Eigen::Vector3d up = frame.col(1).normalized();
  const Eigen::Vector3d forward = (frame.col(2) - up.dot(frame.col(2)) * up).normalized();
  Eigen::Matrix3d rotation;
  rotation << up.cross(forward), up, forward;
  if (!rotation.allFinite() || std::abs(rotation.determinant() - 1) > 1e-6)
    return Eigen::Matrix3d::Identity();
  return rotation;
}

namespace {

// namedEyeCentres and framingFace with `frame` already a rotation (faceFrameRotation).
std::optional<std::pair<Eigen::Vector3d, Eigen::Vector3d>> eyeCentresIn(
    const HeadMesh& head, const Eigen::Matrix3d& frame) {
  const Eigen::Matrix3d toFace = frame.transpose();
  const HeadSubmesh* left = head.findSubmesh("eye_l");
  const HeadSubmesh* right = head.findSubmesh("eye_r");
  if (!left || !right || left->vertexCount <= 0 || right->vertexCount <= 0) return std::nullopt;
  const Eigen::AlignedBox3d all = boundsOf(head, 0, head.vertexCount(), toFace);
  const Eigen::Vector3d leftEye =
      boundsOf(head, left->firstVertex, left->vertexCount, toFace).center();
  const Eigen::Vector3d rightEye =
      boundsOf(head, right->firstVertex, right->vertexCount, toFace).center();
  if (!eyesFitTheFrame(leftEye, rightEye, all)) return std::nullopt;
  return std::pair{leftEye, rightEye};
}

OrbitView framedByEyes(const Eigen::Vector3d& leftEye, const Eigen::Vector3d& rightEye,
                       const Eigen::AlignedBox3d& headBox, const Eigen::Matrix3d& frame) {
  OrbitView view;
  view.frame = frame;
  const double height = headBox.sizes().y();
  view.fovYDegrees = 28;
  view.yawDegrees = 16;
  view.pitchDegrees = 4;
  const Eigen::Vector3d eyes = 0.5 * (leftEye + rightEye);
  // Brows to chin: the eyes sit about 0.09 head heights above the middle of the face.
  const Eigen::Vector3d target(eyes.x(), eyes.y() - 0.03 * height,
                               0.5 * (eyes.z() + headBox.center().z()));
  const double visibleHeight = 0.92 * height;
  view.distance =
      0.5 * visibleHeight / std::tan(0.5 * view.fovYDegrees * kDegree) + 0.25 * headBox.sizes().z();
  if (!(view.distance > 0)) view.distance = 1;  // a single point: any distance shows it
  view.target = view.frame * target;
  view.minDistance = 0.12 * view.distance;
  view.maxDistance = 8.0 * view.distance;
  return view;
}

}  // namespace

std::optional<std::pair<Eigen::Vector3d, Eigen::Vector3d>> namedEyeCentres(
    const HeadMesh& head, const Eigen::Matrix3d& frame) {
  return eyeCentresIn(head, faceFrameRotation(frame));
}

OrbitView OrbitView::framingFace(const Eigen::Vector3d& leftEye, const Eigen::Vector3d& rightEye,
                                 const Eigen::AlignedBox3d& headBox, const Eigen::Matrix3d& frame) {
  return framedByEyes(leftEye, rightEye, headBox, faceFrameRotation(frame));
}

OrbitView OrbitView::framing(const HeadMesh& head, const Eigen::Matrix3d& requestedFrame) {
  OrbitView view;
  view.frame = faceFrameRotation(requestedFrame);
  const Eigen::Matrix3d toFace = view.frame.transpose();
  const Eigen::AlignedBox3d all = boundsOf(head, 0, head.vertexCount(), toFace);
  if (all.isEmpty() || !all.sizes().allFinite()) return view;
  if (const auto eyes = eyeCentresIn(head, view.frame))
    return framedByEyes(eyes->first, eyes->second, all, view.frame);
  view.fovYDegrees = 28;
  view.yawDegrees = 16;
  view.pitchDegrees = 4;
  // Aimed at the bounding box's centre, the head's vertices fill 0.85 of the view from the
  // reset direction: with c a vertex relative to the target in camera axes (looking along -z),
  // a camera at distance d sees it at the tangent |c.y| / (d - c.z), so
  //   d = max over vertices of c.z + max(|c.x|, |c.y|) / (0.85 tan(fov / 2)),
  // the width counted like the height (conservative for any landscape view).
  const Eigen::Vector3d target = all.center();
  const Eigen::Matrix3d toCamera = view.cameraAxesInFace().transpose() * toFace;
  const double tangent = 0.85 * std::tan(0.5 * view.fovYDegrees * kDegree);
  const Eigen::Vector3d centre = view.frame * target;
  view.distance = 0;
  for (int v = 0; v < head.vertexCount(); ++v) {
    const Eigen::Vector3d c = toCamera * (head.positions.col(v).cast<double>() - centre);
    if (c.allFinite())
      view.distance =
          std::max(view.distance, c.z() + std::max(std::abs(c.x()), std::abs(c.y())) / tangent);
  }
  if (!(view.distance > 0)) view.distance = 1;  // a single point: any distance shows it
  view.target = view.frame * target;
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
  return target + distance * frame *
                      Eigen::Vector3d(std::sin(yaw) * std::cos(pitch), std::sin(pitch),
                                      std::cos(yaw) * std::cos(pitch));
}

Eigen::Matrix3d OrbitView::cameraAxesInFace() const {
  return (Eigen::AngleAxisd(yawDegrees * kDegree, Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(-pitchDegrees * kDegree, Eigen::Vector3d::UnitX()))
      .toRotationMatrix();
}

Eigen::Quaterniond OrbitView::orientation() const {
  return Eigen::Quaterniond(frame * cameraAxesInFace());
}

}  // namespace lacrima::scene
