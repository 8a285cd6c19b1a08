#include "CellIndex.h"
#include "Float4.h"
#include "MarchingCubesTable.h"
#include "ParallelChunks.h"
#include "SurfaceMesherField.h"
#include "SurfaceMesherKeyMap.h"
#include "VectorState.h"

#include <lacrima/common/Milliseconds.h>
#include <lacrima/tears/SurfaceMesher.h>
#include <lacrima/tears/TearSimulation.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>

namespace lacrima::tears {
namespace {

using Int4 = int __attribute__((vector_size(16)));  // lane masks of Float4 comparisons
using Lattice = Eigen::Matrix<std::int64_t, 3, 1>;

constexpr int kShift = 2;  // 4^3 cubes: 8^3 ran as fast but doubles the memory of sparse drops
constexpr int kBlock = 1 << kShift;                      // cubes per block edge
constexpr int kBlockCorners = kBlock * kBlock * kBlock;  // corners owned by a block
// Per block: the value, then the gradient's x, y and z at its corners, then four floats that
// nothing reads. A four-wide add that runs past a line's last corner adds exact zeros to the
// corners after it; the padding keeps those within the block, so two threads splatting slabs
// of whole blocks never touch one float.
constexpr int kBlockFloats = 4 * kBlockCorners + 4;
constexpr int kLines = (kBlock + 1) * (kBlock + 1);            // padded (x, y) lines of a block
constexpr std::uint16_t kFullLine = (1u << (kBlock + 1)) - 1;  // a padded line all inside
constexpr unsigned kLowBits = (1u << kBlock) - 1;              // the block's own corners of a line

// The lattice may span at most 2^20 points per axis (as the cell-keyed mesher allowed), so block
// keys, relative to the lowest block, pack into 3 x 21 bits.
constexpr std::int64_t kSpan = (std::int64_t{1} << 20) - 4;
constexpr int kKeyBits = 21;

std::uint64_t pack(const Lattice& relative) {
  return (static_cast<std::uint64_t>(relative.x()) << (2 * kKeyBits)) |
         (static_cast<std::uint64_t>(relative.y()) << kKeyBits) |
         static_cast<std::uint64_t>(relative.z());
}

// floor and ceil of value / step; inline because the baseline x86-64 build calls libm for
// std::floor. The quotients stay far inside the int64 range (build() refuses |x| / s > 1e15).
std::int64_t floorDiv(double value, double step) {
  const double q = value / step;
  const auto t = static_cast<std::int64_t>(q);
  return t - static_cast<std::int64_t>(static_cast<double>(t) > q);
}
std::int64_t ceilDiv(double value, double step) {
  const double q = value / step;
  const auto t = static_cast<std::int64_t>(q);
  return t + static_cast<std::int64_t>(static_cast<double>(t) < q);
}
std::int64_t blockOf(std::int64_t lattice) { return lattice >> kShift; }  // arithmetic shift: floor
int local(std::int64_t lattice) { return static_cast<int>(lattice & (kBlock - 1)); }
int cornerSlot(int x, int y, int z) { return (x * kBlock + y) * kBlock + z; }

// The lattice box of the corners within h of x, per axis [ceil((x - h) / s), floor((x + h) / s)].
struct SupportBox {
  Lattice low, high;
  bool empty() const { return (low.array() > high.array()).any(); }
};
SupportBox supportOf(const Eigen::Vector3d& x, double h, double s) {
  SupportBox b;
  for (int a = 0; a < 3; ++a) {
    b.low[a] = ceilDiv(x[a] - h, s);
    b.high[a] = floorDiv(x[a] + h, s);
  }
  return b;
}

// Per cube edge: the lattice offset of its lower corner and its axis.
struct EdgeStep {
  int dx, dy, dz, axis;
};
std::array<EdgeStep, 12> edgeSteps() {
  std::array<EdgeStep, 12> steps{};
  for (int e = 0; e < 12; ++e) {
    const int k = MarchingCubesTable::edgeLowerCorner(e);
    steps[static_cast<std::size_t>(e)] = {k & 1, (k >> 1) & 1, (k >> 2) & 1,
                                          MarchingCubesTable::edgeAxis(e)};
  }
  return steps;
}

}  // namespace

SurfaceMesher::SurfaceMesher()
    : field_(std::make_unique<SurfaceMesherField>()),
      blockMap_(std::make_unique<detail::SurfaceMesherKeyMap>()) {}

SurfaceMesher::~SurfaceMesher() = default;

const TearSurface& SurfaceMesher::update(TearSimulation& simulation, std::size_t maxCubes,
                                         std::span<const std::uint8_t> skip) {
  const ParticleSet& particles = simulation.particles();
  if (particles.empty()) {  // effects on demand: no particles, no work and no run counted
    surface_.clear();
    stats_ = {};
    return surface_;
  }
  const auto start = SteadyClock::now();
  const ScaledParameters& p = simulation.parameters();
  SurfaceMesherSettings settings{p.h, p.cubeSize, p.iso, maxCubes};
  const UniformGrid& grid = simulation.grid();
  ParallelChunks& parallel = simulation.parallelChunks();
  parallel.setParticleCount(particles.size());
  mesh(particles.position, meshedMasses(particles, skip), grid, settings, &parallel);
  simulation.countSurfaceRun();
  stats_.milliseconds = millisecondsSince(start);
  return surface_;
}

// The particles' masses, zero for those skipped: a massless particle adds nothing to the
// colour field (SurfaceMesherField.h).
std::span<const double> SurfaceMesher::meshedMasses(const ParticleSet& particles,
                                                    std::span<const std::uint8_t> skip) {
  if (skip.empty()) return particles.mass;
  if (skip.size() != particles.mass.size())
    throw std::invalid_argument("surface mesher: one skip flag per particle");
  meshedMass_.assign(particles.mass.begin(), particles.mass.end());
  for (std::size_t i = 0; i < skip.size(); ++i)
    if (skip[i]) meshedMass_[i] = 0;
  return meshedMass_;
}

const TearSurface& SurfaceMesher::build(std::span<const Eigen::Vector3d> positions,
                                        std::span<const double> masses, const UniformGrid& grid,
                                        const SurfaceMesherSettings& settings) {
  return mesh(positions, masses, grid, settings, nullptr);
}

const TearSurface& SurfaceMesher::mesh(std::span<const Eigen::Vector3d> positions,
                                       std::span<const double> masses, const UniformGrid& grid,
                                       const SurfaceMesherSettings& settings,
                                       ParallelChunks* parallel) {
  clearUpperVectorState();
  const auto start = SteadyClock::now();
  const double h = settings.kernelRadius;
  if (!(h > 0) || !std::isfinite(h) || !(settings.cubeSize > 0) ||
      !std::isfinite(settings.cubeSize) || !(settings.iso > 0) || !std::isfinite(settings.iso) ||
      settings.maxCubes == 0)
    throw std::invalid_argument(
        "surface mesher: kernel radius, cube size, iso and maxCubes must be positive");
  surface_.clear();
  stats_ = {};
  if (positions.empty()) return surface_;
  field_->bind(positions, masses, grid, h, parallel);
  const CellIndex& index = grid.index();
  stats_.activeCells = index.cellCount();

  // The box of the particles that carry volume.
  const auto weight = field_->sortedVolumes();
  Eigen::Vector3d low = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity()),
                  high = -low;
  for (std::size_t t = 0; t < index.particleCount(); ++t) {
    if (weight[t] == 0) continue;
    const Eigen::Vector3d x(index.sortedX()[t], index.sortedY()[t], index.sortedZ()[t]);
    low = low.cwiseMin(x);
    high = high.cwiseMax(x);
  }
  if (!low.allFinite()) return surface_;  // no particle carries volume: c = 0 everywhere
  const double extent = (high - low).maxCoeff() + 2 * h;
  if (extent / h >= static_cast<double>(kSpan)) {
    // Particles a million kernel radii apart: beyond any head; refuse rather than wrap keys.
    stats_.capped = true;
    ++cappedBuilds_;
    return surface_;
  }

