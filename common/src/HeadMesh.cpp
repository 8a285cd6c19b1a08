#include <lacrima/common/HeadMesh.h>

#include <Eigen/Geometry>

#include <map>
#include <tuple>

namespace lacrima::inline common {

int HeadMesh::triangleCount() const {
  int count = 0;
  for (const HeadSubmesh& s : submeshes) count += static_cast<int>(s.triangles.size());
  return count;
}

const HeadSubmesh* HeadMesh::findSubmesh(std::string_view name) const {
  for (const HeadSubmesh& s : submeshes)
    if (s.name == name) return &s;
  return nullptr;
}

int HeadMesh::submeshOfVertex(int vertex) const {
  for (int i = 0; i < static_cast<int>(submeshes.size()); ++i) {
    const HeadSubmesh& s = submeshes[static_cast<size_t>(i)];
    if (vertex >= s.firstVertex && vertex < s.firstVertex + s.vertexCount) return i;
  }
  return -1;
}

std::vector<int> weldCoincidentVertices(const Eigen::Matrix3Xf& positions) {
  // Exact equality: uv seams duplicate a position bit for bit, and anything looser would
  // merge genuinely separate surfaces such as the lips at the mouth slit.
  std::map<std::tuple<float, float, float>, int> first;
  std::vector<int> weld(static_cast<size_t>(positions.cols()));
  for (Eigen::Index v = 0; v < positions.cols(); ++v) {
    // NaN compares false both ways and would break the map's ordering: such a vertex is its
    // own root and welds with nothing.
    if (!positions.col(v).allFinite()) {
      weld[static_cast<size_t>(v)] = static_cast<int>(v);
      continue;
    }
    const auto key = std::make_tuple(positions(0, v), positions(1, v), positions(2, v));
    weld[static_cast<size_t>(v)] = first.try_emplace(key, static_cast<int>(v)).first->second;
  }
  return weld;
}

void accumulateNormals(const Eigen::Matrix3Xf& positions,
                       const std::vector<Eigen::Vector3i>& triangles, const std::vector<int>& weld,
                       Eigen::Matrix3Xf& normals) {
  normals.setZero(3, positions.cols());
  for (const Eigen::Vector3i& t : triangles) {
    // The unnormalised cross product weights each face by its area.
    const Eigen::Vector3f n = (positions.col(t[1]) - positions.col(t[0]))
                                  .cross(positions.col(t[2]) - positions.col(t[0]));
    for (int k = 0; k < 3; ++k) normals.col(weld[static_cast<size_t>(t[k])]) += n;
  }
  for (Eigen::Index v = 0; v < positions.cols(); ++v) {
    const int root = weld[static_cast<size_t>(v)];
    if (root != v) normals.col(v) = normals.col(root);
  }
  for (Eigen::Index v = 0; v < positions.cols(); ++v) {
    const float length = normals.col(v).norm();
    // A vertex on no triangle (or only degenerate ones) gets +z rather than NaN.
    normals.col(v) =
        length > 0 ? Eigen::Vector3f(normals.col(v) / length) : Eigen::Vector3f::UnitZ();
  }
}

void HeadMesh::computeNormals() {
  std::vector<Eigen::Vector3i> all;
  all.reserve(static_cast<size_t>(triangleCount()));
  for (const HeadSubmesh& s : submeshes)
    all.insert(all.end(), s.triangles.begin(), s.triangles.end());
  accumulateNormals(positions, all, weldCoincidentVertices(positions), normals);
}

Eigen::Vector3f HeadMesh::boundsMin() const {
  return positions.cols() ? Eigen::Vector3f(positions.rowwise().minCoeff())
                          : Eigen::Vector3f::Zero();
}

Eigen::Vector3f HeadMesh::boundsMax() const {
  return positions.cols() ? Eigen::Vector3f(positions.rowwise().maxCoeff())
                          : Eigen::Vector3f::Zero();
}

}  // namespace lacrima::inline common
