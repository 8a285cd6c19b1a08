#pragma once
// The welded topology of (part of) a triangle mesh, the common input of the geodesic solvers.
//
// A head's vertex array holds uv-seam copies: several vertices at bit-identical positions.
// Distances must flow across seams, so the solvers work on nodes: one node per distinct
// position among the chosen vertices (weldCoincidentVertices decides which are copies), and
// every result is spread back to all copies. Welding is exact on purpose: the lips at the
// mouth slit and the eyelids at the eye opening are a fraction of a millimetre apart but are
// different positions, so they stay different nodes and only the surface joins them.
//
//   nodes     N = { weld root of v : v in the chosen vertex set S }
//   triangles T = { (n(a), n(b), n(c)) : (a, b, c) a mesh triangle with a, b, c in S,
//                   n(a), n(b), n(c) pairwise distinct }   (welding may collapse a triangle:
//                   it then has no surface and is dropped, edges included)
//   edges     E = the sides of T, length |p_i - p_j| (Euclidean, in double)
//   component: connected components of (N, E); a node on no triangle is a component alone.
#include <lacrima/common/HeadMesh.h>

#include <Eigen/Core>

#include <span>
#include <string>
#include <vector>

namespace lacrima::rigging {

struct SurfaceGraph {
  int meshVertexCount = 0;        // size of the mesh's vertex array the graph was built from
  std::vector<int> nodeOfVertex;  // per mesh vertex: its node, or -1 when not chosen
  std::vector<int> vertexOfNode;  // per node: its lowest-numbered chosen mesh vertex
  Eigen::Matrix3Xd positions;     // per node
  std::vector<Eigen::Vector3i> triangles;  // node indices, orientation as in the mesh

  // Adjacency in compressed rows: the neighbours of node i are
  // neighbour[k] for k in [firstNeighbour[i], firstNeighbour[i + 1]), at edgeLength[k].
  std::vector<int> firstNeighbour;  // nodeCount() + 1 entries
  std::vector<int> neighbour;
  std::vector<double> edgeLength;

  std::vector<int> component;  // per node, 0 .. componentCount - 1
  int componentCount = 0;
  double meanEdgeLength = 0;  // over distinct edges; 0 when there are none

  int nodeCount() const { return static_cast<int>(vertexOfNode.size()); }

  // Per-node values spread to every mesh vertex (copies share their node's value); vertices
  // outside the graph get `outside`.
  Eigen::VectorXd toVertices(const Eigen::VectorXd& nodeValues, double outside) const;
};

// All vertices and all triangles. Throws std::invalid_argument for a triangle index outside
// the vertex array or a non-finite position.
SurfaceGraph buildSurfaceGraph(const Eigen::Matrix3Xf& positions,
                               const std::vector<Eigen::Vector3i>& triangles);

// Only the vertices listed (any order, repeats allowed) and the triangles whose three corners
// are all listed. Welding only merges listed vertices with each other, so a vertex outside
// the subset never joins two parts of it.
SurfaceGraph buildSurfaceGraph(const Eigen::Matrix3Xf& positions,
                               const std::vector<Eigen::Vector3i>& triangles,
                               std::span<const int> vertices);

// The whole head: every sub-mesh's vertex range and triangles.
SurfaceGraph buildSurfaceGraph(const HeadMesh& mesh);

// Only the named sub-meshes (e.g. {"skin"} for the skin's feature points): their vertex
// ranges and their triangles. Throws std::invalid_argument naming an unknown sub-mesh.
SurfaceGraph buildSurfaceGraph(const HeadMesh& mesh, const std::vector<std::string>& submeshes);

}  // namespace lacrima::rigging
