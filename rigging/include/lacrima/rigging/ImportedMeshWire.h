#pragma once
// How the importer process (lacrima-import) hands a head back to the program that started it: a
// small binary format on a pipe. The child writes it (writeImportedMesh, writeImportRefusal);
// the parent reads it (readImportAnswer) and trusts nothing in it: a child whose assimp was
// subverted by a crafted file may send anything, so every count is bounded before anything is
// allocated for it, and every index is checked against what it indexes.
//
// Layout, little-endian throughout (f32 = IEEE 754 single, str = u32 byte length + UTF-8 bytes):
//
//   header   magic "LCRMESH\0" (8 bytes), u32 version (1), u32 kind (1 mesh, 2 refusal),
//            u64 payload bytes (exactly the bytes that follow)
//   refusal  str message (why the head cannot be read, without the file's name)
//   mesh     u32 vertices, u32 has uvs (0 or 1), u32 materials, u32 parts
//            f32 x 3 per vertex   positions
//            f32 x 3 per vertex   normals
//            f32 x 2 per vertex   uvs (only with has uvs)
//            per material: str name, str diffuse texture (absolute path or empty),
//                          f32 x 4 diffuse (rgba), f32 x 3 specular, f32 shininess,
//                          u32 transparent (0 or 1)
//            per part:     str name, i32 material (-1 for none), u32 first vertex,
//                          u32 vertex count, u32 triangles, u32 x 3 per triangle (head vertex
//                          indices, each inside the part's own vertex range)
//
// The bounds are those importHeadMesh enforces on a file (MeshImport.h), so whatever it returns
// fits; the writer refuses (std::length_error) what the reader would refuse.
#include <lacrima/common/HeadMesh.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <variant>

namespace lacrima::rigging::wire {

inline constexpr char kMagic[8] = {'L', 'C', 'R', 'M', 'E', 'S', 'H', '\0'};
inline constexpr std::uint32_t kVersion = 1;
inline constexpr std::size_t kHeaderBytes = 24;

inline constexpr std::uint32_t kMaxVertices = 1u << 22;
inline constexpr std::uint32_t kMaxTriangles = 1u << 23;      // over all parts
inline constexpr std::uint32_t kMaxParts = 100'000;           // one per mesh instance
inline constexpr std::uint32_t kMaxMaterials = 100'000;       // at most one per part
inline constexpr std::uint32_t kMaxNameBytes = 4096;          // names and texture paths
inline constexpr std::uint32_t kMaxMessageBytes = 64 * 1024;  // a refusal's text
// The largest answer the bounds allow, rounded up: a reader stops reading beyond it.
inline constexpr std::uint64_t kMaxAnswerBytes = std::uint64_t{1} << 30;

// A head the child could not read, in its own words (importHeadMesh's FileError message).
struct Refusal {
  std::string message;
};
using ImportAnswer = std::variant<HeadMesh, Refusal>;

// The child's side. Throws std::length_error for a head beyond the bounds above.
std::string writeImportedMesh(const HeadMesh& head);
// A message longer than kMaxMessageBytes is cut (at a UTF-8 character boundary).
std::string writeImportRefusal(std::string_view message);

// The parent's side: a pure function of the bytes. Throws FileError at `file` ("the importer's
// answer is malformed: ...") for anything but a well-formed answer within the bounds: a wrong
// magic or version, a size that disagrees with the bytes received, a count over its bound, a
// part outside the vertices, a triangle corner outside its part, a material index out of range,
// a position or normal that is not finite.
ImportAnswer readImportAnswer(std::string_view bytes, const std::string& file);

}  // namespace lacrima::rigging::wire
