// lacrima-bench head: from a head file to a rigged, posable, checked head, stage by stage, as
// the editor's Head workspace and lacrima-player do it (target: the ICT head in <= 1 s on one
// core). Stages: import (assimp; the default head's own loader), read + validate its
// feature-point file, propose the rest from the 8 anchors (proposeFeaturePoints, the default
// head as reference, loaded once beforehand as the editor does at start), then buildRig on the
// proposed file split at its progress stages (surface graphs and solver set-up, geodesic
// weights, head pivot and tear sources, bake), the PoseBlender, and checkRig.
//
// One core: the process pins itself to the CPU it starts on (sched_setaffinity) before
// timing; the rigging code has no thread pool of its own (no OpenMP, Eigen single-threaded),
// so the pin only keeps the scheduler from migrating it.
#include "BenchCommandLine.h"
#include "BenchSupport.h"
#include "RealHeads.h"

#include <lacrima/common/JsonWriter.h>
#include <lacrima/common/Milliseconds.h>
#include <lacrima/common/PoseSet.h>
#include <lacrima/rigging/DefaultHead.h>
#include <lacrima/rigging/FeaturePointFile.h>
#include <lacrima/rigging/FeaturePointProposal.h>
#include <lacrima/rigging/MeshImport.h>
#include <lacrima/rigging/RigBuilder.h>
#include <lacrima/rigging/RigChecks.h>

#include <sched.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <exception>
#include <optional>
#include <string>
#include <vector>

