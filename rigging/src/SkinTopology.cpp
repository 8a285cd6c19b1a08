#include <lacrima/rigging/SkinTopology.h>

#include <lacrima/rigging/SurfaceGraph.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <map>
#include <numeric>
#include <utility>

namespace lacrima::rigging {
namespace {

std::string joined(const std::vector<std::string>& names) {
  std::string out;
  for (const std::string& n : names) out += (out.empty() ? "\"" : ", \"") + n + "\"";
  return out;
}

using Edge = std::pair<int, int>;

// Triangles per undirected welded edge.
std::map<Edge, int> edgeUse(const SurfaceGraph& g) {
  std::map<Edge, int> use;
  for (const Eigen::Vector3i& t : g.triangles)
    for (int k = 0; k < 3; ++k) {
      const int a = t[k], b = t[(k + 1) % 3];
      ++use[{std::min(a, b), std::max(a, b)}];
    }
  return use;
}

int findRoot(std::vector<int>& parent, int x) {
  while (parent[static_cast<std::size_t>(x)] != x)
    x = parent[static_cast<std::size_t>(x)] =
        parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(x)])];
  return x;
}

}  // namespace

std::vector<std::string> checkSkinTopology(const HeadMesh& mesh,
                                           const std::vector<std::string>& skin) {
  std::vector<std::string> warnings;
  const std::string what = "skin " + joined(skin);

  // Degenerate triangles, counted on the mesh's own triangles (welding drops collapsed ones).
  int degenerate = 0, example = -1;
  for (const std::string& name : skin) {
    const HeadSubmesh* s = mesh.findSubmesh(name);
    for (std::size_t k = 0; s && k < s->triangles.size(); ++k) {
      const Eigen::Vector3i& t = s->triangles[k];
      const Eigen::Vector3d a = mesh.positions.col(t[0]).cast<double>();
      const Eigen::Vector3d e1 = mesh.positions.col(t[1]).cast<double>() - a;
      const Eigen::Vector3d e2 = mesh.positions.col(t[2]).cast<double>() - a;
      if (!(e1.cross(e2).norm() > 1e-10 * (e1.squaredNorm() + e2.squaredNorm()))) {
        if (example < 0) example = static_cast<int>(k);
        ++degenerate;
      }
    }
  }
  if (degenerate > 0)
    warnings.push_back(
        what + ": " + std::to_string(degenerate) + " degenerate (zero-area) triangle" +
        (degenerate == 1 ? "" : "s") + ", e.g. local triangle " + std::to_string(example) +
        " of its sub-mesh; influences pass through them but they have no shading normal");

  const SurfaceGraph g = buildSurfaceGraph(mesh, skin);
  int nonManifold = 0;
  Edge firstBad{-1, -1};
  for (const auto& [edge, count] : edgeUse(g))
    if (count > 2 && nonManifold++ == 0) firstBad = edge;
  if (nonManifold > 0)
    warnings.push_back(
        what + ": " + std::to_string(nonManifold) + " non-manifold edge" +
        (nonManifold == 1 ? "" : "s") + " (3 or more triangles), e.g. between vertices " +
        std::to_string(g.vertexOfNode[static_cast<std::size_t>(firstBad.first)]) + " and " +
        std::to_string(g.vertexOfNode[static_cast<std::size_t>(firstBad.second)]) +
        "; geodesic influences may jump between the sheets there");

  // Components with at least one triangle (a stray vertex is harmless).
  std::vector<int> sizes(static_cast<std::size_t>(g.componentCount), 0);
  for (const Eigen::Vector3i& t : g.triangles)
    ++sizes[static_cast<std::size_t>(g.component[static_cast<std::size_t>(t[0])])];
  const int pieces =
      static_cast<int>(std::count_if(sizes.begin(), sizes.end(), [](int n) { return n > 0; }));
  if (pieces == 0)
    warnings.push_back(what + ": no triangles; nothing can be rigged");
  else if (pieces > 1)
    warnings.push_back(what + ": " + std::to_string(pieces) + " disconnected pieces (largest " +
                       std::to_string(*std::max_element(sizes.begin(), sizes.end())) +
                       " triangles); a feature point's influence cannot cross to another piece");
  return warnings;
}

std::optional<Eigen::Vector3d> lowestBoundaryLoopCentre(const HeadMesh& mesh,
                                                        const std::vector<std::string>& skin) {
  const SurfaceGraph g = buildSurfaceGraph(mesh, skin);
  std::vector<int> parent(static_cast<std::size_t>(g.nodeCount()));
  std::iota(parent.begin(), parent.end(), 0);
  std::vector<char> onBoundary(parent.size(), 0);
  for (const auto& [edge, count] : edgeUse(g)) {
    if (count != 1) continue;
    onBoundary[static_cast<std::size_t>(edge.first)] =
        onBoundary[static_cast<std::size_t>(edge.second)] = 1;
    parent[static_cast<std::size_t>(findRoot(parent, edge.first))] = findRoot(parent, edge.second);
  }
  std::map<int, std::pair<Eigen::Vector3d, int>> loops;  // root -> (sum, count)
  for (int n = 0; n < g.nodeCount(); ++n) {
    if (!onBoundary[static_cast<std::size_t>(n)]) continue;
    auto& [sum, count] =
        loops.try_emplace(findRoot(parent, n), Eigen::Vector3d::Zero(), 0).first->second;
    sum += g.positions.col(n);
    ++count;
  }
  std::optional<Eigen::Vector3d> best;
  for (const auto& [root, loop] : loops) {
    const Eigen::Vector3d centre = loop.first / loop.second;
    if (loop.second >= 3 && (!best || centre.y() < best->y())) best = centre;
  }
  return best;
}

}  // namespace lacrima::rigging
