#pragma once
// The camera of a face scene in the terms people steer it by: a target point, yaw about the
// head's up axis (+y), pitch above the horizontal, a distance and a vertical field of view.
// Engine-free, so the framing and the mouse mapping can be tested without a display.
//
//   eye = target + distance (sin(yaw) cos(pitch), sin(pitch), cos(yaw) cos(pitch))
// yaw 0, pitch 0 looks at the face from the front (along -z); positive yaw moves the camera
// towards the face's left (+x), positive pitch above it. The camera always looks at the target
// with +y up; pitch stays within +-85 degrees so it never flips over the top.
//
// framing(head): the reset view. The face (brows to chin, about 0.8 of the head's height) fills
// the view; the target sits on the face's mid line at the eyes' depth between the eyes and the
// mouth, a little to the side and above so the cheeks (where tears run) show their relief.
// Heads without eye_l / eye_r sub-meshes, or whose eyes do not sit side by side in the upper
// half of the head in the view frame (a head in another axis convention), are framed whole from
// the same direction, aimed at their bounding box's centre (in the view frame) with every vertex
// inside 0.85 of the view, so any head in any unit and orientation is seen whole.
//
// The view frame: all of the above is in the face's frame, whose axes (the face's left, up,
// forward) are the columns of `frame` in head coordinates; identity for heads already in the
// face frame (HeadMesh.h). A head in another convention gets its frame from its anchors
// (setViewFrame in FaceScene / FaceViewport): the orbit then turns about the face's up and yaw 0
// looks at the face. With F = frame,
//   eye = target + distance F (sin(yaw) cos(pitch), sin(pitch), cos(yaw) cos(pitch)).
#include <lacrima/common/HeadMesh.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <optional>
#include <utility>

namespace lacrima::scene {

struct OrbitView {
  Eigen::Vector3d target = Eigen::Vector3d::Zero();
  double yawDegrees = 0, pitchDegrees = 0;
  double distance = 1;
  double fovYDegrees = 28;
  double minDistance = 0.01, maxDistance = 100;         // zoom limits
  Eigen::Matrix3d frame = Eigen::Matrix3d::Identity();  // face axes in head coordinates

  // `frame` is made a rotation first (faceFrameRotation).
  static OrbitView framing(const HeadMesh& head,
                           const Eigen::Matrix3d& frame = Eigen::Matrix3d::Identity());
  // framing's rule for a head whose eyes are known: eye centres and the head's box (the head
  // proper, without neck or shoulders) in the face frame. framing(head) is this with the
  // eye sub-meshes' centres (namedEyeCentres) and the whole head's box.
  static OrbitView framingFace(const Eigen::Vector3d& leftEye, const Eigen::Vector3d& rightEye,
                               const Eigen::AlignedBox3d& headBox,
                               const Eigen::Matrix3d& frame = Eigen::Matrix3d::Identity());

  void orbit(double yawDelta, double pitchDelta);
  void zoom(double factor);  // < 1 moves closer; clamped to [minDistance, maxDistance]
  // Moves the target in the view plane by fractions of the view's height (right, up).
  void pan(double right, double up);

  Eigen::Vector3d eye() const;
  // Camera orientation (camera looks along its -z, +y up), in the head frame.
  Eigen::Quaterniond orientation() const;
  // The same without the view frame: the camera's axes in the face frame.
  Eigen::Matrix3d cameraAxesInFace() const;
  bool operator==(const OrbitView&) const = default;
};

// The centres (bounding boxes, in the face frame) of the eye_l / eye_r sub-meshes when the head
// has both and they sit side by side in the upper half of the head in that frame; else nullopt.
std::optional<std::pair<Eigen::Vector3d, Eigen::Vector3d>> namedEyeCentres(
    const HeadMesh& head, const Eigen::Matrix3d& frame = Eigen::Matrix3d::Identity());

// `frame` made a rotation: its up axis (column 1) kept, its forward axis (column 2) made
// perpendicular to up, the side axis up x forward (column 0 only needs to point roughly the same
// way); identity when up and forward are zero, parallel or not finite.
Eigen::Matrix3d faceFrameRotation(const Eigen::Matrix3d& frame);

}  // namespace lacrima::scene
