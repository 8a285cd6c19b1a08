// lacrima-bench proposal: what proposing feature points costs and how close it lands. The
// default head's points proposed on the ICT-FaceKit head from the 8 anchors of its hand-made
// file, as imported (y up, centimetres) and turned to z up in millimetres, by the warp alone
// and feature-aware, with the eyes' and the lips' steps (FeaturePointProposal.h): the error
// against the hand-made points per FDP group, in ES0 and in millimetres, beside the
// milliseconds of each stage (fit, eyes, mouth = the lips' step, snap).
#include "BenchCommandLine.h"
#include "BenchSupport.h"
#include "RealHeads.h"

#include <lacrima/common/JsonWriter.h>
#include <lacrima/rigging/DefaultHead.h>
#include <lacrima/rigging/FeaturePointFile.h>
#include <lacrima/rigging/FeaturePointProposal.h>
#include <lacrima/rigging/MeshImport.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cstdio>
#include <exception>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace lacrima::bench {

namespace {

// What a proposal must reach on the ICT head, in ES0 (docs/rig.md, "Proposing feature points").
constexpr double kMeanTarget = 0.08;
constexpr double kWorstTarget = 0.3;

struct Options {
  int runs = 5;
  bool json = false;
};

std::optional<int> parseOptions(int argc, char** argv, Options& options) {
  BenchCommandLine line("proposal",
                        "Feature-point proposal on the ICT-FaceKit head from its 8 anchors: error "
                        "against the\nhand-made points per FDP group (ES0 and mm) beside "
                        "milliseconds per stage, for the\nhead as imported (y up, cm) and turned "
                        "to z up in mm; warp alone and feature-aware (eyes' and lips'\nsteps).");
  line.wholeNumber("runs", "N", "Timed runs of each proposal, after one warm-up (default 5).", 1,
                   1000, options.runs);
  line.flag("json", "Print one JSON object instead of the tables.", options.json);
  return line.parse(argc, argv);
}

struct Orientation {
  const char* name;
  Eigen::Matrix3f rotation;
  float scale;            // model units per centimetre
  double millimetresPer;  // millimetres per model unit
};

struct GroupError {
  int points = 0;
  double sum = 0, worst = 0;
  std::string worstId;
  double mean() const { return points ? sum / points : 0; }
};

struct MethodResult {
  rigging::ProposalMethod method;
  Timing fit, eyes, mouth, snap, total;
  std::map<int, GroupError> groups;  // by FDP group number
  GroupError all;
  rigging::FeaturePointFile proposed;
  bool sameVertices = true;  // as the first orientation's proposal by the same method
};

struct OrientationResult {
  const Orientation* orientation;
  double es0 = 0;  // model units
  std::vector<MethodResult> methods;
};

const char* nameOf(rigging::ProposalMethod method) {
  return method == rigging::ProposalMethod::Warp ? "warp alone" : "feature-aware";
}

bool meetsTargets(const GroupError& all) {
  return all.mean() <= kMeanTarget && all.worst <= kWorstTarget;
}

// The median of each stage over `runs` proposals (after a warm-up), and the errors.
MethodResult measure(rigging::ProposalMethod method, const rigging::FeaturePointFile& partial,
                     const HeadMesh& mesh, const rigging::FeaturePointFile& hand,
                     const rigging::FeaturePointFile& reference, const HeadMesh& referenceMesh,
                     double es0, int runs) {
  MethodResult out{method, {}, {}, {}, {}, {}, {}, {}, {}, true};
  std::vector<rigging::ProposalTimings> stages;
  rigging::FeaturePointFile& proposed = out.proposed;
  out.total = timeRuns(runs, [&] {
    rigging::ProposalTimings t;
    proposed = rigging::proposeFeaturePoints(partial, mesh, reference, referenceMesh, nullptr,
                                             {method}, &t);
    stages.push_back(t);
  });
  stages.erase(stages.begin());  // the warm-up
  const auto median = [&](double rigging::ProposalTimings::*stage) {
    std::vector<double> v;
    for (const auto& t : stages) v.push_back(t.*stage);
    std::sort(v.begin(), v.end());
    Timing timing;
    timing.medianMs = v[v.size() / 2];
    timing.minMs = v.front();
    timing.maxMs = v.back();
    timing.runs = static_cast<int>(v.size());
    return timing;
  };
  out.fit = median(&rigging::ProposalTimings::fitMs);
  out.eyes = median(&rigging::ProposalTimings::eyesMs);
  out.mouth = median(&rigging::ProposalTimings::mouthMs);
  out.snap = median(&rigging::ProposalTimings::snapMs);

  for (const auto& [id, spec] : hand.points) {
    if (partial.points.count(id)) continue;  // anchors are given, not proposed
    const auto p = proposed.points.find(id);
    if (p == proposed.points.end()) continue;
    const double e =
        (rigging::surfacePosition(p->second.at, mesh) - rigging::surfacePosition(spec.at, mesh))
            .norm() /
        es0;
    for (GroupError* g : {&out.groups[std::stoi(id)], &out.all}) {
      ++g->points;
      g->sum += e;
      if (e > g->worst) g->worst = e, g->worstId = id;
    }
  }
  return out;
}

bool sameVertices(const rigging::FeaturePointFile& a, const rigging::FeaturePointFile& b) {
  if (a.points.size() != b.points.size()) return false;
  for (const auto& [id, spec] : a.points) {
    const auto other = b.points.find(id);
    if (other == b.points.end() || other->second.at.submesh != spec.at.submesh ||
        other->second.at.vertex != spec.at.vertex)
      return false;
  }
  return true;
}

void printTable(const std::vector<OrientationResult>& results, const Timing& import) {
  std::printf(
      "proposal: the default head's feature points proposed on the ICT-FaceKit head from the 8 "
      "anchors of\n  tests/rigging/ict-facekit.fdp.json, against its other points (target: mean "
      "<= %.2f ES0, worst <= %.1f ES0)\n",
      kMeanTarget, kWorstTarget);
  std::printf("  import (importHeadMesh, OBJ)  median %8.2f ms  (min %.2f, max %.2f, %d runs)\n",
              import.medianMs, import.minMs, import.maxMs, import.runs);
  for (const OrientationResult& r : results) {
    const double mm = r.es0 * r.orientation->millimetresPer;
    std::printf("\n  %s (ES0 = %.2f mm)\n", r.orientation->name, mm);
    std::printf("    %-20s %9s %9s %9s %9s %9s\n", "stage (median ms)", "fit", "eyes", "mouth",
                "snap", "total");
    for (const MethodResult& m : r.methods)
      std::printf("    %-20s %9.2f %9.2f %9.2f %9.2f %9.2f\n", nameOf(m.method), m.fit.medianMs,
                  m.eyes.medianMs, m.mouth.medianMs, m.snap.medianMs, m.total.medianMs);
    std::printf("    %-8s %6s", "group", "points");
    for (const MethodResult& m : r.methods)
      std::printf("   %-36s", (std::string(nameOf(m.method)) + ": mean / worst").c_str());
    std::printf("\n");
    const auto row = [&](const std::string& label, int points,
                         const std::vector<const GroupError*>& errors) {
      std::printf("    %-8s %6d", label.c_str(), points);
      for (const GroupError* g : errors)
        std::printf("   %.3f / %.3f ES0 (%4.1f / %4.1f mm) %-5s", g->mean(), g->worst,
                    g->mean() * mm, g->worst * mm, g->worstId.c_str());
      std::printf("\n");
    };
    for (const auto& [group, error] : r.methods.front().groups) {
      std::vector<const GroupError*> errors;
      for (const MethodResult& m : r.methods) errors.push_back(&m.groups.at(group));
      row(std::to_string(group) + ".x", error.points, errors);
    }
    std::vector<const GroupError*> all;
    for (const MethodResult& m : r.methods) all.push_back(&m.all);
    row("all", r.methods.front().all.points, all);
    std::printf("    targets met (%s): %s;  the same vertices as in the first orientation: %s\n",
                nameOf(r.methods.back().method), meetsTargets(r.methods.back().all) ? "yes" : "NO",
                r.methods.front().sameVertices && r.methods.back().sameVertices ? "yes" : "NO");
  }
}

void writeError(JsonWriter& json, const GroupError& g, double mm) {
  json.field("points", g.points);
  json.field("mean_es0", g.mean());
  json.field("worst_es0", g.worst);
  json.field("mean_mm", g.mean() * mm);
  json.field("worst_mm", g.worst * mm);
  json.field("worst_point", g.worstId);
}

void printJson(const std::vector<OrientationResult>& results, const Timing& import) {
  JsonWriter json(JsonWriter::Layout::Compact);
  json.beginObject();
  json.field("benchmark", "proposal");
  writeTiming(json, "import_ms", import);
  json.key("orientations");
  json.beginArray();
  bool pass = true;
  for (const OrientationResult& r : results) {
    const double mm = r.es0 * r.orientation->millimetresPer;
    json.beginObject();
    json.field("orientation", r.orientation->name);
    json.field("es0_mm", mm);
    json.key("methods");
    json.beginArray();
    for (const MethodResult& m : r.methods) {
      json.beginObject();
      json.field("method", m.method == rigging::ProposalMethod::Warp ? "warp" : "feature-aware");
      writeTiming(json, "fit_ms", m.fit);
      writeTiming(json, "eyes_ms", m.eyes);
      writeTiming(json, "mouth_ms", m.mouth);
      writeTiming(json, "snap_ms", m.snap);
      writeTiming(json, "total_ms", m.total);
      json.field("same_vertices", m.sameVertices);
      json.key("groups");
      json.beginArray();
      for (const auto& [group, error] : m.groups) {
        json.beginObject();
        json.field("group", group);
        writeError(json, error, mm);
        json.endObject();
      }
      json.endArray();
      json.key("all");
      json.beginObject();
      writeError(json, m.all, mm);
      json.endObject();
      json.endObject();
    }
    json.endArray();
    json.endObject();
    pass = pass && meetsTargets(r.methods.back().all);
    for (const MethodResult& m : r.methods) pass = pass && m.sameVertices;
  }
  json.endArray();
  json.field("target_mean_es0", kMeanTarget);
  json.field("target_worst_es0", kWorstTarget);
  json.field("pass", pass);
  json.endObject();
  std::fputs(std::move(json).finish().c_str(), stdout);
}

}  // namespace

