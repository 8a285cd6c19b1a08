#include <lacrima/rigging/SurfaceGraph.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

namespace lacrima::rigging {

namespace {

// `chosen[v]` says whether mesh vertex v belongs to the graph.
SurfaceGraph buildFromMask(const Eigen::Matrix3Xf& positions,
                           const std::vector<Eigen::Vector3i>& triangles,
                           const std::vector<char>& chosen) {
  const int n = static_cast<int>(positions.cols());
  for (const Eigen::Vector3i& t : triangles)
    for (int k = 0; k < 3; ++k)
      if (t[k] < 0 || t[k] >= n)
        throw std::invalid_argument("surface graph: triangle corner " + std::to_string(t[k]) +
                                    " is outside the " + std::to_string(n) + " vertices");

  SurfaceGraph g;
  g.meshVertexCount = n;
  g.nodeOfVertex.assign(static_cast<size_t>(n), -1);

  // Node per weld root among the chosen vertices. The root itself may be unchosen (a copy in
  // another sub-mesh); grouping by root still merges exactly the chosen vertices that share a
  // position, and the node takes its lowest-numbered chosen vertex as representative.
  const std::vector<int> weld = weldCoincidentVertices(positions);
  std::vector<int> nodeOfRoot(static_cast<size_t>(n), -1);
  for (int v = 0; v < n; ++v) {
    if (!chosen[static_cast<size_t>(v)]) continue;
    if (!positions.col(v).allFinite())
      throw std::invalid_argument("surface graph: vertex " + std::to_string(v) +
                                  " has a non-finite position");
    int& node = nodeOfRoot[static_cast<size_t>(weld[static_cast<size_t>(v)])];
    if (node < 0) {
      node = static_cast<int>(g.vertexOfNode.size());
      g.vertexOfNode.push_back(v);
    }
    g.nodeOfVertex[static_cast<size_t>(v)] = node;
  }
  const int nodes = g.nodeCount();
  g.positions.resize(3, nodes);
  for (int i = 0; i < nodes; ++i)
    g.positions.col(i) = positions.col(g.vertexOfNode[static_cast<size_t>(i)]).cast<double>();

  std::vector<std::pair<int, int>> edges;
  edges.reserve(triangles.size() * 3);
  for (const Eigen::Vector3i& t : triangles) {
    Eigen::Vector3i m;
    bool inside = true;
    for (int k = 0; k < 3 && inside; ++k) {
      m[k] = g.nodeOfVertex[static_cast<size_t>(t[k])];
      inside = m[k] >= 0;
    }
    if (!inside || m[0] == m[1] || m[1] == m[2] || m[2] == m[0]) continue;
    g.triangles.push_back(m);
    for (int k = 0; k < 3; ++k) {
      const int a = m[k], b = m[(k + 1) % 3];
      edges.emplace_back(std::min(a, b), std::max(a, b));
    }
  }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());

  // Compressed rows, each undirected edge stored in both directions.
  g.firstNeighbour.assign(static_cast<size_t>(nodes) + 1, 0);
  for (const auto& [a, b] : edges) {
    ++g.firstNeighbour[static_cast<size_t>(a) + 1];
    ++g.firstNeighbour[static_cast<size_t>(b) + 1];
  }
  for (int i = 0; i < nodes; ++i)
    g.firstNeighbour[static_cast<size_t>(i) + 1] += g.firstNeighbour[static_cast<size_t>(i)];
  g.neighbour.resize(edges.size() * 2);
  g.edgeLength.resize(edges.size() * 2);
  std::vector<int> fill(g.firstNeighbour.begin(), g.firstNeighbour.end() - 1);
  double lengthSum = 0;
  for (const auto& [a, b] : edges) {
    const double length = (g.positions.col(a) - g.positions.col(b)).norm();
    lengthSum += length;
    const auto ka = static_cast<size_t>(fill[static_cast<size_t>(a)]++);
    const auto kb = static_cast<size_t>(fill[static_cast<size_t>(b)]++);
    g.neighbour[ka] = b;
    g.edgeLength[ka] = length;
    g.neighbour[kb] = a;
    g.edgeLength[kb] = length;
  }
  g.meanEdgeLength = edges.empty() ? 0.0 : lengthSum / static_cast<double>(edges.size());

