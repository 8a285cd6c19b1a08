#include "SurfaceMesherKeyMap.h"
#include "VectorState.h"

#include <lacrima/tears/Kernels.h>
#include <lacrima/tears/MarchingCubesTable.h>
#include <lacrima/tears/SurfaceMesher.h>
#include <lacrima/tears/TearSimulation.h>

#include <chrono>
#include <cmath>
#include <stdexcept>

namespace lacrima::tears {
namespace {

using Clock = std::chrono::steady_clock;
using Lattice = Eigen::Matrix<std::int64_t, 3, 1>;

// Relative lattice coordinates are packed 20 bits per axis (x-major, z-minor), so a key fits in
// 60 bits and an edge key (key << 2 | axis) in 62.
constexpr int kBits = 20;
constexpr std::int64_t kSpan = (std::int64_t{1} << kBits) - 4;  // room for +1 corners and margins

std::uint64_t pack(const Lattice& relative) {
  return (static_cast<std::uint64_t>(relative.x()) << (2 * kBits)) |
         (static_cast<std::uint64_t>(relative.y()) << kBits) | static_cast<std::uint64_t>(relative.z());
}

Lattice cornerOffset(int corner) { return {corner & 1, (corner >> 1) & 1, (corner >> 2) & 1}; }

std::int64_t floorDiv(double value, double step) { return static_cast<std::int64_t>(std::floor(value / step)); }

}  // namespace

SurfaceMesher::SurfaceMesher()
    : cellMap_(std::make_unique<detail::SurfaceMesherKeyMap>()),
      cubeMap_(std::make_unique<detail::SurfaceMesherKeyMap>()),
      cornerMap_(std::make_unique<detail::SurfaceMesherKeyMap>()) {}

SurfaceMesher::~SurfaceMesher() = default;

const TearSurface& SurfaceMesher::update(TearSimulation& simulation, std::size_t maxCubes) {
  const ParticleSet& particles = simulation.particles();
  if (particles.empty()) {  // effects on demand: no particles, no work and no run counted
    surface_.clear();
    stats_ = {};
    return surface_;
  }
  const auto start = Clock::now();
  const ScaledParameters& p = simulation.parameters();
  SurfaceMesherSettings settings{p.h, p.cubeSize, p.iso, maxCubes};
  build(particles.position, particles.mass, simulation.grid(), settings);
  simulation.countSurfaceRun();
  stats_.milliseconds = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
  return surface_;
}

const TearSurface& SurfaceMesher::build(std::span<const Eigen::Vector3d> positions, std::span<const double> masses,
                                        const UniformGrid& grid, const SurfaceMesherSettings& settings) {
  clearUpperVectorState();
  const auto start = Clock::now();
  const double h = settings.kernelRadius;
  if (!(h > 0) || !std::isfinite(h) || !(settings.cubeSize > 0) || !std::isfinite(settings.cubeSize) ||
      !(settings.iso > 0) || !std::isfinite(settings.iso) || settings.maxCubes == 0)
    throw std::invalid_argument("surface mesher: kernel radius, cube size, iso and maxCubes must be positive");
  surface_.clear();
  stats_ = {};
  if (positions.empty()) return surface_;
  field_.bind(positions, masses, grid, h);

  // Active cells: the occupied cells and their 26 neighbours, each once, in a fixed order.
  const CellIndex& index = grid.index();
  Eigen::Vector3i low = index.cellCoordinates(0), high = low;
  for (std::size_t c = 1; c < index.cellCount(); ++c) {
    const Eigen::Vector3i cell = index.cellCoordinates(c);
    low = low.cwiseMin(cell);
    high = high.cwiseMax(cell);
  }
  cellBase_ = low.cast<std::int64_t>() - Lattice::Constant(1);
  const Lattice cellSpan = (high - low).cast<std::int64_t>() + Lattice::Constant(3);
  if (cellSpan.maxCoeff() >= kSpan) {
    // Particles a million kernel radii apart: beyond any head; refuse rather than wrap keys.
    stats_.capped = true;
    ++cappedBuilds_;
    return surface_;
  }
  cellMap_->reset(27 * index.cellCount());
  dilated_.clear();
  for (std::size_t c = 0; c < index.cellCount(); ++c) {
    const Lattice cell = index.cellCoordinates(c).cast<std::int64_t>();
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dz = -1; dz <= 1; ++dz) {
          const Lattice d = cell + Lattice(dx, dy, dz);
          if (cellMap_->insert(pack(d - cellBase_), static_cast<std::int32_t>(dilated_.size())).second)
            dilated_.push_back(d);
        }
  }
  stats_.activeCells = dilated_.size();

