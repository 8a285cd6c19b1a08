// tinygltf writes the JSON and the GLB container; the buffer layout stays here (per-primitive
// windows on shared vertex arrays, dense morph deltas, shared zero targets, min/max, alignment):
// tinygltf takes the buffer as given.
#include <lacrima/exporters/GltfDocument.h>

#include "StagedFiles.h"

#include <lacrima/common/AtomicSave.h>
#include <lacrima/common/Diagnostics.h>

#include <QBuffer>
#include <QByteArray>
#include <QImage>

#include <tiny_gltf.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <sstream>

namespace lacrima::exporters {
namespace {

// A cornea must read as wet glass, whatever shininess the loader guessed.
constexpr float kCorneaRoughness = 0.05f;

// PNG bytes of the image at `path`: PNG files as they are, anything Qt reads converted.
std::string pngBytes(const std::string& path) {
  std::string bytes = readFileBytes(path, "texture");
  static constexpr char kPngSignature[] = "\x89PNG\r\n\x1a\n";
  if (bytes.compare(0, 8, kPngSignature, 8) == 0) return bytes;
  const QImage image =
      QImage::fromData(QByteArray::fromRawData(bytes.data(), static_cast<qsizetype>(bytes.size())));
  if (image.isNull())
    throw FileError({path, 0, 0}, "cannot read texture: not an image format Qt can decode");
  QByteArray png;
  QBuffer buffer(&png);
  buffer.open(QIODevice::WriteOnly);
  if (!image.save(&buffer, "PNG")) throw FileError({path, 0, 0}, "cannot convert texture to PNG");
  return png.toStdString();
}

// glTF roughness for a Blinn-Phong exponent s: GGX alpha = sqrt(2 / (s + 2)) matches the
// highlight width, and glTF's roughness is sqrt(alpha).
double roughnessOf(float shininess) {
  return std::pow(2.0 / (std::max(shininess, 0.0f) + 2.0), 0.25);
}

int accessorType(int components) {
  switch (components) {
    case 1:
      return TINYGLTF_TYPE_SCALAR;
    case 2:
      return TINYGLTF_TYPE_VEC2;
    case 3:
      return TINYGLTF_TYPE_VEC3;
    case 16:
      return TINYGLTF_TYPE_MAT4;
    default:
      return TINYGLTF_TYPE_VEC4;
  }
}

// glTF requires unit normals (validators reject anything else): degenerate or unnormalised
// ones become `fallback` rather than making the whole file invalid.
Eigen::Vector3f unitOr(const Eigen::Vector3f& n, const Eigen::Vector3f& fallback) {
  const float length = n.norm();
  return std::isfinite(length) && length > 1e-20f ? Eigen::Vector3f(n / length) : fallback;
}

// One primitive of the head: a HeadSubmesh with triangles, a window on the vertex arrays.
struct Part {
  const HeadSubmesh* submesh = nullptr;
  std::size_t first = 0, count = 0;
};

}  // namespace

struct GltfDocument::Model {
  tinygltf::Model gltf;
  float scale = 1.0f;
  int animation = -1;
  std::string animationName;

  std::vector<unsigned char>& bytes() { return gltf.buffers[0].data; }

  // Appends `length` bytes as a new buffer view. Views start on 4-byte boundaries, so every
  // float or index inside is aligned to its size, as glTF requires. The bytes are copied as they
  // are in memory, and glTF's are little-endian.
  int addView(const void* data, std::size_t length, int stride, int target) {
    static_assert(std::endian::native == std::endian::little, "glTF buffers are little-endian");
    bytes().resize((bytes().size() + 3) & ~std::size_t{3}, 0);
    tinygltf::BufferView& view = gltf.bufferViews.emplace_back();
    view.buffer = 0;
    view.byteOffset = bytes().size();
    view.byteLength = length;
    view.byteStride = static_cast<std::size_t>(stride);
    view.target = target;
    const auto* begin = static_cast<const unsigned char*>(data);
    bytes().insert(bytes().end(), begin, begin + length);
    return static_cast<int>(gltf.bufferViews.size()) - 1;
  }

