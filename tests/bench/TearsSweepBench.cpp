// lacrima-bench tears-sweep: what accuracy costs in time. Fine reference runs of the full tear
// pipeline on the cheek sheet (or the rigged default head), then runs that each coarsen one
// quantity (sub-step safety factor, kernel size, marching-cubes cube size, neighbour structure,
// pressure solver); each is reported with its error (SweepErrors.h) beside its milliseconds per
// frame, as a table, JSON, a CSV file and a log-log PNG plot.
//
// The solvers come from one list (SweepSolvers.h): a solver added there gets its sub-step rows,
// its reference and check, its dashed curve and its thread axis here with no other change.
//
// Two references, because the solvers are different models:
//   the WCSPH reference   WCSPH at sub-step x0.25 and cube x0.25: every row is measured against
//                         it, so DFSPH rows include the model's difference (an incompressible
//                         fluid against one with a 0.2 m/s speed of sound), not only inaccuracy;
//   each solver's own     that solver at sub-step x0.25 (cube x0.25): its rows measured against
//                         it say how far coarser sub-steps take that solver from where it
//                         converges. Converged means a run at x0.125 ends closer to it (the
//                         "reference check") than any of the solver's sweep rows.
// The cube-size series runs extra meshers on the WCSPH reference simulation, so its particles are
// the reference's and its error is the surface discretisation alone; its ms per frame is that
// simulation + trails + its own mesher.
//
// The thread axis reruns each solver's default row (sub-step x1) with each thread count asked:
// the simulation shares its sub-steps over threads bit-identically (decisions 0005, 0015), so the
// final state hash and every error must be the same, and only the milliseconds may change.
#include "BenchCommandLine.h"
#include "NumberList.h"
#include "SweepErrors.h"
#include "SweepPlot.h"
#include "SweepSolvers.h"
#include "TearsPipeline.h"

#include <lacrima/common/JsonWriter.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <thread>
#include <vector>

