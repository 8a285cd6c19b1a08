#include <lacrima/rigging/DijkstraGeodesics.h>

#include <cmath>
#include <functional>
#include <queue>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace lacrima::rigging {

Eigen::VectorXd dijkstraDistances(const SurfaceGraph& graph, const Eigen::VectorXi& sources,
                                  const Eigen::VectorXd& initial, double cutoff) {
  constexpr double kInfinity = std::numeric_limits<double>::infinity();
  if (initial.size() != 0 && initial.size() != sources.size())
    throw std::invalid_argument("dijkstraDistances: " + std::to_string(initial.size()) +
                                " initial distances for " + std::to_string(sources.size()) +
                                " sources");
  if (std::isnan(cutoff) || cutoff < 0)
    throw std::invalid_argument("dijkstraDistances: the cut-off must be >= 0 (or infinity)");

  std::vector<double> distance(static_cast<size_t>(graph.nodeCount()), kInfinity);
  using Entry = std::pair<double, int>;  // (tentative distance, node)
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> heap;
  for (Eigen::Index k = 0; k < sources.size(); ++k) {
    const int v = sources[k];
    const int node =
        v >= 0 && v < graph.meshVertexCount ? graph.nodeOfVertex[static_cast<size_t>(v)] : -1;
    if (node < 0)
      throw std::invalid_argument("dijkstraDistances: source vertex " + std::to_string(v) +
                                  " is not in the surface graph");
    const double d0 = initial.size() ? initial[k] : 0.0;
    if (!std::isfinite(d0) || d0 < 0)
      throw std::invalid_argument("dijkstraDistances: initial distance of source " +
                                  std::to_string(v) + " must be finite and >= 0");
    if (d0 <= cutoff && d0 < distance[static_cast<size_t>(node)]) {
      distance[static_cast<size_t>(node)] = d0;
      heap.emplace(d0, node);
    }
  }

  // Lazy deletion: a node may sit in the heap several times; only the entry matching its
  // current distance is live. Entries beyond the cut-off are never pushed, so the heap
  // empties exactly when the reachable disc is settled.
  while (!heap.empty()) {
    const auto [d, i] = heap.top();
    heap.pop();
    if (d > distance[static_cast<size_t>(i)]) continue;
    for (int k = graph.firstNeighbour[static_cast<size_t>(i)];
         k < graph.firstNeighbour[static_cast<size_t>(i) + 1]; ++k) {
      const int j = graph.neighbour[static_cast<size_t>(k)];
      const double candidate = d + graph.edgeLength[static_cast<size_t>(k)];
      if (candidate <= cutoff && candidate < distance[static_cast<size_t>(j)]) {
        distance[static_cast<size_t>(j)] = candidate;
        heap.emplace(candidate, j);
      }
    }
  }

  return graph.toVertices(Eigen::Map<const Eigen::VectorXd>(distance.data(), graph.nodeCount()),
                          kInfinity);
}

}  // namespace lacrima::rigging