  // An accessor of `count` float elements with `components` components at `offset` in `view`,
  // whose values are `values` (used only for min/max).
  int addFloats(int view, std::size_t offset, const float* values, std::size_t count,
                int components, bool withBounds = true) {
    tinygltf::Accessor& a = gltf.accessors.emplace_back();
    a.bufferView = view;
    a.byteOffset = offset;
    a.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
    a.count = count;
    a.type = accessorType(components);
    if (withBounds) {
      const auto c = static_cast<std::size_t>(components);
      a.minValues.assign(c, count ? INFINITY : 0.0);
      a.maxValues.assign(c, count ? -INFINITY : 0.0);
      for (std::size_t i = 0; i < count; ++i) {
        for (std::size_t k = 0; k < c; ++k) {
          const double v = values[i * c + k];
          a.minValues[k] = std::min(a.minValues[k], v);
          a.maxValues[k] = std::max(a.maxValues[k], v);
        }
      }
    }
    return static_cast<int>(gltf.accessors.size()) - 1;
  }

  // A tightly packed float array as its own view and accessor.
  int addFloatArray(std::span<const float> values, int components, int target,
                    bool withBounds = true) {
    const int view = addView(values.data(), values.size_bytes(), 0, target);
    return addFloats(view, 0, values.data(), values.size() / static_cast<std::size_t>(components),
                     components, withBounds);
  }

