#include "SubmeshAppend.h"

#include <lacrima/common/Diagnostics.h>

#include <cstdint>
#include <stdexcept>
#include <unordered_map>

namespace lacrima::rigging {

void appendSubmesh(HeadMesh& mesh, const std::string& name, int material, const ThreeModel& model,
                   const Eigen::Matrix3Xf& positions, const std::vector<int>& faceIndices) {
  if (positions.cols() != model.vertices.cols())
    throw std::invalid_argument("appendSubmesh: " + std::to_string(positions.cols()) +
                                " positions for the " + std::to_string(model.vertices.cols()) +
                                " vertices of " + model.path);
  HeadSubmesh sub;
  sub.name = name;
  sub.material = material;
  sub.firstVertex = mesh.vertexCount();

  std::unordered_map<std::uint64_t, int> vertexOf;  // (model vertex, uv) -> global vertex
  vertexOf.reserve(faceIndices.size() * 2);
  std::vector<std::pair<int, int>> corners;  // (model vertex, uv) of each new vertex
  for (int f : faceIndices) {
    const ThreeFace& face = model.faces[static_cast<size_t>(f)];
    int global[4];
    for (int c = 0; c < face.corners; ++c) {
      const int v = face.vertex[static_cast<size_t>(c)];
      const int uv = face.uv[static_cast<size_t>(c)];
      if (uv < 0)
        throw FileError(SourceLocation{model.path},
                        "face " + std::to_string(f) + " has no uvs (expected per-corner uvs)");
      const std::uint64_t key =
          (static_cast<std::uint64_t>(v) << 32) | static_cast<std::uint32_t>(uv);
      const auto [it, added] =
          vertexOf.try_emplace(key, sub.firstVertex + static_cast<int>(corners.size()));
      if (added) corners.emplace_back(v, uv);
      global[c] = it->second;
    }
    sub.triangles.emplace_back(global[0], global[1], global[2]);
    if (face.corners == 4) sub.triangles.emplace_back(global[0], global[2], global[3]);
  }

  sub.vertexCount = static_cast<int>(corners.size());
  const Eigen::Index first = sub.firstVertex, total = first + sub.vertexCount;
  mesh.positions.conservativeResize(3, total);
  mesh.uvs.conservativeResize(2, total);
  for (Eigen::Index i = 0; i < sub.vertexCount; ++i) {
    const auto [v, uv] = corners[static_cast<size_t>(i)];
    mesh.positions.col(first + i) = positions.col(v);
    mesh.uvs.col(first + i) = Eigen::Vector2f(model.uvs(0, uv), 1.0f - model.uvs(1, uv));
  }
  mesh.submeshes.push_back(std::move(sub));
}

}  // namespace lacrima::rigging
