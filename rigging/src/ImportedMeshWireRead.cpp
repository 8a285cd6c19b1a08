// The parent's side of ImportedMeshWire.h: every count bounded before it is used to allocate,
// every index checked against what it indexes.
#include <lacrima/common/Diagnostics.h>
#include <lacrima/rigging/ImportedMeshWire.h>

#include <bit>
#include <cmath>
#include <cstring>

namespace lacrima::rigging::wire {
namespace {

static_assert(std::endian::native == std::endian::little,
              "the wire format is little-endian and read by copying bytes");

class Reader {
 public:
  Reader(std::string_view bytes, const std::string& file) : bytes_(bytes), file_(file) {}

  [[noreturn]] void fail(const std::string& what) const {
    throw FileError(SourceLocation{file_}, "the importer's answer is malformed: " + what +
                                               " (at byte " + std::to_string(at_) + ")");
  }
  std::size_t left() const { return bytes_.size() - at_; }
  void need(std::uint64_t count, const char* what) const {
    if (count > left())
      fail(std::string(what) + " needs " + std::to_string(count) + " bytes, " +
           std::to_string(left()) + " are left");
  }

  template <class T>
  T get(const char* what) {
    need(sizeof(T), what);
    T value;
    std::memcpy(&value, bytes_.data() + at_, sizeof(T));
    at_ += sizeof(T);
    return value;
  }
  std::uint32_t count(const char* what, std::uint32_t limit) {
    const auto n = get<std::uint32_t>(what);
    if (n > limit)
      fail(std::string(what) + " is " + std::to_string(n) + ", more than " + std::to_string(limit));
    return n;
  }
  bool flag(const char* what) {
    const auto n = get<std::uint32_t>(what);
    if (n > 1) fail(std::string(what) + " is " + std::to_string(n) + ", expected 0 or 1");
    return n == 1;
  }
  std::string string(const char* what, std::uint32_t limit) {
    const std::uint32_t n = count(what, limit);
    need(n, what);
    std::string text(bytes_.substr(at_, n));
    at_ += n;
    return text;
  }
  void floats(float* out, std::size_t n, const char* what) {
    need(std::uint64_t{n} * sizeof(float), what);
    std::memcpy(out, bytes_.data() + at_, n * sizeof(float));
    at_ += n * sizeof(float);
  }
  void skip(std::size_t n) { at_ += n; }

