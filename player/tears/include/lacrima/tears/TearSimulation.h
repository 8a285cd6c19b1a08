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
// Pressure: the weakly compressible equation of state (WCSPH, the default) or DFSPH
// (DivergenceFreeSolver.h), chosen in SimulationOptions. Measured with lacrima-bench tears and
// tears-sweep on the sheet and the default head, DFSPH is not faster here: surface tension at
// this resolution, not the speed of sound alone, bounds its sub-steps (about as many as WCSPH's
// at twice the cost each), and its incompressible drops cling harder (adhesion grows as density
// falls), so they run a different course. It stays as an option, tested in every hard case.
//
// Deterministic: the same inputs give bitwise-identical particle states on the same build
// (single thread, ordered containers only, no time-based seeds).
//
// Checkpoints: checkpoint() copies everything that shapes the future (particles with their
// contacts, the Verlet pair list and hence the particle order, the emitter's next id, the skin
// the collider holds, sources, box, trail volumes); restore() puts it back, after which the same
// inputs give the same particles, bit for bit, as the run that took the checkpoint. The copy is
// plain vectors (about 0.2 KB per particle plus the skin), so a player can keep one per second
// of animation and seek by restoring the nearest and stepping forward.
#include <lacrima/common/FapChannels.h>
#include <lacrima/common/HeadMesh.h>
#include <lacrima/tears/AdaptiveTimeStep.h>
#include <lacrima/tears/Emitter.h>
#include <lacrima/tears/CellIndex.h>
#include <lacrima/tears/DivergenceFreeSolver.h>
#include <lacrima/tears/FluidForces.h>
#include <lacrima/tears/Octree.h>
#include <lacrima/tears/PairList.h>
#include <lacrima/tears/Parameters.h>
#include <lacrima/tears/ParticleSet.h>
#include <lacrima/tears/SkinContact.h>
#include <lacrima/tears/UniformGrid.h>

#include <Eigen/Geometry>

#include <array>
#include <memory>
#include <optional>
#include <vector>

namespace lacrima::tears {

class SkinCollider;
class TearSimulation;

// A saved state of one TearSimulation (see the header comment). Copyable and cheap to copy (the
// state is shared and immutable); empty() until assigned from TearSimulation::checkpoint().
class TearCheckpoint {
public:
  TearCheckpoint();
  ~TearCheckpoint();
  TearCheckpoint(const TearCheckpoint&);
  TearCheckpoint& operator=(const TearCheckpoint&);
  TearCheckpoint(TearCheckpoint&&) noexcept;
  TearCheckpoint& operator=(TearCheckpoint&&) noexcept;