int runProposal(int argc, char** argv) {
  Options options;
  if (const std::optional<int> status = parseOptions(argc, argv, options)) return *status;

  std::string why;
  const std::optional<HeadMesh> reference = loadRealMesh(defaultHeadSpec(), why);
  std::optional<LoadedHead> ict = reference ? loadRealHead(ictHeadSpec(), why) : std::nullopt;
  if (!reference || !ict) {
    std::fprintf(stderr, "proposal: skipped: %s\n", why.c_str());
    if (options.json) std::printf("{\"benchmark\": \"proposal\", \"skipped\": true}");
    return 0;
  }
  try {
    const rigging::FeaturePointFile referenceFdp =
        rigging::readFeaturePointFile(defaultHeadSpec().fdpPath);
    const Timing import =
        timeRuns(options.runs, [&] { rigging::importHeadMesh(ictHeadSpec().meshPath); });

    rigging::FeaturePointFile partial = ict->fdp;
    partial.points.clear();
    for (const std::string& id : rigging::proposalAnchors())
      partial.points[id] = ict->fdp.points.at(id);

    const Orientation orientations[] = {
        {"y up, centimetres (as imported)", Eigen::Matrix3f::Identity(), 1.0f, 10.0},
        {"z up, millimetres", Eigen::AngleAxisf(EIGEN_PI / 2, Eigen::Vector3f::UnitX()).matrix(),
         10.0f, 1.0},
    };
    std::vector<OrientationResult> results;
    for (const Orientation& o : orientations) {
      HeadMesh mesh = ict->mesh;
      mesh.positions = (o.scale * o.rotation) * ict->mesh.positions;
      OrientationResult r{&o, 0, {}};
      r.es0 = (rigging::surfacePosition(ict->fdp.points.at("3.5").at, mesh) -
               rigging::surfacePosition(ict->fdp.points.at("3.6").at, mesh))
                  .norm();
      for (const rigging::ProposalMethod method :
           {rigging::ProposalMethod::Warp, rigging::ProposalMethod::FeatureAware}) {
        MethodResult m =
            measure(method, partial, mesh, ict->fdp, referenceFdp, *reference, r.es0, options.runs);
        if (!results.empty())
          m.sameVertices =
              sameVertices(m.proposed, results.front().methods[r.methods.size()].proposed);
        r.methods.push_back(std::move(m));
      }
      results.push_back(std::move(r));
    }
    if (options.json) {
      printJson(results, import);
    } else {
      printTable(results, import);
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "proposal: %s\n", e.what());
    return 1;
  }
  return 0;
}

}  // namespace lacrima::bench