namespace lacrima::bench {

namespace {

using namespace lacrima::tears;

// "x1.5" for a scale of 1.5, "x0.125" for 0.125.
std::string scaleLabel(double scale) {
  char text[24];
  std::snprintf(text, sizeof text, "x%g", scale);
  return text;
}

struct Options {
  int particles = 200;
  int frames = 66;  // 3 s at 22 fps: long enough for drops to run down the sheet
  double fps = 22;
  bool head = false;  // the rigged default head instead of the cheek sheet
  bool json = false;
  int repeats = 3;                 // runs per row; the fastest counts
  int threads = 0;                 // SimulationOptions::threads of every sweep run
  std::vector<double> threadAxis;  // thread counts of the axis; empty: 1 and all hardware threads
  std::string csv, png;
};

std::optional<int> parseOptions(int argc, char** argv, Options& o) {
  BenchCommandLine line(
      "tears-sweep",
      "Error beside ms per frame of the full tear pipeline (simulation + surface + trails) on\n"
      "the cheek sheet or the default head, against a fine WCSPH reference and against each\n"
      "solver's own fine run, sweeping the sub-step safety factor per registered solver,\n"
      "the kernel size, the cube size and the neighbour structure; then each solver's default\n"
      "row at each thread count of the thread axis (the error must not change).");
  line.wholeNumber("particles", "N", "Particles in all (default 200).", 1, 2 * kMaxTearParticles,
                   o.particles);
  line.wholeNumber("frames", "F", "Frames at 22 fps (default 66).", 1, 100000, o.frames);
  line.choice("head",
              "The cheek sheet (default) or the cached default head with the rig's sources.",
              {{"sheet", false}, {"default", true}}, o.head);
  line.wholeNumber("threads", "T",
                   "Threads each sweep run's simulation shares (default 0: LACRIMA_THREADS, else "
                   "all).",
                   0, 256, o.threads);
  line.option(
      "threads-axis", "T1,T2,...",
      "Thread counts the default rows are rerun with (default: 1 and all hardware "
      "threads).",
      [&o](const QString& text) { return readNumberList(text, 1, 256, true, o.threadAxis); });
  line.wholeNumber("repeats", "R",
                   "Runs per row, the fastest milliseconds kept (default 3; the errors are the "
                   "same every time).",
                   1, 100, o.repeats);
  line.flag("json", "One JSON object instead of the table.", o.json);
  line.text("csv", "FILE", "Also write the table as CSV.", o.csv);
  line.text("png", "FILE", "Also draw error against ms per frame (log axes) as a PNG.", o.png);
  return line.parse(argc, argv);
}

// One run's settings: the quantity it sweeps (series), its value label and what it changes.
struct Variant {
  std::string series, label;
  double lambdaScale = 1, kernelScale = 1, cubeScale = 1;
  std::string neighbours = SimulationOptions{}.neighbours.key;  // registry keys
  std::string solver = SimulationOptions{}.pressureSolver.key;
  int threads = 0;  // 0: the sweep's --threads
};

struct Row {
  Variant variant;
  double msPerFrame = 0, substepsPerFrame = 0;
  int threads = 1;
  std::uint64_t stateHash = 0;
  RunErrors vsReference, vsOwn;  // against the WCSPH reference, against the solver's own
  bool surfaceSeries = false;    // the plotted error is the surface error
};

// A solver's converged run and the check that it is converged.
struct SolverReference {
  const SolverEntry* solver = nullptr;
  RunResult fine;         // sub-step x0.25
  double finerMs = 0;     // the check run's ms per frame (sub-step x0.125)
  RunErrors check;        // the x0.125 run against the x0.25 one
  double closestRow = 0;  // the centroid error of the solver's sweep row closest to its reference
  bool converged =
      false;  // check.centroid < closestRow: the curve lies above the reference's noise
};

const TearSettings kDefaults{};
constexpr double kFineLambda = 0.25, kFinerLambda = 0.125, kFineCube = 0.25;

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
  o.scaleSubsteps(v.lambdaScale);
  return o;
}

// Runs the pipeline once; `extraCubes` add meshers at those cube scales (results in `extras`).
RunResult runOnce(const TearScene& scene, const Variant& v, const Options& o,
                  const std::vector<double>& extraCubes = {},
                  std::vector<RunResult>* extras = nullptr) {
  SimulationOptions options = optionsFor(v);
  options.threads = v.threads > 0 ? v.threads : o.threads;
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
  r.threads = sim.threads();
  const ParticleSet& p = sim.particles();
  r.stateHash = stateHash(p);
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
  captureSurface(pipeline.mesher().surface(), r);
  if (extras) {
    extras->clear();
    for (std::size_t k = 0; k < meshers.size(); ++k) {
      RunResult e = r;
      e.msPerFrame = (baseMs + extraMs[k]) / o.frames;
      captureSurface(meshers[k]->surface(), e);
      extras->push_back(std::move(e));
    }
  }
  return r;
}

// Runs the pipeline `--repeats` times and keeps the fastest milliseconds: on a shared machine
// the others' load only ever adds time. The runs are deterministic, so every repeat must end in
// the same state; one that does not is reported (and the first is kept).
RunResult run(const TearScene& scene, const Variant& v, const Options& o,
              const std::vector<double>& extraCubes = {},
              std::vector<RunResult>* extras = nullptr) {
  RunResult best = runOnce(scene, v, o, extraCubes, extras);
  for (int k = 1; k < o.repeats; ++k) {
    std::vector<RunResult> again;
    const RunResult r = runOnce(scene, v, o, extraCubes, extras ? &again : nullptr);
    if (r.stateHash != best.stateHash)
      std::fprintf(stderr, "tears-sweep: %s %s ended in another state on repeat %d\n",
                   v.series.c_str(), v.label.c_str(), k + 1);
    best.msPerFrame = std::min(best.msPerFrame, r.msPerFrame);
    for (std::size_t e = 0; extras && e < extras->size(); ++e)
      (*extras)[e].msPerFrame = std::min((*extras)[e].msPerFrame, again[e].msPerFrame);
  }
  return best;
}

// The errors of a finished run against both references.
class Comparison {
 public:
  Comparison(const std::vector<SolverReference>& refs, double radius)
      : refs_(refs), radius_(radius) {}
  Row row(const Variant& v, const RunResult& r) const {
    Row row{v, r.msPerFrame, r.substepsPerFrame, r.threads, r.stateHash, {}, {}, false};
    row.vsReference = errorsBetween(r, refs_.front().fine, radius_, 2 * radius_);
    row.vsOwn = errorsBetween(r, own(v.solver).fine, radius_, 2 * radius_);
    return row;
  }
  const SolverReference& own(const std::string& solver) const {
    for (const SolverReference& ref : refs_)
      if (ref.solver->key == solver) return ref;
    return refs_.front();
  }

