#pragma once
// Where the texture overlays apply, painted in the head's own uv space at start-up, so they fit
// any head with eye_l / eye_r and skin sub-meshes (nothing is authored per head).
//
// Per skin vertex p, for each eye (centre c, radius r = half the eyeball's largest extent):
//   periocular  1 - smoothstep(1.15, 2.3, |D (p - c)| / r), D = diag(1/1.35, 1/0.85 above the
//               eye's centre or 1/1.6 below it, 1/2): an ellipsoid reaching further sideways
//               and downwards (lids, the bags under the eyes: what reddens when crying) than up
//               (brows), and little in depth; only skin in front of the eyeball's back half.
//               Plus the nose tip, which reddens too: 0.7 (1 - smoothstep(0.2, 1, |p - t| / 1.1
//               r)), t the front-most skin point on the mid line 1 to 3.5 r below the eyes.
//   cheek       1 - smoothstep(0.3, 1.0, |D' (p - k)| / 1.9 r), D' = diag(1/1.3, 1, 1), with
//               k the front-most skin point below the eye at c + (0.25 r outwards, -2.4 r):
//               the cheekbone, where a blush shows; only skin facing forwards (n.z > 0.2).
// The weights of both eyes combine by max. They are interpolated over every skin triangle in
// uv space (barycentric), then the painted area is grown by a few texels (dilation) so bilinear
// filtering at uv seams never pulls in unpainted black.
//
// Mask image: Format_RGBA8888, red = periocular, green = cheek, blue = 0, alpha = 255. Without
// uvs, skin or eyes it is black (no overlay anywhere).
#include <lacrima/common/HeadMesh.h>

#include <QImage>

#include <Eigen/Core>

#include <optional>
#include <vector>

namespace lacrima::scene {

struct EyeSphere {
  Eigen::Vector3f centre = Eigen::Vector3f::Zero();
  float radius = 0;
};

// The eye_l / eye_r sub-meshes' centres and radii (bounding boxes), nullopt when absent or empty.
std::optional<EyeSphere> eyeSphere(const HeadMesh& head, const char* submesh);

struct OverlayVertexWeights {
  std::vector<float> periocular;  // per head vertex, 0 off the skin
  std::vector<float> cheek;
};

OverlayVertexWeights overlayVertexWeights(const HeadMesh& head);

// Paints per-vertex weights of the skin sub-mesh into a size x size mask (see above).
QImage paintOverlayMask(const HeadMesh& head, const OverlayVertexWeights& weights, int size = 512);

}  // namespace lacrima::scene
