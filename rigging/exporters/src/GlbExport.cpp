// Binary glTF writer, written by hand rather than with Debian's tinygltf (libtinygltf-dev 2.7).
// The work of this exporter is laying out the binary buffer (per-primitive windows on shared
// vertex arrays, dense morph deltas, shared zero targets, min/max, alignment), which tinygltf
// leaves to the caller just the same. What it would take over is the 12-byte GLB header, two
// chunk headers and the JSON text: about 40 lines here with lacrima::JsonWriter, which also
// writes the fields in a fixed, readable order. In exchange tinygltf would add two packages
// (Debian ships it as a shared library: libtinygltf-dev + libtinygltf2d), a model struct to
// fill field by field, and a bool-plus-string error channel to translate into FileError.
// It does build and write a .glb with -std=c++20 -Wall -Wextra and GCC 12 (checked), so
// compatibility was not the deciding factor; less, clearer code and no new dependency were.
#include <lacrima/exporters/GlbExport.h>

#include "StagedFiles.h"

#include <lacrima/common/AtomicSave.h>
#include <lacrima/common/Diagnostics.h>
#include <lacrima/common/JsonWriter.h>
#include <lacrima/exporters/RigExport.h>

#include <QBuffer>
#include <QByteArray>
#include <QImage>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <optional>

namespace lacrima::exporters {
namespace {

constexpr std::uint32_t kGlbMagic = 0x46546C67;   // "glTF" read as a little-endian uint32
constexpr std::uint32_t kGlbVersion = 2;
constexpr std::uint32_t kChunkJson = 0x4E4F534A;  // "JSON"
constexpr std::uint32_t kChunkBin = 0x004E4942;   // "BIN\0"
constexpr int kUnsignedShort = 5123;
constexpr int kUnsignedInt = 5125;
constexpr int kFloat = 5126;
constexpr int kArrayBuffer = 34962;
constexpr int kElementArrayBuffer = 34963;
constexpr int kTriangles = 4;
// A cornea must read as wet glass, whatever shininess the loader guessed.
constexpr float kCorneaRoughness = 0.05f;

struct BufferView {
  std::size_t offset = 0;
  std::size_t length = 0;
  int stride = 0;  // 0: not written (tightly packed, one accessor)
  int target = 0;  // 0: not written (images)
};

struct Accessor {
  int view = 0;
  std::size_t offset = 0;
  int componentType = kFloat;
  std::size_t count = 0;
  const char* type = "SCALAR";
  std::vector<double> min, max;  // empty: not written
};

// The BIN chunk, and the buffer views and accessors that describe it.
class BinaryLayout {
public:
  // Appends `length` bytes as a new buffer view. Views start on 4-byte boundaries, so every
  // float or index inside is aligned to its size, as glTF requires.
  int addView(const void* data, std::size_t length, int stride, int target) {
    bytes_.resize((bytes_.size() + 3) & ~std::size_t{3}, '\0');
    views_.push_back({bytes_.size(), length, stride, target});
    bytes_.append(static_cast<const char*>(data), length);
    return static_cast<int>(views_.size()) - 1;
  }

  // An accessor of `count` float vectors with `components` components, whose values are
  // `values` (used only for min/max, which glTF requires for POSITION and we give for all).
  int addFloats(int view, std::size_t offset, const float* values, std::size_t count, int components) {
    static constexpr const char* kTypes[] = {"SCALAR", "VEC2", "VEC3", "VEC4"};
    Accessor a{view, offset, kFloat, count, kTypes[components - 1], {}, {}};
    a.min.assign(static_cast<std::size_t>(components), count ? INFINITY : 0.0);
    a.max.assign(static_cast<std::size_t>(components), count ? -INFINITY : 0.0);
    for (std::size_t i = 0; i < count; ++i) {
      for (int c = 0; c < components; ++c) {
        const double v = values[i * static_cast<std::size_t>(components) + static_cast<std::size_t>(c)];
        a.min[static_cast<std::size_t>(c)] = std::min(a.min[static_cast<std::size_t>(c)], v);
        a.max[static_cast<std::size_t>(c)] = std::max(a.max[static_cast<std::size_t>(c)], v);
      }
    }
    accessors_.push_back(std::move(a));
    return static_cast<int>(accessors_.size()) - 1;
  }

  int addIndices(int view, int componentType, std::size_t count) {
    accessors_.push_back({view, 0, componentType, count, "SCALAR", {}, {}});
    return static_cast<int>(accessors_.size()) - 1;
  }