  // Components by breadth-first search over the adjacency.
  g.component.assign(static_cast<size_t>(nodes), -1);
  std::vector<int> queue;
  queue.reserve(static_cast<size_t>(nodes));
  for (int seed = 0; seed < nodes; ++seed) {
    if (g.component[static_cast<size_t>(seed)] >= 0) continue;
    const int id = g.componentCount++;
    queue.clear();
    queue.push_back(seed);
    g.component[static_cast<size_t>(seed)] = id;
    for (size_t head = 0; head < queue.size(); ++head) {
      const int i = queue[head];
      for (int k = g.firstNeighbour[static_cast<size_t>(i)];
           k < g.firstNeighbour[static_cast<size_t>(i) + 1]; ++k) {
        const int j = g.neighbour[static_cast<size_t>(k)];
        if (g.component[static_cast<size_t>(j)] < 0) {
          g.component[static_cast<size_t>(j)] = id;
          queue.push_back(j);
        }
      }
    }
  }
  return g;
}

SurfaceGraph buildFromSubmeshes(const HeadMesh& mesh,
                                const std::vector<const HeadSubmesh*>& parts) {
  std::vector<char> chosen(static_cast<size_t>(mesh.vertexCount()), 0);
  std::vector<Eigen::Vector3i> triangles;
  for (const HeadSubmesh* s : parts) {
    if (s->firstVertex < 0 || s->vertexCount < 0 ||
        s->firstVertex + s->vertexCount > mesh.vertexCount())
      throw std::invalid_argument("surface graph: sub-mesh '" + s->name +
                                  "' has a vertex range outside the head's vertices");
    std::fill_n(chosen.begin() + s->firstVertex, s->vertexCount, char{1});
    triangles.insert(triangles.end(), s->triangles.begin(), s->triangles.end());
  }
  return buildFromMask(mesh.positions, triangles, chosen);
}

}  // namespace

Eigen::VectorXd SurfaceGraph::toVertices(const Eigen::VectorXd& nodeValues, double outside) const {
  if (nodeValues.size() != nodeCount())
    throw std::invalid_argument("surface graph: " + std::to_string(nodeValues.size()) +
                                " node values for " + std::to_string(nodeCount()) + " nodes");
  Eigen::VectorXd out(meshVertexCount);
  for (int v = 0; v < meshVertexCount; ++v) {
    const int node = nodeOfVertex[static_cast<size_t>(v)];
    out[v] = node < 0 ? outside : nodeValues[node];
  }
  return out;
}

SurfaceGraph buildSurfaceGraph(const Eigen::Matrix3Xf& positions,
                               const std::vector<Eigen::Vector3i>& triangles) {
  return buildFromMask(positions, triangles,
                       std::vector<char>(static_cast<size_t>(positions.cols()), 1));
}

SurfaceGraph buildSurfaceGraph(const Eigen::Matrix3Xf& positions,
                               const std::vector<Eigen::Vector3i>& triangles,
                               std::span<const int> vertices) {
  std::vector<char> chosen(static_cast<size_t>(positions.cols()), 0);
  for (const int v : vertices) {
    if (v < 0 || v >= positions.cols())
      throw std::invalid_argument("surface graph: vertex " + std::to_string(v) +
                                  " is outside the " + std::to_string(positions.cols()) +
                                  " vertices");
    chosen[static_cast<size_t>(v)] = 1;
  }
  return buildFromMask(positions, triangles, chosen);
}

SurfaceGraph buildSurfaceGraph(const HeadMesh& mesh) {
  std::vector<const HeadSubmesh*> all;
  for (const HeadSubmesh& s : mesh.submeshes) all.push_back(&s);
  return buildFromSubmeshes(mesh, all);
}

SurfaceGraph buildSurfaceGraph(const HeadMesh& mesh, const std::vector<std::string>& submeshes) {
  std::vector<const HeadSubmesh*> named;
  for (const std::string& name : submeshes) {
    const HeadSubmesh* s = mesh.findSubmesh(name);
    if (!s) throw std::invalid_argument("surface graph: the head has no sub-mesh '" + name + "'");
    named.push_back(s);
  }
  return buildFromSubmeshes(mesh, named);
}

}  // namespace lacrima::rigging