 private:
  const std::vector<SolverReference>& refs_;
  double radius_;
};

std::string hashText(std::uint64_t hash) {
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(hash));
  return text;
}

bool sameErrors(const RunErrors& a, const RunErrors& b) {
  auto same = [](double x, double y) { return x == y || (std::isnan(x) && std::isnan(y)); };
  return same(a.particleRms, b.particleRms) && same(a.centroid, b.centroid) &&
         same(a.surface, b.surface) && same(a.areaDifference, b.areaDifference) &&
         a.matched == b.matched;
}

// The thread axis of one solver: its default row at each thread count.
struct ThreadAxis {
  const SolverEntry* solver = nullptr;
  std::vector<Row> rows;
  bool identical = true;  // every state hash and error equal to the first count's
};

struct SweepReport {
  const TearScene* scene = nullptr;
  double radius = 0;
  std::vector<SolverReference> refs;
  std::vector<Row> rows;
  std::vector<ThreadAxis> threadAxes;
  bool identical() const {
    return std::all_of(threadAxes.begin(), threadAxes.end(),
                       [](const ThreadAxis& a) { return a.identical; });
  }
};

void printTable(const SweepReport& s) {
  std::printf(
      "  errors in reference particle radii (%.4g head units); ms = full pipeline per frame "
      "(mean); 'own': against the run's own solver at sub-step x%g\n",
      s.radius, kFineLambda);
  for (const SolverReference& ref : s.refs)
    std::printf(
        "  %s reference (x%g, %.3f ms/frame): x%g (%.3f ms/frame) ends %.3g radii (centroid), "
        "%.3g (particle RMS) from it; its closest sweep row %.3g: %s\n",
        ref.solver->name.c_str(), kFineLambda, ref.fine.msPerFrame, kFinerLambda, ref.finerMs,
        ref.check.centroid, ref.check.particleRms, ref.closestRow,
        ref.converged ? "converged" : "NOT converged (the rows are within its noise)");
  std::printf("  %-26s %-9s %9s %8s %7s %9s %9s %9s %8s %9s %9s\n", "swept", "value", "ms/frame",
              "substeps", "threads", "centroid", "RMS", "surface", "area", "own cent.", "own RMS");
  auto print = [](const Row& r) {
    std::printf("  %-26s %-9s %9.3f %8.1f %7d %9.4g %9.4g %9.4g %7.1f%% %9.4g %9.4g\n",
                r.variant.series.c_str(), r.variant.label.c_str(), r.msPerFrame, r.substepsPerFrame,
                r.threads, r.vsReference.centroid, r.vsReference.particleRms, r.vsReference.surface,
                100 * r.vsReference.areaDifference, r.vsOwn.centroid, r.vsOwn.particleRms);
  };
  for (const Row& r : s.rows) print(r);
  for (const ThreadAxis& axis : s.threadAxes) {
    for (const Row& r : axis.rows) print(r);
    std::printf("  %s thread axis: state hash %s, error identical: %s\n", axis.solver->name.c_str(),
                hashText(axis.rows.front().stateHash).c_str(), axis.identical ? "yes" : "NO");
  }
}

