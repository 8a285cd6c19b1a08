// lacrima-bench poses: bake every FAP pose of a head and blend them all per frame, with the
// project's targets beside the figures (bake < 1 s on the default head, < 5 s on the 26.7k-vertex
// ICT head; blend < 0.5 ms per frame on the default head, one core).
//
// Besides synthetic stand-ins of the real vertex counts (tests/common/SyntheticHead.h), the real
// default head and ICT head are rigged through buildRig with their feature-point files
// (RealHeads.h); for those the rig build (geodesic weights + bake) is timed too, since that is
// what a user waits for when a head is loaded.
#include "BenchCommandLine.h"
#include "BenchSupport.h"
#include "RealHeads.h"

#include "../common/SyntheticHead.h"

#include <lacrima/common/JsonWriter.h>
#include <lacrima/common/PoseBaking.h>
#include <lacrima/common/PoseSet.h>
#include <lacrima/rigging/RigBuilder.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>
#include <vector>

namespace lacrima::bench {

namespace {

constexpr double kDefaultBlendTargetMs = 0.5;

struct Options {
  int frames = 2000;  // timed blends per head
  int runs = 5;       // timed bakes per head
  int rigRuns = 1;    // timed rig builds per real head (each also bakes; seconds on ICT)
  bool json = false;
};

struct HeadCase {
  std::string name;
  double bakeTargetMs;
  std::optional<double> blendTargetMs;  // the blend target is set for the default head only
};

struct Figures {
  int vertices = 0, triangles = 0;
  int poses = 0;              // non-empty linear poses
  long long poseEntries = 0;  // sum of pose sizes: the per-frame scatter work
  double meanPoseSize = 0;
  Timing bake, blend;
};

std::optional<int> parseOptions(int argc, char** argv, Options& options) {
  BenchCommandLine line(
      "poses",
      "Bakes all FAP poses of synthetic heads with the default head's and the ICT head's\n"
      "vertex counts, and of the real default and ICT heads rigged by buildRig (skipped\n"
      "with a note when absent), then blends every pose at once per frame.");
  line.wholeNumber("frames", "N", "Timed blends per head, after one warm-up (default 2000).", 1,
                   1'000'000, options.frames);
  line.wholeNumber("runs", "N", "Timed bakes per head, after one warm-up (default 5).", 1, 1000,
                   options.runs);
  line.wholeNumber("rig-runs", "N",
                   "Timed buildRig calls per real head, after one warm-up (default 1).", 1, 1000,
                   options.rigRuns);
  line.flag("json", "Print one JSON object instead of the table.", options.json);
  return line.parse(argc, argv);
}

// Frames that keep every driven channel non-zero (so every pose costs its full price) and
// change from frame to frame like an animation: a slow sine per channel at half its slider span.
std::vector<FapValues> animationFrames(const ChannelMask& driven, int count) {
  std::vector<FapValues> frames(static_cast<size_t>(count), FapValues{});
  for (int f = 0; f < count; ++f)
    for (int fap = 3; fap <= kFapCount; ++fap) {
      if (!driven.test(static_cast<size_t>(channelIndex(fap)))) continue;
      const FapInfo& info = fapInfo(fap);
      const double amplitude = 0.25 * (info.sliderMax - info.sliderMin);
      const double phase = 0.05 * f + 0.7 * fap;
      // Offset from zero so a sine crossing never makes a channel free.
      frames[static_cast<size_t>(f)][static_cast<size_t>(channelIndex(fap))] =
          static_cast<float>(std::round(amplitude * (0.6 + 0.4 * std::sin(phase))));
    }
  return frames;
}

// Bake and blend cost of one head with its rig (rig.mesh is set to `head`).
Figures measureHead(const HeadMesh& head, RigInput rig, const Options& options) {
  rig.mesh = &head;
  Figures figures;
  figures.vertices = head.vertexCount();
  figures.triangles = head.triangleCount();

  PoseSet poses;
  figures.bake = timeRuns(options.runs, [&] { poses = bakePoses(rig); });
  for (const VertexPose& pose : poses.poses)
    if (!pose.empty()) {
      ++figures.poses;
      figures.poseEntries += static_cast<long long>(pose.vertices.size());
    }
  figures.meanPoseSize = figures.poses ? double(figures.poseEntries) / figures.poses : 0.0;

  const PoseBlender blender(head, poses);
  const std::vector<FapValues> frames = animationFrames(poses.drivenChannels(), 64);
  Eigen::Matrix3Xf positions, normals;
  size_t next = 0;
  figures.blend = timeRuns(options.frames, [&] {
    blender.blend(frames[next], positions, normals);
    next = (next + 1) % frames.size();
  });
  return figures;
}

// Heads whose vertex counts match the default MakeHuman head (~4.5k) and ICT-FaceKit (26,719).
synthetic::HeadSpec defaultSizedSpec() {
  synthetic::HeadSpec spec;
  spec.cellsPerUnit = 29;
  spec.eyeRings = 16;
  spec.eyeSegments = 24;
  spec.corneaRings = 4;
  spec.tongueHalfColumns = 4;
  spec.tongueRows = 8;
  return spec;
}

synthetic::HeadSpec ictSizedSpec() {
  synthetic::HeadSpec spec;
  spec.cellsPerUnit = 75;
  spec.eyeRings = 32;
  spec.eyeSegments = 48;
  spec.corneaRings = 8;
  spec.tongueHalfColumns = 8;
  spec.tongueRows = 16;
  return spec;
}

const char* mark(bool pass) { return pass ? "PASS" : "MISS"; }

struct Measured {
  HeadCase head;
  Figures figures;
  std::optional<Timing> rigBuild;  // buildRig incl. geodesic weights and bake (real heads only)
};

bool passes(const Measured& m) {
  return m.figures.bake.medianMs < m.head.bakeTargetMs &&
         (!m.rigBuild || m.rigBuild->medianMs < m.head.bakeTargetMs) &&
         (!m.head.blendTargetMs || m.figures.blend.medianMs < *m.head.blendTargetMs);
}

void printJson(const std::vector<Measured>& measured) {
  JsonWriter json(JsonWriter::Layout::Compact);
  json.beginObject();
  json.field("benchmark", "poses");
  json.key("heads");
  json.beginArray();
  bool pass = true;
  for (const Measured& m : measured) {
    const Figures& f = m.figures;
    json.beginObject();
    json.field("head", m.head.name);
    json.field("vertices", f.vertices);
    json.field("triangles", f.triangles);
    json.field("linear_poses", f.poses);
    json.field("pose_entries", f.poseEntries);
    json.field("mean_pose_vertices", f.meanPoseSize);
    json.field("real_head", m.rigBuild.has_value());
    if (m.rigBuild) writeTiming(json, "rig_build_ms", *m.rigBuild, m.head.bakeTargetMs);
    writeTiming(json, "bake_ms", f.bake, m.head.bakeTargetMs);
    writeTiming(json, "blend_ms_per_frame", f.blend, m.head.blendTargetMs);
    json.endObject();
    pass = pass && passes(m);
  }
  json.endArray();
  json.field("pass", pass);
  json.endObject();
  std::fputs(std::move(json).finish().c_str(), stdout);
}

void printTable(const std::vector<Measured>& measured) {
  std::printf("poses: bake all FAP poses, then blend all of them per frame (one core)\n");
  for (const Measured& m : measured) {
    const HeadCase& c = m.head;
    const Figures& f = m.figures;
    std::printf(
        "  %s: %d vertices, %d triangles, %d linear poses of %.0f vertices on average "
        "(%lld entries)\n",
        c.name.c_str(), f.vertices, f.triangles, f.poses, f.meanPoseSize, f.poseEntries);
    if (m.rigBuild) {
      const Timing& r = *m.rigBuild;
      std::printf(
          "    rig    median %9.3f ms  (min %.3f, max %.3f, %d runs)       target < %g ms  %s"
          "   (buildRig: geodesic weights + bake)\n",
          r.medianMs, r.minMs, r.maxMs, r.runs, c.bakeTargetMs, mark(r.medianMs < c.bakeTargetMs));
    }
    std::printf(
        "    bake   median %9.3f ms  (min %.3f, max %.3f, %d runs)       target < %g ms  %s\n",
        f.bake.medianMs, f.bake.minMs, f.bake.maxMs, f.bake.runs, c.bakeTargetMs,
        mark(f.bake.medianMs < c.bakeTargetMs));
    std::printf("    blend  median %9.4f ms  (min %.4f, max %.4f, %d frames)  ", f.blend.medianMs,
                f.blend.minMs, f.blend.maxMs, f.blend.runs);
    if (c.blendTargetMs) {
      std::printf("target < %g ms   %s\n", *c.blendTargetMs,
                  mark(f.blend.medianMs < *c.blendTargetMs));
    } else {
      std::printf("(no target)\n");
    }
  }
}

}  // namespace

int runPoses(int argc, char** argv) {
  Options options;
  if (const std::optional<int> status = parseOptions(argc, argv, options)) return *status;

  // Each head is measured by measureHead(mesh, rig, ...); a loaded head with its own weights
  // is one more push_back here, with the target of the head it stands for.
  std::vector<Measured> measured;
  const std::pair<HeadCase, synthetic::HeadSpec> synthetics[] = {
      {{"synthetic, default-head size", 1000.0, kDefaultBlendTargetMs}, defaultSizedSpec()},
      {{"synthetic, ICT-head size", 5000.0, std::nullopt}, ictSizedSpec()},
  };
  for (const auto& [headCase, spec] : synthetics) {
    const synthetic::Head head = synthetic::buildHead(spec);
    measured.push_back({headCase, measureHead(head.mesh, head.rig(), options), std::nullopt});
  }

  // The real heads: the rig build is timed, then bakePoses alone and the blend on its RigInput.
  const RealHeadSpec reals[] = {defaultHeadSpec(), ictHeadSpec()};
  const HeadCase realCases[] = {{"default head (MakeHuman hm08)", 1000.0, kDefaultBlendTargetMs},
                                {"ICT-FaceKit head", 5000.0, std::nullopt}};
  for (std::size_t k = 0; k < std::size(reals); ++k) {
    std::string why;
    std::optional<LoadedHead> loaded = loadRealHead(reals[k], why);
    if (!loaded) {
      // Notes go to stderr so --json output stays one parseable object.
      std::fprintf(stderr, "poses: skipping %s: %s\n", realCases[k].name.c_str(), why.c_str());
      continue;
    }
    rigging::BuiltRig rig;
    const Timing rigTiming =
        timeRuns(options.rigRuns, [&] { rig = rigging::buildRig(loaded->mesh, loaded->fdp); });
    measured.push_back({realCases[k], measureHead(loaded->mesh, rig.input, options), rigTiming});
  }

  if (options.json) {
    printJson(measured);
  } else {
    printTable(measured);
  }
  return 0;
}

}  // namespace lacrima::bench
