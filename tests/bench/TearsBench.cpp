// lacrima-bench tears: the full tear pipeline (simulation, surface mesher, trails) on the
// generated cheek sheet (SyntheticSkin.h) or the rigged default head, with the project's targets
// beside the figures: 100 particles <= 1 ms per frame, 10,000 particles <= 45 ms per frame
// (22 fps), neighbour search >= 1 M particles per second. The frame time is the whole pipeline,
// since the player pays for all three stages every frame.
#include "BenchCommandLine.h"
#include "BenchSupport.h"
#include "Octree.h"  // internal to lacrima_tears: the 2009 octree, measured against the grid
#include "TearMethodOptions.h"
#include "TearsPipeline.h"

#include <lacrima/common/JsonWriter.h>
#include <lacrima/common/Milliseconds.h>
#include <lacrima/playback/TearQualityOptions.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace lacrima::bench {

namespace {

using namespace lacrima::tears;

// FNV-1a (64 bits) over the bits of the matrices, in order, as "%016x": with state_hash it lets
// anyone check that the surface and the trails, too, do not change with the thread count.
template <typename... Matrices>
std::string bitsHash(const Matrices&... matrices) {
  std::uint64_t hash = 0xcbf29ce484222325ull;
  const auto mix = [&hash](const auto& m) {
    const auto* b = reinterpret_cast<const unsigned char*>(m.data());
    for (std::size_t k = 0; k < static_cast<std::size_t>(m.size()) * sizeof(*m.data()); ++k)
      hash = (hash ^ b[k]) * 0x100000001b3ull;
  };
  (mix(matrices), ...);
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(hash));
  return text;
}

struct Options {
  int particles = 100;
  int frames = 110;
  double fps = 22;
  bool json = false;
  bool sway = false;
  bool head = false;  // the rigged default head instead of the cheek sheet
  double skin = SimulationOptions{}.neighbourSkin;
  SkinQueryMethod skinQueries = SimulationOptions{}.skinQueries;
  SimulationOptions methods;  // only the method choices are read (TearMethodOptions.h)
  double maxStepMs = 0;
  double substepFactor = 1;                     // scales the CFL and acceleration safety factors
  TearQuality quality = TearQuality::Balanced;  // the apps' level (Balanced: the defaults)
  int threads = 0;  // SimulationOptions::threads (0 = LACRIMA_THREADS or all)
  TearSettings settings;
};

std::optional<int> parseOptions(int argc, char** argv, Options& o) {
  BenchCommandLine line(
      "tears",
      "Runs the tear pipeline (simulation + surface mesher + trails) on a generated, tilted\n"
      "cheek-sized sheet (decimetres) or the default head, with N/2 particles commanded per\n"
      "eye from the first frame, and reports the median frame time of the whole pipeline.");
  line.wholeNumber("particles", "N", "Particles in all (default 100).", 0, 2 * kMaxTearParticles,
                   o.particles);
  line.wholeNumber("frames", "F", "Frames to simulate (default 110: 5 s at 22 fps).", 1, 1000000,
                   o.frames);
  line.number("fps", "R", "Animation frame rate (default 22).", 0, 1000, o.fps,
              BenchCommandLine::Low::Excluded);
  line.option("param", "NAME=VALUE",
              "A tear parameter (pressure viscosity tension adhesion friction gravity kernel "
              "node_size cube_size "
              "iso), validated against its range; repeatable.",
              [&o](const QString& pair) {
                const qsizetype eq = pair.indexOf('=');
                bool ok = false;
                const double value = eq < 0 ? 0 : pair.mid(eq + 1).toDouble(&ok);
                if (!ok) return "expected NAME=VALUE, not '" + pair.toStdString() + "'";
                try {
                  o.settings.set(pair.left(eq).toStdString(), value);
                } catch (const std::invalid_argument& e) {
                  return std::string(e.what());
                }
                return std::string();
              });
  line.choice("skin-queries",
              "Who answers the skin-collision queries: grid (default; shared between threads) or "
              "ode (the reference, one thread at a time).",
              {{"grid", SkinQueryMethod::Grid}, {"ode", SkinQueryMethod::Ode}}, o.skinQueries);
  addTearMethodOptions(line, o.methods);
  line.number("max-step", "MS", "Longest sub-step in milliseconds (default: no cap).", 0, 1000,
              o.maxStepMs);
  line.number("substep-factor", "F", "Scales the CFL and acceleration safety factors (default 1).",
              0, 10, o.substepFactor, BenchCommandLine::Low::Excluded);
  line.choice("quality",
              "The apps' tear quality level, mapped as they map it (default balanced: the "
              "simulation's defaults); --substep-factor then scales its CFL and acceleration "
              "factors further.",
              {{"preview", TearQuality::Preview},
               {"balanced", TearQuality::Balanced},
               {"reference", TearQuality::Reference}},
              o.quality);
  line.number("skin", "S",
              "Verlet skin of the pair list, in kernel radii (default 0.3; 0 = no reuse).", 0, 2,
              o.skin);
  line.wholeNumber("threads", "T",
                   "Threads the simulation shares (default 0: LACRIMA_THREADS, else all); "
                   "results are bit-identical for any count.",
                   0, 256, o.threads);
  line.choice("head", "The cheek sheet (default) or the cached default head (skipped when absent).",
              {{"sheet", false}, {"default", true}}, o.head);
  line.flag("sway", "The sheet (or head) sways (rotates and translates) every frame.", o.sway);
  line.flag("json", "One JSON object instead of the table.", o.json);
  return line.parse(argc, argv);
}

