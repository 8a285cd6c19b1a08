#include "SurfaceMesherField.h"
#include "Float4.h"
#include "Kernels.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace lacrima::tears {
namespace {
using Int4 = int __attribute__((vector_size(16)));  // lane masks of Float4 comparisons
// Occupied cells per shared chunk of the density pass: about 5 particles a cell on a sheet, so
// a chunk is about the particle chunk of the simulation's loops.
constexpr std::size_t kCellChunk = 256;
}  // namespace

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

void SurfaceMesherField::bind(std::span<const Eigen::Vector3d> positions,
                              std::span<const double> masses, const UniformGrid& grid, double h,
                              ParallelChunks* parallel) {
  if (!(h > 0) || !std::isfinite(h))
    throw std::invalid_argument("colour field: kernel radius must be positive");
  if (masses.size() != positions.size())
    throw std::invalid_argument("colour field: one mass per particle");
  const CellIndex& index = grid.index();
  if (index.particleCount() != positions.size() || std::abs(index.edge() - h) > 1e-12 * h)
    throw std::invalid_argument(
        "colour field: the grid is not built over these particles with cell edge h");
  index_ = &index;
  const Poly6Kernel kernel(h);
  h_ = h;
  h2_ = h * h;
  w_ = kernel.valueCoefficient();
  grad_ = kernel.gradientCoefficient();

  const std::size_t n = positions.size();
  const auto order = index.order();
  const double* sx = index.sortedX().data();
  const double* sy = index.sortedY().data();
  const double* sz = index.sortedZ().data();
  Eigen::Vector3d origin = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  double heaviest = 0;
  for (std::size_t s = 0; s < n; ++s) {
    const Eigen::Vector3d x(sx[s], sy[s], sz[s]);
    if (x.allFinite()) origin = origin.cwiseMin(x);
    heaviest = std::max(heaviest, masses[static_cast<std::size_t>(order[s])]);
  }
  volume_.assign(n, 0.0);
  splat_.assign(n, 0.0f);
  if (!(heaviest > 0) || !origin.allFinite()) return;  // nothing carries volume
  const double inverse = 1.0 / h, inverseMass = 1.0 / heaviest;
  fx_.assign(n + 3, 0.0f);
  fy_.assign(n + 3, 0.0f);
  fz_.assign(n + 3, 0.0f);
  fm_.assign(n + 3, 0.0f);
  for (std::size_t s = 0; s < n; ++s) {
    // Non-finite coordinates stay non-finite: every distance to them fails the d > 0 test.
    fx_[s] = static_cast<float>((sx[s] - origin.x()) * inverse);
    fy_[s] = static_cast<float>((sy[s] - origin.y()) * inverse);
    fz_[s] = static_cast<float>((sz[s] - origin.z()) * inverse);
    fm_[s] = static_cast<float>(masses[static_cast<std::size_t>(order[s])] * inverseMass);
  }

  const Float4 one = {1, 1, 1, 1}, zero = {0, 0, 0, 0};
  const Int4 lane = {0, 1, 2, 3};
  const double scale = w_ * h2_ * h2_ * h2_;  // rho = scale * heaviest * sum
  forEachChunkOn(
      parallel, index.cellCount(), kCellChunk,
      [&](int, std::size_t firstCell, std::size_t endCell) {
        for (std::size_t c = firstCell; c < endCell; ++c) {
          // The nine runs of the 27 cells around this cell, shared by all its particles.
          const Eigen::Vector3i cell = index.cellCoordinates(c);
          std::array<CellIndex::Range, 9> rows;
          for (int dx = -1, r = 0; dx <= 1; ++dx)
            for (int dy = -1; dy <= 1; ++dy, ++r)
              rows[static_cast<std::size_t>(r)] = index.row(cell.x() + dx, cell.y() + dy, cell.z());
          for (std::uint32_t s = index.cellStart(c); s < index.cellStart(c + 1); ++s) {
            const Float4 xs = {fx_[s], fx_[s], fx_[s], fx_[s]},
                         ys = {fy_[s], fy_[s], fy_[s], fy_[s]},
                         zs = {fz_[s], fz_[s], fz_[s], fz_[s]};
            Float4 sum = zero;
            for (const CellIndex::Range& r : rows)
              for (std::uint32_t t = r.begin; t < r.end; t += 4) {
                const Float4 ex = load4(&fx_[t]) - xs, ey = load4(&fy_[t]) - ys,
                             ez = load4(&fz_[t]) - zs;
                const Float4 d = one - (ex * ex + ey * ey + ez * ez);
                const Int4 left = Int4{1, 1, 1, 1} * static_cast<int>(r.end - t);
                const Int4 keep = (d > zero) & (lane < left);
                const Float4 kept = reinterpret_cast<Float4>(reinterpret_cast<Int4>(d) & keep);
                sum += load4(&fm_[t]) * kept * kept * kept;
              }
            const double rho = static_cast<double>(sum[0]) + sum[1] + sum[2] + sum[3];
            const double m = masses[static_cast<std::size_t>(order[s])];
            // rho >= m_s W(0) > 0 for a positive mass (the particle sees itself); a non-positive
            // mass contributes nothing to the field.
            if (m > 0 && rho > 0 && std::isfinite(rho)) {
              volume_[s] = m / (scale * heaviest * rho);
              splat_[s] = static_cast<float>(m * inverseMass / rho);
            }
          }
        }
      });
}

double SurfaceMesherField::value(const Eigen::Vector3d& x) const {
  double c = 0;
  forNeighbours(
      x, [&](std::uint32_t t, double, double, double, double d) { c += volume_[t] * d * d * d; });
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
