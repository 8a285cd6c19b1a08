#pragma once
// Named cameras for judging a face and its tears in pictures (lacrima-player --render --view):
//
//   framing        the viewport's reset view (OrbitView::framing): a little to the face's left
//                  and above, the whole face in view
//   front          straight on, level, the same distance
//   three-quarter  45 degrees towards the face's left, slightly above
//   profile        from the face's left side, level
//   close-left     the left cheek under the left eye, where the left tear runs, filling the
//                  view (about 0.3 of the head's height), seen slightly from that side
//   close-right    the same for the right cheek
//
// Left and right are the face's own (MPEG-4's "l" is the face's left, at +x). Engine-free.
//
// From the mesh alone (presetView(head, preset)) the views measure the head by its bounding box
// and aim the close views at the cheek below the eye sub-mesh (eye_l / eye_r); a head without
// them is aimed a quarter of its width to that side of its bounding box centre. That suits the
// default head (a head cut at the neck, eyes named) and no other.
//
// With the face's landmarks (presetView(head, preset, face); a rigged head gives them:
// player::presetView(HeadRig, preset)) every view comes from the face itself, in any unit:
//  - the head's size is the bounding box of the head proper, the vertices above a neck cut
//    kNeckCutBelowChin ES0 below the chin (2.1), so a neck and shoulders do not count. The
//    default head is cut 0.61 ES0 below its chin: its box, and so its views, stay exactly the
//    mesh-only ones;
//  - the eyes are the eye sub-meshes' where the mesh names them eye_l / eye_r side by side in
//    the face frame (as OrbitView::framing finds them: the default head's views, bit for bit),
//    the landmarks' eye centres otherwise.
// The framing then follows OrbitView::framing's rule for a head with eyes (brows to chin in
// view, aimed between the eyes and the mouth), and the others follow the framing as before: on
// the ICT-FaceKit head (centimetres, neck and shoulders) close-left shows the left cheek under
// the eye at the default head's relative size, and so it does in millimetres.
#include <lacrima/common/HeadMesh.h>
#include <lacrima/scene/OrbitView.h>

#include <optional>
#include <string_view>

namespace lacrima::scene {

enum class CameraPreset { Framing, Front, ThreeQuarter, Profile, CloseLeft, CloseRight };

// "framing", "front", "three-quarter", "profile", "close-left", "close-right".
std::string_view toString(CameraPreset preset);
std::optional<CameraPreset> parseCameraPreset(std::string_view name);
// The names above, comma-separated, for help texts and error messages.
std::string_view cameraPresetNames();

OrbitView presetView(const HeadMesh& head, CameraPreset preset);

// Where a face is, in the head's coordinates (the face frame: +x the face's left, +y up, +z
// forward). A rig knows these (rigging::BuiltRig: eyeCentreLeft/Right or the pupils 3.5 / 3.6,
// feature point 2.1, fapu ES0); scene does not link the rig, so they come as plain numbers.
struct FaceLandmarks {
  Eigen::Vector3d eyeLeft = Eigen::Vector3d::Zero();   // centre of the face's left eye
  Eigen::Vector3d eyeRight = Eigen::Vector3d::Zero();  // and of its right eye
  Eigen::Vector3d chin = Eigen::Vector3d::Zero();      // 2.1, the bottom of the chin
  double eyeSeparation = 0;                            // ES0, the face's unit of size
};

// The neck cut of the head proper, in ES0 below the chin (see above).
inline constexpr double kNeckCutBelowChin = 0.75;

// The views of a head from its landmarks. Landmarks that are not finite, an ES0 that is not
// positive or eyes not side by side (left at +x, level within ES0) fall back to the mesh alone.
OrbitView presetView(const HeadMesh& head, CameraPreset preset, const FaceLandmarks& face);

}  // namespace lacrima::scene
