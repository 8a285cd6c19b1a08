#include <lacrima/rigging/MeshImport.h>

#include <lacrima/common/Diagnostics.h>

#include <Eigen/Geometry>

#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <assimp/Importer.hpp>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace lacrima::rigging {

namespace {

namespace fs = std::filesystem;

[[noreturn]] void fail(const std::string& path, const std::string& message) {
  throw FileError(SourceLocation{path}, message);
}

struct MeshInstance {
  unsigned mesh = 0;
  aiMatrix4x4 transform;
};

// What a head file may ask for. A file's size bounds what assimp reads; the vertex and
// triangle bounds hold after instancing, where a few kilobytes of nodes naming one mesh over and
// over could otherwise ask for billions. Heads people rig have tens of thousands of vertices,
// far below them. The node depth bounds the recursion below.
constexpr std::uintmax_t kMaxFileBytes = std::uintmax_t{1} << 30;
constexpr std::size_t kMaxVertices = std::size_t{1} << 22;
constexpr std::size_t kMaxTriangles = std::size_t{1} << 23;
constexpr std::size_t kMaxInstances = 100'000;
constexpr int kMaxNodeDepth = 256;

// Every (node, mesh) pair of the node graph, depth first, with the node's global transform.
void collectInstances(const std::string& path, const aiNode* node, const aiMatrix4x4& parent,
                      int depth, std::vector<MeshInstance>& out) {
  if (depth > kMaxNodeDepth)
    fail(path, "its nodes nest deeper than " + std::to_string(kMaxNodeDepth) + " levels");
  const aiMatrix4x4 global = parent * node->mTransformation;
  for (unsigned i = 0; i < node->mNumMeshes; ++i) {
    if (out.size() == kMaxInstances)
      fail(path, "its nodes place meshes more than " + std::to_string(kMaxInstances) + " times");
    out.push_back({node->mMeshes[i], global});
  }
  for (unsigned i = 0; i < node->mNumChildren; ++i)
    collectInstances(path, node->mChildren[i], global, depth + 1, out);
}

// The texture's absolute path, or "" when it is embedded or missing.
std::string resolveTexture(const aiScene& scene, const std::string& modelPath,
                           const aiString& name) {
  std::string texture = name.C_Str();
  if (texture.empty() || texture.front() == '*' || scene.GetEmbeddedTexture(name.C_Str()))
    return {};
  std::replace(texture.begin(), texture.end(), '\\', '/');  // written on Windows
  fs::path file(texture);
  if (file.is_relative()) file = fs::path(modelPath).parent_path() / file;
  std::error_code error;
  file = fs::absolute(file, error).lexically_normal();
  return !error && fs::is_regular_file(file, error) ? file.string() : std::string();
}

HeadMaterial convertMaterial(const aiScene& scene, const aiMaterial& source,
                             const std::string& path) {
  HeadMaterial m;
  aiString name;
  if (source.Get(AI_MATKEY_NAME, name) == AI_SUCCESS) m.name = name.C_Str();
  aiColor3D colour;
  if (source.Get(AI_MATKEY_COLOR_DIFFUSE, colour) == AI_SUCCESS)
    m.diffuse.head<3>() << colour.r, colour.g, colour.b;
  float opacity = 1.0f;
  if (source.Get(AI_MATKEY_OPACITY, opacity) == AI_SUCCESS)
    m.diffuse[3] = std::clamp(opacity, 0.0f, 1.0f);
  if (source.Get(AI_MATKEY_COLOR_SPECULAR, colour) == AI_SUCCESS)
    m.specular << colour.r, colour.g, colour.b;
  float shininess = 0.0f;
  if (source.Get(AI_MATKEY_SHININESS, shininess) == AI_SUCCESS && shininess > 0.0f)
    m.shininess = shininess;
  aiString texture;
  if (source.GetTextureCount(aiTextureType_DIFFUSE) > 0 &&
      source.GetTexture(aiTextureType_DIFFUSE, 0, &texture) == AI_SUCCESS)
    m.diffuseTexture = resolveTexture(scene, path, texture);
  m.transparent = m.diffuse[3] < 1.0f || source.GetTextureCount(aiTextureType_OPACITY) > 0;
  return m;
}

// The material's name unless it is assimp's stand-in for "none", else the mesh's name.
std::string baseName(const aiMesh& mesh, const HeadMaterial* material) {
  if (material && !material->name.empty() && material->name != AI_DEFAULT_MATERIAL_NAME)
    return material->name;
  if (mesh.mName.length > 0) return mesh.mName.C_Str();
  return "mesh";
}

std::string uniqueName(const std::string& base, std::set<std::string>& used) {
  std::string name = base;
  for (int n = 2; used.count(name); ++n) name = base + "_" + std::to_string(n);
  used.insert(name);
  return name;
}

// What a head file must hold, for the messages of files that do not.
constexpr const char* kExpected =
    "expected a mesh with faces (triangles or polygons), as a head exported from a modeller has";

// "12 vertices, 3 lines and 2 points", from the meshes of a scene assimp read without
// validating it (validation refuses scenes without faces, with a message about aiScene fields).
std::string describeContent(const aiScene& scene) {
  std::size_t vertices = 0, points = 0, lines = 0, polygons = 0;
  for (unsigned m = 0; m < scene.mNumMeshes; ++m) {
    const aiMesh* mesh = scene.mMeshes[m];
    if (!mesh) continue;
    vertices += mesh->mNumVertices;
    for (unsigned f = 0; f < mesh->mNumFaces; ++f) {
      const unsigned n = mesh->mFaces[f].mNumIndices;
      (n == 1 ? points : n == 2 ? lines : polygons) += 1;
    }
  }
  if (scene.mNumMeshes == 0) return "no mesh at all";
  auto count = [](std::size_t n, const char* what) {
    return std::to_string(n) + " " + what + (n == 1 ? "" : "s");
  };
  std::string out = std::to_string(vertices) + (vertices == 1 ? " vertex" : " vertices");
  if (polygons > 0) out += ", " + count(polygons, "face");
  if (lines > 0) out += ", " + count(lines, "line");
  if (points > 0) out += ", " + count(points, "point");
  return out + (polygons == 0 ? " and no face" : "");
}

// Whether any triangle has an area: a mesh of zero-area triangles only (every face a line or a
// point in disguise) has no surface to rig.
bool hasArea(const HeadMesh& head) {
  for (const HeadSubmesh& s : head.submeshes)
    for (const Eigen::Vector3i& t : s.triangles) {
      const Eigen::Vector3f a = head.positions.col(t[0]), b = head.positions.col(t[1]),
                            c = head.positions.col(t[2]);
      if ((b - a).cross(c - a).squaredNorm() > 0.0f) return true;
    }
  return false;
}

}  // namespace

