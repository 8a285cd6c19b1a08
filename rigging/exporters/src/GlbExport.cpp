// The .glb goes through Debian's tinygltf, which writes the JSON and the GLB container. The buffer
// layout stays here (per-primitive windows on shared vertex arrays, dense morph deltas, shared
// zero targets, min/max, alignment): tinygltf takes the buffer as given.
#include <lacrima/exporters/GlbExport.h>

#include "StagedFiles.h"

#include <lacrima/common/AtomicSave.h>
#include <lacrima/common/Diagnostics.h>
#include <lacrima/exporters/RigExport.h>

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
#include <optional>
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

// One primitive: a HeadSubmesh with triangles.
struct Part {
  const HeadSubmesh* submesh = nullptr;
  std::size_t first = 0, count = 0;  // vertex window
};

class GlbBuilder {
 public:
  GlbBuilder(const HeadMesh& head, const std::vector<ExportedPose>& poses)
      : head_(head), poses_(poses), normals_(head.normals) {
    for (const HeadSubmesh& s : head.submeshes) {
      if (!s.triangles.empty())
        parts_.push_back(
            {&s, static_cast<std::size_t>(s.firstVertex), static_cast<std::size_t>(s.vertexCount)});
    }
    // glTF requires unit normals (validators reject anything else); HeadMesh promises them,
    // but a loader's degenerate or unnormalised ones must not make the whole file invalid.
    for (Eigen::Index v = 0; v < normals_.cols(); ++v) {
      const float length = normals_.col(v).norm();
      normals_.col(v) = std::isfinite(length) && length > 0.0f
                            ? Eigen::Vector3f(normals_.col(v) / length)
                            : Eigen::Vector3f::UnitZ();
    }
  }

  tinygltf::Model build() {
    model_.asset.version = "2.0";
    model_.asset.generator = "Lacrima";
    model_.buffers.emplace_back();
    model_.meshes.emplace_back().name = "head";
    tinygltf::Node& node = model_.nodes.emplace_back();
    node.name = "head";
    node.mesh = 0;
    model_.scenes.emplace_back().nodes = {0};
    model_.defaultScene = 0;
    addTextures();
    addGeometry();
    addTargets();
    addMaterials();
    return std::move(model_);
  }

 private:
  std::vector<unsigned char>& bytes() { return model_.buffers[0].data; }

  // Appends `length` bytes as a new buffer view. Views start on 4-byte boundaries, so every
  // float or index inside is aligned to its size, as glTF requires. The bytes are copied as they
  // are in memory, and glTF's are little-endian.
  int addView(const void* data, std::size_t length, int stride, int target) {
    static_assert(std::endian::native == std::endian::little, "glTF buffers are little-endian");
    bytes().resize((bytes().size() + 3) & ~std::size_t{3}, 0);
    tinygltf::BufferView& view = model_.bufferViews.emplace_back();
    view.buffer = 0;
    view.byteOffset = bytes().size();
    view.byteLength = length;
    view.byteStride = static_cast<std::size_t>(stride);
    view.target = target;
    const auto* begin = static_cast<const unsigned char*>(data);
    bytes().insert(bytes().end(), begin, begin + length);
    return static_cast<int>(model_.bufferViews.size()) - 1;
  }

  // An accessor of `count` float vectors with `components` components, whose values are
  // `values` (used only for min/max, which glTF requires for POSITION and we give for all).
  int addFloats(int view, std::size_t offset, const float* values, std::size_t count,
                int components) {
    tinygltf::Accessor& a = model_.accessors.emplace_back();
    a.bufferView = view;
    a.byteOffset = offset;
    a.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
    a.count = count;
    a.type = components == 2 ? TINYGLTF_TYPE_VEC2 : TINYGLTF_TYPE_VEC3;
    a.minValues.assign(static_cast<std::size_t>(components), count ? INFINITY : 0.0);
    a.maxValues.assign(static_cast<std::size_t>(components), count ? -INFINITY : 0.0);
    for (std::size_t i = 0; i < count; ++i) {
      for (std::size_t c = 0; c < static_cast<std::size_t>(components); ++c) {
        const double v = values[i * static_cast<std::size_t>(components) + c];
        a.minValues[c] = std::min(a.minValues[c], v);
        a.maxValues[c] = std::max(a.maxValues[c], v);
      }
    }
    return static_cast<int>(model_.accessors.size()) - 1;
  }

  void addTextures() {
    // Without uvs a texture cannot be placed, and glTF validators reject baseColorTexture
    // on primitives without TEXCOORD_0.
    if (head_.uvs.cols() == 0) return;
    std::map<std::string, int> imageOfPath;
    for (const HeadMaterial& m : head_.materials) {
      int image = -1;
      if (!m.diffuseTexture.empty()) {
        auto [it, isNew] =
            imageOfPath.try_emplace(m.diffuseTexture, static_cast<int>(model_.images.size()));
        if (isNew) {
          const std::string png = pngBytes(m.diffuseTexture);
          // Texture i shows image i; no sampler means repeat wrapping and automatic filtering.
          tinygltf::Image& embedded = model_.images.emplace_back();
          embedded.bufferView = addView(png.data(), png.size(), 0, 0);
          embedded.mimeType = "image/png";
          model_.textures.emplace_back().source = it->second;
        }
        image = it->second;
      }
      textureOfMaterial_.push_back(image);
    }
  }

