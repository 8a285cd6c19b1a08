#include "StreamedGeometry.h"

#include <OgreCamera.h>
#include <OgreHardwareBufferManager.h>
#include <OgreNode.h>

#include <algorithm>

namespace lacrima::scene::detail {
namespace {

std::size_t grown(std::size_t current, std::size_t needed) {
  std::size_t capacity = std::max<std::size_t>(current, 1024);
  while (capacity < needed) capacity *= 2;
  return capacity;
}

}  // namespace

StreamedGeometry::StreamedGeometry(const std::string& name, std::span<const Attribute> layout)
    : Ogre::SimpleRenderable(name),
      vertexData_(std::make_unique<Ogre::VertexData>()),
      indexData_(std::make_unique<Ogre::IndexData>()) {
  std::size_t offset = 0;
  for (const Attribute& a : layout) {
    vertexData_->vertexDeclaration->addElement(0, offset, a.type, a.semantic, a.index);
    offset += Ogre::VertexElement::getTypeSize(a.type);
  }
  floatsPerVertex_ = static_cast<int>(offset / sizeof(float));
  mRenderOp.vertexData = vertexData_.get();
  mRenderOp.indexData = indexData_.get();
  mRenderOp.operationType = Ogre::RenderOperation::OT_TRIANGLE_LIST;
  mRenderOp.useIndexes = true;
  setVisible(false);
  setCastShadows(false);
}

StreamedGeometry::~StreamedGeometry() {
  mRenderOp.vertexData = nullptr;
  mRenderOp.indexData = nullptr;
}

float* StreamedGeometry::lockVertices(int vertices) {
  const auto needed = static_cast<std::size_t>(std::max(vertices, 1));
  if (!vertices_ || vertices_->getNumVertices() < needed) {
    vertices_ = Ogre::HardwareBufferManager::getSingleton().createVertexBuffer(
        static_cast<std::size_t>(floatsPerVertex_) * sizeof(float),
        grown(vertices_ ? vertices_->getNumVertices() : 0, needed),
        Ogre::HardwareBuffer::HBU_DYNAMIC_WRITE_ONLY_DISCARDABLE);
    vertexData_->vertexBufferBinding->setBinding(0, vertices_);
  }
  vertexData_->vertexStart = 0;
  vertexData_->vertexCount = static_cast<std::size_t>(std::max(vertices, 0));
  return static_cast<float*>(
      vertices_->lock(0, needed * vertices_->getVertexSize(), Ogre::HardwareBuffer::HBL_DISCARD));
}

void StreamedGeometry::unlockVertices() { vertices_->unlock(); }

std::uint32_t* StreamedGeometry::lockIndices(int indices) {
  const auto needed = static_cast<std::size_t>(std::max(indices, 1));
  if (!indices_ || indices_->getNumIndexes() < needed) {
    indices_ = Ogre::HardwareBufferManager::getSingleton().createIndexBuffer(
        Ogre::HardwareIndexBuffer::IT_32BIT,
        grown(indices_ ? indices_->getNumIndexes() : 0, needed),
        Ogre::HardwareBuffer::HBU_DYNAMIC_WRITE_ONLY_DISCARDABLE);
    indexData_->indexBuffer = indices_;
  }
  return static_cast<std::uint32_t*>(
      indices_->lock(0, needed * sizeof(std::uint32_t), Ogre::HardwareBuffer::HBL_DISCARD));
}

void StreamedGeometry::unlockIndices() { indices_->unlock(); }

void StreamedGeometry::setDrawn(int indices, const Eigen::Vector3f& low,
                                const Eigen::Vector3f& high) {
  indexData_->indexStart = 0;
  indexData_->indexCount = static_cast<std::size_t>(std::max(indices, 0));
  if (indices <= 0 || !indices_ || !vertices_) {
    hide();
    return;
  }
  setBoundingBox(Ogre::AxisAlignedBox(low.x(), low.y(), low.z(), high.x(), high.y(), high.z()));
  radius_ = 0.5f * (high - low).norm();
  setVisible(true);
  if (Ogre::Node* node = getParentNode()) node->needUpdate();
}

void StreamedGeometry::hide() {
  indexData_->indexCount = 0;
  setVisible(false);
}

Ogre::Real StreamedGeometry::getSquaredViewDepth(const Ogre::Camera* camera) const {
  const Ogre::Vector3 centre = getParentNode()
                                   ? getParentNode()->_getDerivedPosition() + mBox.getCenter()
                                   : mBox.getCenter();
  return (camera->getDerivedPosition() - centre).squaredLength();
}

Ogre::Real StreamedGeometry::getBoundingRadius() const { return radius_; }

}  // namespace lacrima::scene::detail
