#pragma once
// The tear's surface: marching cubes (Lorensen & Cline 1987) over the SPH colour field
// (SurfaceMesherField.h) at the iso value of the tear parameters (thesis 4.3.1).
//
// Where the cubes are. The lattice of edge s = cube_size is global (cube k spans [k s, (k + 1) s]
// on each axis). The colour field is zero farther than h from every particle, so a lattice
// corner has c > 0 only inside some particle's support box (the corners within h of it), and
// only a cube with such a corner can hold the surface. The lattice is cut into BLOCKS of
// 4 x 4 x 4 cubes (kBlock in the source); the active blocks are those meeting a support box
// extended by one corner downwards (so every cube with a corner c > 0 has its lowest corner in an
// active block). Blocks are found through an open-addressing map of their integer coordinates, a
// few lookups per particle; everything inside a block is a dense array.
//
// Cost: one density pass (SurfaceMesherField), then each particle adds its weight to the dense
// corner arrays of its blocks: value and gradient, four floats as one SSE register (Float4.h),
// scaled to kernel units so single precision keeps ~7 digits for any h. The inside bits
// (c >= iso) are packed per block as one 5-bit mask per (x, y) line along z (the fifth bit and
// line from the +x, +y, +z neighbours), so a row of 4 cubes is skipped with one test when its four
// lines agree, and the crossing edges are the set bits of XORs of masks. Buffers keep their
// capacity between frames (nothing is allocated for a steady drop).
//
// Watertight: a vertex is created once per crossing lattice edge, stored in the block of the
// edge's lower corner (block-local table, written before any cube reads it), so neighbouring
// cubes and blocks share it, and the case table resolves ambiguous faces by the face's signs
// alone (MarchingCubesTable.h). For a drop away from the rim every mesh edge has exactly two
// triangles, wound counter-clockwise seen from outside.
//
// Vertices: linear interpolation on the crossing edge, p = p1 + (iso - c1) / (c2 - c1) (p2 - p1)
// (thesis eq. 4.11). Normals: n = -g / |g| with g the analytic poly6 gradient of c at the two
// corners, interpolated the same way (c decreases outwards). Against the exact gradient at the
// vertex: 1.9 degrees mean, 8 worst at the default cube h / 2 on a 500-particle ball, for a
// fraction of the cost of evaluating it there. Where the gradient vanishes: the area-weighted
// triangle normals.
//
// update() can leave particles out (`skip`): the small drops on the skin, which DropCaps.h draws
// as spherical caps. Meshed alone, a drop of a few particles is a bead about 1 mm across with a
// silhouette all round, and a stream of them reads as a string of glass spheres.
//
// Threads: update() borrows the simulation's (TearSimulation::parallelChunks). The colour
// field's density pass is shared in fixed chunks of cells, and the splat in slabs of the lattice
// along y, each adding its particles' shares, in particle order, to its own corners only: every
// corner gets the same additions in the same order for any slab count, so the surface is
// bit-identical for any thread count. Finding the blocks, the inside bits, the vertices and the
// cubes (a fifth of the time at 10,000 particles) stay on the calling thread.
//
// The work is capped (SurfaceMesherSettings::maxCubes, counted as the cubes of the active
// blocks): past the cap the cube size is enlarged until they fit, and stats().capped reports it —
// a coarser surface, never a truncated one with holes.
#include <lacrima/tears/UniformGrid.h>

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

namespace lacrima::tears {

class ParallelChunks;
class ParticleSet;
class SurfaceMesherField;
class TearSimulation;
namespace detail {
class SurfaceMesherKeyMap;
}

struct SurfaceMesherSettings {
  double kernelRadius = 0;  // h, head units
  double cubeSize = 0;      // s, head units (ScaledParameters::cubeSize)
  double iso = 0.5;         // colour-field level (ScaledParameters::iso)
  std::size_t maxCubes = std::size_t{1} << 19;
};

// The extracted mesh. Buffers keep their capacity between frames; the accessors view them as
// Eigen matrices (one column per vertex / triangle).
class TearSurface {
 public:
  int vertexCount() const { return static_cast<int>(position_.size()); }
  int triangleCount() const { return static_cast<int>(triangle_.size()); }
  bool empty() const { return triangle_.empty(); }
  Eigen::Map<const Eigen::Matrix3Xd> positions() const {
    return {position_.empty() ? nullptr : position_.front().data(), 3, vertexCount()};
  }
  Eigen::Map<const Eigen::Matrix3Xd> normals() const {
    return {normal_.empty() ? nullptr : normal_.front().data(), 3, vertexCount()};
  }
  // Vertex indices, counter-clockwise seen from outside the fluid.
  Eigen::Map<const Eigen::Matrix3Xi> triangles() const {
    return {triangle_.empty() ? nullptr : triangle_.front().data(), 3, triangleCount()};
  }
  void clear() {
    position_.clear();
    normal_.clear();
    triangle_.clear();
  }