  // Cube size: as asked unless the lattice would not fit the keys or the cubes the cap.
  double s = settings.cubeSize;
  const double spanLimited = static_cast<double>(cellSpan.maxCoeff() + 2) * h / static_cast<double>(kSpan - 4);
  const double cubesPerCell = std::pow(h / s, 3);
  const double capLimited = h * std::cbrt(static_cast<double>(dilated_.size()) / static_cast<double>(settings.maxCubes));
  if (spanLimited > s || static_cast<double>(dilated_.size()) * cubesPerCell > static_cast<double>(settings.maxCubes)) {
    s = std::max({s, spanLimited, capLimited});
    stats_.capped = true;
  }
  while (!collectCubes(s, settings.maxCubes)) {
    s *= 1.25;  // the estimate ignores the cubes shared by cell borders; close in from above
    stats_.capped = true;
  }
  if (stats_.capped) ++cappedBuilds_;
  stats_.cubeSize = s;
  stats_.cubes = cube_.size();

  collectCorners();
  stats_.corners = corner_.size();
  splat(s);
  march(s, settings.iso);
  computeNormals();
  stats_.milliseconds = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
  return surface_;
}

// Row-major (x-major, z-minor) index of a lattice point in the dense box, or -1 outside it.
std::int64_t SurfaceMesher::denseSlot(const Lattice& p) const {
  const Lattice r = p - denseLow_;
  if ((r.array() < 0).any() || (r.array() >= denseDims_.array()).any()) return -1;
  return (r.x() * denseDims_.y() + r.y()) * denseDims_.z() + r.z();
}

// The corner id of a lattice point, or -1 when it is no cube's corner.
std::int32_t SurfaceMesher::cornerId(const Lattice& p) const {
  if (!dense_) return cornerMap_->find(pack(p - cubeBase_));
  const std::int64_t slot = denseSlot(p);
  return slot < 0 ? -1 : denseCorner_[static_cast<std::size_t>(slot)];
}

