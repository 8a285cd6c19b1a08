// lacrima-bench tears-sweep: what accuracy costs in time. One fine reference run of the full tear
// pipeline on the cheek sheet (or the rigged default head), then runs that each coarsen one
// quantity (sub-step safety factor, kernel size, marching-cubes cube size, neighbour structure,
// pressure solver); each is reported with its error against the reference beside its
// milliseconds per frame, as a table, a CSV file and a log-log PNG plot.
//
// Errors, in units of the reference particle radius so they read as "how many drop radii off":
//   particle RMS  positions after the last frame, matched by particle id (ids are assigned in
//                 emission order, so the same commanded counts give the same ids). Drops are
//                 chaotic (where a drop splits, or which way a particle goes round another, flips
//                 with rounding), so this grows with time even between two fine runs;
//   centroid      distance between each eye's mean particle position and the reference's,
//                 averaged over the eyes: how far the tears ran, insensitive to that chaos;
//   surface       symmetric mean distance between the two final tear surfaces' vertices and the
//                 nearest vertex of the other (a Chamfer distance; vertices of the fine reference
//                 are dense enough that this approximates point-to-surface distance), plus the
//                 relative surface area difference.
// The cube-size series runs extra meshers on the reference simulation, so its particles are the
// reference's and its error is the surface discretisation alone; its ms per frame is that
// simulation + trails + its own mesher. The reference is WCSPH: DFSPH and PBF rows include the
// model's difference (an incompressible fluid against one with a 0.2 m/s speed of sound).
#include "BenchCommandLine.h"
#include "SweepPlot.h"
#include "TearsPipeline.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

