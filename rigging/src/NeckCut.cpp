#include "NeckCut.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

namespace lacrima::rigging {

namespace {

std::uint64_t edgeKey(int a, int b) {
  if (a > b) std::swap(a, b);
  return (static_cast<std::uint64_t>(a) << 32) | static_cast<std::uint32_t>(b);
}

// Faces of the surface around each edge and each vertex, built once: sorted arrays instead of
// hash maps of vectors keep this to a few milliseconds on the 13k-quad body.
class SurfaceTopology {
 public:
  SurfaceTopology(const std::vector<ThreeFace>& faces, const std::vector<int>& surface,
                  Eigen::Index vertexCount)
      : faces_(faces), vertexStart_(static_cast<size_t>(vertexCount) + 1, 0) {
    for (int f : surface) {
      const ThreeFace& face = faces[static_cast<size_t>(f)];
      for (int c = 0; c < face.corners; ++c) {
        const int v = face.vertex[static_cast<size_t>(c)];
        edges_.emplace_back(edgeKey(v, face.vertex[static_cast<size_t>((c + 1) % face.corners)]),
                            f);
        ++vertexStart_[static_cast<size_t>(v) + 1];
      }
    }
    std::sort(edges_.begin(), edges_.end());
    for (size_t v = 1; v < vertexStart_.size(); ++v) vertexStart_[v] += vertexStart_[v - 1];
    vertexFaces_.resize(vertexStart_.back());
    std::vector<int> fill(vertexStart_.begin(), vertexStart_.end() - 1);
    for (int f : surface) {
      const ThreeFace& face = faces[static_cast<size_t>(f)];
      for (int c = 0; c < face.corners; ++c)
        vertexFaces_[static_cast<size_t>(
            fill[static_cast<size_t>(face.vertex[static_cast<size_t>(c)])]++)] = f;
    }
  }

  // The faces that share edge (a, b), as a range of (key, face) pairs.
  auto facesOfEdge(int a, int b) const {
    const std::uint64_t key = edgeKey(a, b);
    return std::equal_range(edges_.begin(), edges_.end(), std::make_pair(key, 0),
                            [](const auto& x, const auto& y) { return x.first < y.first; });
  }

  // The vertices joined to v by an edge.
  std::vector<int> neighbours(int v) const {
    std::vector<int> result;
    for (int i = vertexStart_[static_cast<size_t>(v)]; i < vertexStart_[static_cast<size_t>(v) + 1];
         ++i) {
      const ThreeFace& face = faces_[static_cast<size_t>(vertexFaces_[static_cast<size_t>(i)])];
      const int c = cornerOf(face, v);
      result.push_back(face.vertex[static_cast<size_t>((c + 1) % face.corners)]);
      result.push_back(face.vertex[static_cast<size_t>((c + face.corners - 1) % face.corners)]);
    }
    std::sort(result.begin(), result.end());
    result.erase(std::unique(result.begin(), result.end()), result.end());
    return result;
  }

  // Going straight on through v, arriving from u: the one edge of v that shares no face with
  // edge (u, v). Only a regular vertex (four quads) has exactly one.
  int straightOn(int u, int v) const {
    std::vector<int> candidates = neighbours(v);
    std::erase(candidates, u);
    const auto [first, last] = facesOfEdge(u, v);
    for (auto it = first; it != last; ++it) {
      const ThreeFace& face = faces_[static_cast<size_t>(it->second)];
      const int c = cornerOf(face, v);
      std::erase(candidates, face.vertex[static_cast<size_t>((c + 1) % face.corners)]);
      std::erase(candidates,
                 face.vertex[static_cast<size_t>((c + face.corners - 1) % face.corners)]);
    }
    if (candidates.size() != 1)
      throw std::runtime_error("the neck edge loop meets vertex " + std::to_string(v) +
                               ", which is not a regular quad vertex");
    return candidates.front();
  }

 private:
  static int cornerOf(const ThreeFace& face, int v) {
    for (int c = 0; c < face.corners; ++c)
      if (face.vertex[static_cast<size_t>(c)] == v) return c;
    return 0;  // unreachable: callers only ask faces listed for v
  }

  const std::vector<ThreeFace>& faces_;
  std::vector<std::pair<std::uint64_t, int>> edges_;  // (edge, face), sorted
  std::vector<int> vertexStart_;                      // CSR offsets into vertexFaces_
  std::vector<int> vertexFaces_;
};

}  // namespace

std::vector<int> facesAboveEdgeLoop(const Eigen::Matrix3Xf& vertices,
                                    const std::vector<ThreeFace>& faces,
                                    const std::vector<int>& surface, int loopVertex) {
  if (surface.empty()) throw std::runtime_error("no faces to cut");
  if (loopVertex < 0 || loopVertex >= vertices.cols())
    throw std::runtime_error("the neck loop vertex " + std::to_string(loopVertex) +
                             " is not in the mesh");
  const SurfaceTopology topology(faces, surface, vertices.cols());

  const std::vector<int> around = topology.neighbours(loopVertex);
  if (around.empty())
    throw std::runtime_error("the neck loop vertex " + std::to_string(loopVertex) +
                             " is on no face of the body");
  auto sideways = [&](int w) {
    const Eigen::Vector3f d = vertices.col(w) - vertices.col(loopVertex);
    return std::abs(d.x()) / d.norm();
  };
  const int first = *std::max_element(around.begin(), around.end(),
                                      [&](int a, int b) { return sideways(a) < sideways(b); });

  std::vector<std::uint64_t> loop{edgeKey(loopVertex, first)};
  for (int u = loopVertex, v = first; v != loopVertex;) {
    const int w = topology.straightOn(u, v);
    loop.push_back(edgeKey(v, w));
    u = v;
    v = w;
    if (loop.size() > surface.size())
      throw std::runtime_error("the neck edge loop through vertex " + std::to_string(loopVertex) +
                               " does not close");
  }
  std::sort(loop.begin(), loop.end());

  int top = surface.front();
  float topY = -std::numeric_limits<float>::infinity();
  for (int f : surface) {
    const ThreeFace& face = faces[static_cast<size_t>(f)];
    for (int c = 0; c < face.corners; ++c)
      if (vertices(1, face.vertex[static_cast<size_t>(c)]) > topY) {
        topY = vertices(1, face.vertex[static_cast<size_t>(c)]);
        top = f;
      }
  }

  std::vector<char> reached(faces.size(), 0);
  std::vector<int> stack{top}, kept;
  reached[static_cast<size_t>(top)] = 1;
  while (!stack.empty()) {
    const int f = stack.back();
    stack.pop_back();
    kept.push_back(f);
    const ThreeFace& face = faces[static_cast<size_t>(f)];
    for (int c = 0; c < face.corners; ++c) {
      const int a = face.vertex[static_cast<size_t>(c)];
      const int b = face.vertex[static_cast<size_t>((c + 1) % face.corners)];
      if (std::binary_search(loop.begin(), loop.end(), edgeKey(a, b))) continue;
      const auto [from, to] = topology.facesOfEdge(a, b);
      for (auto it = from; it != to; ++it)
        if (!reached[static_cast<size_t>(it->second)]) {
          reached[static_cast<size_t>(it->second)] = 1;
          stack.push_back(it->second);
        }
    }
  }
  if (kept.size() == surface.size())
    throw std::runtime_error("the neck edge loop through vertex " + std::to_string(loopVertex) +
                             " does not separate the head from the body");
  std::sort(kept.begin(), kept.end());
  return kept;
}

}  // namespace lacrima::rigging