  // Triangle indices, 16-bit when every index fits (glTF forbids the largest value of the type,
  // the restart index), else 32-bit.
  int addIndices(const std::vector<std::uint32_t>& indices, std::size_t vertexCount) {
    const bool wide = vertexCount > 65535;
    tinygltf::Accessor a;
    if (wide) {
      a.bufferView =
          addView(indices.data(), indices.size() * 4, 0, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
    } else {
      const std::vector<std::uint16_t> narrow(indices.begin(), indices.end());
      a.bufferView =
          addView(narrow.data(), narrow.size() * 2, 0, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
    }
    a.componentType =
        wide ? TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT : TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
    a.count = indices.size();
    a.type = TINYGLTF_TYPE_SCALAR;
    gltf.accessors.push_back(std::move(a));
    return static_cast<int>(gltf.accessors.size()) - 1;
  }

  void useExtension(const std::string& name) {
    if (std::find(gltf.extensionsUsed.begin(), gltf.extensionsUsed.end(), name) ==
        gltf.extensionsUsed.end())
      gltf.extensionsUsed.push_back(name);
  }

  tinygltf::Animation& animation_() {
    if (animation < 0) {
      gltf.animations.emplace_back().name = animationName;
      animation = static_cast<int>(gltf.animations.size()) - 1;
    }
    return gltf.animations[static_cast<std::size_t>(animation)];
  }

  void addChannel(int node, const char* path, int input, int output, const char* interpolation) {
    tinygltf::Animation& a = animation_();
    tinygltf::AnimationSampler& sampler = a.samplers.emplace_back();
    sampler.input = input;
    sampler.output = output;
    sampler.interpolation = interpolation;
    tinygltf::AnimationChannel& channel = a.channels.emplace_back();
    channel.sampler = static_cast<int>(a.samplers.size()) - 1;
    channel.target_node = node;
    channel.target_path = path;
  }

  // Keyframe times as an accessor; glTF requires their min and max.
  int addTimes(std::span<const float> times) { return addFloatArray(times, 1, 0); }
};

// Builds the head's mesh into a document: textures, geometry, targets, materials, skin.
class GltfDocument::HeadBuilder {
 public:
  HeadBuilder(GltfDocument::Model& model, const HeadMesh& head,
              const std::vector<ExportedPose>& poses, const GltfHeadSkin* skin)
      : m_(model), head_(head), poses_(poses), skin_(skin) {
    for (const HeadSubmesh& s : head.submeshes) {
      if (!s.triangles.empty())
        parts_.push_back(
            {&s, static_cast<std::size_t>(s.firstVertex), static_cast<std::size_t>(s.vertexCount)});
    }
    positions_ = head.positions * m_.scale;
    normals_.resize(3, head.normals.cols());
    for (Eigen::Index v = 0; v < normals_.cols(); ++v)
      normals_.col(v) = unitOr(head.normals.col(v), Eigen::Vector3f::UnitZ());
  }

  // Returns the mesh's index.
  int build(const std::vector<std::string>& targetNames) {
    m_.gltf.meshes.emplace_back().name = "head";
    mesh_ = static_cast<int>(m_.gltf.meshes.size()) - 1;
    materialBase_ = static_cast<int>(m_.gltf.materials.size());
    addTextures();
    addGeometry();
    addTargets(targetNames);
    addMaterials();
    return mesh_;
  }

 private:
  tinygltf::Mesh& mesh() { return m_.gltf.meshes[static_cast<std::size_t>(mesh_)]; }

  void addTextures() {
    // Without uvs a texture cannot be placed, and glTF validators reject baseColorTexture
    // on primitives without TEXCOORD_0.
    if (head_.uvs.cols() == 0) return;
    std::map<std::string, int> textureOfPath;
    for (const HeadMaterial& m : head_.materials) {
      int texture = -1;
      if (!m.diffuseTexture.empty()) {
        auto [it, isNew] =
            textureOfPath.try_emplace(m.diffuseTexture, static_cast<int>(m_.gltf.textures.size()));
        if (isNew) {
          const std::string png = pngBytes(m.diffuseTexture);
          // No sampler means repeat wrapping and automatic filtering.
          tinygltf::Image& embedded = m_.gltf.images.emplace_back();
          embedded.bufferView = m_.addView(png.data(), png.size(), 0, 0);
          embedded.mimeType = "image/png";
          m_.gltf.textures.emplace_back().source = static_cast<int>(m_.gltf.images.size()) - 1;
        }
        texture = it->second;
      }
      textureOfMaterial_.push_back(texture);
    }
  }

  void addGeometry() {
    const auto n = static_cast<std::size_t>(head_.vertexCount());
    // One view per attribute over all vertices; each primitive's accessor is a window on it.
    // Several accessors share a view, so glTF requires byteStride.
    const int positions = m_.addView(positions_.data(), n * 12, 12, TINYGLTF_TARGET_ARRAY_BUFFER);
    const int normals = m_.addView(normals_.data(), n * 12, 12, TINYGLTF_TARGET_ARRAY_BUFFER);
    const bool hasUvs = head_.uvs.cols() != 0;
    const int uvs =
        hasUvs ? m_.addView(head_.uvs.data(), n * 8, 8, TINYGLTF_TARGET_ARRAY_BUFFER) : -1;
    int joints = -1, weights = -1;
    if (skin_) {
      std::vector<std::uint8_t> jointBytes(4 * n, 0);
      std::vector<float> weightValues(4 * n, 0.0f);
      for (std::size_t v = 0; v < n; ++v) {
        jointBytes[4 * v] = static_cast<std::uint8_t>(skin_->jointOfVertex[v]);
        weightValues[4 * v] = 1.0f;
      }
      joints = m_.addView(jointBytes.data(), jointBytes.size(), 4, TINYGLTF_TARGET_ARRAY_BUFFER);
      weights = m_.addView(weightValues.data(), weightValues.size() * 4, 16,
                           TINYGLTF_TARGET_ARRAY_BUFFER);
    }
    for (const Part& part : parts_) {
      tinygltf::Primitive& p = mesh().primitives.emplace_back();
      p.attributes["POSITION"] = m_.addFloats(positions, part.first * 12,
                                              positions_.data() + 3 * part.first, part.count, 3);
      p.attributes["NORMAL"] =
          m_.addFloats(normals, part.first * 12, normals_.data() + 3 * part.first, part.count, 3);
      if (hasUvs)
        p.attributes["TEXCOORD_0"] =
            m_.addFloats(uvs, part.first * 8, head_.uvs.data() + 2 * part.first, part.count, 2);
      if (skin_) {
        tinygltf::Accessor& j = m_.gltf.accessors.emplace_back();
        j.bufferView = joints;
        j.byteOffset = part.first * 4;
        j.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE;
        j.count = part.count;
        j.type = TINYGLTF_TYPE_VEC4;
        p.attributes["JOINTS_0"] = static_cast<int>(m_.gltf.accessors.size()) - 1;
        p.attributes["WEIGHTS_0"] = m_.addFloats(weights, part.first * 16, nullptr, part.count, 4,
                                                 /*withBounds=*/false);
      }
      std::vector<std::uint32_t> indices;
      indices.reserve(part.submesh->triangles.size() * 3);
      for (const Eigen::Vector3i& t : part.submesh->triangles)
        for (int k = 0; k < 3; ++k)
          indices.push_back(static_cast<std::uint32_t>(t[k]) -
                            static_cast<std::uint32_t>(part.first));
      p.indices = m_.addIndices(indices, part.count);
      p.material = part.submesh->material < 0 ? -1 : materialBase_ + part.submesh->material;
      p.mode = TINYGLTF_MODE_TRIANGLES;
    }
  }

  void addTargets(const std::vector<std::string>& targetNames) {
    if (poses_.empty()) return;
    // Dense deltas of every (pose, primitive) pair the pose touches; untouched pairs share
    // one all-zero block per primitive instead of repeating zeros. Offsets count floats.
    std::vector<float> deltas;
    std::vector<std::vector<std::optional<std::size_t>>> placed(poses_.size());
    std::size_t zeroVertices = 0;
    for (std::size_t p = 0; p < poses_.size(); ++p) {
      const ExportedPose& pose = poses_[p];
      for (const Part& part : parts_) {
        // Pose vertices are ascending: the ones in this primitive are one run.
        const auto begin = std::lower_bound(pose.vertices.begin(), pose.vertices.end(),
                                            static_cast<int>(part.first));
        const auto end =
            std::lower_bound(begin, pose.vertices.end(), static_cast<int>(part.first + part.count));
        if (begin == end) {
          placed[p].push_back(std::nullopt);
          zeroVertices = std::max(zeroVertices, part.count);
          continue;
        }
        const std::size_t offset = deltas.size();
        placed[p].push_back(offset);
        deltas.resize(offset + 3 * part.count, 0.0f);
        for (auto it = begin; it != end; ++it) {
          const auto k = static_cast<Eigen::Index>(it - pose.vertices.begin());
          const std::size_t local = offset + 3 * (static_cast<std::size_t>(*it) - part.first);
          for (int c = 0; c < 3; ++c)
            deltas[local + static_cast<std::size_t>(c)] = pose.offsets(c, k) * m_.scale;
        }
      }
    }
    const std::size_t zeroOffset = deltas.size();
    deltas.resize(zeroOffset + 3 * zeroVertices, 0.0f);
    const int view =
        m_.addView(deltas.data(), deltas.size() * sizeof(float), 12, TINYGLTF_TARGET_ARRAY_BUFFER);
    std::vector<int> zeroAccessor(parts_.size(), -1);
    for (std::size_t p = 0; p < poses_.size(); ++p) {
      for (std::size_t i = 0; i < parts_.size(); ++i) {
        const std::size_t count = parts_[i].count;
        int& target = mesh().primitives[i].targets.emplace_back()["POSITION"];
        if (const std::optional<std::size_t>& offset = placed[p][i]) {
          target = m_.addFloats(view, *offset * sizeof(float), deltas.data() + *offset, count, 3);
        } else {
          if (zeroAccessor[i] < 0)
            zeroAccessor[i] = m_.addFloats(view, zeroOffset * sizeof(float),
                                           deltas.data() + zeroOffset, count, 3);
          target = zeroAccessor[i];
        }
      }
    }
    mesh().weights.assign(poses_.size(), 0.0);
    tinygltf::Value::Array names;
    for (const std::string& name : targetNames) names.emplace_back(name);
    mesh().extras = tinygltf::Value(
        tinygltf::Value::Object{{"targetNames", tinygltf::Value(std::move(names))}});
  }

  void addMaterials() {
    for (std::size_t i = 0; i < head_.materials.size(); ++i) {
      const HeadMaterial& m = head_.materials[i];
      const bool cornea = isCorneaMaterial(head_, static_cast<int>(i));
      tinygltf::Material& material = m_.gltf.materials.emplace_back();
      material.name = m.name;
      tinygltf::PbrMetallicRoughness& pbr = material.pbrMetallicRoughness;
      pbr.baseColorFactor = {m.diffuse.x(), m.diffuse.y(), m.diffuse.z(), m.diffuse.w()};
      if (i < textureOfMaterial_.size()) pbr.baseColorTexture.index = textureOfMaterial_[i];
      pbr.metallicFactor = 0.0;
      const double roughness = roughnessOf(m.shininess);
      pbr.roughnessFactor = cornea ? std::min(roughness, double{kCorneaRoughness}) : roughness;
      // OPAQUE would ignore alpha altogether: lashes would show their card outlines.
      if (m.transparent || cornea || m.diffuse.w() < 1.0f) material.alphaMode = "BLEND";
    }
  }

  GltfDocument::Model& m_;
  const HeadMesh& head_;
  const std::vector<ExportedPose>& poses_;
  const GltfHeadSkin* skin_;
  Eigen::Matrix3Xf positions_, normals_;  // scaled; unit length
  std::vector<Part> parts_;
  int mesh_ = -1, materialBase_ = 0;
  std::vector<int> textureOfMaterial_;  // texture index per material, -1 for none
};

GltfDocument::GltfDocument(double unitScale) : model_(std::make_unique<Model>()) {
  model_->scale = static_cast<float>(unitScale);
  model_->gltf.asset.version = "2.0";
  model_->gltf.asset.generator = "Lacrima";
  model_->gltf.buffers.emplace_back();
  model_->gltf.scenes.emplace_back();
  model_->gltf.defaultScene = 0;
}

GltfDocument::~GltfDocument() = default;

int GltfDocument::addNode(const std::string& name, int parent) {
  tinygltf::Model& g = model_->gltf;
  g.nodes.emplace_back().name = name;
  const int node = static_cast<int>(g.nodes.size()) - 1;
  if (parent < 0)
    g.scenes[0].nodes.push_back(node);
  else
    g.nodes[static_cast<std::size_t>(parent)].children.push_back(node);
  return node;
}

void GltfDocument::setTranslation(int node, const Eigen::Vector3d& headUnits) {
  const Eigen::Vector3d t = headUnits * static_cast<double>(model_->scale);
  model_->gltf.nodes[static_cast<std::size_t>(node)].translation = {t.x(), t.y(), t.z()};
}

void GltfDocument::setScale(int node, const Eigen::Vector3d& scale) {
  model_->gltf.nodes[static_cast<std::size_t>(node)].scale = {scale.x(), scale.y(), scale.z()};
}

void GltfDocument::setMesh(int node, int mesh) {
  model_->gltf.nodes[static_cast<std::size_t>(node)].mesh = mesh;
}

int GltfDocument::addHead(const HeadMesh& head, const std::vector<ExportedPose>& poses,
                          const std::vector<std::string>& targetNames, int parent,
                          const GltfHeadSkin* skin, std::vector<int>* jointNodes) {
  const int mesh = HeadBuilder(*model_, head, poses, skin).build(targetNames);
  const int node = addNode("head", parent);
  setMesh(node, mesh);
  if (!skin) return node;
  tinygltf::Model& g = model_->gltf;
  std::vector<int> nodes;
  std::vector<float> inverseBinds;
  for (const GltfHeadSkin::Joint& joint : skin->joints) {
    const int jointNode = addNode(
        joint.name, joint.parent < 0 ? parent : nodes[static_cast<std::size_t>(joint.parent)]);
    const Eigen::Vector3f parentPosition =
        joint.parent < 0 ? Eigen::Vector3f::Zero()
                         : skin->joints[static_cast<std::size_t>(joint.parent)].position;
    setTranslation(jointNode, (joint.position - parentPosition).cast<double>());
    nodes.push_back(jointNode);
    // The inverse bind matrix takes the head's coordinates to the joint's at rest: a translation
    // by minus the joint's position (column-major 4 x 4).
    const Eigen::Vector3f t = -joint.position * model_->scale;
    const float matrix[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, t.x(), t.y(), t.z(), 1};
    inverseBinds.insert(inverseBinds.end(), matrix, matrix + 16);
  }
  tinygltf::Skin& s = g.skins.emplace_back();
  s.name = "head";
  s.joints = nodes;
  s.skeleton = nodes.front();
  s.inverseBindMatrices = model_->addFloatArray(inverseBinds, 16, 0, /*withBounds=*/false);
  g.nodes[static_cast<std::size_t>(node)].skin = static_cast<int>(g.skins.size()) - 1;
  if (jointNodes) *jointNodes = std::move(nodes);
  return node;
}

int GltfDocument::addWaterMaterial(const GltfWater& water) {
  tinygltf::Model& g = model_->gltf;
  tinygltf::Material& material = g.materials.emplace_back();
  material.name = water.name;
  material.pbrMetallicRoughness.baseColorFactor = {water.baseColor.x(), water.baseColor.y(),
                                                   water.baseColor.z(), water.baseColor.w()};
  material.pbrMetallicRoughness.metallicFactor = 0.0;
  material.pbrMetallicRoughness.roughnessFactor = water.roughness;
  material.doubleSided = water.thickness == 0;
  if (water.vertexAlphaBlended) material.alphaMode = "BLEND";
  using Object = tinygltf::Value::Object;
  if (water.transmission > 0) {
    material.extensions["KHR_materials_transmission"] =
        tinygltf::Value(Object{{"transmissionFactor", tinygltf::Value(water.transmission)}});
    model_->useExtension("KHR_materials_transmission");
  }
  material.extensions["KHR_materials_ior"] =
      tinygltf::Value(Object{{"ior", tinygltf::Value(water.ior)}});
  model_->useExtension("KHR_materials_ior");
  if (water.thickness > 0) {
    material.extensions["KHR_materials_volume"] =
        tinygltf::Value(Object{{"thicknessFactor", tinygltf::Value(water.thickness)}});
    model_->useExtension("KHR_materials_volume");
  }
  return static_cast<int>(g.materials.size()) - 1;
}

std::optional<int> GltfDocument::addMesh(const std::string& name,
                                         std::span<const GltfSurface> surfaces) {
  tinygltf::Mesh mesh;
  mesh.name = name;
  Model& m = *model_;
  for (const GltfSurface& s : surfaces) {
    if (!s.positions || !s.triangles || s.triangles->cols() == 0) continue;
    const auto n = static_cast<std::size_t>(s.positions->cols());
    const Eigen::Matrix3Xf positions = (*s.positions * static_cast<double>(m.scale)).cast<float>();
    Eigen::Matrix3Xf normals(3, s.positions->cols());
    for (Eigen::Index v = 0; v < normals.cols(); ++v)
      normals.col(v) = unitOr(
          s.normals ? Eigen::Vector3f(s.normals->col(v).cast<float>()) : Eigen::Vector3f::Zero(),
          Eigen::Vector3f::UnitY());
    tinygltf::Primitive& p = mesh.primitives.emplace_back();
    p.attributes["POSITION"] =
        m.addFloatArray({positions.data(), 3 * n}, 3, TINYGLTF_TARGET_ARRAY_BUFFER);
    p.attributes["NORMAL"] =
        m.addFloatArray({normals.data(), 3 * n}, 3, TINYGLTF_TARGET_ARRAY_BUFFER, false);
    if (s.alpha) {
      std::vector<float> colours(4 * n, 1.0f);
      for (std::size_t v = 0; v < n; ++v)
        colours[4 * v + 3] =
            static_cast<float>(std::clamp((*s.alpha)(static_cast<Eigen::Index>(v)), 0.0, 1.0));
      p.attributes["COLOR_0"] = m.addFloatArray(colours, 4, TINYGLTF_TARGET_ARRAY_BUFFER, false);
    }
    std::vector<std::uint32_t> indices(s.triangles->data(),
                                       s.triangles->data() + 3 * s.triangles->cols());
    p.indices = m.addIndices(indices, n);
    p.material = s.material;
    p.mode = TINYGLTF_MODE_TRIANGLES;
  }
  if (mesh.primitives.empty()) return std::nullopt;
  m.gltf.meshes.push_back(std::move(mesh));
  return static_cast<int>(m.gltf.meshes.size()) - 1;
}

void GltfDocument::setAnimationName(const std::string& name) {
  model_->animationName = name;
  if (model_->animation >= 0) model_->animation_().name = name;
}

void GltfDocument::animateWeights(int node, std::span<const float> times,
                                  std::span<const float> weights, int targets) {
  const int input = model_->addTimes(times);
  const int output = model_->addFloatArray(weights, 1, 0, false);
  static_cast<void>(targets);  // the count is the rows' length: weights.size() / times.size()
  model_->addChannel(node, "weights", input, output, "LINEAR");
}

void GltfDocument::animateRotation(int node, std::span<const float> times,
                                   std::span<const Eigen::Quaternionf> rotations) {
  std::vector<float> xyzw;
  xyzw.reserve(4 * rotations.size());
  for (const Eigen::Quaternionf& q : rotations) {
    const Eigen::Quaternionf u = q.normalized();
    xyzw.insert(xyzw.end(), {u.x(), u.y(), u.z(), u.w()});
  }
  const int input = model_->addTimes(times);
  model_->addChannel(node, "rotation", input, model_->addFloatArray(xyzw, 4, 0, false), "LINEAR");
}

void GltfDocument::animateScale(int node, std::span<const float> times,
                                std::span<const Eigen::Vector3f> scales,
                                GltfInterpolation interpolation) {
  std::vector<float> xyz;
  xyz.reserve(3 * scales.size());
  for (const Eigen::Vector3f& s : scales) xyz.insert(xyz.end(), {s.x(), s.y(), s.z()});
  const int input = model_->addTimes(times);
  model_->addChannel(node, "scale", input, model_->addFloatArray(xyz, 3, 0, false),
                     interpolation == GltfInterpolation::Step ? "STEP" : "LINEAR");
}

std::size_t GltfDocument::binaryBytes() const { return model_->gltf.buffers[0].data.size(); }

void GltfDocument::save(const std::string& path) const {
  // GLB's lengths are 32 bits, and tinygltf 2.7 writes accessor offsets as int without checking
  // either: past 2 GiB it would write a broken file instead of failing.
  const std::size_t binBytes = binaryBytes();
  if (binBytes > static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max()))
    throw FileError({path, 0, 0}, "cannot export: " + std::to_string(binBytes) +
                                      " bytes exceed the 2 GiB tinygltf can write");
  // tinygltf's file writer neither checks its writes nor uses a temporary, so it writes to
  // memory and saveAtomically writes the file, as for every other file.
  std::ostringstream glb;
  if (!tinygltf::TinyGLTF().WriteGltfSceneToStream(&model_->gltf, glb, false, true))
    throw FileError({path, 0, 0}, "cannot export: tinygltf could not write the model");
  saveAtomically(path, std::move(glb).str());
}

}  // namespace lacrima::exporters