namespace lacrima::bench {

namespace {

using namespace lacrima::tears;

// "x1.5" for a scale of 1.5: four characters of the number at most.
std::string scaleLabel(double scale) {
  return std::string("x").append(std::to_string(scale), 0, 4);
}

struct Options {
  int particles = 200;
  int frames = 66;  // 3 s at 22 fps: long enough for drops to run down the sheet
  double fps = 22;
  bool head = false;  // the rigged default head instead of the cheek sheet
  int threads = 0;    // SimulationOptions::threads of every run
  std::string csv, png;
};

std::optional<int> parseOptions(int argc, char** argv, Options& o) {
  BenchCommandLine line(
      "tears-sweep",
      "Error against a fine reference run beside ms per frame of the full tear pipeline\n"
      "(simulation + surface + trails) on the cheek sheet or the default head, sweeping the\n"
      "sub-step safety factor, the kernel size, the cube size, the neighbour structure and\n"
      "the pressure solver (WCSPH, DFSPH, PBF).");
  line.wholeNumber("particles", "N", "Particles in all (default 200).", 1, 2 * kMaxTearParticles,
                   o.particles);
  line.wholeNumber("frames", "F", "Frames at 22 fps (default 66).", 1, 100000, o.frames);
  line.choice("head",
              "The cheek sheet (default) or the cached default head with the rig's sources.",
              {{"sheet", false}, {"default", true}}, o.head);
  line.wholeNumber("threads", "T",
                   "Threads each run's simulation shares (default 0: LACRIMA_THREADS, else all).",
                   0, 256, o.threads);
  line.text("csv", "FILE", "Also write the table as CSV.", o.csv);
  line.text("png", "FILE", "Also draw error against ms per frame (log axes) as a PNG.", o.png);
  return line.parse(argc, argv);
}

// One run's settings: the quantity it sweeps (series), its value label and what it changes.
struct Variant {
  std::string series, label;
  double lambdaScale = 1, kernelScale = 1, cubeScale = 1;
  NeighbourMethod neighbours = NeighbourMethod::Grid;
  PressureMethod solver = PressureMethod::Wcsph;
};

// What a run leaves behind for the comparison.
struct RunResult {
  double msPerFrame = 0;  // mean over frames of the full pipeline
  double substepsPerFrame = 0;
  std::map<std::uint64_t, Eigen::Vector3d> particles;
  std::array<Eigen::Vector3d, 2> centroid{Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
  std::vector<Eigen::Vector3d> surfaceVertices;
  double surfaceArea = 0;
};

struct Row {
  Variant variant;
  double msPerFrame = 0, substepsPerFrame = 0;
  double particleRms = 0, centroidError = 0, surfaceError = 0, areaDifference = 0;
  int matched = 0;
  bool surfaceSeries = false;  // the plotted error is the surface error
};

const TearSettings kDefaults{};
const SimulationOptions kDefaultOptions{};

TearSettings settingsFor(const Variant& v) {
  TearSettings s;
  s.set("kernel", kDefaults.kernel * v.kernelScale);
  s.set("cube_size", kDefaults.cubeSize * v.cubeScale);
  return s;
}

SimulationOptions optionsFor(const Variant& v) {
  SimulationOptions o;
  o.neighbours = v.neighbours;
  o.pressureSolver = v.solver;
  o.lambdaCfl = kDefaultOptions.lambdaCfl * v.lambdaScale;
  o.lambdaAcceleration = kDefaultOptions.lambdaAcceleration * v.lambdaScale;
  // Explicit viscosity overshoots past k dt = 1 (AdaptiveTimeStep.h): scale it down, never up.
  o.lambdaViscosity =
      std::min(kDefaultOptions.lambdaViscosity, kDefaultOptions.lambdaViscosity * v.lambdaScale);
  return o;
}

void capture(const TearSurface& surface, RunResult& out) {
  const auto x = surface.positions();
  const auto t = surface.triangles();
  out.surfaceVertices.assign(static_cast<std::size_t>(x.cols()), Eigen::Vector3d::Zero());
  for (Eigen::Index i = 0; i < x.cols(); ++i)
    out.surfaceVertices[static_cast<std::size_t>(i)] = x.col(i);
  out.surfaceArea = 0;
  for (Eigen::Index k = 0; k < t.cols(); ++k) {
    const Eigen::Vector3d a = x.col(t(0, k)), b = x.col(t(1, k)), c = x.col(t(2, k));
    out.surfaceArea += 0.5 * (b - a).cross(c - a).norm();
  }
}

// Runs the pipeline; `extraCubes` add meshers at those cube scales (results in `extras`).
RunResult run(const TearScene& scene, const Variant& v, const Options& o,
              const std::vector<double>& extraCubes = {},
              std::vector<RunResult>* extras = nullptr) {
  SimulationOptions options = optionsFor(v);
  options.threads = o.threads;
  TearPipeline pipeline(scene, settingsFor(v), options);
  TearSimulation& sim = pipeline.simulation();
  std::vector<std::unique_ptr<SurfaceMesher>> meshers;
  for (std::size_t k = 0; k < extraCubes.size(); ++k)
    meshers.push_back(std::make_unique<SurfaceMesher>());
  std::vector<double> extraMs(extraCubes.size(), 0.0);
  const double dt = 1.0 / o.fps;
  const int left = (o.particles + 1) / 2, right = o.particles / 2;
  double totalMs = 0, baseMs = 0;  // base: simulation + trails, shared by the extra meshers
  for (int f = 0; f < o.frames; ++f) {
    const FrameTimes t = pipeline.step(scene.rest, left, right, dt);
    totalMs += t.total();
    baseMs += t.simulation + t.trails;
    if (sim.particles().empty()) continue;
    for (std::size_t k = 0; k < meshers.size(); ++k) {
      SurfaceMesherSettings s;
      s.kernelRadius = sim.kernelRadius();
      s.cubeSize = sim.parameters().cubeSize / v.cubeScale * extraCubes[k];
      s.iso = sim.parameters().iso;
      meshers[k]->build(sim.particles().position, sim.particles().mass, sim.grid(), s);
      extraMs[k] += meshers[k]->stats().milliseconds;
    }
  }
  RunResult r;
  r.msPerFrame = totalMs / o.frames;
  r.substepsPerFrame = static_cast<double>(sim.counters().substeps) / o.frames;
  const ParticleSet& p = sim.particles();
  std::array<int, 2> count{0, 0};
  for (int i = 0; i < p.size(); ++i) {
    const auto s = static_cast<std::size_t>(i);
    r.particles.emplace(p.id[s], p.position[s]);
    const auto e = static_cast<std::size_t>(p.eye[s]);
    r.centroid[e] += p.position[s];
    ++count[e];
  }
  for (std::size_t e = 0; e < 2; ++e)
    if (count[e] > 0) r.centroid[e] /= count[e];
  capture(pipeline.mesher().surface(), r);
  if (extras) {
    extras->clear();
    for (std::size_t k = 0; k < meshers.size(); ++k) {
      RunResult e;
      e.msPerFrame = (baseMs + extraMs[k]) / o.frames;
      e.substepsPerFrame = r.substepsPerFrame;
      e.particles = r.particles;
      e.centroid = r.centroid;
      capture(meshers[k]->surface(), e);
      extras->push_back(std::move(e));
    }
  }
  return r;
}

// Nearest-vertex lookups through a hash grid of cell edge `cell` (exact: rings grow until the
// best distance found is inside the searched cube).
class NearestVertex {
 public:
  NearestVertex(const std::vector<Eigen::Vector3d>& points, double cell)
      : points_(points), cell_(cell) {
    for (std::size_t i = 0; i < points.size(); ++i)
      cells_[key(cellOf(points[i]))].push_back(static_cast<int>(i));
  }
  double distance(const Eigen::Vector3d& x) const {
    if (points_.empty()) return std::numeric_limits<double>::infinity();
    const Eigen::Vector3i c = cellOf(x);
    double best = std::numeric_limits<double>::infinity();
    for (int ring = 0; ring < 64; ++ring) {
      for (int dx = -ring; dx <= ring; ++dx)
        for (int dy = -ring; dy <= ring; ++dy)
          for (int dz = -ring; dz <= ring; ++dz) {
            if (std::max({std::abs(dx), std::abs(dy), std::abs(dz)}) != ring)
              continue;  // the shell only
            const auto it = cells_.find(key(c + Eigen::Vector3i(dx, dy, dz)));
            if (it == cells_.end()) continue;
            for (int i : it->second)
              best = std::min(best, (points_[static_cast<std::size_t>(i)] - x).norm());
          }
      if (best <= ring * cell_) return best;  // nothing outside this cube can be closer
    }
    for (const Eigen::Vector3d& p : points_)
      best = std::min(best, (p - x).norm());  // far away: brute force
    return best;
  }

