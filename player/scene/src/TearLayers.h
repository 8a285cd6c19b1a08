#pragma once
// The tears as three streamed objects: the tear surface (marching-cubes mesh, premultiplied
// water shading), the wet trails (skin-hugging strips with per-vertex wetness, depth-biased)
// and particle spheres (camera-facing impostors, 4 vertices and 6 indices each, shaded and
// depth-corrected as spheres: fast for 10,000 particles). A null or empty input hides its object.
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

class TearLayers {
 public:
  TearLayers(Ogre::SceneManager& scene, Ogre::SceneNode& node, const std::string& namePrefix,
             const std::string& group);
  ~TearLayers();
  TearLayers(const TearLayers&) = delete;
  TearLayers& operator=(const TearLayers&) = delete;

  void showSurface(const tears::TearSurface* surface);
  void showTrails(const tears::TrailMesh* trails);
  void showParticles(const tears::ParticleSet* particles, double radius);

 private:
  Ogre::SceneNode& node_;
  std::unique_ptr<StreamedGeometry> surface_, trails_, particles_;
};

}  // namespace lacrima::scene::detail