  // The BIN chunk's content, padded to a multiple of 4 bytes.
  std::string finish() {
    bytes_.resize((bytes_.size() + 3) & ~std::size_t{3}, '\0');
    return std::move(bytes_);
  }
  std::size_t size() const { return (bytes_.size() + 3) & ~std::size_t{3}; }

  void writeJson(JsonWriter& json) const {
    json.key("accessors");
    json.beginArray();
    for (const Accessor& a : accessors_) {
      json.beginObject();
      json.field("bufferView", a.view);
      if (a.offset != 0) json.field("byteOffset", static_cast<long long>(a.offset));
      json.field("componentType", a.componentType);
      json.field("count", static_cast<long long>(a.count));
      json.field("type", a.type);
      if (!a.min.empty()) {
        json.key("min");
        json.numberRow(a.min);
        json.key("max");
        json.numberRow(a.max);
      }
      json.endObject();
    }
    json.endArray();
    json.key("bufferViews");
    json.beginArray();
    for (const BufferView& v : views_) {
      json.beginObject();
      json.field("buffer", 0);
      json.field("byteOffset", static_cast<long long>(v.offset));
      json.field("byteLength", static_cast<long long>(v.length));
      if (v.stride != 0) json.field("byteStride", v.stride);
      if (v.target != 0) json.field("target", v.target);
      json.endObject();
    }
    json.endArray();
    json.key("buffers");
    json.beginArray();
    json.beginObject();
    json.field("byteLength", static_cast<long long>(size()));
    json.endObject();
    json.endArray();
  }

private:
  std::string bytes_;
  std::vector<BufferView> views_;
  std::vector<Accessor> accessors_;
};

// PNG bytes of the image at `path`: PNG files as they are, anything Qt reads converted.
std::string pngBytes(const std::string& path) {
  std::string bytes = readFileBytes(path, "texture");
  static constexpr char kPngSignature[] = "\x89PNG\r\n\x1a\n";
  if (bytes.compare(0, 8, kPngSignature, 8) == 0) return bytes;
  const QImage image = QImage::fromData(QByteArray::fromRawData(bytes.data(), static_cast<qsizetype>(bytes.size())));
  if (image.isNull()) throw FileError({path, 0, 0}, "cannot read texture: not an image format Qt can decode");
  QByteArray png;
  QBuffer buffer(&png);
  buffer.open(QIODevice::WriteOnly);
  if (!image.save(&buffer, "PNG")) throw FileError({path, 0, 0}, "cannot convert texture to PNG");
  return png.toStdString();
}

// glTF roughness for a Blinn-Phong exponent s: GGX alpha = sqrt(2 / (s + 2)) matches the
// highlight width, and glTF's roughness is sqrt(alpha).
double roughnessOf(float shininess) { return std::pow(2.0 / (std::max(shininess, 0.0f) + 2.0), 0.25); }

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
        parts_.push_back({&s, static_cast<std::size_t>(s.firstVertex), static_cast<std::size_t>(s.vertexCount)});
    }
    // glTF requires unit normals (validators reject anything else); HeadMesh promises them,
    // but a loader's degenerate or unnormalised ones must not make the whole file invalid.
    for (Eigen::Index v = 0; v < normals_.cols(); ++v) {
      const float length = normals_.col(v).norm();
      normals_.col(v) = std::isfinite(length) && length > 0.0f ? Eigen::Vector3f(normals_.col(v) / length)
                                                                : Eigen::Vector3f::UnitZ();
    }
  }

  std::string build() {
    addTextures();
    addGeometry();
    addTargets();
    JsonWriter json(JsonWriter::Layout::Compact);
    json.beginObject();
    json.key("asset");
    json.beginObject();
    json.field("version", "2.0");
    json.field("generator", "Lacrima");
    json.endObject();
    json.field("scene", 0);
    json.key("scenes");
    json.beginArray();
    json.beginObject();
    json.key("nodes");
    json.beginArray();
    json.integer(0);
    json.endArray();
    json.endObject();
    json.endArray();
    json.key("nodes");
    json.beginArray();
    json.beginObject();
    json.field("name", "head");
    json.field("mesh", 0);
    json.endObject();
    json.endArray();
    writeMesh(json);
    writeMaterials(json);
    writeTextures(json);
    layout_.writeJson(json);
    json.endObject();
    return container(std::move(json).finish(), layout_.finish());
  }

