#pragma once
// Real-time tears on a deforming face: SPH (Müller et al. 2003) with skin adhesion and friction
// (the 2009 thesis), collision with the skin through ODE contact queries, emission driven by the
// absolute particle counts of FAP 69 (left eye) and 70 (right eye).
//
// Per frame the caller passes the deformed head positions, the two tear counts and the frame's
// duration; the simulation sub-steps adaptively (AdaptiveTimeStep.h) and exposes the particles,
// the kernel radius and the neighbour grid for the surface mesher and trail builder, which live
// in another layer. With both counts at zero and no particles left, step() does no work at all:
// no skin update, no ODE query, no neighbour search (see counters()).
//
// Pressure: the weakly compressible equation of state (WCSPH, the default) or DFSPH, chosen in
// SimulationOptions. Measured with lacrima-bench tears and tears-sweep on the sheet and the
// default head, DFSPH is not faster here: surface tension at this resolution, not the speed of
// sound alone, bounds its sub-steps (about as many as WCSPH's at twice the cost each), and its
// incompressible drops cling harder (adhesion grows as density falls), so they run a different
// course. It stays as an option, tested in every hard case.
//
// Deterministic: the same inputs give bitwise-identical particle states on the same build
// (single thread, ordered containers only, no time-based seeds).
//
// Checkpoints (TearCheckpoint.h): checkpoint() saves everything that shapes the future,
// restore() puts it back.
//
// The solver's parts (neighbour search, density, pressure, viscosity, surface tension, skin
// contact and collision, emission, time step) are internal to the library: this header names
// them only through a pointer, so its users compile against the public headers alone.
#include <lacrima/common/FapChannels.h>
#include <lacrima/common/HeadMesh.h>
#include <lacrima/tears/ParticleSet.h>
#include <lacrima/tears/SimulationOptions.h>
#include <lacrima/tears/TearCheckpoint.h>
#include <lacrima/tears/TearCounters.h>
#include <lacrima/tears/TearSettings.h>
#include <lacrima/tears/UniformGrid.h>

#include <Eigen/Geometry>

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

namespace lacrima::tears {

struct EmissionSite;
class ParallelChunks;

// What TearSimulation::forHead takes from the head besides its skin.
struct HeadTearOptions {
  std::optional<Eigen::Vector3d> leftSource,
      rightSource;  // head frame, e.g. the rig's tear sources
  bool eyesCollide = true;
};

// A point of the collision surface (the skin, and the eyes for forHead simulations).
struct SkinPoint {
  int triangle = -1;  // -1: nothing within the radius asked
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();  // the triangle's, unit, outward
  double distance = 0;                               // from the query point
  bool found() const { return triangle >= 0; }
};

struct EyeWetness {
  int count = 0;           // particles of this eye now
  double trailVolume = 0;  // water left on the skin so far (trail + dried tears), head units^3
  double skin = 0;         // 1 - exp(-trailVolume / reference volume), for the wet-skin blend
  double eye = 0;          // min(1, count / reference count), for the watery-eye blend
};

class TearSimulation {
 public:
  // `restPositions`: all head vertices (3 x n); `skinTriangles`: the skin's triangles by global
  // vertex index (counter-clockwise outside). Every later frame passes positions of the same size.
  TearSimulation(const Eigen::Matrix3Xf& restPositions,
                 const std::vector<Eigen::Vector3i>& skinTriangles,
                 const TearSettings& settings = {}, const SimulationOptions& options = {});
  // A simulation on a head's "skin" sub-mesh. The collision surface is the skin followed by the
  // eyeballs and corneas (eye_l, eye_r, cornea_l, cornea_r, when present and eyesCollide), which
  // close the eye openings of the skin; contact triangles past the skin's are eyes (the trail
  // builder, given the skin alone, ignores them). Sources: those given, else defaultTearSource.
  static std::unique_ptr<TearSimulation> forHead(const HeadMesh& head,
                                                 const TearSettings& settings = {},
                                                 const SimulationOptions& options = {},
                                                 const HeadTearOptions& headOptions = {});
  // Where forHead puts an eye's source when none is given: the skin vertex nearest to a point
  // 1.1 eyeball radii from the eyeball's centre, 25 degrees below straight ahead (the lower lid
  // margin of a typical head; on the default head it is the very vertex the rig's rule, lid
  // mid-point minus IRISD0 / 4, picks). Without the eye's sub-mesh: the box rule of the
  // constructor.
  static Eigen::Vector3d defaultTearSource(const HeadMesh& head, Eye eye);
  ~TearSimulation();
  TearSimulation(const TearSimulation&) = delete;
  TearSimulation& operator=(const TearSimulation&) = delete;

