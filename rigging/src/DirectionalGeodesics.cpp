#include <lacrima/rigging/DirectionalGeodesics.h>

#include <Eigen/Geometry>

#include <cmath>
#include <functional>
#include <limits>
#include <queue>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace lacrima::rigging {

namespace {

// Below this length the projection of the direction onto a triangle counts as zero.
constexpr double kNoProjection = 1e-6;
// An update must lower a value by more than this (relative) to reopen a node; it bounds the
// label-correcting passes without changing the result beyond rounding.
constexpr double kImprovement = 1e-12;

// A triangle's metric as a map from a step in its plane to the plane where it is round.
struct TriangleMetric {
  Eigen::Vector3d along = Eigen::Vector3d::Zero();   // a_T / rho_T
  Eigen::Vector3d across = Eigen::Vector3d::Zero();  // c_T / across

  Eigen::Vector2d map(const Eigen::Vector3d& step) const {
    return {step.dot(along), step.dot(across)};
  }
};

TriangleMetric metricOf(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                        const Eigen::Vector3d& c, const Eigen::Vector3d& origin,
                        const Eigen::Vector3d& u, const DirectionalReach& reach) {
  TriangleMetric m;
  Eigen::Vector3d normal = (b - a).cross(c - a);
  const double twiceArea = normal.norm();
  // A triangle without area has no plane: any orthonormal pair keeps its edges' lengths
  // finite, and it carries no surface to stretch.
  if (!(twiceArea > 0)) normal = u.unitOrthogonal();
  normal.normalize();
  const Eigen::Vector3d projected = u - u.dot(normal) * normal;
  const double rho = ((a + b + c) / 3.0 - origin).dot(u) > 0 ? reach.ahead : reach.behind;
  if (projected.norm() > kNoProjection) {
    const Eigen::Vector3d alongUnit = projected.normalized();
    m.along = alongUnit / rho;
    m.across = normal.cross(alongUnit) / reach.across;
  } else {  // the motion is normal to the triangle: round, of radius `across`
    const Eigen::Vector3d first = normal.unitOrthogonal();
    m.along = first / reach.across;
    m.across = normal.cross(first) / reach.across;
  }
  return m;
}

// min over lambda in (0, 1) of sA + lambda (sB - sA) + |c - lambda b|, in the round plane, with
// A at the origin; +infinity when the minimum is at an end (the edge updates cover those).
double triangleUpdate(double sA, double sB, const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
  constexpr double kInfinity = std::numeric_limits<double>::infinity();
  const double length = b.norm();
  const double delta = sB - sA;
  if (!(length > 0) || std::abs(delta) >= length) return kInfinity;
  const Eigen::Vector2d unit = b / length;
  const double along = c.dot(unit);
  const double height = std::abs(c.x() * unit.y() - c.y() * unit.x());
  if (!(height > 0)) return kInfinity;
  // Stationary where the path from the point on AB to C leaves AB at the angle whose cosine
  // is delta / |b|: the point sits `offset` before C's foot on AB.
  const double offset = delta * height / std::sqrt(length * length - delta * delta);
  const double lambda = (along - offset) / length;
  if (!(lambda > 0 && lambda < 1)) return kInfinity;
  return sA + lambda * delta + (c - lambda * b).norm();
}

}  // namespace

