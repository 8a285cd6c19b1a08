#pragma once
// What one rendered frame shows: the deformed head, the tears and the texture-blend weights.
// It is the seam between the engine-free playback layer (which produces it) and the OGRE scene
// (which draws it). Pointers stay valid until the producer's next frame; null means "nothing of
// this kind this frame", which is how effects that are switched off or not needed cost nothing
// downstream either.
#include <lacrima/common/HeadMesh.h>

#include <Eigen/Core>

#include <array>

namespace lacrima::tears {
class ParticleSet;
class TearSurface;
class TrailMesh;
}  // namespace lacrima::tears

namespace lacrima::playback {

// Texture-blend weights, each in [0, 1].
struct OverlayWeights {
  double redness = 0;                   // redder, darker skin around both eyes
  std::array<double, 2> wetEyes{0, 0};  // glossy, watery overlay on the left / right eye
  double blush = 0;                     // cheeks (optional effect)
  bool operator==(const OverlayWeights&) const = default;
};

struct FrameView {
  const HeadMesh* neutral = nullptr;            // topology, uvs, sub-meshes, materials
  const Eigen::Matrix3Xf* positions = nullptr;  // deformed head, 3 x vertex count
  const Eigen::Matrix3Xf* normals = nullptr;
  const tears::ParticleSet* particles = nullptr;  // non-null only when particle spheres are on
  double particleRadius = 0;                      // head units
  const tears::TearSurface* surface = nullptr;    // non-null when the surface is on and non-empty
  const tears::TearSurface* drops = nullptr;      // small drops on the skin as caps (DropCaps.h),
                                                  // shown with the surface; null when none
  const tears::TrailMesh* trails = nullptr;       // non-null when trails are on and non-empty
  OverlayWeights overlays;
  bool textureBlending = true;
  // Increases whenever anything above changed. A renderer that has drawn this revision need
  // not draw again (a static scene is not re-rendered).
  long long revision = 0;
};

}  // namespace lacrima::playback