 private:
  Eigen::Vector3i cellOf(const Eigen::Vector3d& x) const {
    return (x / cell_).array().floor().cast<int>();
  }
  static std::int64_t key(const Eigen::Vector3i& c) {
    return (std::int64_t(c.x() & 0x1fffff) << 42) | (std::int64_t(c.y() & 0x1fffff) << 21) |
           std::int64_t(c.z() & 0x1fffff);
  }
  const std::vector<Eigen::Vector3d>& points_;
  double cell_;
  std::unordered_map<std::int64_t, std::vector<int>> cells_;
};

double meanNearest(const std::vector<Eigen::Vector3d>& from, const NearestVertex& to) {
  if (from.empty()) return 0;
  double sum = 0;
  for (const Eigen::Vector3d& x : from) sum += to.distance(x);
  return sum / static_cast<double>(from.size());
}

Row compare(const Variant& v, const RunResult& r, const RunResult& ref, double radius,
            double cell) {
  Row row{v, r.msPerFrame, r.substepsPerFrame, 0, 0, 0, 0, 0, false};
  row.centroidError =
      0.5 * ((r.centroid[0] - ref.centroid[0]).norm() + (r.centroid[1] - ref.centroid[1]).norm()) /
      radius;
  double sum = 0;
  for (const auto& [id, x] : r.particles) {
    const auto it = ref.particles.find(id);
    if (it == ref.particles.end()) continue;
    sum += (x - it->second).squaredNorm();
    ++row.matched;
  }
  row.particleRms = row.matched ? std::sqrt(sum / row.matched) / radius : 0;
  if (r.surfaceVertices.empty() || ref.surfaceVertices.empty()) {
    row.surfaceError = std::numeric_limits<double>::quiet_NaN();
  } else {
    const NearestVertex toRef(ref.surfaceVertices, cell), toRun(r.surfaceVertices, cell);
    row.surfaceError =
        0.5 * (meanNearest(r.surfaceVertices, toRef) + meanNearest(ref.surfaceVertices, toRun)) /
        radius;
  }
  row.areaDifference =
      ref.surfaceArea > 0 ? std::abs(r.surfaceArea - ref.surfaceArea) / ref.surfaceArea : 0;
  return row;
}

}  // namespace

int runTearsSweep(int argc, char** argv) {
  Options o;
  if (const std::optional<int> status = parseOptions(argc, argv, o)) return *status;
  const std::optional<TearScene> loaded = benchScene(o.head, "tears-sweep");
  if (!loaded) return 0;
  const TearScene& scene = *loaded;

  // The reference: the smallest sub-step and cube of the sweep, default kernel, grid.
  const double kFineLambda = 0.25, kFineCube = 0.25;
  const Variant reference{
      "reference", "fine", kFineLambda, 1, kFineCube, NeighbourMethod::Grid, PressureMethod::Wcsph};
  std::printf(
      "tears-sweep: %d particles, %d frames at %g fps on the %s; reference: sub-step x%g, cube x%g "
      "...\n",
      o.particles, o.frames, o.fps, scene.name.c_str(), kFineLambda, kFineCube);
  std::fflush(stdout);
  const std::vector<double> cubeScales = {0.5, 1, 2};
  std::vector<RunResult> cubeRuns;
  const RunResult ref = run(scene, reference, o, cubeScales, &cubeRuns);
  const double radius =
      scene.simulate(settingsFor(reference), optionsFor(reference))->particleRadius();
  const double cell = 2 * radius;

  std::vector<Row> rows;
  rows.push_back(compare(reference, ref, ref, radius, cell));
  for (double s : {0.5, 1.0, 1.5, 2.0}) {
    const Variant v{"sub-step factor (lambda)", scaleLabel(s), s, 1, 1, NeighbourMethod::Grid};
    rows.push_back(compare(v, run(scene, v, o), ref, radius, cell));
  }
  for (double s : {0.5, 1.0, 1.5, 2.0}) {
    const Variant v{"DFSPH, sub-step factor", scaleLabel(s),        s, 1, 1,
                    NeighbourMethod::Grid,    PressureMethod::Dfsph};
    rows.push_back(compare(v, run(scene, v, o), ref, radius, cell));
  }
  for (double s : {1.0, 2.0, 3.0}) {  // PBF at its default iterations, then fewer sub-steps
    const Variant v{"PBF, sub-step factor", scaleLabel(s),      s, 1, 1,
                    NeighbourMethod::Grid,  PressureMethod::Pbf};
    rows.push_back(compare(v, run(scene, v, o), ref, radius, cell));
  }
  for (double s : {0.5, 0.75, 1.0, 1.5}) {
    const Variant v{"kernel size", scaleLabel(s), 1, s, 1, NeighbourMethod::Grid};
    rows.push_back(compare(v, run(scene, v, o), ref, radius, cell));
  }
  for (std::size_t k = 0; k < cubeScales.size(); ++k) {
    const Variant v{"cube size (surface)", scaleLabel(cubeScales[k]), kFineLambda, 1,
                    cubeScales[k],         NeighbourMethod::Grid};
    Row row = compare(v, cubeRuns[k], ref, radius, cell);
    row.surfaceSeries = true;
    rows.push_back(row);
  }
  for (NeighbourMethod m : {NeighbourMethod::Grid, NeighbourMethod::Octree}) {
    const Variant v{
        "neighbour structure", m == NeighbourMethod::Grid ? "grid" : "octree", 1, 1, 1, m};
    rows.push_back(compare(v, run(scene, v, o), ref, radius, cell));
  }

  std::printf(
      "  errors in reference particle radii (%.4g head units); ms = full pipeline per frame "
      "(mean)\n",
      radius);
  std::printf("  %-26s %-7s %10s %9s %13s %10s %12s %10s %8s\n", "swept", "value", "ms/frame",
              "substeps", "particle RMS", "centroid", "surface err", "area diff", "matched");
  for (const Row& r : rows)
    std::printf("  %-26s %-7s %10.3f %9.1f %13.4g %10.4g %12.4g %9.1f%% %8d\n",
                r.variant.series.c_str(), r.variant.label.c_str(), r.msPerFrame, r.substepsPerFrame,
                r.particleRms, r.centroidError, r.surfaceError, 100 * r.areaDifference, r.matched);

  if (!o.csv.empty()) {
    std::ofstream csv(o.csv);
    csv << "scene,series,value,solver,lambda_scale,kernel_scale,cube_scale,neighbours,ms_per_frame,"
           "substeps_per_frame,"
           "particle_rms_radii,centroid_error_radii,surface_error_radii,area_difference,matched_"
           "particles\n";
    for (const Row& r : rows) {
      const Variant& v = r.variant;
      csv << (o.head ? "default_head" : "cheek_sheet") << ',' << v.series << ',' << v.label << ','
          << pressureMethodName(v.solver) << ',' << v.lambdaScale << ',' << v.kernelScale << ','
          << v.cubeScale << ',' << (v.neighbours == NeighbourMethod::Grid ? "grid" : "octree")
          << ',' << r.msPerFrame << ',' << r.substepsPerFrame << ',' << r.particleRms << ','
          << r.centroidError << ',' << r.surfaceError << ',' << r.areaDifference << ',' << r.matched
          << '\n';
    }
    if (!csv) {
      std::fprintf(stderr, "tears-sweep: cannot write %s\n", o.csv.c_str());
      return 1;
    }
    std::printf("  wrote %s\n", o.csv.c_str());
  }
  if (!o.png.empty()) {
    std::vector<PlotSeries> series;
    for (const Row& r : rows) {
      if (r.variant.series == "reference") continue;
      if (series.empty() || series.back().name.rfind(r.variant.series, 0) != 0)
        series.push_back(
            {r.variant.series + (r.surfaceSeries ? ": surface error" : ": centroid error"), {}});
      series.back().points.push_back(
          {r.msPerFrame, r.surfaceSeries ? r.surfaceError : r.centroidError, r.variant.label});
    }
    std::string why;
    if (!writeLogLogPlot(o.png,
                         "Tears on the " + scene.name + ": error against cost (" +
                             std::to_string(o.particles) + " particles, " +
                             std::to_string(o.frames) + " frames)",
                         "ms per frame (simulation + surface + trails)",
                         "error vs reference (particle radii)", series, why)) {
      std::fprintf(stderr, "tears-sweep: %s\n", why.c_str());
      return 1;
    }
    std::printf("  wrote %s (zero errors are not drawn on log axes)\n", o.png.c_str());
  }
  return 0;
}

}  // namespace lacrima::bench