  // Cube size: as asked unless the lattice would not fit the keys or the blocks the cap. The
  // occupied cells alone hold cells (h / s)^3 cubes: a lower bound that sets an absurdly small
  // s right before the blocks are counted.
  double s = settings.cubeSize;
  const double spanLimited = extent / static_cast<double>(kSpan - 4);
  const double cells = static_cast<double>(index.cellCount());
  const double capLimited = h * std::cbrt(cells / static_cast<double>(settings.maxCubes));
  if (spanLimited > s || cells * std::pow(h / s, 3) > static_cast<double>(settings.maxCubes)) {
    s = std::max({s, spanLimited, capLimited});
    stats_.capped = true;
  }
  // Far from the origin the lattice coordinates must stay exact in a double and an int64.
  if (std::max(low.cwiseAbs().maxCoeff(), high.cwiseAbs().maxCoeff()) / s > 1e15) {
    stats_.capped = true;
    ++cappedBuilds_;
    return surface_;
  }
  blockBase_ = Lattice(blockOf(ceilDiv(low.x() - h, s) - 1), blockOf(ceilDiv(low.y() - h, s) - 1),
                       blockOf(ceilDiv(low.z() - h, s) - 1));
  const std::size_t maxBlocks = std::max<std::size_t>(1, settings.maxCubes / kBlockCorners);
  while (!collectBlocks(s, maxBlocks)) {
    s *= 1.25;
    stats_.capped = true;
    blockBase_ = Lattice(blockOf(ceilDiv(low.x() - h, s) - 1), blockOf(ceilDiv(low.y() - h, s) - 1),
                         blockOf(ceilDiv(low.z() - h, s) - 1));
  }
  if (stats_.capped) ++cappedBuilds_;
  stats_.cubeSize = s;
  stats_.blocks = block_.size();
  stats_.cubes = stats_.corners = block_.size() * kBlockCorners;