Eigen::VectorXd directionalDistances(const SurfaceGraph& graph, const Eigen::VectorXi& sources,
                                     const Eigen::Vector3d& origin,
                                     const Eigen::Vector3d& direction,
                                     const DirectionalReach& reach) {
  constexpr double kInfinity = std::numeric_limits<double>::infinity();
  for (const double r : {reach.across, reach.ahead, reach.behind})
    if (!std::isfinite(r) || r <= 0)
      throw std::invalid_argument("directionalDistances: every reach must be finite and > 0");
  if (!origin.allFinite())
    throw std::invalid_argument("directionalDistances: the origin is not finite");
  const double directionLength = direction.norm();
  if (!std::isfinite(directionLength) || !(directionLength > 0))
    throw std::invalid_argument("directionalDistances: the direction must be finite and non-zero");
  const Eigen::Vector3d u = direction / directionLength;

  const int n = graph.nodeCount();
  const auto triangles = static_cast<int>(graph.triangles.size());
  std::vector<TriangleMetric> metrics(graph.triangles.size());
  std::vector<int> firstTriangle(static_cast<size_t>(n) + 1, 0), triangleOf;
  for (int t = 0; t < triangles; ++t) {
    const Eigen::Vector3i& f = graph.triangles[static_cast<size_t>(t)];
    metrics[static_cast<size_t>(t)] = metricOf(graph.positions.col(f[0]), graph.positions.col(f[1]),
                                               graph.positions.col(f[2]), origin, u, reach);
    for (int k = 0; k < 3; ++k) ++firstTriangle[static_cast<size_t>(f[k]) + 1];
  }
  for (int i = 0; i < n; ++i)
    firstTriangle[static_cast<size_t>(i) + 1] += firstTriangle[static_cast<size_t>(i)];
  triangleOf.resize(static_cast<size_t>(firstTriangle.back()));
  {
    std::vector<int> fill(firstTriangle.begin(), firstTriangle.end() - 1);
    for (int t = 0; t < triangles; ++t)
      for (int k = 0; k < 3; ++k)
        triangleOf[static_cast<size_t>(
            fill[static_cast<size_t>(graph.triangles[static_cast<size_t>(t)][k])]++)] = t;
  }

  std::vector<double> s(static_cast<size_t>(n), kInfinity);
  using Entry = std::pair<double, int>;  // (tentative distance, node)
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> heap;
  for (const int v : sources) {
    const int node =
        v >= 0 && v < graph.meshVertexCount ? graph.nodeOfVertex[static_cast<size_t>(v)] : -1;
    if (node < 0)
      throw std::invalid_argument("directionalDistances: source vertex " + std::to_string(v) +
                                  " is not in the surface graph");
    if (s[static_cast<size_t>(node)] > 0) {
      s[static_cast<size_t>(node)] = 0;
      heap.emplace(0.0, node);
    }
  }
  auto lower = [&](int node, double candidate) {
    double& slot = s[static_cast<size_t>(node)];
    if (candidate < 1.0 && candidate < slot - kImprovement * (1.0 + candidate)) {
      slot = candidate;
      heap.emplace(candidate, node);
    }
  };

  // Label correcting: a node may be popped again after a later update lowered it; only the
  // entry matching its current value is live.
  while (!heap.empty()) {
    const auto [d, i] = heap.top();
    heap.pop();
    if (d > s[static_cast<size_t>(i)]) continue;
    const Eigen::Vector3d pi = graph.positions.col(i);
    for (int k = firstTriangle[static_cast<size_t>(i)];
         k < firstTriangle[static_cast<size_t>(i) + 1]; ++k) {
      const int t = triangleOf[static_cast<size_t>(k)];
      const Eigen::Vector3i& f = graph.triangles[static_cast<size_t>(t)];
      const TriangleMetric& m = metrics[static_cast<size_t>(t)];
      for (int corner = 0; corner < 3; ++corner) {
        const int c = f[corner];
        if (c == i) continue;
        const int other = f[0] + f[1] + f[2] - i - c;
        const Eigen::Vector2d toC = m.map(graph.positions.col(c) - pi);
        lower(c, d + toC.norm());
        const double sOther = s[static_cast<size_t>(other)];
        if (std::isfinite(sOther))
          lower(c, triangleUpdate(d, sOther, m.map(graph.positions.col(other) - pi), toC));
      }
    }
  }

  return graph.toVertices(Eigen::Map<const Eigen::VectorXd>(s.data(), n), kInfinity);
}

}  // namespace lacrima::rigging
