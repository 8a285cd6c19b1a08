#pragma once
// How far one tear run ends from another (lacrima-bench tears-sweep): what a run leaves behind
// and the errors between two of them, in units of a particle radius so they read as "how many
// drop radii off":
//   particle RMS  positions after the last frame, matched by particle id (ids are assigned in
//                 emission order, so the same commanded counts give the same ids). Drops are
//                 chaotic (where a drop splits, or which way a particle goes round another, flips
//                 with rounding), so this grows with time even between two fine runs;
//   centroid      distance between each eye's mean particle position and the other run's,
//                 averaged over the eyes: how far the tears ran, insensitive to that chaos;
//   surface       symmetric mean distance between the two final tear surfaces' vertices and the
//                 nearest vertex of the other (a Chamfer distance; vertices of a fine reference
//                 are dense enough that this approximates point-to-surface distance), plus the
//                 relative surface area difference.
#include <lacrima/tears/SurfaceMesher.h>

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <map>
#include <vector>

namespace lacrima::bench {

// What a run leaves behind for the comparison.
struct RunResult {
  double msPerFrame = 0;  // mean over frames of the full pipeline
  double substepsPerFrame = 0;
  int threads = 1;              // the simulation's, resolved
  std::uint64_t stateHash = 0;  // tears::stateHash of the final particles (bitwise identity)
  std::map<std::uint64_t, Eigen::Vector3d> particles;  // by id
  std::array<Eigen::Vector3d, 2> centroid{Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
  std::vector<Eigen::Vector3d> surfaceVertices;
  double surfaceArea = 0;
};

// Copies the final surface's vertices and sums its area.
void captureSurface(const tears::TearSurface& surface, RunResult& out);

struct RunErrors {
  double particleRms = 0, centroid = 0, surface = 0, areaDifference = 0;  // radii; area: ratio
  int matched = 0;  // particles found in both runs
};

// `run` against `reference`; `radius` is the unit, `cell` the nearest-vertex grid's cell edge.
// The surface error is NaN when either run has no surface.
RunErrors errorsBetween(const RunResult& run, const RunResult& reference, double radius,
                        double cell);

}  // namespace lacrima::bench