bool writeCsv(const SweepReport& s, const Options& o) {
  std::ofstream csv(o.csv);
  csv << "scene,series,value,solver,lambda_scale,kernel_scale,cube_scale,neighbours,threads,"
         "ms_per_frame,substeps_per_frame,state_hash,particle_rms_radii,centroid_error_radii,"
         "surface_error_radii,area_difference,matched_particles,own_reference_particle_rms_radii,"
         "own_reference_centroid_error_radii,own_reference_surface_error_radii\n";
  auto line = [&](const Row& r) {
    const Variant& v = r.variant;
    csv << (o.head ? "default_head" : "cheek_sheet") << ',' << v.series << ',' << v.label << ','
        << v.solver << ',' << v.lambdaScale << ',' << v.kernelScale << ',' << v.cubeScale << ','
        << v.neighbours << ',' << r.threads << ',' << r.msPerFrame << ',' << r.substepsPerFrame
        << ',' << hashText(r.stateHash) << ',' << r.vsReference.particleRms << ','
        << r.vsReference.centroid << ',' << r.vsReference.surface << ','
        << r.vsReference.areaDifference << ',' << r.vsReference.matched << ','
        << r.vsOwn.particleRms << ',' << r.vsOwn.centroid << ',' << r.vsOwn.surface << '\n';
  };
  for (const Row& r : s.rows) line(r);
  for (const ThreadAxis& axis : s.threadAxes)
    for (const Row& r : axis.rows) line(r);
  if (!csv) {
    std::fprintf(stderr, "tears-sweep: cannot write %s\n", o.csv.c_str());
    return false;
  }
  return true;
}

void writeErrors(JsonWriter& json, std::string_view name, const RunErrors& e) {
  json.key(name);
  json.beginObject();
  json.field("centroid_radii", e.centroid);
  json.field("particle_rms_radii", e.particleRms);
  json.field("surface_radii", e.surface);
  json.field("area_difference", e.areaDifference);
  json.field("matched_particles", e.matched);
  json.endObject();
}

void writeRow(JsonWriter& json, const Row& r) {
  const Variant& v = r.variant;
  json.beginObject();
  json.field("series", v.series);
  json.field("value", v.label);
  json.field("solver", v.solver);
  json.field("lambda_scale", v.lambdaScale);
  json.field("kernel_scale", v.kernelScale);
  json.field("cube_scale", v.cubeScale);
  json.field("neighbours", v.neighbours);
  json.field("threads", r.threads);
  json.field("ms_per_frame", r.msPerFrame);
  json.field("substeps_per_frame", r.substepsPerFrame);
  json.field("state_hash", hashText(r.stateHash));
  writeErrors(json, "vs_wcsph_reference", r.vsReference);
  writeErrors(json, "vs_own_reference", r.vsOwn);
  json.endObject();
}

void printJson(const SweepReport& s, const Options& o) {
  JsonWriter json(JsonWriter::Layout::Compact);
  json.beginObject();
  json.field("benchmark", "tears-sweep");
  json.field("scene", o.head ? "default_head" : "cheek_sheet");
  json.field("particles", o.particles);
  json.field("frames", o.frames);
  json.field("fps", o.fps);
  json.field("repeats", o.repeats);
  json.field("particle_radius", s.radius);
  json.key("references");
  json.beginArray();
  for (const SolverReference& ref : s.refs) {
    json.beginObject();
    json.field("solver", ref.solver->key);
    json.field("lambda_scale", kFineLambda);
    json.field("ms_per_frame", ref.fine.msPerFrame);
    json.field("check_lambda_scale", kFinerLambda);
    json.field("check_ms_per_frame", ref.finerMs);
    writeErrors(json, "check", ref.check);
    json.field("closest_row_centroid_radii", ref.closestRow);
    json.field("converged", ref.converged);
    json.endObject();
  }
  json.endArray();
  json.key("rows");
  json.beginArray();
  for (const Row& r : s.rows) writeRow(json, r);
  json.endArray();
  json.key("thread_axis");
  json.beginArray();
  for (const ThreadAxis& axis : s.threadAxes) {
    json.beginObject();
    json.field("solver", axis.solver->key);
    json.field("error_identical", axis.identical);
    json.key("runs");
    json.beginArray();
    for (const Row& r : axis.rows) writeRow(json, r);
    json.endArray();
    json.endObject();
  }
  json.endArray();
  json.field("error_identical", s.identical());
  json.endObject();
  std::fputs(std::move(json).finish().c_str(), stdout);
}

