#pragma once
// The head as one OGRE mesh: all sub-meshes share one vertex array in two buffers,
//   source 0 (dynamic, rewritten every frame): position, normal    (6 floats)
//   source 1 (static):                         uv0, occlusion (uv1), tangent (uv2), horizons
//                                              (uv3, uv4): StaticShading     (15 floats)
// so a frame uploads the CPU-blended pose (PoseBlender) with one discard-lock and memcpy-like
// loop (about 0.26 MB for the default head) and OGRE never animates anything itself. Each head
// sub-mesh with triangles becomes an OGRE sub-mesh whose vertex data is a window
// [firstVertex, firstVertex + vertexCount) onto those shared buffers, with indices relative to
// it (16-bit when they fit): each draw call then covers only its own vertices, which matters on
// a software rasteriser, where vertex work runs on the calling thread. Bounds are the neutral
// bounds grown by half their size on every side, so no expression gets culled.
#include <lacrima/common/HeadMesh.h>
#include <lacrima/scene/SkinHorizons.h>

#include <OgreHardwareVertexBuffer.h>
#include <OgreMesh.h>

#include <vector>

namespace Ogre {
class Entity;
class SceneManager;
class SubEntity;
}  // namespace Ogre

namespace lacrima::scene::detail {

// What the shaders need per vertex that no pose changes, computed once per head; vertices
// beyond a vector's size get 1, (1, 0, 0, 1) and no horizon.
struct StaticShading {
  Eigen::Matrix2Xf uvs;                   // UntexturedParts.h's drawnUvs; none: the head's own
  std::vector<float> occlusion;           // HeadOcclusion.h
  std::vector<Eigen::Vector4f> tangents;  // HeadTangents.h
  std::vector<Horizons> horizons;         // SkinHorizons.h
};

class HeadGeometry {
 public:
  HeadGeometry(Ogre::SceneManager& scene, const HeadMesh& head, const StaticShading& shading,
               const std::string& name, const std::string& group);
  ~HeadGeometry();
  HeadGeometry(const HeadGeometry&) = delete;
  HeadGeometry& operator=(const HeadGeometry&) = delete;

  void update(const Eigen::Matrix3Xf& positions, const Eigen::Matrix3Xf& normals);
  Ogre::Entity& entity() { return *entity_; }
  // The sub-entity drawing head sub-mesh `submesh`, nullptr when it has no triangles.
  Ogre::SubEntity* subEntity(std::size_t submesh) const;

 private:
  Ogre::SceneManager& scene_;
  Ogre::MeshPtr mesh_;
  Ogre::VertexDeclaration* declaration_ = nullptr;  // shared by every sub-mesh's vertex window
  Ogre::VertexBufferBinding* binding_ = nullptr;
  Ogre::HardwareVertexBufferSharedPtr dynamic_;
  Ogre::Entity* entity_ = nullptr;
  std::vector<int> subEntityOf_;  // head sub-mesh -> OGRE sub-mesh index, -1 none
  int vertexCount_ = 0;
};

}  // namespace lacrima::scene::detail