  void addGeometry() {
    const auto n = static_cast<std::size_t>(head_.vertexCount());
    // One view per attribute over all vertices; each primitive's accessor is a window on it.
    // Several accessors share a view, so glTF requires byteStride.
    const int positions = addView(head_.positions.data(), n * 12, 12, TINYGLTF_TARGET_ARRAY_BUFFER);
    const int normals = addView(normals_.data(), n * 12, 12, TINYGLTF_TARGET_ARRAY_BUFFER);
    const bool hasUvs = head_.uvs.cols() != 0;
    const int uvs = hasUvs ? addView(head_.uvs.data(), n * 8, 8, TINYGLTF_TARGET_ARRAY_BUFFER) : -1;
    for (const Part& part : parts_) {
      tinygltf::Primitive& p = model_.meshes[0].primitives.emplace_back();
      p.attributes["POSITION"] = addFloats(positions, part.first * 12,
                                           head_.positions.data() + 3 * part.first, part.count, 3);
      p.attributes["NORMAL"] =
          addFloats(normals, part.first * 12, normals_.data() + 3 * part.first, part.count, 3);
      if (hasUvs)
        p.attributes["TEXCOORD_0"] =
            addFloats(uvs, part.first * 8, head_.uvs.data() + 2 * part.first, part.count, 2);
      p.indices = addIndices(part);
      p.material = part.submesh->material;
      p.mode = TINYGLTF_MODE_TRIANGLES;
    }
  }

  int addIndices(const Part& part) {
    // glTF forbids the largest value of the index type (restart index): 16 bits hold indices
    // up to 65534, i.e. up to 65535 vertices.
    const bool wide = part.count > 65535;
    std::vector<std::uint32_t> indices;
    for (const Eigen::Vector3i& t : part.submesh->triangles)
      for (int k = 0; k < 3; ++k)
        indices.push_back(static_cast<std::uint32_t>(t[k]) -
                          static_cast<std::uint32_t>(part.first));
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
    model_.accessors.push_back(std::move(a));
    return static_cast<int>(model_.accessors.size()) - 1;
  }

  void addTargets() {
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
            deltas[local + static_cast<std::size_t>(c)] = pose.offsets(c, k);
        }
      }
    }
    const std::size_t zeroOffset = deltas.size();
    deltas.resize(zeroOffset + 3 * zeroVertices, 0.0f);
    const int view =
        addView(deltas.data(), deltas.size() * sizeof(float), 12, TINYGLTF_TARGET_ARRAY_BUFFER);
    std::vector<int> zeroAccessor(parts_.size(), -1);
    tinygltf::Mesh& mesh = model_.meshes[0];
    for (std::size_t p = 0; p < poses_.size(); ++p) {
      for (std::size_t i = 0; i < parts_.size(); ++i) {
        const std::size_t count = parts_[i].count;
        int& target = mesh.primitives[i].targets.emplace_back()["POSITION"];
        if (const std::optional<std::size_t>& offset = placed[p][i]) {
          target = addFloats(view, *offset * sizeof(float), deltas.data() + *offset, count, 3);
        } else {
          if (zeroAccessor[i] < 0)
            zeroAccessor[i] =
                addFloats(view, zeroOffset * sizeof(float), deltas.data() + zeroOffset, count, 3);
          target = zeroAccessor[i];
        }
      }
    }
    mesh.weights.assign(poses_.size(), 0.0);
    tinygltf::Value::Array names;
    for (const ExportedPose& pose : poses_) names.emplace_back(pose.name);
    mesh.extras = tinygltf::Value(
        tinygltf::Value::Object{{"targetNames", tinygltf::Value(std::move(names))}});
  }

  void addMaterials() {
    for (std::size_t i = 0; i < head_.materials.size(); ++i) {
      const HeadMaterial& m = head_.materials[i];
      const bool cornea = isCorneaMaterial(head_, static_cast<int>(i));
      tinygltf::Material& material = model_.materials.emplace_back();
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

  const HeadMesh& head_;
  const std::vector<ExportedPose>& poses_;
  Eigen::Matrix3Xf normals_;  // head_.normals made unit length
  std::vector<Part> parts_;
  tinygltf::Model model_;
  std::vector<int> textureOfMaterial_;  // texture (= image) index per material, -1 for none
};

}  // namespace

void exportGlb(const HeadMesh& head, const PoseSet& poses, const std::string& path) {
  const std::vector<ExportedPose> exported = prepareRigExport(head, poses, path);
  const tinygltf::Model model = GlbBuilder(head, exported).build();
  // GLB's lengths are 32 bits, and tinygltf 2.7 writes accessor offsets as int without checking
  // either: past 2 GiB it would write a broken file instead of failing.
  const std::size_t binBytes = model.buffers[0].data.size();
  if (binBytes > static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max()))
    throw FileError({path, 0, 0}, "cannot export: " + std::to_string(binBytes) +
                                      " bytes exceed the 2 GiB tinygltf can write");
  // tinygltf's file writer neither checks its writes nor uses a temporary, so it writes to
  // memory and saveAtomically writes the file, as for every other file.
  std::ostringstream glb;
  if (!tinygltf::TinyGLTF().WriteGltfSceneToStream(&model, glb, false, true))
    throw FileError({path, 0, 0}, "cannot export: tinygltf could not write the model");
  saveAtomically(path, std::move(glb).str());
}

}  // namespace lacrima::exporters
