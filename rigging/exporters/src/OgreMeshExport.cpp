#include <lacrima/exporters/OgreMeshExport.h>

#include "OgreMaterialScript.h"
#include "RigBounds.h"
#include "StagedFiles.h"

#include <lacrima/common/Diagnostics.h>
#include <lacrima/exporters/HeadlessOgre.h>
#include <lacrima/exporters/RigExport.h>

#include <OgreAnimation.h>
#include <OgreAnimationTrack.h>
#include <OgreHardwareBufferManager.h>
#include <OgreKeyFrame.h>
#include <OgreMaterial.h>
#include <OgreMaterialManager.h>
#include <OgreMesh.h>
#include <OgreMeshManager.h>
#include <OgreMeshSerializer.h>
#include <OgrePose.h>
#include <OgreSubMesh.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <limits>

namespace lacrima::exporters {
namespace {

namespace fs = std::filesystem;

// MeshSerializer writes to a DataStream; collecting the bytes in memory lets the .mesh go
// through StagedFiles like the other files, instead of OGRE writing to the target directly.
class StringDataStream : public Ogre::DataStream {
 public:
  StringDataStream() : Ogre::DataStream(WRITE) {}

  std::string take() { return std::move(bytes_); }

  size_t read(void*, size_t) override { return 0; }
  size_t write(const void* buffer, size_t count) override {
    // Overwrites after a seek() back, appends at the end.
    const size_t end = position_ + count;
    if (end > bytes_.size()) bytes_.resize(end);
    std::memcpy(bytes_.data() + position_, buffer, count);
    position_ = end;
    mSize = bytes_.size();
    return count;
  }
  void skip(long count) override {
    seek(static_cast<size_t>(std::max(0L, static_cast<long>(position_) + count)));
  }
  void seek(size_t position) override { position_ = std::min(position, bytes_.size()); }
  size_t tell() const override { return position_; }
  bool eof() const override { return position_ >= bytes_.size(); }
  void close() override {}

 private:
  std::string bytes_;
  size_t position_ = 0;
};

// A manual mesh under a name nobody else uses (an application's OGRE may hold meshes of its
// own), removed from the MeshManager when the export is done.
class ScratchMesh {
 public:
  ScratchMesh() {
    static std::atomic<unsigned> counter{0};
    const std::string name = "lacrima/export/" + std::to_string(++counter);
    mesh_ = Ogre::MeshManager::getSingleton().createManual(name, Ogre::RGN_DEFAULT);
  }
  ~ScratchMesh() {
    Ogre::MeshManager::getSingleton().remove(mesh_);
    mesh_.reset();
  }
  ScratchMesh(const ScratchMesh&) = delete;
  ScratchMesh& operator=(const ScratchMesh&) = delete;

  Ogre::Mesh& operator*() const { return *mesh_; }
  Ogre::Mesh* operator->() const { return mesh_.get(); }

 private:
  Ogre::MeshPtr mesh_;
};

// A sub-mesh records its material as a MaterialPtr, and the serializer writes that material's
// name: a name OGRE does not know would be written as "". So the materials a sub-mesh names get
// stand-ins (empty materials) for the duration of the export; materials that already exist, e.g.
// in an editor that shows this head, are used as they are and left alone.
class StandInMaterials {
 public:
  explicit StandInMaterials(const std::vector<std::string>& names) {
    auto& manager = Ogre::MaterialManager::getSingleton();
    for (const std::string& name : names) {
      if (!manager.getByName(name)) created_.push_back(manager.create(name, Ogre::RGN_DEFAULT));
    }
  }
  ~StandInMaterials() {
    for (const Ogre::MaterialPtr& material : created_)
      Ogre::MaterialManager::getSingleton().remove(material);
  }
  StandInMaterials(const StandInMaterials&) = delete;
  StandInMaterials& operator=(const StandInMaterials&) = delete;

