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
// Heads without eye_l / eye_r sub-meshes are framed by their bounding box.
#include <lacrima/common/HeadMesh.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace lacrima::scene {

struct OrbitView {
  Eigen::Vector3d target = Eigen::Vector3d::Zero();
  double yawDegrees = 0, pitchDegrees = 0;
  double distance = 1;
  double fovYDegrees = 28;
  double minDistance = 0.01, maxDistance = 100;  // zoom limits

  static OrbitView framing(const HeadMesh& head);

  void orbit(double yawDelta, double pitchDelta);
  void zoom(double factor);  // < 1 moves closer; clamped to [minDistance, maxDistance]
  // Moves the target in the view plane by fractions of the view's height (right, up).
  void pan(double right, double up);

  Eigen::Vector3d eye() const;
  // Camera orientation (camera looks along its -z, +y up), in the head frame.
  Eigen::Quaterniond orientation() const;
  bool operator==(const OrbitView&) const = default;
};

}  // namespace lacrima::scene