// Every cube meeting an active cell: on each axis k from floor(d h / s) to floor((d + 1) h / s),
// a superset of the cubes whose interior overlaps the cell [d h, (d + 1) h] (at most one extra
// cube per axis, at the rim, where c = 0). Returns false once more than maxCubes are found.
bool SurfaceMesher::collectCubes(double s, std::size_t maxCubes) {
  const double h = field_.kernelRadius();
  cubeBase_ = Lattice(floorDiv(static_cast<double>(cellBase_.x()) * h, s), floorDiv(static_cast<double>(cellBase_.y()) * h, s),
                      floorDiv(static_cast<double>(cellBase_.z()) * h, s)) -
              Lattice::Constant(1);
  const double perCell = std::pow(h / s + 1.0, 3);
  const double expected = std::min(static_cast<double>(maxCubes), perCell * static_cast<double>(dilated_.size()));
  // The corners' bounding box: every cube of every dilated cell plus its +1 corners. Dense when
  // it holds at most ~8 lattice points per expected cube (filling an int costs far less than a
  // hash probe), else the hash maps keep memory proportional to the cubes.
  Lattice cellHigh = dilated_.front();
  for (const Lattice& d : dilated_) cellHigh = cellHigh.cwiseMax(d);
  Lattice boxHigh;
  for (int a = 0; a < 3; ++a) {
    denseLow_[a] = floorDiv(static_cast<double>(cellBase_[a]) * h, s);
    boxHigh[a] = floorDiv(static_cast<double>(cellHigh[a] + 1) * h, s) + 1;
  }
  denseDims_ = boxHigh - denseLow_ + Lattice::Constant(1);
  const double boxPoints = static_cast<double>(denseDims_.x()) * static_cast<double>(denseDims_.y()) *
                           static_cast<double>(denseDims_.z());
  dense_ = boxPoints <= 8.0 * expected + 4096.0 && boxPoints <= double(std::int64_t{1} << 26);
  // The dense arrays are all -1 except the slots the last build set, listed: clearing those is
  // proportional to the cubes, where refilling the box would be proportional to its volume
  // (two drops far apart make a large, nearly empty box).
  for (std::int64_t slot : denseCubeSlots_) denseCube_[static_cast<std::size_t>(slot)] = -1;
  denseCubeSlots_.clear();
  if (dense_) {
    if (denseCube_.size() < static_cast<std::size_t>(boxPoints)) denseCube_.resize(static_cast<std::size_t>(boxPoints), -1);
  } else {
    cubeMap_->reset(static_cast<std::size_t>(expected));
  }
  cube_.clear();
  for (const Lattice& d : dilated_) {
    Lattice lo, hi;
    for (int a = 0; a < 3; ++a) {
      lo[a] = floorDiv(static_cast<double>(d[a]) * h, s);
      hi[a] = floorDiv(static_cast<double>(d[a] + 1) * h, s);
    }
    for (std::int64_t x = lo.x(); x <= hi.x(); ++x)
      for (std::int64_t y = lo.y(); y <= hi.y(); ++y) {
        // The z run of this (x, y) is contiguous in the dense box: one index, then +1 per cube.
        const std::int64_t row = dense_ ? denseSlot(Lattice(x, y, lo.z())) - lo.z() : 0;
        for (std::int64_t z = lo.z(); z <= hi.z(); ++z) {
          const Lattice k(x, y, z);
          const auto id = static_cast<std::int32_t>(cube_.size());
          if (dense_) {
            std::int32_t& slot = denseCube_[static_cast<std::size_t>(row + z)];
            if (slot >= 0) continue;
            slot = id;
            denseCubeSlots_.push_back(row + z);
          } else if (!cubeMap_->insert(pack(k - cubeBase_), id).second) {
            continue;
          }
          cube_.push_back(k);
          if (cube_.size() > maxCubes) return false;
        }
      }
  }
  return true;
}

// The eight corners of every cube, each lattice point once.
void SurfaceMesher::collectCorners() {
  corner_.clear();
  cubeCorner_.resize(cube_.size());
  for (std::int64_t slot : denseCornerSlots_) denseCorner_[static_cast<std::size_t>(slot)] = -1;
  denseCornerSlots_.clear();
  if (dense_) {
    if (denseCorner_.size() < denseCube_.size()) denseCorner_.resize(denseCube_.size(), -1);
    // Corner k of a cube is `step[k]` slots from its corner 0 (the box is row-major).
    const std::int64_t dz = 1, dy = denseDims_.z(), dx = denseDims_.y() * denseDims_.z();
    std::array<std::int64_t, 8> step;
    for (int k = 0; k < 8; ++k) step[static_cast<std::size_t>(k)] = (k & 1) * dx + ((k >> 1) & 1) * dy + ((k >> 2) & 1) * dz;
    for (std::size_t i = 0; i < cube_.size(); ++i) {
      const std::int64_t base = denseSlot(cube_[i]);  // in the box, and so are its +1 corners
      for (int k = 0; k < 8; ++k) {
        const std::int64_t at = base + step[static_cast<std::size_t>(k)];
        std::int32_t& slot = denseCorner_[static_cast<std::size_t>(at)];
        if (slot < 0) {
          slot = static_cast<std::int32_t>(corner_.size());
          corner_.push_back(cube_[i] + cornerOffset(k));
          denseCornerSlots_.push_back(at);
        }
        cubeCorner_[i][static_cast<std::size_t>(k)] = slot;
      }
    }
    return;
  }
  cornerMap_->reset(cube_.size() + cube_.size() / 2 + 64);
  for (std::size_t i = 0; i < cube_.size(); ++i)
    for (int k = 0; k < 8; ++k) {
      const Lattice p = cube_[i] + cornerOffset(k);
      const auto [id, inserted] = cornerMap_->insert(pack(p - cubeBase_), static_cast<std::int32_t>(corner_.size()));
      if (inserted) corner_.push_back(p);
      cubeCorner_[i][static_cast<std::size_t>(k)] = id;
    }
}