 private:
  friend class SurfaceMesher;
  friend class DropCaps;
  std::vector<Eigen::Vector3d> position_, normal_;
  std::vector<Eigen::Vector3i> triangle_;
};

struct SurfaceMesherStats {
  std::size_t activeCells = 0;         // grid cells (edge h) holding particles
  std::size_t blocks = 0;              // active blocks of 4^3 cubes
  std::size_t cubes = 0, corners = 0;  // in the active blocks (cubes whose lowest corner is in one)
  double cubeSize = 0;                 // the size used (larger than asked when capped)
  std::size_t slabs = 0;               // y slabs the corner sums were shared in (1: not shared)
  bool capped = false;
  double milliseconds = 0;  // of the last build / update
};

class SurfaceMesher {
 public:
  SurfaceMesher();
  ~SurfaceMesher();
  SurfaceMesher(const SurfaceMesher&) = delete;
  SurfaceMesher& operator=(const SurfaceMesher&) = delete;

  // Meshes the simulation's particles with its kernel radius, cube size and iso value (already
  // in head units, TearSettings.h). Does nothing (and leaves an empty surface) when there are no
  // particles; otherwise counts a surface run on the simulation. `maxCubes` bounds the work.
  // `skip`: empty, or one flag per particle; a non-zero flag leaves that particle out.
  const TearSurface& update(TearSimulation& simulation,
                            std::size_t maxCubes = SurfaceMesherSettings{}.maxCubes,
                            std::span<const std::uint8_t> skip = {});

  // Meshes any particle set; `grid` must be built over `positions` with cell edge
  // settings.kernelRadius. Throws std::invalid_argument for non-positive or non-finite settings.
  const TearSurface& build(std::span<const Eigen::Vector3d> positions,
                           std::span<const double> masses, const UniformGrid& grid,
                           const SurfaceMesherSettings& settings);

  const TearSurface& surface() const { return surface_; }
  const SurfaceMesherStats& stats() const { return stats_; }
  // The colour field of the last build (valid while its particles and grid are unchanged).
  const SurfaceMesherField& field() const { return *field_; }
  long long cappedBuilds() const { return cappedBuilds_; }

 private:
  std::span<const double> meshedMasses(const ParticleSet& particles,
                                       std::span<const std::uint8_t> skip);

  struct AxisPoint {
    int block;  // relative to the support's lowest block
    int local;  // block-local coordinate
  };
  using Lattice = Eigen::Matrix<std::int64_t, 3, 1>;

  // Per slab of the splat: its particles (sorted order), the blocks of one support box, and the
  // box's points per axis with their offsets (lattice - x) / h.
  struct SplatScratch {
    std::vector<std::uint32_t> particles;
    std::vector<std::int32_t> blocks;
    std::vector<AxisPoint> axis;
    std::vector<float> offset;
  };

  bool collectBlocks(double s, std::size_t maxBlocks);
  void linkBlocks();
  const TearSurface& mesh(std::span<const Eigen::Vector3d> positions,
                          std::span<const double> masses, const UniformGrid& grid,
                          const SurfaceMesherSettings& settings, ParallelChunks* parallel);
  void splat(double s, double lowY, double highY, ParallelChunks* parallel);
  std::size_t cutSlabs(double s, double lowY, double highY, const ParallelChunks* parallel);
  void splatSlab(double s, std::int64_t yFrom, std::int64_t yTo, SplatScratch& scratch);
  void classify(float iso);
  void createVertices(double s, float iso);
  void march();
  void fallbackNormals();
  std::int32_t blockAt(const Lattice& block) const;

  std::unique_ptr<SurfaceMesherField> field_;
  TearSurface surface_;
  SurfaceMesherStats stats_;
  long long cappedBuilds_ = 0;
  std::vector<double> meshedMass_;

  std::unique_ptr<detail::SurfaceMesherKeyMap> blockMap_;
  Lattice blockBase_;           // block keys are packed relative to this
  std::vector<Lattice> block_;  // block coordinates (lattice point / 4)
  std::vector<std::array<std::int32_t, 8>>
      neighbour_;  // block + (i & 1, (i >> 1) & 1, i >> 2), -1 = none
  // Per block 4 x 64 floats, corner (x * 4 + y) * 4 + z: the sums of a d^3, then of a d^2 e_x,
  // a d^2 e_y, a d^2 e_z (d = 1 - r^2/h^2, e = (corner - x) / h, a = V w h^6).
  std::vector<float> sum_;
  std::vector<std::uint8_t> inside_;         // 16 per block: bit z of line (x, y)
  std::vector<std::uint16_t> line_;          // 25 per block: 5-bit masks of lines x, y = 0..4
  std::vector<std::uint32_t> surfaceBlock_;  // blocks whose lines are neither all out nor all in
  std::vector<std::int32_t> edgeVertex_;     // 3 per corner (axis); valid on crossing edges only
  std::vector<std::int64_t> slabBound_;      // lattice y where each slab starts, then the end
  std::vector<double> heightSample_;         // scratch: the heights the slabs are cut at
  std::vector<SplatScratch> splatScratch_;   // one per slab
  std::vector<std::uint8_t> normalFallback_;
  bool anyFallback_ = false;
};

}  // namespace lacrima::tears