// Curves: per solver its sub-step rows against the WCSPH reference (solid) and, for the other
// solvers, against their own reference (dashed, hollow markers, same colour), and its reference
// check as one point; then the kernel, cube and neighbour series against the WCSPH reference.
bool drawPlot(const SweepReport& s, const Options& o) {
  std::vector<PlotSeries> series;
  const int solverCount = int(s.refs.size());
  for (int k = 0; k < solverCount; ++k) {
    const SolverEntry& solver = *s.refs[std::size_t(k)].solver;
    const std::string prefix = std::string(solver.name) + " sub-step";
    PlotSeries vsRef{
        prefix + ": centroid vs " + s.refs.front().solver->name + " ref", {}, k, false, true};
    PlotSeries vsOwn{prefix + ": centroid vs own " + solver.name + " ref", {}, k, true, true};
    for (const Row& r : s.rows)
      if (r.variant.series == prefix + " factor") {
        vsRef.points.push_back({r.msPerFrame, r.vsReference.centroid, r.variant.label});
        vsOwn.points.push_back({r.msPerFrame, r.vsOwn.centroid, r.variant.label});
      }
    series.push_back(std::move(vsRef));
    if (k > 0) series.push_back(std::move(vsOwn));  // the first is the common reference
  }
  for (int k = 0; k < solverCount; ++k) {
    const SolverReference& ref = s.refs[std::size_t(k)];
    series.push_back({std::string(ref.solver->name) + " ref check: x0.125 vs x0.25",
                      {{ref.finerMs, ref.check.centroid, scaleLabel(kFinerLambda)}},
                      k,
                      false,
                      true,
                      PlotSeries::Shape::Diamond});
  }
  int colour = solverCount;
  for (const char* name : {"kernel size", "cube size (surface)", "neighbour structure"}) {
    const bool surface = std::string(name) == "cube size (surface)";
    PlotSeries curve{std::string(surface ? "cube size: surface" : name) +
                         (surface ? " error vs WCSPH ref" : ": centroid vs WCSPH ref"),
                     {},
                     colour++,
                     false,
                     true};
    for (const Row& r : s.rows)
      if (r.variant.series == name)
        curve.points.push_back({r.msPerFrame,
                                surface ? r.vsReference.surface : r.vsReference.centroid,
                                r.variant.label});
    series.push_back(std::move(curve));
  }
  std::string why;
  const PlotAxes axes{
      "Tears on the " + s.scene->name + ": error against cost (" + std::to_string(o.particles) +
          " particles, " + std::to_string(o.frames) + " frames)",
      "ms per frame (simulation + surface + trails)", "error (particle radii)", true, true};
  if (!writePlot(o.png, axes, series, why)) {
    std::fprintf(stderr, "tears-sweep: %s\n", why.c_str());
    return false;
  }
  return true;
}

}  // namespace