  linkBlocks();
  splat(s, low.y(), high.y(), parallel);
  const auto iso = static_cast<float>(settings.iso);
  classify(iso);
  createVertices(s, iso);
  march();
  if (anyFallback_) fallbackNormals();
  stats_.milliseconds = millisecondsSince(start);
  return surface_;
}

std::int32_t SurfaceMesher::blockAt(const Lattice& block) const {
  return blockMap_->find(pack(block - blockBase_));
}

// The blocks of every particle's support box, extended by one corner downwards, in particle
// order (deterministic). Returns false once more than maxBlocks are found.
bool SurfaceMesher::collectBlocks(double s, std::size_t maxBlocks) {
  const double h = field_->kernelRadius();
  const CellIndex& index = field_->index();
  const auto weight = field_->sortedVolumes();
  blockMap_->reset(std::min(maxBlocks, 4 * block_.size() + 64));
  block_.clear();
  Lattice lastLow = Lattice::Constant(1), lastHigh = Lattice::Zero();  // an empty range
  for (std::size_t t = 0; t < index.particleCount(); ++t) {
    if (weight[t] == 0) continue;
    const SupportBox box =
        supportOf({index.sortedX()[t], index.sortedY()[t], index.sortedZ()[t]}, h, s);
    if (box.empty()) continue;  // no lattice point within h: adds nothing
    Lattice bl, bh;
    for (int a = 0; a < 3; ++a) {
      bl[a] = blockOf(box.low[a] - 1);
      bh[a] = blockOf(box.high[a]);
    }
    if (bl == lastLow && bh == lastHigh) continue;  // the same blocks as the particle before
    lastLow = bl;
    lastHigh = bh;
    for (std::int64_t x = bl.x(); x <= bh.x(); ++x)
      for (std::int64_t y = bl.y(); y <= bh.y(); ++y)
        for (std::int64_t z = bl.z(); z <= bh.z(); ++z) {
          const Lattice b(x, y, z);
          if (!blockMap_->insert(pack(b - blockBase_), static_cast<std::int32_t>(block_.size()))
                   .second)
            continue;
          block_.push_back(b);
          if (block_.size() > maxBlocks) return false;
        }
  }
  return true;
}

