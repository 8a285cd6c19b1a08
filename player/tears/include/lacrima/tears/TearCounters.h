#pragma once
// Tallies of the work a TearSimulation did: deterministic counts (the same inputs give the same
// numbers, which lacrima-bench tears --json prints and the tests compare) and the wall-clock
// times of the last frame's stages.

namespace lacrima::tears {

struct TearCounters {
  long long frames = 0;    // step() calls
  long long sphSteps = 0;  // frames in which the fluid was simulated
  long long substeps = 0;
  long long clamped = 0;         // particle accelerations/velocities clamped (last resort)
  long long substepCapHits = 0;  // sub-steps that wanted to be shorter than the cap allows
  // DFSPH Jacobi sweeps; PBF constraint sweeps count as density sweeps
  long long divergenceIterations = 0, densityIterations = 0;
  long long solverCapped = 0;  // DFSPH solves stopped at the iteration cap
  // Which limit set each sub-step (the adaptive time step); the rest ended the frame.
  long long cflLimited = 0, accelerationLimited = 0, viscosityLimited = 0;
  long long recycled = 0;  // left the box, re-emitted at their source
  long long spawned = 0, removed = 0;
  long long neighbourSearches = 0;  // pair-list builds (the list is reused between them)
  long long straySubsteps = 0,
            strays = 0;  // sub-steps that kept the list with strays; their strays
  // Skin queries answered by the collider's grid, or by ODE (SimulationOptions::skinQueries),
  // ODE trimesh refits, particles the moving skin swept through, contacts kept without a query.
  long long gridQueries = 0;
  long long trimeshUpdates = 0, odeQueries = 0, sweptParticles = 0, contactsTracked = 0;
  long long bruteForceQueries = 0;  // nearest-skin queries ODE could not answer in full (scanned)
  long long surfaceRuns = 0;        // incremented by the surface mesher via countSurfaceRun()
  // Pendant drops (DropDetachment_Tate1864.h): sub-steps in which some contact faced down, so
  // the drops hanging there were weighed; contacts whose drop let go, summed over sub-steps.
  long long pendantSubsteps = 0, releasedContacts = 0;
};

// Milliseconds spent per stage in the last frame.
struct StageTimes {
  double neighbours = 0, density = 0, forces = 0, collision = 0, emission = 0;
};

}  // namespace lacrima::tears