// c and grad c at the corners, particle by particle: each particle adds V (h^2 - r^2)^3 and
// V (h^2 - r^2)^2 (corner - x) to the corners within h of it ((2h/s)^3 of them), cheaper than
// gathering 27 cells per corner; the vertices' normals then interpolate the corner gradients.
void SurfaceMesher::splat(double s) {
  const double h = field_.kernelRadius(), h2 = h * h;
  const CellIndex& index = field_.index();
  const auto volume = field_.sortedVolumes();
  const double* sx = index.sortedX().data();
  const double* sy = index.sortedY().data();
  const double* sz = index.sortedZ().data();
  cornerValue_.assign(corner_.size(), 0.0);
  cornerGradient_.assign(corner_.size(), Eigen::Vector3d::Zero());
  for (std::size_t t = 0; t < index.particleCount(); ++t) {
    const Eigen::Vector3d x(sx[t], sy[t], sz[t]);
    if (volume[t] == 0 || !x.allFinite()) continue;
    const double v = volume[t];
    const std::int64_t x0 = static_cast<std::int64_t>(std::ceil((x.x() - h) / s)), x1 = floorDiv(x.x() + h, s);
    const std::int64_t y0 = static_cast<std::int64_t>(std::ceil((x.y() - h) / s)), y1 = floorDiv(x.y() + h, s);
    for (std::int64_t i = x0; i <= x1; ++i) {
      const double ex = static_cast<double>(i) * s - x.x();
      for (std::int64_t j = y0; j <= y1; ++j) {
        const double ey = static_cast<double>(j) * s - x.y();
        const double rest = h2 - ex * ex - ey * ey;
        if (rest <= 0) continue;
        const double reach = std::sqrt(rest);
        const std::int64_t z0 = static_cast<std::int64_t>(std::ceil((x.z() - reach) / s)), z1 = floorDiv(x.z() + reach, s);
        for (std::int64_t k = z0; k <= z1; ++k) {
          const double ez = static_cast<double>(k) * s - x.z();
          const double d = rest - ez * ez;
          if (d <= 0) continue;
          const std::int32_t c = cornerId(Lattice(i, j, k));
          if (c < 0) continue;
          const double vd2 = v * d * d;
          cornerValue_[static_cast<std::size_t>(c)] += vd2 * d;
          cornerGradient_[static_cast<std::size_t>(c)] += vd2 * Eigen::Vector3d(ex, ey, ez);
        }
      }
    }
  }
  const Poly6Kernel kernel(h);
  const double w = kernel.valueCoefficient(), g = kernel.gradientCoefficient();
  for (double& value : cornerValue_) value *= w;
  for (Eigen::Vector3d& gradient : cornerGradient_) gradient *= g;
}