int runTearsSweep(int argc, char** argv) {
  Options o;
  if (const std::optional<int> status = parseOptions(argc, argv, o)) return *status;
  const std::optional<TearScene> loaded = benchScene(o.head, "tears-sweep");
  if (!loaded) return 0;
  const TearScene& scene = *loaded;
  if (o.threadAxis.empty())
    o.threadAxis = {1.0, double(std::max(1u, std::thread::hardware_concurrency()))};

  if (!o.json) {
    std::printf(
        "tears-sweep: %d particles, %d frames at %g fps on the %s, fastest of %d runs each; "
        "references: each solver at sub-step x%g, cube x%g ...\n",
        o.particles, o.frames, o.fps, scene.name.c_str(), o.repeats, kFineLambda, kFineCube);
    std::fflush(stdout);
  }
  SweepReport s;
  s.scene = &scene;
  const std::vector<SolverEntry> solvers = sweepSolvers();  // outlives the report's pointers

  // The references, the WCSPH one first; its extra meshers are the cube-size series.
  const std::vector<double> cubeScales = {0.5, 1, 2};
  std::vector<RunResult> cubeRuns;
  for (const SolverEntry& solver : solvers) {
    Variant fine{"reference", "fine", kFineLambda, 1, kFineCube};
    fine.solver = solver.key;
    Variant finer = fine;
    finer.lambdaScale = kFinerLambda;
    SolverReference ref;
    ref.solver = &solver;
    ref.fine = s.refs.empty() ? run(scene, fine, o, cubeScales, &cubeRuns) : run(scene, fine, o);
    if (s.refs.empty())
      s.radius = scene.simulate(settingsFor(fine), optionsFor(fine))->particleRadius();
    const RunResult check = run(scene, finer, o);
    ref.finerMs = check.msPerFrame;
    ref.check = errorsBetween(check, ref.fine, s.radius, 2 * s.radius);
    s.refs.push_back(std::move(ref));
  }
  const Comparison compare(s.refs, s.radius);

  s.rows.push_back(compare.row({"reference", "fine", kFineLambda, 1, kFineCube}, s.refs[0].fine));
  for (SolverReference& ref : s.refs) {
    const std::string series = std::string(ref.solver->name) + " sub-step factor";
    double closest = std::numeric_limits<double>::infinity();
    for (double lambda : {0.5, 1.0, 1.5, 2.0}) {
      Variant v{series, scaleLabel(lambda), lambda};
      v.solver = ref.solver->key;
      s.rows.push_back(compare.row(v, run(scene, v, o)));
      closest = std::min(closest, s.rows.back().vsOwn.centroid);
    }
    ref.closestRow = closest;
    ref.converged = ref.check.centroid < closest;
  }
  for (double k : {0.5, 0.75, 1.0, 1.5}) {
    const Variant v{"kernel size", scaleLabel(k), 1, k};
    s.rows.push_back(compare.row(v, run(scene, v, o)));
  }
  for (std::size_t k = 0; k < cubeScales.size(); ++k) {
    const Variant v{"cube size (surface)", scaleLabel(cubeScales[k]), kFineLambda, 1,
                    cubeScales[k]};
    Row row = compare.row(v, cubeRuns[k]);
    row.surfaceSeries = true;
    s.rows.push_back(row);
  }
  for (const std::string& key : registeredKeys(MethodFamily::NeighbourStructure)) {
    Variant v{"neighbour structure", key};
    v.neighbours = key;
    s.rows.push_back(compare.row(v, run(scene, v, o)));
  }
  for (const SolverEntry& solver : solvers) {
    ThreadAxis axis;
    axis.solver = &solver;
    for (double t : o.threadAxis) {
      const int threads = int(t);
      Variant v{solver.name + " threads", std::to_string(threads) + " thr"};
      v.solver = solver.key;
      v.threads = threads;
      axis.rows.push_back(compare.row(v, run(scene, v, o)));
      const Row& first = axis.rows.front();
      const Row& last = axis.rows.back();
      axis.identical = axis.identical && last.stateHash == first.stateHash &&
                       sameErrors(last.vsReference, first.vsReference) &&
                       sameErrors(last.vsOwn, first.vsOwn);
    }
    s.threadAxes.push_back(std::move(axis));
  }

  if (o.json)
    printJson(s, o);
  else
    printTable(s);
  if (!o.csv.empty()) {
    if (!writeCsv(s, o)) return 1;
    if (!o.json) std::printf("  wrote %s\n", o.csv.c_str());
  }
  if (!o.png.empty()) {
    if (!drawPlot(s, o)) return 1;
    if (!o.json) std::printf("  wrote %s (zero errors are not drawn on log axes)\n", o.png.c_str());
  }
  return 0;
}

}  // namespace lacrima::bench
