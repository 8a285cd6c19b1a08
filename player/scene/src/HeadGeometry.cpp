#include "HeadGeometry.h"

#include <OgreEntity.h>
#include <OgreHardwareBufferManager.h>
#include <OgreMeshManager.h>
#include <OgreSceneManager.h>
#include <OgreSubEntity.h>
#include <OgreSubMesh.h>

#include <algorithm>
#include <cstdint>
#include <cstring>

namespace lacrima::scene::detail {
namespace {

template <typename Index>
Ogre::HardwareIndexBufferSharedPtr indexBuffer(const std::vector<Eigen::Vector3i>& triangles,
                                               int base,
                                               Ogre::HardwareIndexBuffer::IndexType type) {
  std::vector<Index> indices;
  indices.reserve(triangles.size() * 3);
  for (const Eigen::Vector3i& t : triangles)
    for (int k = 0; k < 3; ++k) indices.push_back(static_cast<Index>(t[k] - base));
  auto buffer = Ogre::HardwareBufferManager::getSingleton().createIndexBuffer(
      type, indices.size(), Ogre::HardwareBuffer::HBU_STATIC_WRITE_ONLY);
  buffer->writeData(0, indices.size() * sizeof(Index), indices.data(), true);
  return buffer;
}

}  // namespace

HeadGeometry::HeadGeometry(Ogre::SceneManager& scene, const HeadMesh& head,
                           const StaticShading& shading, const std::string& name,
                           const std::string& group)
    : scene_(scene), vertexCount_(head.vertexCount()) {
  auto& buffers = Ogre::HardwareBufferManager::getSingleton();
  const auto n = static_cast<std::size_t>(head.vertexCount());
  mesh_ = Ogre::MeshManager::getSingleton().createManual(name, group);
  declaration_ = buffers.createVertexDeclaration();
  binding_ = buffers.createVertexBufferBinding();
  Ogre::VertexDeclaration* declaration = declaration_;
  declaration->addElement(0, 0, Ogre::VET_FLOAT3, Ogre::VES_POSITION);
  declaration->addElement(0, 12, Ogre::VET_FLOAT3, Ogre::VES_NORMAL);
  declaration->addElement(1, 0, Ogre::VET_FLOAT2, Ogre::VES_TEXTURE_COORDINATES, 0);
  declaration->addElement(1, 8, Ogre::VET_FLOAT1, Ogre::VES_TEXTURE_COORDINATES, 1);
  declaration->addElement(1, 12, Ogre::VET_FLOAT4, Ogre::VES_TEXTURE_COORDINATES, 2);
  declaration->addElement(1, 28, Ogre::VET_FLOAT4, Ogre::VES_TEXTURE_COORDINATES, 3);
  declaration->addElement(1, 44, Ogre::VET_FLOAT4, Ogre::VES_TEXTURE_COORDINATES, 4);

  dynamic_ = buffers.createVertexBuffer(6 * sizeof(float), n,
                                        Ogre::HardwareBuffer::HBU_DYNAMIC_WRITE_ONLY_DISCARDABLE);
  constexpr std::size_t kStatic = 15;  // floats per vertex in source 1
  std::vector<float> fixed(kStatic * n, 0.0f);
  const Eigen::Matrix2Xf& uvs =
      shading.uvs.cols() == head.positions.cols() ? shading.uvs : head.uvs;
  const bool hasUvs = uvs.cols() == head.positions.cols();
  for (std::size_t v = 0; v < n; ++v) {
    float* out = fixed.data() + kStatic * v;
    if (hasUvs) {
      out[0] = uvs(0, static_cast<Eigen::Index>(v));
      out[1] = uvs(1, static_cast<Eigen::Index>(v));
    }
    out[2] = v < shading.occlusion.size() ? shading.occlusion[v] : 1.0f;
    const Eigen::Vector4f tangent =
        v < shading.tangents.size() ? shading.tangents[v] : Eigen::Vector4f(1, 0, 0, 1);
    for (int k = 0; k < 4; ++k) out[3 + k] = tangent[k];
    if (v < shading.horizons.size()) std::copy_n(shading.horizons[v].begin(), 8, out + 7);
  }
  auto staticBuffer = buffers.createVertexBuffer(kStatic * sizeof(float), n,
                                                 Ogre::HardwareBuffer::HBU_STATIC_WRITE_ONLY);
  staticBuffer->writeData(0, fixed.size() * sizeof(float), fixed.data(), true);
  binding_->setBinding(0, dynamic_);
  binding_->setBinding(1, staticBuffer);

  subEntityOf_.assign(head.submeshes.size(), -1);
  int next = 0;
  for (std::size_t s = 0; s < head.submeshes.size(); ++s) {
    const HeadSubmesh& source = head.submeshes[s];
    if (source.triangles.empty()) continue;
    // The sub-mesh's own vertex range, unless a triangle reaches outside it (then all vertices).
    int first = source.firstVertex, count = source.vertexCount;
    for (const Eigen::Vector3i& t : source.triangles)
      if (t.minCoeff() < first || t.maxCoeff() >= first + count) {
        first = 0;
        count = static_cast<int>(n);
        break;
      }
    Ogre::SubMesh* sub = mesh_->createSubMesh(source.name + "#" + std::to_string(s));
    sub->useSharedVertices = false;
    sub->vertexData = OGRE_NEW Ogre::VertexData(declaration_, binding_);  // does not own them
    sub->vertexData->vertexStart = static_cast<std::size_t>(first);
    sub->vertexData->vertexCount = static_cast<std::size_t>(count);
    sub->indexData->indexBuffer =
        count > 65535 ? indexBuffer<std::uint32_t>(source.triangles, first,
                                                   Ogre::HardwareIndexBuffer::IT_32BIT)
                      : indexBuffer<std::uint16_t>(source.triangles, first,
                                                   Ogre::HardwareIndexBuffer::IT_16BIT);
    sub->indexData->indexStart = 0;
    sub->indexData->indexCount = source.triangles.size() * 3;
    subEntityOf_[s] = next++;
  }

  Eigen::Vector3f low = head.boundsMin(), high = head.boundsMax();
  if (n == 0) low = high = Eigen::Vector3f::Zero();
  const Eigen::Vector3f pad = 0.5f * (high - low) + Eigen::Vector3f::Constant(1e-3f);
  low -= pad;
  high += pad;
  mesh_->_setBounds(Ogre::AxisAlignedBox(low.x(), low.y(), low.z(), high.x(), high.y(), high.z()),
                    false);
  mesh_->_setBoundingSphereRadius(0.5f * (high - low).norm());
  mesh_->load();

  update(head.positions, head.normals.cols() == head.positions.cols()
                             ? head.normals
                             : Eigen::Matrix3Xf::Zero(3, head.positions.cols()));
  entity_ = scene_.createEntity(mesh_);
}

HeadGeometry::~HeadGeometry() {
  if (entity_) scene_.destroyEntity(entity_);
  dynamic_.reset();
  const std::string name = mesh_->getName(), group = mesh_->getGroup();
  mesh_.reset();
  Ogre::MeshManager::getSingleton().remove(name, group);  // deletes the sub-meshes' vertex windows
  auto& buffers = Ogre::HardwareBufferManager::getSingleton();
  buffers.destroyVertexBufferBinding(binding_);
  buffers.destroyVertexDeclaration(declaration_);
}

void HeadGeometry::update(const Eigen::Matrix3Xf& positions, const Eigen::Matrix3Xf& normals) {
  if (positions.cols() != vertexCount_ || normals.cols() != vertexCount_ || vertexCount_ == 0)
    return;
  auto* out = static_cast<float*>(dynamic_->lock(Ogre::HardwareBuffer::HBL_DISCARD));
  const float* p = positions.data();
  const float* q = normals.data();
  for (int v = 0; v < vertexCount_; ++v, out += 6, p += 3, q += 3) {
    std::memcpy(out, p, 3 * sizeof(float));
    std::memcpy(out + 3, q, 3 * sizeof(float));
  }
  dynamic_->unlock();
}

Ogre::SubEntity* HeadGeometry::subEntity(std::size_t submesh) const {
  if (submesh >= subEntityOf_.size() || subEntityOf_[submesh] < 0) return nullptr;
  return entity_->getSubEntity(static_cast<std::size_t>(subEntityOf_[submesh]));
}

}  // namespace lacrima::scene::detail
