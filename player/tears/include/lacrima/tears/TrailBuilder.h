#pragma once
// Wet trails behind sliding drops (thesis 4.3.2, "fluid trail synthesis").
//
// Every update the drops are found (DropFinder.h) and matched to last update's drops by their
// particles' ids (a drop continues the track most of its particles belonged to). For a tracked
// drop touching the skin:
//   * its centre is projected on the skin; the direction of motion t is the tangential part of
//     the centre's displacement since the last update, both points evaluated on the CURRENT
//     skin, so skin motion is not mistaken for sliding;
//   * across the motion, a = n x t (n: skin normal), the drop's left and right boundaries are
//     its extreme particles along a (plus a particle radius), or the edges of the footprint of a
//     drop of its volume (DropFootprint.h) where that is wider, projected on the skin; the middle
//     point is the centre raised along n by min(h, middleHeightFraction x the drop's height);
//   * once the centre is more than d_min from the last cross-section's centre, a new section
//     (left, middle, right) is stored and joined to the last one by four triangles
//       (L0, M0, M1), (L0, M1, L1), (M0, R0, R1), (M0, R1, M1),
//     wound counter-clockwise seen from outside the skin.
// Sharp turns: where the inner boundary point would land behind the last cross-section (along
// the new direction), the strip would fold over itself; the inner side then keeps the last
// section's point (the segment fans out around it), and any triangle left without area or
// facing into the skin is not drawn.
// A drop in the air (no particle touching the skin, as one falling off the chin) wets nothing
// and ends its track: where it lands, a new trail starts.
// A drop that splits hands its last section to every part, so the trail branches from it; drops
// that merge continue the track of the larger share. In the update of a split or merge the
// centre jumps without the fluid having moved there, so that update neither changes the
// direction nor adds a section; the next one does, from the shared section. Trail points are skin
// anchors (TrailSkin.h) and the mesh is rebuilt from the current skin every update.
//
// Drying: a section's alpha falls linearly from 1 to 0 over drySeconds; a segment is dropped
// when its newer section is dry, a section when nothing refers to it. At most maxSections
// sections are kept (the oldest segments go first), so memory is bounded by the settings.
#include <lacrima/tears/DropFinder.h>
#include <lacrima/tears/Scratch.h>
#include <lacrima/tears/TrailSkin.h>

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace lacrima::tears {

class TearSimulation;

struct TrailSettings {
  double minimumStepKernels = 0.5;    // d_min in kernel radii
  double middleHeightFraction = 0.5;  // of the drop's height over the skin (capped at h)
  double drySeconds = 10;
  double contactAngleDegrees = 70;  // water on skin: the drop's footprint (DropFootprint.h)
  int maxSections = 4096;           // 3 trail points each
};

struct TrailSection {
  std::array<SkinAnchor, 3> point;  // left, middle (raised), right
  double age = 0;                   // seconds
  Eye eye = Eye::Left;
};

struct TrailSegment {
  int from = 0, to = 0;  // sections, `to` the newer
};

// The trail mesh: three vertices per section, four triangles per segment. Buffers keep their
// capacity between updates.
class TrailMesh {
 public:
  int vertexCount() const { return static_cast<int>(position_.size()); }
  int triangleCount() const { return static_cast<int>(triangle_.size()); }
  bool empty() const { return triangle_.empty(); }
  Eigen::Map<const Eigen::Matrix3Xd> positions() const {
    return {position_.empty() ? nullptr : position_.front().data(), 3, vertexCount()};
  }
  Eigen::Map<const Eigen::Matrix3Xd> normals() const {  // the skin's, outward
    return {normal_.empty() ? nullptr : normal_.front().data(), 3, vertexCount()};
  }
  Eigen::Map<const Eigen::VectorXd> alpha() const {  // 1 wet .. 0 dry
    return {alpha_.empty() ? nullptr : alpha_.data(), vertexCount()};
  }
  Eigen::Map<const Eigen::Matrix3Xi> triangles() const {
    return {triangle_.empty() ? nullptr : triangle_.front().data(), 3, triangleCount()};
  }
  std::size_t bytes() const;  // held by a copy (the buffers' sizes, not their capacities)

 private:
  friend class TrailBuilder;
  std::vector<Eigen::Vector3d> position_, normal_;
  std::vector<double> alpha_;
  std::vector<Eigen::Vector3i> triangle_;
};

class TrailBuilder {
 public:
  // `skinTriangles`: the skin's triangles by head vertex index, the same list (and order) the
  // simulation was built with, so particle contact triangles index into it. The simulation may
  // collide with more (TearSimulation::forHead appends the eyes): contacts past this list are
  // not on the skin and leave no trail.
  //
  // A TrailBuilder is a plain value: a copy continues exactly as the original would (keep one
  // beside a TearCheckpoint to seek).
  explicit TrailBuilder(std::vector<Eigen::Vector3i> skinTriangles,
                        const TrailSettings& settings = {});

  // One update after the simulation's step, with the head positions of that step and the
  // frame's duration (drying). No work at all when there are neither particles nor trails.
  const TrailMesh& update(const TearSimulation& simulation, const Eigen::Matrix3Xf& headPositions,
                          double dt);
  // Same for any particle set: `grid` built over its positions with cell edge h.
  const TrailMesh& update(const ParticleSet& particles, const UniformGrid& grid, double h,
                          double particleRadius, const Eigen::Matrix3Xf& headPositions, double dt);

  const TrailMesh& mesh() const { return mesh_; }
  std::span<const TrailSection> sections() const { return sections_; }
  std::span<const TrailSegment> segments() const { return segments_; }
  // Wet trail area per eye, sum over triangles of area x mean alpha (head units^2): a measure
  // for the wet-skin texture blend.
  double wetArea(Eye eye) const { return wetArea_[static_cast<std::size_t>(eye)]; }
  long long branches() const { return branches_; }  // splits seen so far
  int trackedDrops() const { return static_cast<int>(tracks_.size()); }
  double lastMilliseconds() const { return milliseconds_; }
  // Memory a copy holds (what a checkpoint kept beside the simulation costs).
  std::size_t bytes() const;

 private:
  struct Track {
    SkinAnchor centre;                   // last centre on the skin (triangle -1: never touched)
    Eigen::Vector3d direction{0, 0, 0};  // last tangential direction of motion (unit or zero)
    int lastSection = -1;
  };
  void advance(const ParticleSet& particles, const UniformGrid& grid, double h,
               double particleRadius);
  void findPreviousTracks(const ParticleSet& particles);
  // `reshaped`: the drop split off or merged this update, so its centre jumped.
  void continueTrack(Track& track, const ParticleSet& particles, const FoundDrop& drop, double h,
                     double particleRadius, bool reshaped);
  void dryAndCap();
  void rebuildMesh();

  TrailSkin skin_;
  TrailSettings settings_;
  std::vector<TrailSection> sections_;
  std::vector<TrailSegment> segments_;
  std::vector<Track> tracks_;
  std::vector<std::pair<std::uint64_t, int>> owner_;  // particle id -> track, sorted by id
  // Working buffers of an update, kept for their capacity; a copy kept beside a checkpoint does
  // not take them (Scratch.h).
  struct Buffers {
    DropFinder finder;
    std::vector<Track> nextTracks;
    // Per particle of the finder's list (k): (id, k) sorted by id, the drop of k and the track
    // that owned it before.
    std::vector<std::pair<std::uint64_t, int>> byId;
    std::vector<int> dropOf, previousTrack;
    std::vector<std::pair<int, int>> votes;
    std::vector<int> seeds, remap, predecessorUse, predecessor, sources, heirsSeen;
    std::vector<std::uint8_t> referenced;
  };
  Scratch<Buffers> work_;
  TrailMesh mesh_;
  UniformGrid emptyGrid_;  // passed on when the simulation has no particles (its grid is not built)
  std::array<double, 2> wetArea_{0, 0};
  long long branches_ = 0;
  double milliseconds_ = 0;
};

}  // namespace lacrima::tears
