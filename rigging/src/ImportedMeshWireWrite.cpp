// The importer process's side of ImportedMeshWire.h.
#include <lacrima/rigging/ImportedMeshWire.h>

#include <bit>
#include <cstring>
#include <stdexcept>

namespace lacrima::rigging::wire {
namespace {

static_assert(std::endian::native == std::endian::little,
              "the wire format is little-endian and written by copying bytes");

class Writer {
 public:
  template <class T>
  void put(T value) {
    static_assert(std::is_arithmetic_v<T>);
    char bytes[sizeof(T)];
    std::memcpy(bytes, &value, sizeof(T));
    out_.append(bytes, sizeof(T));
  }
  void putFloats(const float* data, std::size_t count) {
    out_.append(reinterpret_cast<const char*>(data), count * sizeof(float));
  }
  void putString(std::string_view text) {
    put(static_cast<std::uint32_t>(text.size()));
    out_.append(text);
  }
  std::string& bytes() { return out_; }

 private:
  std::string out_;
};

void beginAnswer(Writer& w, std::uint32_t kind) {
  w.bytes().append(kMagic, sizeof kMagic);
  w.put(kVersion);
  w.put(kind);
  w.put(std::uint64_t{0});  // the payload's size, filled in by finish()
}

std::string finish(Writer& w) {
  std::string& out = w.bytes();
  const std::uint64_t payload = out.size() - kHeaderBytes;
  std::memcpy(out.data() + kHeaderBytes - sizeof payload, &payload, sizeof payload);
  return std::move(out);
}

void check(bool ok, const std::string& what) {
  if (!ok) throw std::length_error("the head does not fit the importer's answer: " + what);
}

// `text` cut to at most `limit` bytes without splitting a UTF-8 character.
std::string_view cut(std::string_view text, std::size_t limit) {
  if (text.size() <= limit) return text;
  std::size_t end = limit;
  while (end > 0 && (static_cast<unsigned char>(text[end]) & 0xC0) == 0x80) --end;
  return text.substr(0, end);
}

}  // namespace

std::string writeImportedMesh(const HeadMesh& head) {
  const auto vertices = static_cast<std::size_t>(head.positions.cols());
  check(vertices <= kMaxVertices, std::to_string(vertices) + " vertices");
  check(head.normals.cols() == head.positions.cols(), "normals missing");
  const bool hasUvs = head.uvs.cols() > 0;
  check(!hasUvs || head.uvs.cols() == head.positions.cols(), "uvs and vertices disagree");
  check(head.submeshes.size() <= kMaxParts, std::to_string(head.submeshes.size()) + " parts");
  check(head.materials.size() <= kMaxMaterials,
        std::to_string(head.materials.size()) + " materials");
  check(static_cast<std::size_t>(head.triangleCount()) <= kMaxTriangles, "too many triangles");

  Writer w;
  w.bytes().reserve(kHeaderBytes + vertices * 8 * sizeof(float) +
                    static_cast<std::size_t>(head.triangleCount()) * 12);
  beginAnswer(w, 1);
  w.put(static_cast<std::uint32_t>(vertices));
  w.put(std::uint32_t{hasUvs ? 1u : 0u});
  w.put(static_cast<std::uint32_t>(head.materials.size()));
  w.put(static_cast<std::uint32_t>(head.submeshes.size()));
  w.putFloats(head.positions.data(), 3 * vertices);
  w.putFloats(head.normals.data(), 3 * vertices);
  if (hasUvs) w.putFloats(head.uvs.data(), 2 * vertices);
  for (const HeadMaterial& m : head.materials) {
    check(m.name.size() <= kMaxNameBytes,
          "a material name over " + std::to_string(kMaxNameBytes) + " bytes");
    w.putString(m.name);
    // A texture path too long to send cannot be opened either: the part gets its plain colour.
    w.putString(m.diffuseTexture.size() <= kMaxNameBytes ? m.diffuseTexture : std::string());
    w.putFloats(m.diffuse.data(), 4);
    w.putFloats(m.specular.data(), 3);
    w.put(m.shininess);
    w.put(std::uint32_t{m.transparent ? 1u : 0u});
  }
  for (const HeadSubmesh& s : head.submeshes) {
    check(s.name.size() <= kMaxNameBytes,
          "a part name over " + std::to_string(kMaxNameBytes) + " bytes");
    w.putString(s.name);
    w.put(static_cast<std::int32_t>(s.material));
    w.put(static_cast<std::uint32_t>(s.firstVertex));
    w.put(static_cast<std::uint32_t>(s.vertexCount));
    w.put(static_cast<std::uint32_t>(s.triangles.size()));
    for (const Eigen::Vector3i& t : s.triangles)
      for (int c = 0; c < 3; ++c) w.put(static_cast<std::uint32_t>(t[c]));
  }
  return finish(w);
}

std::string writeImportRefusal(std::string_view message) {
  Writer w;
  beginAnswer(w, 2);
  w.putString(cut(message, kMaxMessageBytes));
  return finish(w);
}

}  // namespace lacrima::rigging::wire