void SurfaceMesher::linkBlocks() {
  neighbour_.resize(block_.size());
  for (std::size_t b = 0; b < block_.size(); ++b) {
    neighbour_[b][0] = static_cast<std::int32_t>(b);
    for (int k = 1; k < 8; ++k)
      neighbour_[b][static_cast<std::size_t>(k)] =
          blockAt(block_[b] + Lattice(k & 1, (k >> 1) & 1, k >> 2));
  }
}

// c and grad c at the corners, particle by particle: each particle adds a d^2 (d, e) to the
// corners of its support box with d > 0 (d = 1 - r^2/h^2, e = (corner - x) / h, a = V w h^6),
// cheaper than gathering 27 cells per corner. c = sum a d^3 and grad c = -6 / h sum a d^2 e.
//
// Threads: the lattice is cut into slabs along y and each slab adds its particles' shares to
// its own corners only, particle by particle in sorted order. Every corner thus receives the
// same additions in the same order however many slabs there are, so the sums are bit-identical
// for any thread count, and one thread runs the one slab exactly as before. The cut is along y
// because tears run down the face: streams are long in y and narrow in x, so slabs across them
// share few particles (cut along x, the particles within h of a cut were a third of the sheet's).
void SurfaceMesher::splat(double s, double lowY, double highY, ParallelChunks* parallel) {
  sum_.resize(block_.size() * kBlockFloats);
  std::memset(sum_.data(), 0, sum_.size() * sizeof(float));
  const std::size_t slabs = cutSlabs(s, lowY, highY, parallel);
  stats_.slabs = slabs;
  forEachChunkOn(parallel, slabs, 1, [&](int k, std::size_t, std::size_t) {
    const auto slab = static_cast<std::size_t>(k);
    splatSlab(s, slabBound_[slab], slabBound_[slab + 1], splatScratch_[slab]);
  });
}

// Slabs of about equal particle counts, two per thread when the simulation shares its loops
// (the pool hands them out in order, so a slow slab does not hold a thread idle), one
// otherwise. Slab k covers lattice y in [slabBound_[k], slabBound_[k + 1]), whole blocks (see
// kBlockFloats for why); the cuts are the quantiles of a sample of the particles' heights (up to
// 1,024), inside the box of the particles with volume (the others may lie anywhere). Each slab
// gets the particles whose support reaches it, in sorted order. Returns the slab count.
std::size_t SurfaceMesher::cutSlabs(double s, double lowY, double highY,
                                    const ParallelChunks* parallel) {
  const std::size_t slabs =
      parallel && parallel->shared() ? 2 * static_cast<std::size_t>(parallel->threads()) : 1;
  slabBound_.assign(slabs + 1, std::numeric_limits<std::int64_t>::min());
  slabBound_.back() = std::numeric_limits<std::int64_t>::max();
  if (splatScratch_.size() < slabs) splatScratch_.resize(slabs);
  for (std::size_t k = 0; k < slabs; ++k) splatScratch_[k].particles.clear();
  const CellIndex& index = field_->index();
  const auto y = index.sortedY();
  const auto weight = field_->sortedSplatWeights();
  if (slabs == 1) {
    for (std::uint32_t t = 0; t < y.size(); ++t)
      if (weight[t] != 0) splatScratch_[0].particles.push_back(t);
    return 1;
  }
  const std::size_t stride = std::max<std::size_t>(1, y.size() / 1024);
  heightSample_.clear();
  for (std::size_t t = 0; t < y.size(); t += stride)
    heightSample_.push_back(std::isfinite(y[t]) ? std::clamp(y[t], lowY, highY) : lowY);
  std::sort(heightSample_.begin(), heightSample_.end());
  for (std::size_t k = 1; k < slabs; ++k)
    slabBound_[k] =
        std::max(slabBound_[k - 1],
                 kBlock * blockOf(floorDiv(heightSample_[k * heightSample_.size() / slabs], s)));
  const double h = field_->kernelRadius();
  for (std::uint32_t t = 0; t < y.size(); ++t) {
    if (weight[t] == 0) continue;
    const std::int64_t low = ceilDiv(y[t] - h, s), high = floorDiv(y[t] + h, s);
    std::size_t k = 0;
    while (slabBound_[k + 1] <= low) ++k;  // the last bound is the int64 maximum
    for (; k < slabs && slabBound_[k] <= high; ++k) splatScratch_[k].particles.push_back(t);
  }
  return slabs;
}