 private:
  std::vector<Ogre::MaterialPtr> created_;
};

// Buffers are created with a shadow copy: with a real render system (an export from inside the
// editor) the serializer can then read them back; the headless buffer manager ignores the flag.
Ogre::HardwareVertexBufferSharedPtr vertexBuffer(size_t vertexSize, size_t count,
                                                 const float* data) {
  auto buffer = Ogre::HardwareBufferManager::getSingleton().createVertexBuffer(
      vertexSize, count, Ogre::HardwareBuffer::HBU_STATIC_WRITE_ONLY, true);
  buffer->writeData(0, buffer->getSizeInBytes(), data, true);
  return buffer;
}

void addSharedGeometry(Ogre::Mesh& mesh, const HeadMesh& head) {
  const auto n = static_cast<size_t>(head.vertexCount());
  const bool hasUvs = head.uvs.cols() != 0;
  // The mesh owns and deletes its shared vertex data when it is unloaded.
  mesh.sharedVertexData = new Ogre::VertexData();
  Ogre::VertexData& data = *mesh.sharedVertexData;
  data.vertexCount = n;
  Ogre::VertexDeclaration& declaration = *data.vertexDeclaration;
  declaration.addElement(0, 0, Ogre::VET_FLOAT3, Ogre::VES_POSITION);
  declaration.addElement(1, 0, Ogre::VET_FLOAT3, Ogre::VES_NORMAL);
  if (hasUvs)
    declaration.addElement(1, 3 * sizeof(float), Ogre::VET_FLOAT2, Ogre::VES_TEXTURE_COORDINATES,
                           0);

  // Eigen's 3 x n column-major storage already is x y z per vertex.
  data.vertexBufferBinding->setBinding(0,
                                       vertexBuffer(3 * sizeof(float), n, head.positions.data()));
  const size_t stride = hasUvs ? 5 : 3;
  std::vector<float> attributes(n * stride);
  for (size_t v = 0; v < n; ++v) {
    float* out = &attributes[v * stride];
    const auto col = static_cast<Eigen::Index>(v);
    for (int k = 0; k < 3; ++k) out[k] = head.normals(k, col);
    if (hasUvs) {
      out[3] = head.uvs(0, col);  // already v-down, as OGRE samples textures
      out[4] = head.uvs(1, col);
    }
  }
  data.vertexBufferBinding->setBinding(1,
                                       vertexBuffer(stride * sizeof(float), n, attributes.data()));
}

template <typename Index>
void fillIndices(Ogre::HardwareIndexBuffer& buffer, const std::vector<Eigen::Vector3i>& triangles) {
  std::vector<Index> indices;
  indices.reserve(triangles.size() * 3);
  for (const Eigen::Vector3i& t : triangles)
    for (int k = 0; k < 3; ++k) indices.push_back(static_cast<Index>(t[k]));
  buffer.writeData(0, buffer.getSizeInBytes(), indices.data(), true);
}

void addSubmesh(Ogre::Mesh& mesh, const HeadSubmesh& source, const std::string& material) {
  Ogre::SubMesh* sub = source.name.empty() ? mesh.createSubMesh() : mesh.createSubMesh(source.name);
  sub->useSharedVertices = true;
  sub->operationType = Ogre::RenderOperation::OT_TRIANGLE_LIST;
  sub->setMaterialName(material);
  const size_t count = source.triangles.size() * 3;
  sub->indexData->indexStart = 0;
  sub->indexData->indexCount = count;
  if (count == 0) return;
  // Indices are global (shared geometry): a sub-mesh late in the vertex array needs 32 bits
  // even if it is small. 0xFFFF itself is avoided: GL may treat it as primitive restart.
  int largest = 0;
  for (const Eigen::Vector3i& t : source.triangles) largest = std::max(largest, t.maxCoeff());
  const bool wide = largest >= std::numeric_limits<std::uint16_t>::max();
  auto buffer = Ogre::HardwareBufferManager::getSingleton().createIndexBuffer(
      wide ? Ogre::HardwareIndexBuffer::IT_32BIT : Ogre::HardwareIndexBuffer::IT_16BIT, count,
      Ogre::HardwareBuffer::HBU_STATIC_WRITE_ONLY, true);
  if (wide)
    fillIndices<std::uint32_t>(*buffer, source.triangles);
  else
    fillIndices<std::uint16_t>(*buffer, source.triangles);
  sub->indexData->indexBuffer = buffer;
}

void addPoses(Ogre::Mesh& mesh, const std::vector<ExportedPose>& exported) {
  constexpr unsigned short kSharedGeometry = 0;  // pose/track target 0; sub-mesh i is i + 1
  for (const ExportedPose& source : exported) {
    Ogre::Pose* pose = mesh.createPose(kSharedGeometry, source.name);
    for (size_t k = 0; k < source.vertices.size(); ++k) {
      const auto offset = source.offsets.col(static_cast<Eigen::Index>(k));
      pose->addVertex(static_cast<size_t>(source.vertices[k]),
                      Ogre::Vector3(offset.x(), offset.y(), offset.z()));
    }
  }
  // Created even with no poses, so a player can always look up "fap".
  Ogre::Animation* animation = mesh.createAnimation("fap", 0);
  Ogre::VertexAnimationTrack* track = animation->createVertexTrack(kSharedGeometry, Ogre::VAT_POSE);
  Ogre::VertexPoseKeyFrame* key = track->createVertexPoseKeyFrame(0);
  for (size_t i = 0; i < exported.size(); ++i)
    key->addPoseReference(static_cast<unsigned short>(i), 0.0f);
}

void setBounds(Ogre::Mesh& mesh, const Eigen::AlignedBox3f& box) {
  const Eigen::Vector3f lo = box.min(), hi = box.max();
  mesh._setBounds(Ogre::AxisAlignedBox(lo.x(), lo.y(), lo.z(), hi.x(), hi.y(), hi.z()), false);
  // OGRE's bounding radius is measured from the mesh origin: the farthest corner.
  mesh._setBoundingSphereRadius(lo.cwiseAbs().cwiseMax(hi.cwiseAbs()).norm());
}

std::string serializeMesh(const HeadMesh& head, const std::vector<ExportedPose>& exported,
                          const std::vector<std::string>& materialNames,
                          const Eigen::AlignedBox3f& bounds) {
  // A sub-mesh without material gets OGRE's BaseWhite, which every OGRE with a render system
  // defines, so it renders and loads without a warning.
  std::vector<std::string> submeshMaterials;
  for (const HeadSubmesh& s : head.submeshes)
    submeshMaterials.push_back(s.material < 0 ? "BaseWhite"
                                              : materialNames[static_cast<size_t>(s.material)]);

  HeadlessOgre ogre;
  StandInMaterials standIns(submeshMaterials);
  ScratchMesh mesh;  // declared last: it refers to the materials and needs the managers
  addSharedGeometry(*mesh, head);
  for (size_t i = 0; i < head.submeshes.size(); ++i)
    addSubmesh(*mesh, head.submeshes[i], submeshMaterials[i]);
  addPoses(*mesh, exported);
  setBounds(*mesh, bounds);
  // Edge lists serve stencil shadows only, which Lacrima does not use; built, they would be
  // written into the file too.
  mesh->setAutoBuildEdgeLists(false);
  // A manual mesh without a loader counts as loaded only after load(); unloading it later is
  // what frees the buffers built above.
  mesh->load();
  auto stream = std::make_shared<StringDataStream>();
  Ogre::MeshSerializer().exportMesh(&*mesh, stream);
  return stream->take();
}

}  // namespace

void exportOgreMesh(const HeadMesh& head, const PoseSet& poses, const std::string& meshPath,
                    const OgreExportOptions& options) {
  const std::vector<ExportedPose> exported = prepareRigExport(head, poses, meshPath);
  if (!std::isfinite(options.boundsRangeFactor) || options.boundsRangeFactor < 0.0f)
    throw FileError({meshPath, 0, 0}, "cannot export: bounds range factor " +
                                          std::to_string(options.boundsRangeFactor) +
                                          " is not a finite value >= 0");
  const fs::path target(meshPath);
  const fs::path folder = target.parent_path().empty() ? fs::path(".") : target.parent_path();
  std::error_code error;
  if (!fs::is_directory(folder, error))
    throw FileError({meshPath, 0, 0},
                    "cannot write: '" + folder.string() + "' is not an existing folder");

  const std::string stem = target.stem().string();
  const OgreMaterialScript materials =
      makeOgreMaterialScript(head, options.materialPrefix.empty() ? stem : options.materialPrefix);

  // Every file goes to a temporary first; only when all are complete do they replace their
  // targets, so a missing texture or an OGRE error leaves the folder as it was.
  StagedFiles files;
  if (options.writeMaterials) {
    for (const OgreMaterialScript::TextureCopy& texture : materials.textures) {
      const fs::path destination = folder / texture.fileName;
      // Re-exporting into the folder the textures already live in: nothing to copy.
      if (fs::equivalent(texture.source, destination, error)) continue;
      files.add(destination.string(), readFileBytes(texture.source, "texture"));
    }
    files.add((folder / (stem + ".material")).string(), materials.text);
  }
  std::string meshBytes;
  try {
    meshBytes = serializeMesh(head, exported, materials.names,
                              reachableBounds(head, poses, exported, options.boundsRangeFactor));
  } catch (const Ogre::Exception& e) {
    throw FileError({meshPath, 0, 0}, "cannot export: OGRE: " + e.getDescription());
  }
  files.add(meshPath, meshBytes);
  files.commit();
}

}  // namespace lacrima::exporters