 private:
  std::string_view bytes_;
  const std::string& file_;
  std::size_t at_ = 0;
};

void readMaterial(Reader& in, HeadMaterial& m) {
  m.name = in.string("a material's name length", kMaxNameBytes);
  m.diffuseTexture = in.string("a material's texture path length", kMaxNameBytes);
  in.floats(m.diffuse.data(), 4, "a material's diffuse colour");
  in.floats(m.specular.data(), 3, "a material's specular colour");
  m.shininess = in.get<float>("a material's shininess");
  m.transparent = in.flag("a material's transparency");
  if (!m.diffuse.allFinite() || !m.specular.allFinite() || !std::isfinite(m.shininess))
    in.fail("material \"" + m.name + "\" has a colour or shininess that is not a finite number");
}

void readPart(Reader& in, int vertices, int materials, std::uint64_t& triangleTotal,
              HeadSubmesh& s) {
  s.name = in.string("a part's name length", kMaxNameBytes);
  s.material = in.get<std::int32_t>("a part's material");
  const auto first = in.get<std::uint32_t>("a part's first vertex");
  const auto count = in.get<std::uint32_t>("a part's vertex count");
  if (s.material < -1 || s.material >= materials)
    in.fail("part \"" + s.name + "\" names material " + std::to_string(s.material) + " of " +
            std::to_string(materials));
  if (first > static_cast<std::uint32_t>(vertices) ||
      count > static_cast<std::uint32_t>(vertices) - first)
    in.fail("part \"" + s.name + "\" has vertices " + std::to_string(first) + " to " +
            std::to_string(std::uint64_t{first} + count) + " of " + std::to_string(vertices));
  s.firstVertex = static_cast<int>(first);
  s.vertexCount = static_cast<int>(count);
  const std::uint32_t triangles = in.count("a part's triangle count", kMaxTriangles);
  triangleTotal += triangles;
  if (triangleTotal > kMaxTriangles)
    in.fail("the parts have more than " + std::to_string(kMaxTriangles) + " triangles");
  in.need(std::uint64_t{triangles} * 12, "a part's triangles");
  s.triangles.resize(triangles);
  for (Eigen::Vector3i& t : s.triangles)
    for (int c = 0; c < 3; ++c) {
      const auto v = in.get<std::uint32_t>("a triangle corner");
      if (v < first || v - first >= count)
        in.fail("a triangle of part \"" + s.name + "\" uses vertex " + std::to_string(v) +
                ", outside the part's vertices " + std::to_string(first) + " to " +
                std::to_string(std::uint64_t{first} + count));
      t[c] = static_cast<int>(v);
    }
}

HeadMesh readMesh(Reader& in) {
  const std::uint32_t vertices = in.count("the vertex count", kMaxVertices);
  const bool hasUvs = in.flag("the uv flag");
  const std::uint32_t materials = in.count("the material count", kMaxMaterials);
  const std::uint32_t parts = in.count("the part count", kMaxParts);
  // The fixed-size arrays must all be there before any is allocated.
  in.need(std::uint64_t{vertices} * (hasUvs ? 8 : 6) * sizeof(float), "the vertex arrays");
  // Each material and part takes at least its fixed fields.
  in.need(std::uint64_t{materials} * (2 * 4 + 8 * 4 + 4) + std::uint64_t{parts} * (4 + 4 * 4),
          "the materials and parts");

  HeadMesh head;
  const auto n = static_cast<Eigen::Index>(vertices);
  head.positions.resize(3, n);
  head.normals.resize(3, n);
  in.floats(head.positions.data(), 3 * std::size_t{vertices}, "the positions");
  in.floats(head.normals.data(), 3 * std::size_t{vertices}, "the normals");
  if (hasUvs) {
    head.uvs.resize(2, n);
    in.floats(head.uvs.data(), 2 * std::size_t{vertices}, "the uvs");
  } else {
    head.uvs.resize(2, 0);
  }
  for (Eigen::Index v = 0; v < n; ++v)
    if (!head.positions.col(v).allFinite() || !head.normals.col(v).allFinite())
      in.fail("vertex " + std::to_string(v + 1) + " has a coordinate that is not finite");

  head.materials.resize(materials);
  for (HeadMaterial& m : head.materials) readMaterial(in, m);
  head.submeshes.resize(parts);
  std::uint64_t triangles = 0;
  for (HeadSubmesh& s : head.submeshes)
    readPart(in, static_cast<int>(vertices), static_cast<int>(materials), triangles, s);
  if (in.left() != 0) in.fail(std::to_string(in.left()) + " bytes after the last part");
  // The importer refuses a head without triangles itself; a mesh answer must have some.
  if (triangles == 0) in.fail("a mesh without triangles");
  return head;
}

}  // namespace

ImportAnswer readImportAnswer(std::string_view bytes, const std::string& file) {
  Reader in(bytes, file);
  in.need(kHeaderBytes, "the header");
  if (std::memcmp(bytes.data(), kMagic, sizeof kMagic) != 0)
    in.fail("it does not start with the importer's magic \"LCRMESH\"");
  in.skip(sizeof kMagic);
  const auto version = in.get<std::uint32_t>("the version");
  if (version != kVersion)
    in.fail("version " + std::to_string(version) + ", expected " + std::to_string(kVersion) +
            " (is lacrima-import from another Lacrima?)");
  const auto kind = in.get<std::uint32_t>("the kind");
  const auto payload = in.get<std::uint64_t>("the payload size");
  if (payload != in.left())
    in.fail("the header announces " + std::to_string(payload) + " bytes, " +
            std::to_string(in.left()) + " came");
  if (kind == 2) {
    Refusal refusal{in.string("the message length", kMaxMessageBytes)};
    if (in.left() != 0) in.fail(std::to_string(in.left()) + " bytes after the message");
    return refusal;
  }
  if (kind != 1) in.fail("kind " + std::to_string(kind) + ", expected 1 (a mesh) or 2 (refused)");
  return readMesh(in);
}

}  // namespace lacrima::rigging::wire