// The shares of the slab's particles for its corners, those with lattice y in [yFrom, yTo).
// The box's per-axis offsets, blocks and block-local coordinates are tabulated once per
// particle, for the whole box so that they do not depend on the slab, and the corner loop is a
// handful of single-precision operations and one four-float add.
void SurfaceMesher::splatSlab(double s, std::int64_t yFrom, std::int64_t yTo,
                              SplatScratch& scratch) {
  const double h = field_->kernelRadius(), inverse = 1.0 / h;
  const auto step = static_cast<float>(s * inverse);
  const CellIndex& index = field_->index();
  const auto weight = field_->sortedSplatWeights();
  Lattice lastLow = Lattice::Constant(1), lastHigh = Lattice::Zero(), dims = Lattice::Zero();
  const Float4 lane = {0, 1, 2, 3}, zero = {0, 0, 0, 0};
  for (const std::uint32_t t : scratch.particles) {
    const Eigen::Vector3d x(index.sortedX()[t], index.sortedY()[t], index.sortedZ()[t]);
    const SupportBox box = supportOf(x, h, s);
    if (box.empty()) continue;
    const Lattice n = box.high - box.low + Lattice::Ones();
    // The box's y points inside the slab (the bounds may be the int64 limits).
    const std::int64_t jBegin = yFrom > box.low.y() ? yFrom - box.low.y() : 0;
    const std::int64_t jEnd = yTo <= box.high.y() ? yTo - box.low.y() : n.y();
    if (jBegin >= jEnd) continue;
    Lattice bl, bh;
    for (int a = 0; a < 3; ++a) {
      bl[a] = blockOf(box.low[a]);
      bh[a] = blockOf(box.high[a]);
    }
    if (bl != lastLow ||
        bh != lastHigh) {  // look the support's blocks up once per run of particles
      lastLow = bl;
      lastHigh = bh;
      dims = bh - bl + Lattice::Ones();
      scratch.blocks.clear();
      for (std::int64_t bx = bl.x(); bx <= bh.x(); ++bx)
        for (std::int64_t by = bl.y(); by <= bh.y(); ++by)
          for (std::int64_t bz = bl.z(); bz <= bh.z(); ++bz)
            scratch.blocks.push_back(blockAt(Lattice(bx, by, bz)));
    }
    // Per axis and box point: offset from the particle in kernel units, block (relative to bl)
    // and block-local coordinate. Offsets are padded with four zeros for four-wide loads.
    scratch.axis.resize(static_cast<std::size_t>(n.sum()));
    scratch.offset.resize(static_cast<std::size_t>(n.sum()) + 12);
    std::array<AxisPoint*, 3> axis{};
    std::array<float*, 3> offset{};
    for (int a = 0, at = 0; a < 3; at += static_cast<int>(n[a]) + 4, ++a) {
      axis[static_cast<std::size_t>(a)] = &scratch.axis[static_cast<std::size_t>(at - 4 * a)];
      offset[static_cast<std::size_t>(a)] = &scratch.offset[static_cast<std::size_t>(at)];
      const auto firstOffset =
          static_cast<float>((static_cast<double>(box.low[a]) * s - x[a]) * inverse);
      for (std::int64_t k = 0; k < n[a]; ++k) {
        const std::int64_t lattice = box.low[a] + k;
        offset[static_cast<std::size_t>(a)][k] = firstOffset + static_cast<float>(k) * step;
        axis[static_cast<std::size_t>(a)][k] = {static_cast<int>(blockOf(lattice) - bl[a]),
                                                local(lattice)};
      }
      for (int k = 0; k < 4; ++k) offset[static_cast<std::size_t>(a)][n[a] + k] = 0.0f;
    }
    const float weightT = weight[t];
    const Float4 a = {weightT, weightT, weightT, weightT};
    for (std::int64_t i = 0; i < n.x(); ++i) {
      const float ex = offset[0][i];
      for (std::int64_t j = jBegin; j < jEnd; ++j) {
        const float ey = offset[1][j];
        const float rest = 1.0f - ex * ex - ey * ey;
        if (rest <= 0) continue;
        const std::size_t row =
            static_cast<std::size_t>((axis[0][i].block * dims.y() + axis[1][j].block) * dims.z());
        const auto slot =
            static_cast<std::size_t>(cornerSlot(axis[0][i].local, axis[1][j].local, 0));
        const Float4 rest4 = {rest, rest, rest, rest}, ex4 = {ex, ex, ex, ex},
                     ey4 = {ey, ey, ey, ey};
        // The z run, one block at a time, four corners per step (contiguous in the block):
        // lanes past the run or outside the support add exact zeros.
        for (std::int64_t k = 0; k < n.z();) {
          const int blockZ = axis[2][k].block;
          std::int64_t end = k + 1;
          while (end < n.z() && axis[2][end].block == blockZ) ++end;
          const std::int32_t b = scratch.blocks[row + static_cast<std::size_t>(blockZ)];
          float* base = &sum_[static_cast<std::size_t>(b) * kBlockFloats + slot +
                              static_cast<std::size_t>(axis[2][k].local)];
          for (; k < end; k += 4, base += 4) {
            const Float4 ez = load4(&offset[2][k]);
            const Float4 d = rest4 - ez * ez;
            const auto left = static_cast<float>(end - k);
            const Int4 keep = (d > zero) & (lane < Float4{left, left, left, left});
            const Float4 w = reinterpret_cast<Float4>(reinterpret_cast<Int4>(a * d * d) & keep);
            store4(base, load4(base) + w * d);
            store4(base + kBlockCorners, load4(base + kBlockCorners) + w * ex4);
            store4(base + 2 * kBlockCorners, load4(base + 2 * kBlockCorners) + w * ey4);
            store4(base + 3 * kBlockCorners, load4(base + 3 * kBlockCorners) + w * ez);
          }
          k = end;
        }
      }
    }
  }
}