private:
  struct PrimitiveAccessors {
    int position = -1, normal = -1, uv = -1, indices = -1;
    std::vector<int> targets;  // one per exported pose
  };

  void addTextures() {
    // Without uvs a texture cannot be placed, and glTF validators reject baseColorTexture
    // on primitives without TEXCOORD_0.
    if (head_.uvs.cols() == 0) return;
    std::map<std::string, int> imageOfPath;
    for (const HeadMaterial& m : head_.materials) {
      int image = -1;
      if (!m.diffuseTexture.empty()) {
        auto [it, isNew] = imageOfPath.try_emplace(m.diffuseTexture, static_cast<int>(imageViews_.size()));
        if (isNew) {
          const std::string png = pngBytes(m.diffuseTexture);
          imageViews_.push_back(layout_.addView(png.data(), png.size(), 0, 0));
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
    const int positions = layout_.addView(head_.positions.data(), n * 12, 12, kArrayBuffer);
    const int normals = layout_.addView(normals_.data(), n * 12, 12, kArrayBuffer);
    const bool hasUvs = head_.uvs.cols() != 0;
    const int uvs = hasUvs ? layout_.addView(head_.uvs.data(), n * 8, 8, kArrayBuffer) : -1;
    for (const Part& part : parts_) {
      PrimitiveAccessors a;
      a.position = layout_.addFloats(positions, part.first * 12, head_.positions.data() + 3 * part.first, part.count, 3);
      a.normal = layout_.addFloats(normals, part.first * 12, normals_.data() + 3 * part.first, part.count, 3);
      if (hasUvs) a.uv = layout_.addFloats(uvs, part.first * 8, head_.uvs.data() + 2 * part.first, part.count, 2);
      a.indices = addIndices(part);
      primitives_.push_back(std::move(a));
    }
  }

  int addIndices(const Part& part) {
    // glTF forbids the largest value of the index type (restart index): 16 bits hold indices
    // up to 65534, i.e. up to 65535 vertices.
    const bool wide = part.count > 65535;
    std::vector<std::uint32_t> indices;
    for (const Eigen::Vector3i& t : part.submesh->triangles)
      for (int k = 0; k < 3; ++k) indices.push_back(static_cast<std::uint32_t>(t[k]) - static_cast<std::uint32_t>(part.first));
    int view;
    if (wide) {
      view = layout_.addView(indices.data(), indices.size() * 4, 0, kElementArrayBuffer);
    } else {
      const std::vector<std::uint16_t> narrow(indices.begin(), indices.end());
      view = layout_.addView(narrow.data(), narrow.size() * 2, 0, kElementArrayBuffer);
    }
    return layout_.addIndices(view, wide ? kUnsignedInt : kUnsignedShort, indices.size());
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
        const auto begin = std::lower_bound(pose.vertices.begin(), pose.vertices.end(), static_cast<int>(part.first));
        const auto end = std::lower_bound(begin, pose.vertices.end(), static_cast<int>(part.first + part.count));
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
          for (int c = 0; c < 3; ++c) deltas[local + static_cast<std::size_t>(c)] = pose.offsets(c, k);
        }
      }
    }
    const std::size_t zeroOffset = deltas.size();
    deltas.resize(zeroOffset + 3 * zeroVertices, 0.0f);
    const int view = layout_.addView(deltas.data(), deltas.size() * sizeof(float), 12, kArrayBuffer);
    std::vector<int> zeroAccessor(parts_.size(), -1);
    for (std::size_t p = 0; p < poses_.size(); ++p) {
      for (std::size_t i = 0; i < parts_.size(); ++i) {
        const std::size_t count = parts_[i].count;
        int& target = primitives_[i].targets.emplace_back();
        if (const std::optional<std::size_t>& offset = placed[p][i]) {
          target = layout_.addFloats(view, *offset * sizeof(float), deltas.data() + *offset, count, 3);
        } else {
          if (zeroAccessor[i] < 0)
            zeroAccessor[i] = layout_.addFloats(view, zeroOffset * sizeof(float), deltas.data() + zeroOffset, count, 3);
          target = zeroAccessor[i];
        }
      }
    }
  }

  void writeMesh(JsonWriter& json) const {
    json.key("meshes");
    json.beginArray();
    json.beginObject();
    json.field("name", "head");
    json.key("primitives");
    json.beginArray();
    for (std::size_t i = 0; i < parts_.size(); ++i) {
      const PrimitiveAccessors& a = primitives_[i];
      json.beginObject();
      json.key("attributes");
      json.beginObject();
      json.field("POSITION", a.position);
      json.field("NORMAL", a.normal);
      if (a.uv >= 0) json.field("TEXCOORD_0", a.uv);
      json.endObject();
      json.field("indices", a.indices);
      if (parts_[i].submesh->material >= 0) json.field("material", parts_[i].submesh->material);
      json.field("mode", kTriangles);
      if (!a.targets.empty()) {
        json.key("targets");
        json.beginArray();
        for (int t : a.targets) {
          json.beginObject();
          json.field("POSITION", t);
          json.endObject();
        }
        json.endArray();
      }
      json.endObject();
    }
    json.endArray();
    if (!poses_.empty()) {
      json.key("weights");
      json.beginArray();
      for (std::size_t p = 0; p < poses_.size(); ++p) json.number(0.0);
      json.endArray();
      json.key("extras");
      json.beginObject();
      json.key("targetNames");
      json.beginArray();
      for (const ExportedPose& pose : poses_) json.string(pose.name);
      json.endArray();
      json.endObject();
    }
    json.endObject();
    json.endArray();
  }

  void writeMaterials(JsonWriter& json) const {
    if (head_.materials.empty()) return;
    json.key("materials");
    json.beginArray();
    for (std::size_t i = 0; i < head_.materials.size(); ++i) {
      const HeadMaterial& m = head_.materials[i];
      const bool cornea = isCorneaMaterial(head_, static_cast<int>(i));
      json.beginObject();
      json.field("name", m.name);
      json.key("pbrMetallicRoughness");
      json.beginObject();
      json.key("baseColorFactor");
      const double colour[] = {m.diffuse.x(), m.diffuse.y(), m.diffuse.z(), m.diffuse.w()};
      json.numberRow(colour);
      if (i < textureOfMaterial_.size() && textureOfMaterial_[i] >= 0) {
        json.key("baseColorTexture");
        json.beginObject();
        json.field("index", textureOfMaterial_[i]);
        json.endObject();
      }
      json.field("metallicFactor", 0.0);
      const double roughness = roughnessOf(m.shininess);
      json.field("roughnessFactor", cornea ? std::min(roughness, double{kCorneaRoughness}) : roughness);
      json.endObject();
      // OPAQUE would ignore alpha altogether: lashes would show their card outlines.
      if (m.transparent || cornea || m.diffuse.w() < 1.0f) json.field("alphaMode", "BLEND");
      json.endObject();
    }
    json.endArray();
  }

  void writeTextures(JsonWriter& json) const {
    if (imageViews_.empty()) return;
    // Texture i shows image i; no sampler means repeat wrapping and automatic filtering.
    json.key("textures");
    json.beginArray();
    for (std::size_t i = 0; i < imageViews_.size(); ++i) {
      json.beginObject();
      json.field("source", static_cast<int>(i));
      json.endObject();
    }
    json.endArray();
    json.key("images");
    json.beginArray();
    for (int view : imageViews_) {
      json.beginObject();
      json.field("bufferView", view);
      json.field("mimeType", "image/png");
      json.endObject();
    }
    json.endArray();
  }

  // GLB: 12-byte header (magic, version, total length), then the JSON chunk padded with
  // spaces and the BIN chunk padded with zeros, each to a multiple of 4 bytes and preceded by
  // its length and type. All numbers are little-endian uint32, as on the machines we build for.
  static std::string container(std::string json, const std::string& bin) {
    static_assert(std::endian::native == std::endian::little, "GLB numbers are little-endian");
    json.resize((json.size() + 3) & ~std::size_t{3}, ' ');
    std::string glb;
    auto put = [&glb](std::uint32_t value) { glb.append(reinterpret_cast<const char*>(&value), 4); };
    put(kGlbMagic);
    put(kGlbVersion);
    put(static_cast<std::uint32_t>(12 + 8 + json.size() + 8 + bin.size()));
    put(static_cast<std::uint32_t>(json.size()));
    put(kChunkJson);
    glb += json;
    put(static_cast<std::uint32_t>(bin.size()));
    put(kChunkBin);
    glb += bin;
    return glb;
  }

  const HeadMesh& head_;
  const std::vector<ExportedPose>& poses_;
  Eigen::Matrix3Xf normals_;  // head_.normals made unit length
  std::vector<Part> parts_;
  BinaryLayout layout_;
  std::vector<PrimitiveAccessors> primitives_;
  std::vector<int> imageViews_;         // buffer view of each image
  std::vector<int> textureOfMaterial_;  // texture (= image) index per material, -1 for none
};

}  // namespace

void exportGlb(const HeadMesh& head, const PoseSet& poses, const std::string& path) {
  const std::vector<ExportedPose> exported = prepareRigExport(head, poses, path);
  const std::string glb = GlbBuilder(head, exported).build();
  // The header's length field is 32 bits.
  if (glb.size() > std::numeric_limits<std::uint32_t>::max())
    throw FileError({path, 0, 0}, "cannot export: " + std::to_string(glb.size()) + " bytes exceed GLB's 4 GiB limit");
  saveAtomically(path, glb);
}

}  // namespace lacrima::exporters
