#include "TriangleGeometry.h"

#include <lacrima/tears/TrailSkin.h>

#include <algorithm>
#include <limits>
#include <memory>
#include <stdexcept>

namespace lacrima::tears {

TrailSkin::TrailSkin(std::vector<Eigen::Vector3i> triangles) {
  auto tables = std::make_shared<Tables>();
  Tables& t = *tables;
  t.triangles = std::move(triangles);
  for (const auto& triangle : t.triangles) {
    if (triangle.minCoeff() < 0) throw std::invalid_argument("trail skin: negative vertex index");
    t.maxVertex = std::max(t.maxVertex, triangle.maxCoeff());
  }
  t.vertexStart.assign(static_cast<std::size_t>(t.maxVertex + 2), 0);
  for (const auto& triangle : t.triangles)
    for (int k = 0; k < 3; ++k) ++t.vertexStart[static_cast<std::size_t>(triangle[k] + 1)];
  for (std::size_t v = 1; v < t.vertexStart.size(); ++v) t.vertexStart[v] += t.vertexStart[v - 1];
  t.vertexTriangles.resize(static_cast<std::size_t>(t.vertexStart.back()));
  std::vector<int> fill(t.vertexStart.begin(), t.vertexStart.end() - 1);
  for (std::size_t i = 0; i < t.triangles.size(); ++i)
    for (int k = 0; k < 3; ++k)
      t.vertexTriangles[static_cast<std::size_t>(
          fill[static_cast<std::size_t>(t.triangles[i][k])]++)] = static_cast<int>(i);
  tables_ = std::move(tables);
}

Eigen::Vector3d TrailSkin::normal(int triangle) const {
  const Eigen::Vector3i& t = tables_->triangles[static_cast<std::size_t>(triangle)];
  const Eigen::Vector3d a = vertex(t[0]);
  const Eigen::Vector3d n = (vertex(t[1]) - a).cross(vertex(t[2]) - a);
  const double norm = n.norm();
  const double scale = (vertex(t[1]) - a).squaredNorm() + (vertex(t[2]) - a).squaredNorm();
  // Zero area relative to the edges: no direction to speak of.
  return norm > 1e-12 * scale && norm > 0 ? Eigen::Vector3d(n / norm) : Eigen::Vector3d::Zero();
}

Eigen::Vector3d TrailSkin::point(const SkinAnchor& anchor) const {
  const Eigen::Vector3i& t = tables_->triangles[static_cast<std::size_t>(anchor.triangle)];
  const Eigen::Vector3d& w = anchor.barycentric;
  return w[0] * vertex(t[0]) + w[1] * vertex(t[1]) + w[2] * vertex(t[2]) +
         anchor.height * normal(anchor.triangle);
}

void TrailSkin::contactSeeds(std::span<const SkinContact> contacts, std::span<const int> members,
                             std::vector<int>& seeds) const {
  seeds.clear();
  for (int i : members) {
    const int t = contacts[static_cast<std::size_t>(i)].triangle;
    if (t >= 0 && t < triangleCount() && std::find(seeds.begin(), seeds.end(), t) == seeds.end()) {
      seeds.push_back(t);
      if (seeds.size() == kMaxSeeds) return;
    }
  }
}

SkinAnchor TrailSkin::closest(const Eigen::Vector3d& x, std::span<const int> seeds) const {
  SkinAnchor best;
  double bestDistance = std::numeric_limits<double>::infinity();
  auto consider = [&](int triangle) {
    if (normal(triangle).isZero()) return false;  // degenerate: no normal to raise points along
    const Eigen::Vector3i& t = tables_->triangles[static_cast<std::size_t>(triangle)];
    const TrianglePoint p = closestPointOnTriangle(x, vertex(t[0]), vertex(t[1]), vertex(t[2]));
    const double d = (p.point - x).squaredNorm();
    if (d >= bestDistance) return false;
    bestDistance = d;
    best.triangle = triangle;
    best.barycentric = p.barycentric;
    return true;
  };
  for (int s : seeds)
    if (s >= 0 && s < triangleCount()) consider(s);
  // Walk: the triangles around the best one's vertices, until none is closer (bounded, so a
  // pathological mesh cannot loop for long).
  for (int step = 0; step < 64 && best.triangle >= 0; ++step) {
    const int current = best.triangle;
    const Eigen::Vector3i& t = tables_->triangles[static_cast<std::size_t>(current)];
    for (int k = 0; k < 3; ++k)
      for (int i = tables_->vertexStart[static_cast<std::size_t>(t[k])];
           i < tables_->vertexStart[static_cast<std::size_t>(t[k]) + 1]; ++i)
        consider(tables_->vertexTriangles[static_cast<std::size_t>(i)]);
    if (best.triangle == current) break;
  }
  return best;
}

}  // namespace lacrima::tears