// Inside bits (c >= iso) per block, then the padded 9 x 9 lines of 9 bits each; the blocks whose
// lines are neither all outside nor all inside hold the surface.
void SurfaceMesher::classify(float iso) {
  const std::size_t n = block_.size();
  inside_.resize(n * kBlock * kBlock);
  for (std::size_t b = 0; b < n; ++b) {
    const float* c = &sum_[b * kBlockFloats];
    std::uint8_t* mask = &inside_[b * kBlock * kBlock];
    for (int line = 0; line < kBlock * kBlock; ++line, c += kBlock) {
      unsigned bits = 0;
      for (int z = 0; z < kBlock; ++z) bits |= static_cast<unsigned>(c[z] >= iso) << z;
      mask[line] = static_cast<std::uint8_t>(bits);
    }
  }
  line_.resize(n * kLines);
  surfaceBlock_.clear();
  for (std::size_t b = 0; b < n; ++b) {
    const auto& near = neighbour_[b];
    std::uint16_t* lines = &line_[b * kLines];
    unsigned any = 0, all = kFullLine;
    for (int x = 0; x <= kBlock; ++x)
      for (int y = 0; y <= kBlock; ++y) {
        const int side = (x >> kShift) | ((y >> kShift) << 1);
        const std::int32_t own = near[static_cast<std::size_t>(side)],
                           above = near[static_cast<std::size_t>(side | 4)];
        const int slot = (x & (kBlock - 1)) * kBlock + (y & (kBlock - 1));
        unsigned bits = own >= 0 ? inside_[static_cast<std::size_t>(own) * kBlock * kBlock +
                                           static_cast<std::size_t>(slot)]
                                 : 0u;
        if (above >= 0)
          bits |= (inside_[static_cast<std::size_t>(above) * kBlock * kBlock +
                           static_cast<std::size_t>(slot)] &
                   1u)
                  << kBlock;
        lines[x * (kBlock + 1) + y] = static_cast<std::uint16_t>(bits);
        any |= bits;
        all &= bits;
      }
    if (any != 0 && all != kFullLine) surfaceBlock_.push_back(static_cast<std::uint32_t>(b));
  }
}

