#include "TriangleGrid.h"

#include <algorithm>
#include <cmath>

namespace lacrima::tears {

void TriangleGrid::build(std::span<const SkinFace> faces, double minimumCell) {
  lo_.resize(faces.size());
  hi_.resize(faces.size());
  normal_.resize(faces.size());
  offset_.resize(faces.size());
  all_.clear();
  exhaustive_ = false;
  Eigen::Vector3d boundsLo = Eigen::Vector3d::Constant(HUGE_VAL),
                  boundsHi = Eigen::Vector3d::Constant(-HUGE_VAL);
  double sideSum = 0;
  for (std::size_t t = 0; t < faces.size(); ++t) {
    const SkinFace& f = faces[t];
    if (f.degenerate) continue;
    normal_[t] = f.normal;
    offset_[t] = f.normal.dot(f.a);
    lo_[t] = f.a.cwiseMin(f.b).cwiseMin(f.c);
    hi_[t] = f.a.cwiseMax(f.b).cwiseMax(f.c);
    boundsLo = boundsLo.cwiseMin(lo_[t]);
    boundsHi = boundsHi.cwiseMax(hi_[t]);
    sideSum += (hi_[t] - lo_[t]).maxCoeff();
    all_.push_back(static_cast<int>(t));
  }
  if (all_.empty()) {
    dims_.setZero();
    cellStart_.assign(1, 0);
    cellTriangles_.clear();
    return;
  }
  const double extent = (boundsHi - boundsLo).maxCoeff() +
                        boundsLo.cwiseAbs().cwiseMax(boundsHi.cwiseAbs()).maxCoeff();
  // An infinite corner leaves no usable cells: every query then visits every triangle.
  exhaustive_ = !std::isfinite(extent);
  if (exhaustive_) return;
  const double margin = 1e-4 * extent;
  margin_ = margin;
  for (int t : all_) {
    lo_[static_cast<std::size_t>(t)].array() -= margin;
    hi_[static_cast<std::size_t>(t)].array() += margin;
  }
  boundsLo.array() -= margin;
  boundsHi.array() += margin;

  const Eigen::Vector3d size = boundsHi - boundsLo;  // positive: the margin widens every side
  auto cellCount = [&](double c) {
    double n = 1;
    for (int a = 0; a < 3; ++a) n *= std::floor(size[a] / c) + 1;
    return n;
  };
  double cell = std::max(minimumCell, sideSum / static_cast<double>(all_.size()));
  if (!(cell > 0) || !std::isfinite(cell)) cell = size.maxCoeff();
  const double maxCells = 4.0 * static_cast<double>(all_.size()) + 64;
  while (cellCount(cell) > maxCells) cell *= 1.25;
  origin_ = boundsLo;
  extent_ = size;
  inverseCell_ = 1.0 / cell;
  for (int a = 0; a < 3; ++a) dims_[a] = static_cast<int>(size[a] * inverseCell_) + 1;

  const auto cells = static_cast<std::size_t>(dims_.prod());
  cellStart_.assign(cells + 1, 0);
  first_.resize(faces.size());
  last_.resize(faces.size());
  for (int t : all_) {
    const auto s = static_cast<std::size_t>(t);
    cellRange(lo_[s], hi_[s], first_[s], last_[s]);
    anyCell(first_[s], last_[s], [&](std::size_t cell) {
      ++cellStart_[cell + 1];
      return false;
    });
  }
  for (std::size_t c = 0; c < cells; ++c) cellStart_[c + 1] += cellStart_[c];
  cellTriangles_.resize(static_cast<std::size_t>(cellStart_[cells]));
  fill_.assign(cellStart_.begin(), cellStart_.end() - 1);
  for (int t : all_) {
    const auto s = static_cast<std::size_t>(t);
    anyCell(first_[s], last_[s], [&](std::size_t cell) {
      cellTriangles_[static_cast<std::size_t>(fill_[cell]++)] = t;
      return false;
    });
  }
}

}  // namespace lacrima::tears
