#include "FeaturePointProposalLips.h"

#include <lacrima/rigging/DijkstraGeodesics.h>
#include <lacrima/rigging/SurfaceGraph.h>

#include <algorithm>

namespace lacrima::rigging {
namespace {

// How far from its warped place a lip point's vertex may be, in units of the mouth's width: on
// the ICT head the farthest proposed inner-lip points (2.6, 2.7) end 0.07 of it from the
// hand-made ones, and a quarter still keeps the search on the lips, away from nose and chin.
constexpr double kSearchRadius = 0.25;

struct LipPoint {
  const char* id;
  bool upper;
};
const LipPoint kLipPoints[] = {{"2.2", true},  {"2.6", true},  {"2.7", true},
                               {"2.3", false}, {"2.8", false}, {"2.9", false}};

// The graph node nearest `p`.
Eigen::Index nearestNode(const SurfaceGraph& graph, const Eigen::Vector3d& p) {
  Eigen::Index node = 0;
  (graph.positions.colwise() - p).colwise().squaredNorm().minCoeff(&node);
  return node;
}

}  // namespace

void placeLipPoints(const std::vector<std::string>& ids, const HeadMesh& mesh,
                    const std::vector<std::string>& skin,
                    const std::map<std::string, Eigen::Vector3d>& anchors, const std::string& path,
                    Warnings* warnings, Eigen::Matrix3Xd& carried) {
  std::vector<std::pair<Eigen::Index, const LipPoint*>> lipPoints;  // (column of `carried`, which)
  for (const LipPoint& point : kLipPoints)
    if (const auto it = std::find(ids.begin(), ids.end(), point.id); it != ids.end())
      lipPoints.emplace_back(static_cast<Eigen::Index>(it - ids.begin()), &point);
  if (lipPoints.empty()) return;
  const SurfaceGraph graph = buildSurfaceGraph(mesh, skin);
  if (graph.nodeCount() == 0) return;

  // (1) Distances along the skin from the nose tip and from the chin, per node.
  const auto distancesFrom = [&](const char* anchor) {
    const Eigen::VectorXi source = Eigen::VectorXi::Constant(
        1, graph.vertexOfNode[static_cast<std::size_t>(nearestNode(graph, anchors.at(anchor)))]);
    const Eigen::VectorXd perVertex = dijkstraDistances(graph, source);
    Eigen::VectorXd perNode(graph.nodeCount());
    for (int n = 0; n < graph.nodeCount(); ++n)
      perNode[n] = perVertex[graph.vertexOfNode[static_cast<std::size_t>(n)]];
    return perNode;
  };
  const Eigen::VectorXd fromNose = distancesFrom("9.3"), fromChin = distancesFrom("2.10");
  const double radius = kSearchRadius * (anchors.at("8.3") - anchors.at("8.4")).norm();

  // (2), (3) The nearest node of each point's side within the radius.
  std::string unplaced;
  for (const auto& [c, point] : lipPoints) {
    const Eigen::VectorXd distance =
        (graph.positions.colwise() - carried.col(c)).colwise().norm().transpose();
    Eigen::Index best = -1;
    for (Eigen::Index n = 0; n < distance.size(); ++n)
      if (distance[n] <= radius && (fromNose[n] < fromChin[n]) == point->upper &&
          (best < 0 || distance[n] < distance[best]))
        best = n;
    if (best >= 0)
      carried.col(c) = graph.positions.col(best);
    else
      unplaced += (unplaced.empty() ? "" : ", ") + std::string(point->id);
  }
  if (!unplaced.empty() && warnings)
    warnings->push_back(Diagnostic{
        SourceLocation{path, 0, 0},
        "the lips could not be told apart near the inner-lip point(s) " + unplaced +
            " (no skin vertex of that lip's side nearby: lips modelled shut?): proposed at the "
            "nearest skin vertex, which may be on the other lip; check that 2.2, 2.6, 2.7 are on "
            "the upper lip and 2.3, 2.8, 2.9 on the lower one"});
}

}  // namespace lacrima::rigging