  bool empty() const { return !state_; }
  int particleCount() const;
  std::size_t bytes() const;  // memory held by the saved state

private:
  friend class TearSimulation;
  struct State;
  std::shared_ptr<const State> state_;
};

// How pressure keeps the fluid from compressing: the weakly compressible equation of state of
// Müller 2003 (sub-steps bound by the speed of sound), or DFSPH (DivergenceFreeSolver.h: two
// iterative solves per sub-step, sub-steps bound by relative motion and by the net fluid
// acceleration of the previous sub-step).
enum class PressureSolver { Wcsph, Dfsph };

struct SimulationOptions {
  // Height of the head in its own units, which fixes the unit scale (Parameters.h); 0 = the
  // height of the skin mesh. Set it when the skin is not a whole head (test sheets).
  double headHeight = 0;
  NeighbourMethod neighbours = NeighbourMethod::Grid;  // measured faster (lacrima-bench tears)
  // Verlet skin in kernel radii: pair candidates are listed within h (1 + skin) and reused
  // until the two largest displacements sum to skin h (PairList.h). 0 = search every sub-step.
  double neighbourSkin = 0.3;
  SurfaceTensionModel surfaceTension = SurfaceTensionModel::Mueller;
  bool clampNegativePressure = true;
  double lambdaCfl = 0.4, lambdaAcceleration = 0.4, lambdaViscosity = 1.0;
  PressureSolver pressureSolver = PressureSolver::Wcsph;
  // DFSPH: mean compression left after a step at the table's default pressure (0.004); the
  // pressure parameter scales it inversely (pressure x10 = ten times tighter), within
  // [1e-4, 0.1]. The divergence solve uses the same tolerance per step.
  double dfsphTolerance = 0.01;
  int dfsphMaxIterations = 50;
  // Longest sub-step allowed, seconds (0 = only the stability limits bound it). DFSPH has no
  // sound-speed limit, so this caps how far the fluid moves between collision passes.
  double maxSubstepSeconds = 0;
  // Sub-steps per frame before the last resort (clamping, counted in TearCounters::clamped).
  int maxSubsteps = 500;
  // Free particles look for the skin this far (kernel radii) and then skip the query until
  // they have travelled the clearance found (SkinCollider.h): farther means fewer, dearer queries.
  double collisionProbeKernels = 1;
  double trailDecayMetres = 0.1;     // mass e-folds every 10 cm slid over the skin
  double massFloor = 0.2;            // of the emitted mass
  double boxMarginMetres = 0.03;     // simulation box = skin bounds grown by this
  double wetnessReferenceParticles = 100;  // volume/count at which wetness approaches 1
};

struct TearCounters {
  long long frames = 0;             // step() calls
  long long sphSteps = 0;           // frames in which the fluid was simulated
  long long substeps = 0;
  long long clamped = 0;            // particle accelerations/velocities clamped (last resort)
  long long substepCapHits = 0;     // sub-steps that wanted to be shorter than the cap allows
  long long divergenceIterations = 0, densityIterations = 0;  // DFSPH Jacobi sweeps
  long long solverCapped = 0;       // DFSPH solves stopped at the iteration cap
  // Which limit set each sub-step (AdaptiveTimeStep.h); the rest ended the frame.
  long long cflLimited = 0, accelerationLimited = 0, viscosityLimited = 0;
  long long recycled = 0;           // left the box, re-emitted at their source
  long long spawned = 0, removed = 0;
  long long neighbourSearches = 0;  // pair-list builds (reused between them, PairList.h)
  long long straySubsteps = 0, strays = 0;  // sub-steps that kept the list with strays; their strays
  long long trimeshUpdates = 0, odeQueries = 0, sweptParticles = 0, contactsTracked = 0;
  long long bruteForceQueries = 0;  // nearest-skin queries ODE could not answer in full (scanned)
  long long surfaceRuns = 0;        // incremented by the surface mesher via countSurfaceRun()
};

// Milliseconds spent per stage in the last frame.
struct StageTimes {
  double neighbours = 0, density = 0, forces = 0, collision = 0, emission = 0;
};

// What TearSimulation::forHead takes from the head besides its skin.
struct HeadTearOptions {
  std::optional<Eigen::Vector3d> leftSource, rightSource;  // head frame, e.g. the rig's tear sources
  bool eyesCollide = true;
};

// A point of the collision surface (the skin, and the eyes for forHead simulations).
struct SkinPoint {
  int triangle = -1;                                 // -1: nothing within the radius asked
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();  // the triangle's, unit, outward
  double distance = 0;                               // from the query point
  bool found() const { return triangle >= 0; }
};

struct EyeWetness {
  int count = 0;              // particles of this eye now
  double trailVolume = 0;     // water left on the skin so far (trail + dried tears), head units^3
  double skin = 0;            // 1 - exp(-trailVolume / reference volume), for the wet-skin blend
  double eye = 0;             // min(1, count / reference count), for the watery-eye blend
};

class TearSimulation {
public:
  // `restPositions`: all head vertices (3 x n); `skinTriangles`: the skin's triangles by global
  // vertex index (counter-clockwise outside). Every later frame passes positions of the same size.
  TearSimulation(const Eigen::Matrix3Xf& restPositions, const std::vector<Eigen::Vector3i>& skinTriangles,
                 const TearSettings& settings = {}, const SimulationOptions& options = {});
  // A simulation on a head's "skin" sub-mesh. The collision surface is the skin followed by the
  // eyeballs and corneas (eye_l, eye_r, cornea_l, cornea_r, when present and eyesCollide), which
  // close the eye openings of the skin; contact triangles past the skin's are eyes (the trail
  // builder, given the skin alone, ignores them). Sources: those given, else defaultTearSource.
  static std::unique_ptr<TearSimulation> forHead(const HeadMesh& head, const TearSettings& settings = {},
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
  void countSurfaceRun() { ++counters_.surfaceRuns; }

private:
  void simulate(double dt);
  void updateSkin(const Eigen::Matrix3Xf& positions);
  EmissionSite siteFor(Eye eye);
  void recycleEscaped(std::array<EmissionSite, 2>& sites, std::array<bool, 2>& siteKnown);
  void updatePairs();

  std::uint64_t instance_;  // tells this simulation's checkpoints from others'
  TearSettings settings_;
  SimulationOptions options_;
  UnitScale scale_;
  ScaledParameters params_;

  std::vector<int> skinVertices_;  // head vertex of each skin vertex
  Eigen::Matrix3Xd skinPositions_;
  std::vector<Eigen::Vector3i> skinTriangles_;  // in skin vertex indices
  std::unique_ptr<SkinCollider> collider_;
  bool skinStale_ = true;  // the collider's surface is older than the last frame seen

  ParticleSet particles_;
  CellIndex cellIndex_;       // cell edge h (1 + skin), orders the particles
  VerletPairs candidates_;
  ActivePairs pairs_;
  NeighbourList fullList_;    // octree comparison path only
  Octree octree_;
  mutable UniformGrid exposedGrid_;
  mutable bool exposedGridStale_ = true;

  DensitySolver density_;
  PressureForce pressure_;
  ViscosityForce viscosity_;
  MuellerSurfaceTension mueller_;
  AkinciSurfaceTension akinci_;
  FluidForcePass forcePass_;
  SkinContactForces contact_;
  TrailMassLoss massLoss_;
  Emitter emitter_;
  AdaptiveTimeStep stepper_;
  DivergenceFreeSolver dfsph_;
  double lastSubstep_ = 0;  // DFSPH: the divergence solve's expected step (0: none yet)
  double lastNetAcceleration_ = -1;  // DFSPH: of the last sub-step (-1: none yet)

  std::array<Eigen::Vector3d, 2> sources_;
  Eigen::AlignedBox3d box_;
  std::array<double, 2> trailVolume_{0, 0};
  TearCounters counters_;
  StageTimes times_;
  std::vector<Eigen::Vector3d> previous_, contactNormal_;
  std::array<std::vector<int>, 2> escaped_;  // per eye, this sub-step (scratch)
};

}  // namespace lacrima::tears
