#pragma once
// What a head's parts look like when its file gives them no texture (a custom head such as the
// ICT-FaceKit head, whose materials are plain greys): without this its eyes are blank balls
// and its skin and teeth one grey.
//
//   eyes  (role eye_left / eye_right, no texture): a generated eye texture (sclera, iris, pupil)
//         mapped by projecting each eye's vertices along its gaze (+z, the face frame's
//         forward) onto the disc of the eyeball seen from the front, so the iris and the pupil
//         sit where the eye looks and turn with it;
//   skin, teeth (no texture and a grey colour): a skin tone, an ivory;
//   lashes (attached, no texture, grey): not drawn, since a lash shell without its alpha
//         texture is a solid band over the eye.
// A part with a texture, or with a colour of its own (not grey), keeps it. The roles come from
// the rig (HeadSubmesh::role); the default head's own parts are named by role and textured.
#include <lacrima/common/HeadMesh.h>

#include <Eigen/Core>
#include <QImage>

#include <optional>

namespace lacrima::scene {

// Eye: 0 left, 1 right, -1 not an eye.
int eyeSideOf(const HeadSubmesh& part);
// An eye part drawn with the generated eye texture and projected uvs.
bool drawsGeneratedEye(const HeadMesh& head, const HeadSubmesh& part);
// The uvs to draw `head` with: its own (zeros where it has none), the generated eyes' projected.
Eigen::Matrix2Xf drawnUvs(const HeadMesh& head);

// Where the iris ends and where the pupil ends, as radii of the eyeball's front disc; in the
// generated texture the disc is the whole image (uv radius 0.5).
inline constexpr double kIrisOfEyeball = 0.46;
inline constexpr double kPupilOfIris = 0.42;
// The generated eye texture, `size` pixels square.
QImage generatedEyeTexture(int size = 256);

// What an untextured grey part is, if it is one of those above (lashes are hidden, the others
// drawn in untexturedColour).
enum class UntexturedKind { Skin, Teeth, Lashes };
std::optional<UntexturedKind> untexturedKind(const HeadSubmesh& part, const HeadMaterial& material);
Eigen::Vector4f untexturedColour(UntexturedKind kind);

}  // namespace lacrima::scene