HeadMesh importHeadMesh(const std::string& path) {
  std::error_code error;
  if (!fs::exists(path, error)) fail(path, "no such file");
  if (!fs::is_regular_file(path, error)) fail(path, "not a regular file");
  const std::uintmax_t bytes = fs::file_size(path, error);
  if (bytes == 0 && !error) fail(path, std::string("the file is empty; ") + kExpected);
  if (!error && bytes > kMaxFileBytes)
    fail(path, "the file is " + std::to_string(bytes >> 20) + " MiB; a head may be at most " +
                   std::to_string(kMaxFileBytes >> 20) + " MiB");

  Assimp::Importer importer;
  // JoinIdenticalVertices merges the OBJ reader's per-corner copies (same position, uv and
  // normal), so a vertex index names a point of the head and poses stay small. Its numbering
  // is first-use order, deterministic for a file (see the header).
  const aiScene* scene =
      importer.ReadFile(path, aiProcess_Triangulate | aiProcess_JoinIdenticalVertices |
                                  aiProcess_ValidateDataStructure);
  if (!scene) {
    const std::string why = importer.GetErrorString();
    // Read again unvalidated: if that works, the file is readable but has nothing to rig (no
    // faces), which deserves a plain message rather than assimp's validation text.
    Assimp::Importer raw;
    if (const aiScene* unvalidated = raw.ReadFile(path, 0))
      fail(path, "no faces in it (" + describeContent(*unvalidated) + "); " + kExpected);
    fail(path, "assimp cannot read it: " + why);
  }
  if ((scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE) || !scene->mRootNode)
    fail(path, "assimp read an incomplete scene (no mesh data)");

  std::vector<MeshInstance> instances;
  collectInstances(path, scene->mRootNode, aiMatrix4x4(), 0, instances);

  HeadMesh head;
  std::size_t vertexTotal = 0, faceTotal = 0;
  bool anyUvs = false;
  for (const MeshInstance& instance : instances) {
    const aiMesh& mesh = *scene->mMeshes[instance.mesh];
    vertexTotal += mesh.mNumVertices;
    faceTotal += mesh.mNumFaces;
    anyUvs = anyUvs || mesh.HasTextureCoords(0);
    if (vertexTotal > kMaxVertices || faceTotal > kMaxTriangles)
      fail(path, "its meshes, as its nodes place them, have more than " +
                     std::to_string(kMaxVertices) + " vertices or " +
                     std::to_string(kMaxTriangles) + " faces; a head may have at most that");
  }
  head.positions.resize(3, static_cast<Eigen::Index>(vertexTotal));
  head.uvs = anyUvs ? Eigen::Matrix2Xf::Zero(2, static_cast<Eigen::Index>(vertexTotal))
                    : Eigen::Matrix2Xf(2, 0);

  std::map<unsigned, int> materialOf;  // assimp material index -> head material index
  std::set<std::string> names;
  int next = 0;
  for (const MeshInstance& instance : instances) {
    const aiMesh& mesh = *scene->mMeshes[instance.mesh];
    HeadSubmesh sub;
    if (mesh.mMaterialIndex < scene->mNumMaterials) {
      auto [it, added] =
          materialOf.try_emplace(mesh.mMaterialIndex, static_cast<int>(head.materials.size()));
      if (added)
        head.materials.push_back(
            convertMaterial(*scene, *scene->mMaterials[mesh.mMaterialIndex], path));
      sub.material = it->second;
    }
    sub.name = uniqueName(
        baseName(mesh,
                 sub.material >= 0 ? &head.materials[static_cast<size_t>(sub.material)] : nullptr),
        names);
    sub.firstVertex = next;
    sub.vertexCount = static_cast<int>(mesh.mNumVertices);
    for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
      const aiVector3D p = instance.transform * mesh.mVertices[v];
      head.positions.col(next + static_cast<int>(v)) << p.x, p.y, p.z;
      if (mesh.HasTextureCoords(0))
        head.uvs.col(next + static_cast<int>(v)) << mesh.mTextureCoords[0][v].x,
            1.0f - mesh.mTextureCoords[0][v].y;
    }
    // A mirroring transform turns counter-clockwise triangles clockwise: swap two corners back.
    const bool mirrored = instance.transform.Determinant() < 0;
    for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
      const aiFace& face = mesh.mFaces[f];
      if (face.mNumIndices != 3) continue;  // points and lines have no surface
      Eigen::Vector3i t(next + static_cast<int>(face.mIndices[0]),
                        next + static_cast<int>(face.mIndices[1]),
                        next + static_cast<int>(face.mIndices[2]));
      if (mirrored) std::swap(t[1], t[2]);
      sub.triangles.push_back(t);
    }
    next += sub.vertexCount;
    head.submeshes.push_back(std::move(sub));
  }
  if (head.triangleCount() == 0)
    fail(path, "no triangles in it (" + describeContent(*scene) + "); " + kExpected);
  if (!head.positions.allFinite()) {
    Eigen::Index bad = 0;
    while (head.positions.col(bad).allFinite()) ++bad;
    fail(path, "vertex " + std::to_string(bad + 1) +
                   " has a coordinate that is not a finite number; a head's vertices must be");
  }
  if (!hasArea(head))
    fail(path, "every one of its " + std::to_string(head.triangleCount()) +
                   " triangles has zero area (no surface); " + kExpected);
  head.computeNormals();
  return head;
}

}  // namespace lacrima::rigging
