#include "SweepErrors.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <unordered_map>

namespace lacrima::bench {

namespace {

// Nearest-vertex lookups through a hash grid of cell edge `cell` (exact: rings grow until the
// best distance found is inside the searched cube).
class NearestVertex {
 public:
  NearestVertex(const std::vector<Eigen::Vector3d>& points, double cell)
      : points_(points), cell_(cell) {
    for (std::size_t i = 0; i < points.size(); ++i)
      cells_[key(cellOf(points[i]))].push_back(static_cast<int>(i));
  }
  double distance(const Eigen::Vector3d& x) const {
    if (points_.empty()) return std::numeric_limits<double>::infinity();
    const Eigen::Vector3i c = cellOf(x);
    double best = std::numeric_limits<double>::infinity();
    for (int ring = 0; ring < 64; ++ring) {
      for (int dx = -ring; dx <= ring; ++dx)
        for (int dy = -ring; dy <= ring; ++dy)
          for (int dz = -ring; dz <= ring; ++dz) {
            if (std::max({std::abs(dx), std::abs(dy), std::abs(dz)}) != ring)
              continue;  // the shell only
            const auto it = cells_.find(key(c + Eigen::Vector3i(dx, dy, dz)));
            if (it == cells_.end()) continue;
            for (int i : it->second)
              best = std::min(best, (points_[static_cast<std::size_t>(i)] - x).norm());
          }
      if (best <= ring * cell_) return best;  // nothing outside this cube can be closer
    }
    for (const Eigen::Vector3d& p : points_)
      best = std::min(best, (p - x).norm());  // far away: brute force
    return best;
  }

 private:
  Eigen::Vector3i cellOf(const Eigen::Vector3d& x) const {
    return (x / cell_).array().floor().cast<int>();
  }
  static std::int64_t key(const Eigen::Vector3i& c) {
    return (std::int64_t(c.x() & 0x1fffff) << 42) | (std::int64_t(c.y() & 0x1fffff) << 21) |
           std::int64_t(c.z() & 0x1fffff);
  }
  const std::vector<Eigen::Vector3d>& points_;
  double cell_;
  std::unordered_map<std::int64_t, std::vector<int>> cells_;
};

double meanNearest(const std::vector<Eigen::Vector3d>& from, const NearestVertex& to) {
  if (from.empty()) return 0;
  double sum = 0;
  for (const Eigen::Vector3d& x : from) sum += to.distance(x);
  return sum / static_cast<double>(from.size());
}

}  // namespace

void captureSurface(const tears::TearSurface& surface, RunResult& out) {
  const auto x = surface.positions();
  const auto t = surface.triangles();
  out.surfaceVertices.assign(static_cast<std::size_t>(x.cols()), Eigen::Vector3d::Zero());
  for (Eigen::Index i = 0; i < x.cols(); ++i)
    out.surfaceVertices[static_cast<std::size_t>(i)] = x.col(i);
  out.surfaceArea = 0;
  for (Eigen::Index k = 0; k < t.cols(); ++k) {
    const Eigen::Vector3d a = x.col(t(0, k)), b = x.col(t(1, k)), c = x.col(t(2, k));
    out.surfaceArea += 0.5 * (b - a).cross(c - a).norm();
  }
}

RunErrors errorsBetween(const RunResult& run, const RunResult& reference, double radius,
                        double cell) {
  RunErrors e;
  e.centroid = 0.5 *
               ((run.centroid[0] - reference.centroid[0]).norm() +
                (run.centroid[1] - reference.centroid[1]).norm()) /
               radius;
  double sum = 0;
  for (const auto& [id, x] : run.particles) {
    const auto it = reference.particles.find(id);
    if (it == reference.particles.end()) continue;
    sum += (x - it->second).squaredNorm();
    ++e.matched;
  }
  e.particleRms = e.matched ? std::sqrt(sum / e.matched) / radius : 0;
  if (run.surfaceVertices.empty() || reference.surfaceVertices.empty()) {
    e.surface = std::numeric_limits<double>::quiet_NaN();
  } else {
    const NearestVertex toRef(reference.surfaceVertices, cell), toRun(run.surfaceVertices, cell);
    e.surface =
        0.5 *
        (meanNearest(run.surfaceVertices, toRef) + meanNearest(reference.surfaceVertices, toRun)) /
        radius;
  }
  e.areaDifference = reference.surfaceArea > 0
                         ? std::abs(run.surfaceArea - reference.surfaceArea) / reference.surfaceArea
                         : 0;
  return e;
}

}  // namespace lacrima::bench
