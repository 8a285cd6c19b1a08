#pragma once
// The tears as four streamed objects: the tear surface (marching-cubes mesh, premultiplied
// water shading), the small drops on the skin (spherical caps, shaded the same), the wet trails
// (skin-hugging strips with per-vertex wetness, depth-biased) and particle spheres (camera-facing
// impostors, 4 vertices and 6 indices each, shaded and depth-corrected as spheres: fast for 10,000
// particles). A null or empty input hides its object.
#include "StreamedGeometry.h"

#include <memory>
#include <string>

namespace Ogre {
class SceneManager;
class SceneNode;
}  // namespace Ogre

namespace lacrima::tears {
class ParticleSet;
class TearSurface;
class TrailMesh;
}  // namespace lacrima::tears

namespace lacrima::scene::detail {

// Render queue groups: the opaque head first (main queue, 50), then the backdrop behind it,
// then trails on the skin, then the tear water over them, then eyelashes and brows in front of
// everything.
inline constexpr unsigned char kBackdropQueue = 51;
inline constexpr unsigned char kTrailQueue = 52;
inline constexpr unsigned char kTearQueue = 53;
inline constexpr unsigned char kCardQueue = 54;

// Where trails overlap (drops following one another down the same path each leave one), the
// skin must be tinted and the water's light added once, not once per strip: stacked, a stream
// of drops would draw a dark line with a blown-out highlight. The trail's two passes therefore
// run under a stencil test: the tint pass draws where no trail has drawn yet this frame and marks
// the pixel 1, the light pass draws where the mark is 1 and raises it to 2. Trails are drawn
// newest first, so the freshest water wins where they overlap.
class TrailStencil;

class TearLayers {
 public:
  TearLayers(Ogre::SceneManager& scene, Ogre::SceneNode& node, const std::string& namePrefix,
             const std::string& group);
  ~TearLayers();
  TearLayers(const TearLayers&) = delete;
  TearLayers& operator=(const TearLayers&) = delete;

  void showSurface(const tears::TearSurface* surface);
  void showDrops(const tears::TearSurface* caps);
  void showTrails(const tears::TrailMesh* trails);
  void showParticles(const tears::ParticleSet* particles, double radius);

 private:
  Ogre::SceneManager& scene_;
  Ogre::SceneNode& node_;
  std::unique_ptr<StreamedGeometry> surface_, drops_, trails_, particles_;
  std::unique_ptr<TrailStencil> stencil_;
};

}  // namespace lacrima::scene::detail