// Millions of particles per second through one neighbour search (structure + lists).
double searchRate(NeighbourSearch& search, const std::vector<Eigen::Vector3d>& x, double h) {
  if (x.empty()) return 0;
  NeighbourList list;
  search.find(x, h, list);  // warm
  int runs = 0;
  const auto start = SteadyClock::now();
  double seconds = 0;
  do {
    search.find(x, h, list);
    ++runs;
    seconds = std::chrono::duration<double>(SteadyClock::now() - start).count();
  } while (seconds < 0.2);
  return static_cast<double>(x.size()) * runs / seconds / 1e6;
}

// Median milliseconds of checkpoint() and of restore() on the simulation's current state (the
// state is restored to itself, so the run is not disturbed).
std::pair<double, double> checkpointCost(TearSimulation& sim) {
  std::vector<double> save, load;
  for (int run = 0; run < 21; ++run) {
    auto start = SteadyClock::now();
    const TearCheckpoint c = sim.checkpoint();
    save.push_back(millisecondsSince(start));
    start = SteadyClock::now();
    sim.restore(c);
    load.push_back(millisecondsSince(start));
  }
  std::sort(save.begin(), save.end());
  std::sort(load.begin(), load.end());
  return {save[save.size() / 2], load[load.size() / 2]};
}

const char* mark(bool pass) { return pass ? "PASS" : "MISS"; }

// Where the particles are at one frame: touching the skin (on the face), free inside the
// skin's bounds (in the air over the face: falling, or thrown off it), or outside those bounds
// (off the face, in the box's margin, on their way out to be recycled).
struct Population {
  int frame = 0;
  int onFace = 0, inAir = 0, offFace = 0;
  long long recycled = 0;  // since the previous sample
};

Population populationOf(const ParticleSet& p, const Eigen::AlignedBox3d& skinBounds) {
  Population counts;
  for (int i = 0; i < p.size(); ++i) {
    const auto s = static_cast<std::size_t>(i);
    if (p.contact[s].triangle >= 0)
      ++counts.onFace;
    else if (skinBounds.contains(p.position[s]))
      ++counts.inAir;
    else
      ++counts.offFace;
  }
  return counts;
}

Eigen::AlignedBox3d skinBoundsOf(const TearScene& scene) {
  Eigen::AlignedBox3d bounds;
  for (const Eigen::Vector3i& t : scene.skinTriangles)
    for (int a = 0; a < 3; ++a) bounds.extend(scene.rest.col(t[a]).cast<double>());
  return bounds;
}

}  // namespace