// One vertex per crossing edge whose lower corner the block owns, in a fixed order (block, line,
// axis, z), before any cube looks one up.
void SurfaceMesher::createVertices(double s, float iso) {
  edgeVertex_.resize(block_.size() * kBlockCorners * 3);
  normalFallback_.clear();
  anyFallback_ = false;
  // Value and gradient sum of a corner (block-relative coordinates up to kBlock); zeros in a
  // missing block.
  const auto corner = [&](std::size_t b, int x, int y, int z) {
    const int side = (x >> kShift) | ((y >> kShift) << 1) | ((z >> kShift) << 2);
    const std::int32_t owner = neighbour_[b][static_cast<std::size_t>(side)];
    std::array<double, 4> v{};
    if (owner < 0) return v;
    const float* at = &sum_[static_cast<std::size_t>(owner) * kBlockFloats +
                            static_cast<std::size_t>(
                                cornerSlot(x & (kBlock - 1), y & (kBlock - 1), z & (kBlock - 1)))];
    for (int k = 0; k < 4; ++k) v[static_cast<std::size_t>(k)] = at[k * kBlockCorners];
    return v;
  };
  for (const std::uint32_t b : surfaceBlock_) {
    const std::uint16_t* lines = &line_[b * kLines];
    const Lattice origin = block_[b] * kBlock;
    for (int x = 0; x < kBlock; ++x)
      for (int y = 0; y < kBlock; ++y) {
        const unsigned m = lines[x * (kBlock + 1) + y];
        const std::array<unsigned, 3> crossing = {
            (m ^ lines[(x + 1) * (kBlock + 1) + y]) & kLowBits,
            (m ^ lines[x * (kBlock + 1) + y + 1]) & kLowBits, (m ^ (m >> 1)) & kLowBits};
        for (int axis = 0; axis < 3; ++axis)
          for (unsigned bits = crossing[static_cast<std::size_t>(axis)]; bits != 0;
               bits &= bits - 1) {
            const int z = std::countr_zero(bits);
            const std::array<double, 4> lower = corner(b, x, y, z);
            const std::array<double, 4> upper =
                corner(b, x + (axis == 0), y + (axis == 1), z + (axis == 2));
            // One end is inside (>= iso) and the other outside (< iso), so the values differ and
            // mu is in [0, 1].
            const double a = lower[0], mu = (static_cast<double>(iso) - a) / (upper[0] - a);
            Eigen::Vector3d p = (origin + Lattice(x, y, z)).cast<double>() * s;
            p[axis] += mu * s;
            // The normal is -grad c / |grad c| = +sum / |sum| (grad c = -6 / h sum).
            Eigen::Vector3d g;
            for (int k = 0; k < 3; ++k)
              g[k] = lower[static_cast<std::size_t>(k + 1)] +
                     mu * (upper[static_cast<std::size_t>(k + 1)] -
                           lower[static_cast<std::size_t>(k + 1)]);
            const double norm = g.norm();
            const auto id = static_cast<std::int32_t>(surface_.position_.size());
            edgeVertex_[(b * kBlockCorners + static_cast<std::size_t>(cornerSlot(x, y, z))) * 3 +
                        static_cast<std::size_t>(axis)] = id;
            surface_.position_.push_back(p);
            // The sum is ~0.1 on a surface; far below that its direction is single-precision noise.
            const bool usable = norm > 1e-6 && std::isfinite(norm);
            surface_.normal_.push_back(usable ? Eigen::Vector3d(g / norm)
                                              : Eigen::Vector3d::Zero());
            normalFallback_.push_back(usable ? 0 : 1);
            anyFallback_ = anyFallback_ || !usable;
          }
      }
  }
}

