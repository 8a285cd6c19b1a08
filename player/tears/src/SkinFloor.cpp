#include "SkinFloor.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace lacrima::tears {

void SkinFloor::build(const Eigen::Matrix3Xd& vertices, std::span<const Eigen::Vector3i> triangles,
                      const Eigen::AlignedBox3d& box, double cell) {
  minX_ = box.min().x();
  minZ_ = box.min().z();
  bottom_ = box.min().y();
  // At most kMaxCells columns (8 MB): a tiny kernel widens the cells, which only makes the
  // test more conservative. A degenerate box gets one column.
  const double sizeX = std::max(0.0, box.sizes().x()), sizeZ = std::max(0.0, box.sizes().z());
  cell_ = cell > 0 && std::isfinite(cell) ? cell : 1;
  cell_ = std::max(cell_, std::sqrt(sizeX * sizeZ / kMaxCells));
  cell_ = std::max({cell_, sizeX / 4096, sizeZ / 4096});
  auto columnsAlong = [this](double extent) {
    return std::clamp(static_cast<int>(std::ceil(extent / cell_)), 1, 4096);
  };
  columnsX_ = columnsAlong(sizeX);
  columnsZ_ = columnsAlong(sizeZ);
  lowest_.assign(static_cast<std::size_t>(columnsX_) * static_cast<std::size_t>(columnsZ_),
                 std::numeric_limits<double>::infinity());
  for (const Eigen::Vector3i& t : triangles) {
    const Eigen::Vector3d a = vertices.col(t[0]), b = vertices.col(t[1]), c = vertices.col(t[2]);
    const Eigen::Vector3d lo = a.cwiseMin(b).cwiseMin(c), hi = a.cwiseMax(b).cwiseMax(c);
    const int x0 =
        std::clamp(static_cast<int>(std::floor((lo.x() - minX_) / cell_)), 0, columnsX_ - 1);
    const int x1 =
        std::clamp(static_cast<int>(std::floor((hi.x() - minX_) / cell_)), 0, columnsX_ - 1);
    const int z0 =
        std::clamp(static_cast<int>(std::floor((lo.z() - minZ_) / cell_)), 0, columnsZ_ - 1);
    const int z1 =
        std::clamp(static_cast<int>(std::floor((hi.z() - minZ_) / cell_)), 0, columnsZ_ - 1);
    for (int z = z0; z <= z1; ++z)
      for (int x = x0; x <= x1; ++x) {
        double& column = lowest_[static_cast<std::size_t>(z) * columnsX_ + x];
        column = std::min(column, lo.y());
      }
  }
}

bool SkinFloor::fallsClear(const Eigen::Vector3d& x, const Eigen::Vector3d& v, double g,
                           double clearance) const {
  if (lowest_.empty() || !x.allFinite() || !v.allFinite()) return false;
  const double s = -v.y();  // downward speed
  if (s < 0 || g < 0) return false;
  const double d = std::max(0.0, x.y() - bottom_);
  double fallTime;
  if (g > 0)
    fallTime = (std::sqrt(s * s + 2 * g * d) - s) / g;
  else if (s > 0)
    fallTime = d / s;
  else
    return false;  // at rest with no gravity: it stays, whatever is below
  const double reach = std::hypot(v.x(), v.z()) * fallTime + clearance;
  const double fx = (x.x() - minX_) / cell_, fz = (x.z() - minZ_) / cell_, r = reach / cell_;
  if (!(r < kMaxColumns)) return false;
  const int x0 = std::max(0, static_cast<int>(std::floor(fx - r)));
  const int x1 = std::min(columnsX_ - 1, static_cast<int>(std::floor(fx + r)));
  const int z0 = std::max(0, static_cast<int>(std::floor(fz - r)));
  const int z1 = std::min(columnsZ_ - 1, static_cast<int>(std::floor(fz + r)));
  if (x1 < x0 || z1 < z0) return true;  // beside the box: no surface there at all
  if (static_cast<long long>(x1 - x0 + 1) * (z1 - z0 + 1) > kMaxColumns) return false;
  const double ceiling = x.y() + clearance;
  for (int z = z0; z <= z1; ++z)
    for (int c = x0; c <= x1; ++c)
      if (lowest_[static_cast<std::size_t>(z) * columnsX_ + c] <= ceiling) return false;
  return true;
}

}  // namespace lacrima::tears