  // Tear source of an eye in the head frame. Particles appear on the skin nearest to it.
  void setSource(Eye eye, const Eigen::Vector3d& point);
  const Eigen::Vector3d& source(Eye eye) const { return sources_[static_cast<std::size_t>(eye)]; }

  // The closest point of the collision surface, as of the last frame, within `radius` of x, on
  // the outer side of its triangle (the one query the emitter and contacts use).
  SkinPoint nearestSkinPoint(const Eigen::Vector3d& x, double radius);

  // Advances one frame of duration dt (seconds) with the skin at `positions`.
  void step(const Eigen::Matrix3Xf& positions, int leftCount, int rightCount, double dt);
  // Same, reading the counts from FAP 69 and 70 (negative and fractional values: 0 and floor).
  void step(const Eigen::Matrix3Xf& positions, const FapValues& channels, double dt);

  // The particles. Their order is not stable between frames: the solver keeps them sorted by
  // grid cell for memory locality (follow a particle by its id).
  const ParticleSet& particles() const { return particles_; }
  int count(Eye eye) const;
  double kernelRadius() const { return params_.h; }
  double particleRadius() const { return params_.particleRadius; }
  const ScaledParameters& parameters() const { return params_; }
  const TearSettings& settings() const { return settings_; }
  const SimulationOptions& options() const { return options_; }
  // Threads the sub-steps share: options().threads resolved (SimulationOptions.h).
  int threads() const;
  const UnitScale& scale() const { return scale_; }
  Eigen::Vector3d gravity() const { return {0, -params_.gravity, 0}; }
  // Particles leaving this box are recycled.
  const Eigen::AlignedBox3d& box() const { return box_; }

  // The neighbour grid (cell edge = kernelRadius()) of the current particle positions, built on
  // first use after each frame; its occupiedCells() are where the colour field is non-zero.
  const UniformGrid& grid() const;

  EyeWetness wetness(Eye eye) const;

  // Saves the state between two step() calls; restore() returns this simulation to it. The
  // checkpoint must come from this object (std::invalid_argument otherwise, and for an empty
  // one). Counters and stage times are tallies of work done and are not rolled back.
  TearCheckpoint checkpoint() const;
  void restore(const TearCheckpoint& checkpoint);

  const TearCounters& counters() const { return counters_; }
  const StageTimes& lastFrameTimes() const { return times_; }

 private:
  // The surface mesher borrows the sub-steps' threads between frames (only on the thread that
  // steps this simulation, never during step()) and counts its runs in counters().
  friend class SurfaceMesher;
  ParallelChunks& parallelChunks();
  void countSurfaceRun() { ++counters_.surfaceRuns; }

  struct Internals;      // the solver's parts (TearSimulationInternals.h)
  struct EmissionSites;  // where each eye emits in this frame, found on first need

  void simulate(double dt);
  void updateSkin(const Eigen::Matrix3Xf& positions);
  EmissionSite siteFor(Eye eye);
  void recycleEscaped(EmissionSites& sites);

  std::uint64_t instance_;  // tells this simulation's checkpoints from others'
  TearSettings settings_;
  SimulationOptions options_;
  UnitScale scale_;
  ScaledParameters params_;

  std::vector<int> skinVertices_;  // head vertex of each skin vertex
  Eigen::Matrix3Xd skinPositions_;
  std::vector<Eigen::Vector3i> skinTriangles_;  // in skin vertex indices
  bool skinStale_ = true;  // the collider's surface is older than the last frame seen

  ParticleSet particles_;
  std::unique_ptr<Internals> internals_;
  mutable UniformGrid exposedGrid_;
  mutable bool exposedGridStale_ = true;

  std::array<Eigen::Vector3d, 2> sources_;
  Eigen::AlignedBox3d box_;
  std::array<double, 2> trailVolume_{0, 0};
  TearCounters counters_;
  StageTimes times_;
};

}  // namespace lacrima::tears
