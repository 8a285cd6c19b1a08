#include <lacrima/tears/Kernels.h>
#include <lacrima/tears/SurfaceMesherField.h>

#include <cmath>
#include <stdexcept>

namespace lacrima::tears {

template <typename Visit>
void SurfaceMesherField::forNeighbours(const Eigen::Vector3d& x, Visit&& visit) const {
  const CellIndex& index = *index_;
  const Eigen::Vector3i cell = index.cellOf(x);
  const double* sx = index.sortedX().data();
  const double* sy = index.sortedY().data();
  const double* sz = index.sortedZ().data();
  for (int dx = -1; dx <= 1; ++dx)
    for (int dy = -1; dy <= 1; ++dy) {
      const CellIndex::Range r = index.row(cell.x() + dx, cell.y() + dy, cell.z());
      for (std::uint32_t t = r.begin; t < r.end; ++t) {
        const double ex = x.x() - sx[t], ey = x.y() - sy[t], ez = x.z() - sz[t];
        const double r2 = ex * ex + ey * ey + ez * ez;
        if (r2 < h2_) visit(t, ex, ey, ez, h2_ - r2);
      }
    }
}

void SurfaceMesherField::bind(std::span<const Eigen::Vector3d> positions, std::span<const double> masses,
                              const UniformGrid& grid, double h) {
  if (!(h > 0) || !std::isfinite(h)) throw std::invalid_argument("colour field: kernel radius must be positive");
  if (masses.size() != positions.size()) throw std::invalid_argument("colour field: one mass per particle");
  const CellIndex& index = grid.index();
  if (index.particleCount() != positions.size() || std::abs(index.edge() - h) > 1e-12 * h)
    throw std::invalid_argument("colour field: the grid is not built over these particles with cell edge h");
  index_ = &index;
  const Poly6Kernel kernel(h);
  h_ = h;
  h2_ = h * h;
  w_ = kernel.valueCoefficient();
  grad_ = kernel.gradientCoefficient();

  const std::size_t n = positions.size();
  const auto order = index.order();
  mass_.resize(n);
  volume_.resize(n);
  for (std::size_t s = 0; s < n; ++s) mass_[s] = masses[static_cast<std::size_t>(order[s])];
  const double* sx = index.sortedX().data();
  const double* sy = index.sortedY().data();
  const double* sz = index.sortedZ().data();
  for (std::size_t s = 0; s < n; ++s) {
    double rho = 0;  // sum of m (h^2 - r^2)^3, scaled by w_ once at the end
    forNeighbours({sx[s], sy[s], sz[s]}, [&](std::uint32_t t, double, double, double, double d) {
      rho += mass_[t] * d * d * d;
    });
    // rho >= m_s W(0) > 0 for a positive mass (the particle sees itself); a non-positive mass
    // contributes nothing to the field.
    volume_[s] = (mass_[s] > 0 && rho > 0) ? mass_[s] / (w_ * rho) : 0.0;
  }
}

double SurfaceMesherField::value(const Eigen::Vector3d& x) const {
  double c = 0;
  forNeighbours(x, [&](std::uint32_t t, double, double, double, double d) { c += volume_[t] * d * d * d; });
  return w_ * c;
}

Eigen::Vector3d SurfaceMesherField::gradient(const Eigen::Vector3d& x) const {
  Eigen::Vector3d g = Eigen::Vector3d::Zero();
  forNeighbours(x, [&](std::uint32_t t, double ex, double ey, double ez, double d) {
    const double f = volume_[t] * d * d;
    g += f * Eigen::Vector3d(ex, ey, ez);
  });
  return grad_ * g;
}

}  // namespace lacrima::tears
