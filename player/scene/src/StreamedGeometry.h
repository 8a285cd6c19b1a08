#pragma once
// Geometry whose size changes every frame (tear surface, trails, particle impostors): one
// dynamic vertex buffer and one 32-bit index buffer, both rewritten with a discard lock each
// frame and replaced by one twice as large only when a frame needs more, so steady playback
// allocates nothing. An empty frame hides the object (no draw call at all).
#include <OgreHardwareIndexBuffer.h>
#include <OgreHardwareVertexBuffer.h>
#include <OgreSimpleRenderable.h>

#include <Eigen/Core>

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

namespace lacrima::scene::detail {

class StreamedGeometry : public Ogre::SimpleRenderable {
 public:
  struct Attribute {
    Ogre::VertexElementType type;
    Ogre::VertexElementSemantic semantic;
    unsigned short index = 0;
  };
  StreamedGeometry(const std::string& name, std::span<const Attribute> layout);
  ~StreamedGeometry() override;

  int floatsPerVertex() const { return floatsPerVertex_; }
  // Write access to `vertices` vertices (floatsPerVertex() floats each); unlock before drawing.
  float* lockVertices(int vertices);
  void unlockVertices();
  std::uint32_t* lockIndices(int indices);
  void unlockIndices();
  // Draws the first `indices` indices; 0 hides the object.
  void setDrawn(int indices, const Eigen::Vector3f& low, const Eigen::Vector3f& high);
  void hide();

  Ogre::Real getSquaredViewDepth(const Ogre::Camera* camera) const override;
  Ogre::Real getBoundingRadius() const override;

 private:
  std::unique_ptr<Ogre::VertexData> vertexData_;
  std::unique_ptr<Ogre::IndexData> indexData_;
  Ogre::HardwareVertexBufferSharedPtr vertices_;
  Ogre::HardwareIndexBufferSharedPtr indices_;
  int floatsPerVertex_ = 0;
  Ogre::Real radius_ = 0;
};

}  // namespace lacrima::scene::detail