namespace lacrima::bench {

namespace {

constexpr double kIctTargetMs = 1000.0;

// The stages, in order; buildRig's are cut at its progress reports (RigBuilder.cpp).
enum Stage {
  kImport,
  kReadFdp,
  kPropose,
  kRigSetUp,  // feature points, FAPU, eye groups, surface graphs, solver factorisation
  kWeights,   // geodesic influence of every feature point (and the attached parts)
  kPivotTears,
  kBake,
  kBlender,
  kChecks,
  kStageCount
};
constexpr std::array<const char*, kStageCount> kStageNames = {"import",
                                                              "read + validate fdp",
                                                              "propose (8 anchors)",
                                                              "rig set-up",
                                                              "geodesic weights",
                                                              "neck pivot + tear sources",
                                                              "bake poses",
                                                              "blender",
                                                              "checks"};

struct Options {
  int runs = 5;
  bool json = false;
};

struct HeadCase {
  RealHeadSpec spec;
  std::optional<double> targetMs;
  std::array<std::vector<double>, kStageCount> ms;  // per stage, one entry per run
  std::vector<double> totalMs;
  int vertices = 0, triangles = 0, checks = 0, warnings = 0;
  std::string skipped;  // why, when the head is absent
};

std::optional<int> parseOptions(int argc, char** argv, Options& options) {
  BenchCommandLine line("head",
                        "From a head file to a rigged, posable, checked head: milliseconds of\n"
                        "each stage (import, feature points, proposal from 8 anchors, rig, bake,\n"
                        "blender, checks) for the ICT head and the default head, one core.");
  line.wholeNumber("runs", "N", "Timed runs per head, interleaved, after one warm-up (default 5).",
                   1, 100, options.runs);
  line.flag("json", "Print one JSON object instead of the table.", options.json);
  return line.parse(argc, argv);
}

// Pins the process to the CPU it runs on; returns that CPU, or -1 when the kernel refuses.
int pinToOneCore() {
  const int cpu = sched_getcpu();
  if (cpu < 0) return -1;
  cpu_set_t set;
  CPU_ZERO(&set);
  CPU_SET(cpu, &set);
  return sched_setaffinity(0, sizeof set, &set) == 0 ? cpu : -1;
}

// The anchors of the proposal, cut from a complete file: what a user clicks.
rigging::FeaturePointFile anchorsOnly(const rigging::FeaturePointFile& complete) {
  rigging::FeaturePointFile partial = complete;
  partial.points.clear();
  for (const std::string& id : rigging::proposalAnchors())
    if (const auto p = complete.points.find(id); p != complete.points.end())
      partial.points.insert(*p);
  return partial;
}

struct Reference {
  HeadMesh mesh;
  rigging::FeaturePointFile fdp;
};

// One pass from file to checked rig, each stage's milliseconds into `c`.
void runOnce(HeadCase& c, const Reference& reference, bool record) {
  std::array<double, kStageCount> ms{};
  auto start = SteadyClock::now();
  auto lap = [&](Stage s) {
    ms[s] = millisecondsSince(start);
    start = SteadyClock::now();
  };
  const HeadMesh mesh =
      c.spec.defaultHead ? rigging::loadDefaultHead() : rigging::importHeadMesh(c.spec.meshPath);
  lap(kImport);
  Warnings warnings;
  const rigging::FeaturePointFile complete =
      rigging::readFeaturePointFile(c.spec.fdpPath, &warnings);
  rigging::validateFeaturePoints(complete, mesh, &warnings);
  lap(kReadFdp);
  const rigging::FeaturePointFile partial = anchorsOnly(complete);
  const rigging::FeaturePointFile proposed =
      rigging::proposeFeaturePoints(partial, mesh, reference.fdp, reference.mesh, &warnings);
  lap(kPropose);
  rigging::RigOptions options;
  Stage current = kRigSetUp;
  options.progress = [&](double, std::string_view stage) {
    const Stage next = stage.rfind("influence", 0) == 0 ? kWeights
                       : stage == "head and tears"      ? kPivotTears
                       : stage == "baking poses"        ? kBake
                       : stage == "done"                ? kBlender
                                                        : current;
    if (next == current) return;
    lap(current);
    current = next;
  };
  const rigging::BuiltRig rig = rigging::buildRig(mesh, proposed, options);
  start = SteadyClock::now();  // "done" closed the bake; the blender starts now
  const PoseBlender blender(mesh, rig.poses);
  lap(kBlender);
  const std::vector<rigging::RigCheck> checks = rigging::checkRig(mesh, proposed, rig);
  lap(kChecks);
  if (!record) return;
  double total = 0;
  for (int s = 0; s < kStageCount; ++s) {
    c.ms[static_cast<std::size_t>(s)].push_back(ms[static_cast<std::size_t>(s)]);
    total += ms[static_cast<std::size_t>(s)];
  }
  c.totalMs.push_back(total);
  c.vertices = mesh.vertexCount();
  c.triangles = mesh.triangleCount();
  c.checks = static_cast<int>(checks.size());
  c.warnings = static_cast<int>(warnings.size() + rig.warnings.size());
}

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

}  // namespace

int runHead(int argc, char** argv) {
  Options options;
  if (const auto exit = parseOptions(argc, argv, options)) return *exit;
  const int cpu = pinToOneCore();

  std::vector<HeadCase> heads;
  heads.push_back({ictHeadSpec(), kIctTargetMs, {}, {}, 0, 0, 0, 0, {}});
  heads.push_back({defaultHeadSpec(), std::nullopt, {}, {}, 0, 0, 0, 0, {}});

  // The proposal's reference: the default head and its file, loaded once like the editor does.
  std::string why;
  std::optional<LoadedHead> defaultHead = loadRealHead(defaultHeadSpec(), why);
  if (!defaultHead) {
    std::fprintf(stderr, "lacrima-bench head: the default head is needed as the reference: %s\n",
                 why.c_str());
    return 1;
  }
  const Reference reference{std::move(defaultHead->mesh), std::move(defaultHead->fdp)};
  for (HeadCase& c : heads) {
    if (!c.spec.defaultHead && !loadRealMesh(c.spec, c.skipped)) continue;
    try {
      runOnce(c, reference, false);  // warm-up: page cache, allocators
    } catch (const std::exception& e) {
      c.skipped = e.what();
    }
  }
  // Interleaved: run k of every head before run k + 1 of any, so load drifts hit all alike.
  for (int run = 0; run < options.runs; ++run)
    for (HeadCase& c : heads)
      if (c.skipped.empty()) runOnce(c, reference, true);

  bool pass = true;
  for (const HeadCase& c : heads)
    if (c.targetMs && c.skipped.empty()) pass = pass && median(c.totalMs) <= *c.targetMs;

  if (options.json) {
    JsonWriter json(JsonWriter::Layout::Compact);
    json.beginObject();
    json.field("benchmark", "head");
    json.field("cpu", cpu);
    json.key("heads");
    json.beginArray();
    for (const HeadCase& c : heads) {
      json.beginObject();
      json.field("head", c.spec.name);
      if (!c.skipped.empty()) {
        json.field("skipped", c.skipped);
        json.endObject();
        continue;
      }
      json.field("vertices", c.vertices);
      json.field("triangles", c.triangles);
      json.key("stages_ms");
      json.beginObject();
      for (int s = 0; s < kStageCount; ++s)
        json.field(kStageNames[static_cast<std::size_t>(s)],
                   median(c.ms[static_cast<std::size_t>(s)]));
      json.endObject();
      json.field("total_ms", median(c.totalMs));
      if (c.targetMs) {
        json.field("target_ms", *c.targetMs);
        json.field("pass", median(c.totalMs) <= *c.targetMs);
      }
      json.endObject();
    }
    json.endArray();
    json.field("pass", pass);
    json.endObject();
    std::fputs(std::move(json).finish().c_str(), stdout);
    std::fputc('\n', stdout);
    return 0;
  }

  std::printf("head: file to rigged, posable, checked head; median ms of %d interleaved runs, %s\n",
              options.runs,
              cpu >= 0 ? ("pinned to CPU " + std::to_string(cpu)).c_str() : "not pinned");
  for (const HeadCase& c : heads) {
    if (!c.skipped.empty()) {
      std::printf("\n%s: skipped (%s)\n", c.spec.name.c_str(), c.skipped.c_str());
      continue;
    }
    std::printf("\n%s: %d vertices, %d triangles; %d checks, %d warnings\n", c.spec.name.c_str(),
                c.vertices, c.triangles, c.checks, c.warnings);
    for (int s = 0; s < kStageCount; ++s) {
      const auto& v = c.ms[static_cast<std::size_t>(s)];
      std::printf("  %-27s %8.1f ms  (%.1f - %.1f)\n", kStageNames[static_cast<std::size_t>(s)],
                  median(v), *std::min_element(v.begin(), v.end()),
                  *std::max_element(v.begin(), v.end()));
    }
    std::printf("  %-27s %8.1f ms", "total", median(c.totalMs));
    if (c.targetMs)
      std::printf("  (target <= %.0f ms: %s)", *c.targetMs,
                  median(c.totalMs) <= *c.targetMs ? "pass" : "FAIL");
    std::printf("\n");
  }
  return 0;
}

}  // namespace lacrima::bench
