#pragma once
// The face frame: +x the face's own left, +y up, +z forward (out of the face), the frame the
// rest of Lacrima assumes (HeadMesh.h): the tears fall along -y, the unit scale is the head's
// extent along y, the orbit camera and the reference renders look at the face from +z. A head
// exported Z-up, or facing -z or +y, is brought into it before the rig is built.
//
// Measured from the feature points, in the mesh's own coordinates:
//
//   x = (e_L - e_R) / |e_L - e_R|                        right eye to left eye (MPEG-4's left is
//                                                        the face's own left)
//   u = (e_L + e_R) / 2 - m                              mouth to between the eyes
//   y = (u - (u.x) x) / |u - (u.x) x|                    up, made orthogonal to the eye line
//   z = x × y                                            forward, right-handed
//   A = [x y z]                                          (columns; A^T A = I, det A = 1)
//
// with e_L, e_R the pupils 3.5 / 3.6 (else the mid-points of the eye corners 3.7-3.11 and
// 3.8-3.12, the anchors a user places first) and m the mid-point of the mouth corners 8.3 / 8.4
// (else the chin 2.10). The eye line is the most precise of these (two symmetric points far
// apart), so it is kept exactly and the up vector gives way to it.
//
// The rotation applied is not A^T itself but the nearest of the 24 axis-aligned rotations
// (a permutation of the axes with signs, det +1):
//
//   R = argmax over R in G24 of trace(R A)   ( = argmin |R A - I|_F, since |R A - I|_F^2 =
//                                              6 - 2 trace(R A) )
//
// R covers every export convention (Y-up or Z-up, facing any axis) and is exact in floating
// point: it only moves and negates coordinates, so a Y-up head (R = I) is left bit-identical
// and a Z-up copy of it comes out with the same numbers. What remains, R A, is how far the face
// is turned in the model (a head modelled looking down stays looking down); its angle
//
//   tilt = acos((trace(R A) - 1) / 2)
//
// is reported and warned about above kFaceTiltWarningDegrees.
#include <lacrima/common/Diagnostics.h>
#include <lacrima/common/HeadMesh.h>
#include <lacrima/rigging/FeaturePointFile.h>

#include <Eigen/Core>

#include <optional>

namespace lacrima::rigging {

// Anatomy alone turns the measured frame a few degrees from the axes of a head modelled upright
// (the mouth sits in front of the eyes: the default head 5.0 degrees, the ICT head 2.5; a head
// in a natural pose stays within about 10); beyond 20 the face is turned in the model, and
// "down" for the tears is the model's, not the chin's.
inline constexpr double kFaceTiltWarningDegrees = 20.0;

struct FaceFrame {
  // canonical = rotation * mesh coordinates; one of the 24 axis-aligned rotations.
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  // A: the face's axes (columns left, up, forward) in mesh coordinates, as measured.
  Eigen::Matrix3d measured = Eigen::Matrix3d::Identity();
  double tiltDegrees = 0;    // angle of rotation * measured: the face's turn left in the model
  bool wasMeasured = false;  // false when the points needed were missing or degenerate
};

// A from the eyes and the mouth (see above), or nullopt when they are not three distinct
// points off one line (the eyes coincide, or the mouth lies on the eye line).
std::optional<Eigen::Matrix3d> faceAxes(const Eigen::Vector3d& leftEye,
                                        const Eigen::Vector3d& rightEye,
                                        const Eigen::Vector3d& mouth);

// The face's axes from the feature points of `fdp` on `mesh` (validated), or nullopt when the
// eyes (3.5/3.6 or the corners) or the mouth (8.3/8.4 or 2.10) are missing or degenerate.
std::optional<Eigen::Matrix3d> faceAxes(const FeaturePointFile& fdp, const HeadMesh& mesh);

// R: the rotation in G24 nearest to A^T (maximises trace(R A)); ties go to the first in a fixed
// order, so the answer is deterministic.
Eigen::Matrix3d nearestAxisRotation(const Eigen::Matrix3d& axes);

// The angle of a rotation matrix, in degrees, in [0, 180].
double rotationDegrees(const Eigen::Matrix3d& rotation);

// The whole frame for a validated file on its mesh; rotation I and wasMeasured false when the
// axes cannot be measured.
FaceFrame measureFaceFrame(const FeaturePointFile& fdp, const HeadMesh& mesh);

// x <- R x for every column, done by moving and negating coordinates (R must be in G24), so the
// result is exact. Positions and normals alike (R is a rotation).
void applyAxisRotation(const Eigen::Matrix3d& rotation, Eigen::Matrix3Xf& columns);
Eigen::Vector3d applyAxisRotation(const Eigen::Matrix3d& rotation, const Eigen::Vector3d& x);

// Brings a head and its validated feature-point file into the face frame: measures it, rotates
// the mesh's positions and normals and every coordinate the file gives in mesh coordinates (eye
// centres, neck pivot, stored positions; radii are lengths and stay). Nothing is touched when
// R = I. Appends a warning naming fdp.path when the frame cannot be measured (the head is used
// as modelled) or the face is tilted more than kFaceTiltWarningDegrees.
FaceFrame bringToFaceFrame(HeadMesh& mesh, FeaturePointFile& fdp, Warnings* warnings);

}  // namespace lacrima::rigging
