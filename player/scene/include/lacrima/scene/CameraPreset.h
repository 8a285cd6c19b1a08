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
// Left and right are the face's own (MPEG-4's "l" is the face's left, at +x). The close views
// aim at the cheek below the eye sub-mesh (eye_l / eye_r); a head without them is aimed a
// quarter of its width to that side of its bounding box centre. Engine-free.
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

}  // namespace lacrima::scene