// The cubes of the surface blocks, row by row along z: a row whose four lines agree has no
// surface; otherwise the case table's triangles, their vertices looked up in the block owning
// each edge's lower corner.
void SurfaceMesher::march() {
  static const std::array<EdgeStep, 12> steps = edgeSteps();
  const MarchingCubesTable& table = MarchingCubesTable::instance();
  for (const std::uint32_t b : surfaceBlock_) {
    const std::uint16_t* lines = &line_[b * kLines];
    const auto& near = neighbour_[b];
    for (int x = 0; x < kBlock; ++x)
      for (int y = 0; y < kBlock; ++y) {
        const unsigned l0 = lines[x * (kBlock + 1) + y], l1 = lines[(x + 1) * (kBlock + 1) + y];
        const unsigned l2 = lines[x * (kBlock + 1) + y + 1],
                       l3 = lines[(x + 1) * (kBlock + 1) + y + 1];
        // Cube z is all outside when no line has bit z or z + 1, all inside when every line has
        // both: only the other cubes of the row are looked at.
        const unsigned any = l0 | l1 | l2 | l3, all = l0 & l1 & l2 & l3;
        const unsigned uniform = ~(any | (any >> 1)) | (all & (all >> 1));
        for (unsigned mixed = ~uniform & kLowBits; mixed != 0; mixed &= mixed - 1) {
          const int z = std::countr_zero(mixed);
          // Corner k of the cube: line (k & 3) (x + 1 for bit 0, y + 1 for bit 1), z + (k >> 2).
          const auto face = [&](int at) {
            return ((l0 >> at) & 1u) | (((l1 >> at) & 1u) << 1) | (((l2 >> at) & 1u) << 2) |
                   (((l3 >> at) & 1u) << 3);
          };
          const unsigned configuration = face(z) | (face(z + 1) << 4);
          const MarchingCubesCase& c = table[static_cast<int>(configuration)];
          for (int t = 0; t < c.triangleCount; ++t) {
            Eigen::Vector3i triangle;
            for (int v = 0; v < 3; ++v) {
              const EdgeStep& e =
                  steps[static_cast<std::size_t>(c.edges[static_cast<std::size_t>(3 * t + v)])];
              const int px = x + e.dx, py = y + e.dy, pz = z + e.dz;
              const int side = (px >> kShift) | ((py >> kShift) << 1) | ((pz >> kShift) << 2);
              // A crossing edge's lower corner lies in an active block (the support boxes were
              // extended downwards), so the owner exists and has created the vertex.
              const auto owner = static_cast<std::size_t>(near[static_cast<std::size_t>(side)]);
              const int slot = cornerSlot(px & (kBlock - 1), py & (kBlock - 1), pz & (kBlock - 1));
              triangle[v] =
                  edgeVertex_[(owner * kBlockCorners + static_cast<std::size_t>(slot)) * 3 +
                              static_cast<std::size_t>(e.axis)];
            }
            surface_.triangle_.push_back(triangle);
          }
        }
      }
  }
}

// Where the interpolated gradient vanished: the area-weighted normals of the vertex's triangles.
void SurfaceMesher::fallbackNormals() {
  for (const Eigen::Vector3i& t : surface_.triangle_) {
    const Eigen::Vector3d& a = surface_.position_[static_cast<std::size_t>(t[0])];
    const Eigen::Vector3d areaNormal =
        (surface_.position_[static_cast<std::size_t>(t[1])] - a)
            .cross(surface_.position_[static_cast<std::size_t>(t[2])] - a);
    for (int k = 0; k < 3; ++k)
      if (normalFallback_[static_cast<std::size_t>(t[k])])
        surface_.normal_[static_cast<std::size_t>(t[k])] += areaNormal;
  }
  for (std::size_t v = 0; v < surface_.normal_.size(); ++v) {
    if (!normalFallback_[v]) continue;
    const double norm = surface_.normal_[v].norm();
    surface_.normal_[v] =
        norm > 0 ? Eigen::Vector3d(surface_.normal_[v] / norm) : Eigen::Vector3d::UnitY();
  }
}

}  // namespace lacrima::tears