int runTears(int argc, char** argv) {
  Options o;
  if (const std::optional<int> status = parseOptions(argc, argv, o)) return *status;

  std::optional<TearScene> scene = benchScene(o.head, "tears");
  if (!scene) return 0;
  // The level's options exactly as the player and the editor get them (one mapping,
  // playback::simulationOptions); the bench's own choices then replace the level's.
  TearQualitySettings quality;
  quality.level = o.quality;
  SimulationOptions simOptions = playback::simulationOptions(quality);
  simOptions.neighbours = o.methods.neighbours;
  simOptions.skinQueries = o.skinQueries;
  simOptions.surfaceTension = o.methods.surfaceTension;
  simOptions.neighbourSkin = o.skin;
  simOptions.pressureSolver = o.methods.pressureSolver;
  simOptions.maxSubstepSeconds = o.maxStepMs / 1000;
  simOptions.lambdaCfl *= o.substepFactor;
  simOptions.lambdaAcceleration *= o.substepFactor;
  simOptions.threads = o.threads;
  TearPipeline pipeline(*scene, o.settings, simOptions);
  TearSimulation& sim = pipeline.simulation();
  const int left = (o.particles + 1) / 2, right = o.particles / 2;
  const double dt = 1.0 / o.fps;

  std::vector<double> frameMs, simulationMs;
  StageTimes total;
  double surfaceTotal = 0, trailsTotal = 0;
  bool finite = true;
  Eigen::Matrix3Xf positions = scene->rest;
  // Half a second between population samples (and the last frame).
  const int sampleEvery = std::max(1, static_cast<int>(std::lround(o.fps / 2)));
  const Eigen::AlignedBox3d skinBounds = skinBoundsOf(*scene);
  std::vector<Population> population;
  long long recycledBefore = 0;
  for (int f = 0; f < o.frames; ++f) {
    if (o.sway) positions = scene->positionsAt(f * dt, true);
    const FrameTimes t = pipeline.step(positions, left, right, dt);
    frameMs.push_back(t.total());
    simulationMs.push_back(t.simulation);
    surfaceTotal += t.surface;
    trailsTotal += t.trails;
    const StageTimes& s = sim.lastFrameTimes();
    total.neighbours += s.neighbours;
    total.density += s.density;
    total.forces += s.forces;
    total.collision += s.collision;
    total.emission += s.emission;
    if ((f + 1) % sampleEvery == 0 || f + 1 == o.frames) {
      Population counts = populationOf(sim.particles(), skinBounds);
      counts.frame = f + 1;
      counts.recycled = sim.counters().recycled - recycledBefore;
      recycledBefore = sim.counters().recycled;
      population.push_back(counts);
    }
  }
  const ParticleSet& p = sim.particles();
  double maxDistance = 0;
  for (int i = 0; i < p.size(); ++i) {
    finite = finite && p.position[static_cast<std::size_t>(i)].allFinite() &&
             p.velocity[static_cast<std::size_t>(i)].allFinite();
    maxDistance =
        std::max(maxDistance,
                 (p.position[static_cast<std::size_t>(i)] - scene->centre).norm() / scene->radius);
  }
  std::vector<double> sorted = frameMs;
  std::sort(sorted.begin(), sorted.end());
  const double median = sorted[sorted.size() / 2];
  std::sort(simulationMs.begin(), simulationMs.end());
  const double simulationMedian = simulationMs[simulationMs.size() / 2];
  const double mean = [&] {
    double s = 0;
    for (double v : frameMs) s += v;
    return s / static_cast<double>(frameMs.size());
  }();
  const auto [checkpointMs, restoreMs] = checkpointCost(sim);
  const std::size_t checkpointBytes = sim.checkpoint().bytes();
  UniformGrid grid;
  Octree octree(sim.parameters().nodeSize);
  const double gridRate = searchRate(grid, p.position, sim.kernelRadius());
  NeighbourList finalList;
  grid.find(p.position, sim.kernelRadius(), finalList);
  const double neighboursPerParticle =
      p.empty() ? 0.0 : static_cast<double>(finalList.indices.size()) / p.size();
  const double octreeRate = searchRate(octree, p.position, sim.kernelRadius());
  // Compression at the start of the last sub-step, rho / rho0 (rho0 = 1): what the pressure
  // solver left.
  double densityMax = 0, densitySum = 0;
  for (const double rho : p.density) {
    densityMax = std::max(densityMax, rho);
    densitySum += rho;
  }
  const double densityMean = p.empty() ? 0.0 : densitySum / p.size();
  const double n = o.frames;
  const TearCounters& c = sim.counters();
  const double target = o.particles <= 100 ? 1.0 : (o.particles >= 10000 ? 1000.0 / 22.0 : 0);

  const TearSurface& surface = pipeline.mesher().surface();
  const TrailMesh& trail = pipeline.trails().mesh();
  const std::string surfaceHash =
      bitsHash(surface.positions(), surface.normals(), surface.triangles());
  const std::string trailHash =
      bitsHash(trail.positions(), trail.normals(), trail.alpha(), trail.triangles());
  if (o.json) {
    JsonWriter json(JsonWriter::Layout::Compact);
    json.beginObject();
    json.field("benchmark", "tears");
    json.field("particles_requested", o.particles);
    json.field("particles_alive", p.size());
    json.field("frames", o.frames);
    json.field("fps", o.fps);
    json.field("neighbours", o.methods.neighbours.key);
    json.field("skin_queries", o.skinQueries == SkinQueryMethod::Grid ? "grid" : "ode");
    json.field("tension_model", o.methods.surfaceTension.key);
    json.field("solver", o.methods.pressureSolver.key);
    // The values the solver ran with, its defaults included: {"iterations": 4, ...}.
    const MethodInfo solver =
        *findMethod(MethodFamily::PressureSolver, o.methods.pressureSolver.key);
    const MethodValues solverValues(solver, o.methods.pressureSolver);
    json.key("solver_parameters");
    json.beginObject();
    for (const MethodParameter& parameter : solver.parameters)
      json.field(parameter.key, solverValues.number(parameter.key));
    json.endObject();
    json.field("max_substep_ms", o.maxStepMs);
    json.field("substep_factor", o.substepFactor);
    json.field("quality", toString(o.quality));
    json.field("scene", o.head ? "default_head" : "cheek_sheet");
    json.field("sway", o.sway);
    json.field("threads", sim.threads());
    char hash[17];
    std::snprintf(hash, sizeof hash, "%016llx", static_cast<unsigned long long>(stateHash(p)));
    json.field("state_hash", hash);
    json.field("surface_hash", surfaceHash);
    json.field("trail_hash", trailHash);
    json.field("ms_per_frame", median);
    json.field("ms_per_frame_mean", mean);
    json.field("ms_per_frame_max", sorted.back());
    json.field("ms_per_frame_simulation", simulationMedian);
    if (target > 0) {
      json.field("target_ms_per_frame", target);
      json.field("pass", median <= target);
    }
    json.key("stages");
    json.beginObject();
    json.field("neighbours", total.neighbours / n);
    json.field("density", total.density / n);
    json.field("forces", total.forces / n);
    json.field("collision", total.collision / n);
    json.field("emission", total.emission / n);
    json.field("surface", surfaceTotal / n);
    json.field("trails", trailsTotal / n);
    json.endObject();
    json.key("counters");
    json.beginObject();
    json.field("sph_steps", c.sphSteps);
    json.field("substeps", c.substeps);
    json.field("clamped", c.clamped);
    json.field("substep_cap_hits", c.substepCapHits);
    json.field("recycled", c.recycled);
    json.field("pendant_substeps", c.pendantSubsteps);
    json.field("released_contacts", c.releasedContacts);
    json.field("surface_runs", c.surfaceRuns);
    json.field("spawned", c.spawned);
    json.field("neighbour_searches", c.neighbourSearches);
    json.field("stray_substeps", c.straySubsteps);
    json.field("cfl_limited", c.cflLimited);
    json.field("acceleration_limited", c.accelerationLimited);
    json.field("viscosity_limited", c.viscosityLimited);
    json.field("trimesh_updates", c.trimeshUpdates);
    json.field("grid_queries", c.gridQueries);
    json.field("ode_queries", c.odeQueries);
    json.field("contacts_tracked", c.contactsTracked);
    json.field("swept_particles", c.sweptParticles);
    json.field("brute_force_queries", c.bruteForceQueries);
    json.field("divergence_iterations", c.divergenceIterations);
    json.field("density_iterations", c.densityIterations);
    json.field("solver_capped", c.solverCapped);
    json.endObject();
    json.key("neighbour_search_mparticles_per_s");
    json.beginObject();
    json.field("grid", gridRate);
    json.field("octree", octreeRate);
    json.field("target_at_least", 1.0);
    json.endObject();
    json.key("population");  // every half second: where the particles are (Population)
    json.beginArray();
    for (const Population& counts : population) {
      json.beginObject();
      json.field("frame", counts.frame);
      json.field("on_face", counts.onFace);
      json.field("in_air", counts.inAir);
      json.field("off_face", counts.offFace);
      json.field("recycled", counts.recycled);
      json.endObject();
    }
    json.endArray();
    json.field("checkpoint_ms", checkpointMs);
    json.field("restore_ms", restoreMs);
    json.field("checkpoint_bytes", static_cast<long long>(checkpointBytes));
    json.field("kernel_radius", sim.kernelRadius());
    json.field("neighbours_per_particle", neighboursPerParticle);
    json.field("density_max", densityMax);
    json.field("density_mean", densityMean);
    json.field("all_finite", finite);
    json.field("max_distance", maxDistance);
    json.endObject();
    std::fputs(std::move(json).finish().c_str(), stdout);
    return finite ? 0 : 1;
  }

  std::printf(
      "tears on the %s: %d particles requested, %d alive, %d frames at %g fps, %s, %s neighbours, "
      "%s tension%s, %d thread%s\n",
      scene->name.c_str(), o.particles, p.size(), o.frames, o.fps,
      describeMethod(MethodFamily::PressureSolver, o.methods.pressureSolver).c_str(),
      describeMethod(MethodFamily::NeighbourStructure, o.methods.neighbours).c_str(),
      describeMethod(MethodFamily::SurfaceTension, o.methods.surfaceTension).c_str(),
      o.sway ? ", swaying" : "", sim.threads(), sim.threads() == 1 ? "" : "s");
  std::printf("  frame time     median %8.3f ms  (mean %.3f, max %.3f; simulation alone %.3f)",
              median, mean, sorted.back(), simulationMedian);
  if (target > 0) std::printf("   target <= %.3g ms  %s", target, mark(median <= target));
  std::printf(
      "\n  stages (mean ms/frame): neighbours %.3f  density %.3f  forces %.3f  collision %.3f  "
      "emission %.3f"
      "  surface %.3f  trails %.3f\n",
      total.neighbours / n, total.density / n, total.forces / n, total.collision / n,
      total.emission / n, surfaceTotal / n, trailsTotal / n);
  std::printf(
      "  counters: sph_steps %lld  substeps %lld (%.1f/frame)  clamped %lld  recycled %lld  "
      "skin queries %lld (%s)  trimesh_updates %lld  surface_runs %lld\n"
      "  pendant drops: weighed in %lld sub-steps, %lld contacts let go\n",
      c.sphSteps, c.substeps, c.substeps / n, c.clamped, c.recycled, c.gridQueries + c.odeQueries,
      o.skinQueries == SkinQueryMethod::Grid ? "grid" : "ode", c.trimeshUpdates, c.surfaceRuns,
      c.pendantSubsteps, c.releasedContacts);
  std::printf(
      "  sub-step limits: cfl %lld  acceleration %lld  viscosity %lld  frame end %lld   pair-list "
      "builds %lld (%.1f/frame)\n",
      c.cflLimited, c.accelerationLimited, c.viscosityLimited,
      c.substeps - c.cflLimited - c.accelerationLimited - c.viscosityLimited, c.neighbourSearches,
      c.neighbourSearches / n);
  // The iterative solvers' sweeps (DFSPH's two solves; PBF counts its constraint sweeps as
  // density sweeps).
  if (c.divergenceIterations > 0 || c.densityIterations > 0)
    std::printf(
        "  solver: %.2f divergence and %.2f density sweeps per sub-step, %lld solves capped\n",
        c.substeps ? static_cast<double>(c.divergenceIterations) / c.substeps : 0.0,
        c.substeps ? static_cast<double>(c.densityIterations) / c.substeps : 0.0, c.solverCapped);
  std::printf(
      "  where the particles are (frame: on the face / in the air / off the face, "
      "recycled since the previous line):\n");
  for (const Population& counts : population)
    std::printf("    %5d: %6d / %6d / %6d   recycled %lld\n", counts.frame, counts.onFace,
                counts.inAir, counts.offFace, counts.recycled);
  std::printf("  neighbours within h per particle at the end: %.1f\n", neighboursPerParticle);
  std::printf("  density at the end: max %.4f, mean %.4f rho0\n", densityMax, densityMean);
  std::printf("  checkpoint %.3f ms, restore %.3f ms, %.1f kB\n", checkpointMs, restoreMs,
              checkpointBytes / 1024.0);
  std::printf(
      "  neighbour search: grid %.2f M particles/s, octree %.2f M particles/s   target >= 1  %s\n",
      gridRate, octreeRate, mark(gridRate >= 1));
  std::printf("  state hash (positions and velocities): %016llx\n",
              static_cast<unsigned long long>(stateHash(p)));
  std::printf("  surface hash %s, trail hash %s\n", surfaceHash.c_str(), trailHash.c_str());
  std::printf("  all finite: %s   max distance from the skin centre: %.2f half skin heights\n",
              finite ? "yes" : "NO", maxDistance);
  return finite ? 0 : 1;
}

}  // namespace lacrima::bench
