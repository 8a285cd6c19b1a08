#pragma once
// How a TearSimulation computes, as opposed to what it simulates (the tear parameters,
// TearSettings.h): the neighbour structure, the pressure and surface-tension methods (keys of
// their registries, with the methods' own parameters: TearMethods.h), the sub-step limits and
// the bookkeeping scales. The defaults are the measured best (lacrima-bench tears and
// tears-sweep).
#include <lacrima/tears/TearMethods.h>

#include <algorithm>

namespace lacrima::tears {

// Who answers the collider's skin queries (which triangle a particle touches, which one its path
// crosses): a uniform grid over the skin's triangles, which every thread may ask at once, or
// ODE's trimesh collision, the reference the grid is tested against, which Debian's ODE lets
// only one thread ask at a time (docs/decisions/0017).
enum class SkinQueryMethod { Grid, Ode };

// How the sub-steps' loops are cut for threads by default: chunks of 1,024 particles, shared from
// 2,500 particles on (measured: ParallelChunks.h).
inline constexpr int kDefaultChunkParticles = 1024;
inline constexpr int kDefaultShareFromParticles = 2500;

struct SimulationOptions {
  // Height of the head in its own units, which fixes the unit scale (TearSettings.h); 0 = the
  // height of the skin mesh. Set it when the skin is not a whole head (test sheets).
  double headHeight = 0;
  // Where pair candidates come from: "grid" (Verlet lists over the cell sort) was measured
  // faster than "octree", the 2009 thesis's (lacrima-bench tears).
  MethodChoice neighbours{"grid"};
  // Verlet skin in kernel radii: pair candidates are listed within h (1 + skin) and reused
  // until the two largest displacements sum to skin h. 0 = search every sub-step.
  double neighbourSkin = 0.3;
  // "mueller", the colour-field curvature force of Müller et al. 2003, or "akinci", the
  // cohesion and curvature forces of Akinci et al. 2013.
  MethodChoice surfaceTension{"mueller"};
  double lambdaCfl = 0.4, lambdaAcceleration = 0.4, lambdaViscosity = 1.0;
  // Scales the sub-step safety factors from their defaults: the accuracy lever of the quality
  // levels, tears-sweep and tears-slide. lambda_c and lambda_a scale with `factor`; lambda_v
  // only shrinks (min(1, factor)), since explicit viscosity overshoots past k dt = 1
  // (AdaptiveTimeStep.h).
  void scaleSubsteps(double factor) {
    const SimulationOptions defaults;
    lambdaCfl = defaults.lambdaCfl * factor;
    lambdaAcceleration = defaults.lambdaAcceleration * factor;
    lambdaViscosity = std::min(defaults.lambdaViscosity, defaults.lambdaViscosity * factor);
  }
  // "wcsph", a stiff equation of state (Müller et al. 2003's p = k (rho - rho0) in Monaghan's
  // 1994 regime; sub-steps bound by the speed of sound), "dfsph", divergence-free SPH (Bender &
  // Koschier 2015/2017), or "pbf", position-based fluids (Macklin & Müller 2013): decision 0009.
  MethodChoice pressureSolver{"wcsph"};
  // Longest sub-step allowed, seconds (0 = only the stability limits bound it). DFSPH has no
  // sound-speed limit, so this caps how far the fluid moves between collision passes.
  double maxSubstepSeconds = 0;
  // Sub-steps per frame before the last resort (clamping, counted in TearCounters::clamped).
  int maxSubsteps = 500;
  // Free particles look for the skin this far (kernel radii) and then skip the query until
  // they have travelled the clearance found: farther means fewer, dearer queries.
  double collisionProbeKernels = 1;
  SkinQueryMethod skinQueries = SkinQueryMethod::Grid;  // measured faster (decision 0017)
  double trailDecayMetres = 0.1;           // mass e-folds every 10 cm slid over the skin
  double massFloor = 0.2;                  // of the emitted mass
  double boxMarginMetres = 0.03;           // simulation box = skin bounds grown by this
  double wetnessReferenceParticles = 100;  // volume/count at which wetness approaches 1
  // Threads the sub-steps share (the calling thread included): 0 = the environment variable
  // LACRIMA_THREADS when set, else every hardware thread. Results are bit-identical whatever
  // the count (docs/decisions/0015); below 2,500 particles every loop stays on the caller.
  int threads = 0;
  // How the sub-steps' per-particle loops are cut for those threads: fixed chunks of
  // chunkParticles, shared from shareFromParticles particles on. The chunk size may change the
  // last bits, the thread count never does; tests lower both to run small scenes through the
  // shared paths.
  int chunkParticles = kDefaultChunkParticles;
  int shareFromParticles = kDefaultShareFromParticles;
};

}  // namespace lacrima::tears