// The vertex on the cube edge from corner `lowerCorner` (at lattice point `lower`) along `axis`
// to `upperCorner`: created once per edge, keyed by the lower corner's id and the axis, so the
// cubes sharing the edge share the vertex (watertight) without a hash of lattice keys.
std::int32_t SurfaceMesher::vertexOnEdge(const Lattice& lower, std::int32_t lowerCorner, std::int32_t upperCorner,
                                         int axis, double s, double iso) {
  std::int32_t& id = edgeVertex_[3 * static_cast<std::size_t>(lowerCorner) + static_cast<std::size_t>(axis)];
  if (id >= 0) return id;
  id = static_cast<std::int32_t>(surface_.position_.size());
  const double a = cornerValue_[static_cast<std::size_t>(lowerCorner)];
  const double b = cornerValue_[static_cast<std::size_t>(upperCorner)];
  // One end is inside (>= iso) and the other outside (< iso), so b - a != 0 and mu is in [0, 1].
  const double mu = (iso - a) / (b - a);
  Eigen::Vector3d p = lower.cast<double>() * s;
  p[axis] += mu * s;
  surface_.position_.push_back(p);
  const Eigen::Vector3d& ga = cornerGradient_[static_cast<std::size_t>(lowerCorner)];
  vertexGradient_.push_back(ga + mu * (cornerGradient_[static_cast<std::size_t>(upperCorner)] - ga));
  return id;
}

void SurfaceMesher::march(double s, double iso) {
  const MarchingCubesTable& table = MarchingCubesTable::instance();
  edgeVertex_.assign(3 * corner_.size(), -1);  // keeps its capacity between frames
  vertexGradient_.clear();
  for (std::size_t i = 0; i < cube_.size(); ++i) {
    const auto& corners = cubeCorner_[i];
    int configuration = 0;
    for (int k = 0; k < 8; ++k)
      if (cornerValue_[static_cast<std::size_t>(corners[static_cast<std::size_t>(k)])] >= iso) configuration |= 1 << k;
    if (configuration == 0 || configuration == 255) continue;
    const MarchingCubesCase& c = table[configuration];
    for (int t = 0; t < c.triangleCount; ++t) {
      Eigen::Vector3i triangle;
      for (int v = 0; v < 3; ++v) {
        const int edge = c.edges[static_cast<std::size_t>(3 * t + v)];
        const int lowerK = MarchingCubesTable::edgeLowerCorner(edge), upperK = MarchingCubesTable::edgeUpperCorner(edge);
        const Lattice lower = cube_[i] + cornerOffset(lowerK);
        triangle[v] = vertexOnEdge(lower, corners[static_cast<std::size_t>(lowerK)],
                                   corners[static_cast<std::size_t>(upperK)], MarchingCubesTable::edgeAxis(edge), s, iso);
      }
      surface_.triangle_.push_back(triangle);
    }
  }
}

void SurfaceMesher::computeNormals() {
  const std::size_t n = surface_.position_.size();
  surface_.normal_.resize(n);
  normalFallback_.assign(n, 0);
  bool anyFallback = false;
  const double h = field_.kernelRadius();
  for (std::size_t v = 0; v < n; ++v) {
    const Eigen::Vector3d& g = vertexGradient_[v];
    const double norm = g.norm();
    // |grad c| of a surface is ~1 / h; far below that the direction is rounding noise.
    if (norm > 1e-9 / h && std::isfinite(norm)) {
      surface_.normal_[v] = -g / norm;
    } else {
      surface_.normal_[v].setZero();
      normalFallback_[v] = 1;
      anyFallback = true;
    }
  }
  if (!anyFallback) return;
  for (const Eigen::Vector3i& t : surface_.triangle_) {
    const Eigen::Vector3d& a = surface_.position_[static_cast<std::size_t>(t[0])];
    const Eigen::Vector3d areaNormal = (surface_.position_[static_cast<std::size_t>(t[1])] - a)
                                           .cross(surface_.position_[static_cast<std::size_t>(t[2])] - a);
    for (int k = 0; k < 3; ++k)
      if (normalFallback_[static_cast<std::size_t>(t[k])]) surface_.normal_[static_cast<std::size_t>(t[k])] += areaNormal;
  }
  for (std::size_t v = 0; v < n; ++v) {
    if (!normalFallback_[v]) continue;
    const double norm = surface_.normal_[v].norm();
    surface_.normal_[v] = norm > 0 ? Eigen::Vector3d(surface_.normal_[v] / norm) : Eigen::Vector3d::UnitY();
  }
}

}  // namespace lacrima::tears
