#pragma once
// Multi-source shortest paths along the edges of a SurfaceGraph (Dijkstra).
//
//   d(v) = min over sources s and edge paths s = n_0, n_1, ..., n_k = node(v) of
//          d0(s) + sum_i |p(n_{i+1}) - p(n_i)|
// computed with a binary heap in O((V + E) log V), and only over the nodes with d <= cutoff
// when a cut-off is given: the search stops as soon as the nearest unsettled node lies
// beyond it, so a feature point with a small radius costs time in proportion to the area it
// covers, not to the head.
//
// Graph paths are polylines on the surface, so d is never below the true geodesic distance
// on a flat mesh (nor below the straight segment on any mesh); it is above it by the mesh's
// "metrication" error, which does not vanish under refinement (on an equilateral lattice up
// to 2/sqrt(3) - 1 = 15.5% halfway between edge directions; ~22% on an icosphere; more across
// long thin triangles). The heat method converges; this is exact along edges, cheap, and
// local with the cut-off.
#include <lacrima/rigging/SurfaceGraph.h>

#include <Eigen/Core>

#include <limits>

namespace lacrima::rigging {

// Distances per MESH vertex (size graph.meshVertexCount; seam copies share their node's
// value). `sources` are mesh vertices in the graph; `initial` gives each source's starting
// distance (empty: all 0; repeated sources keep the smallest). Vertices farther than `cutoff`,
// unreachable, or outside the graph get +infinity.
// Throws std::invalid_argument for a source outside the graph, a size mismatch, a negative or
// non-finite initial distance, or a NaN / negative cut-off.
Eigen::VectorXd dijkstraDistances(const SurfaceGraph& graph, const Eigen::VectorXi& sources,
                                  const Eigen::VectorXd& initial = Eigen::VectorXd(),
                                  double cutoff = std::numeric_limits<double>::infinity());

}  // namespace lacrima::rigging
