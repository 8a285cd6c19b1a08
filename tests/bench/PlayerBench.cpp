// lacrima-bench player: frames per second of the whole player on the demo (media/demo/
// crying.fap on the default head): per animation frame the playback produces the frame (pose
// blend, tear simulation, surface, trails) and FaceRenderer draws it (upload, render, read
// back). Target: >= 30 fps at 1280x720 with software rendering. Needs an X display (OGRE is
// GLX only): run under xvfb-run.
#include "BenchCommandLine.h"
#include "BenchGuiApp.h"
#include "BenchSupport.h"

#include <lacrima/common/JsonWriter.h>
#include <lacrima/common/MediaFiles.h>
#include <lacrima/common/Milliseconds.h>
#include <lacrima/playback/Playback.h>
#include <lacrima/scene/FaceRenderer.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

namespace lacrima::bench {

namespace {

constexpr double kTargetFps = 30;

struct Options {
  int width = 1280, height = 720;
  int frames = 0;  // 0: the whole demo once
  bool json = false;
};

std::optional<int> parseOptions(int argc, char** argv, Options& o) {
  BenchCommandLine line(
      "player",
      "Plays the demo (media/demo/crying.fap) on the default head through the player's\n"
      "playback and renderer, one render per animation frame, and reports frames per second\n"
      "of the whole loop with each stage's share. Needs an X display: run under xvfb-run.");
  line.imageSize("size", "Image size (default 1280x720).", o.width, o.height);
  line.wholeNumber("frames", "N",
                   "Frames to play (default: the whole demo; longer runs replay it).", 1, 1000000,
                   o.frames);
  line.flag("json", "One JSON object instead of the table.", o.json);
  return line.parse(argc, argv);
}

struct Stage {
  const char* name;
  double total = 0;  // ms over all frames
};

}  // namespace

int runPlayer(int argc, char** argv) {
  Options o;
  if (const std::optional<int> status = parseOptions(argc, argv, o)) return *status;
  if (const std::optional<int> status = missingDisplayOrHead("player")) return *status;
  const BenchGuiApp app;

  try {
    const auto rigStart = SteadyClock::now();
    const auto rig = playback::loadDefaultHeadRig();
    const double rigMs = millisecondsSince(rigStart);
    playback::Playback playback(*rig);
    const std::string demo = findMediaFile("demo/crying.fap");
    playback.open(demo);
    scene::FaceRenderer renderer(rig->head, QSize(o.width, o.height));
    // Warm-up: the first render compiles the shaders.
    renderer.show(playback.view());
    renderer.render();

    const int demoFrames = playback.frameCount();
    const int frames = o.frames > 0 ? o.frames : demoFrames;
    std::array<Stage, 7> stages{
        {{"blend"}, {"simulation"}, {"surface"}, {"trails"}, {"upload"}, {"render"}, {"readback"}}};
    std::vector<double> frameMs;
    frameMs.reserve(static_cast<std::size_t>(frames));
    int peakParticles = 0;
    playback.reset();
    const auto start = SteadyClock::now();
    for (int i = 0; i < frames; ++i) {
      const int f = i % demoFrames;
      const auto t0 = SteadyClock::now();
      if (f == 0 && i > 0) playback.reset();
      const playback::FrameView& view = playback.seek(f / playback.frameRate());
      renderer.show(view);
      const QImage image = renderer.render();
      frameMs.push_back(millisecondsSince(t0));
      const playback::ProducerTimes& p = playback.producer().lastTimes();
      const scene::RenderTimes& r = renderer.lastTimes();
      const std::array<double, 7> ms{p.blend,  p.simulation, p.surface, p.trails,
                                     r.upload, r.render,     r.readback};
      for (std::size_t s = 0; s < stages.size(); ++s) stages[s].total += ms[s];
      peakParticles = std::max(peakParticles, playback.producer().particleCount());
      if (image.isNull()) throw std::runtime_error("the renderer returned no image");
    }
    const double wallMs = millisecondsSince(start);
    const double fps = frames * 1000.0 / wallMs;
    std::vector<double> sorted = frameMs;
    std::sort(sorted.begin(), sorted.end());
    const double median = sorted[sorted.size() / 2], worst = sorted.back();
    double staged = 0;
    for (const Stage& s : stages) staged += s.total;
    const double other = std::max(0.0, wallMs - staged);
    const bool pass = fps >= kTargetFps;

    if (o.json) {
      JsonWriter json(JsonWriter::Layout::Compact);
      json.beginObject();
      json.field("benchmark", "player");
      json.field("animation", demo);
      json.field("width", o.width);
      json.field("height", o.height);
      json.field("frames", frames);
      json.field("peak_particles", peakParticles);
      json.field("checkpoints", playback.checkpointCount());
      json.field("checkpoint_bytes", static_cast<long long>(playback.checkpointBytes()));
      json.field("rig_ms", rigMs);
      json.field("fps", fps);
      json.field("ms_per_frame_mean", wallMs / frames);
      json.field("ms_per_frame_median", median);
      json.field("ms_per_frame_max", worst);
      json.key("stages_ms_per_frame");
      json.beginObject();
      for (const Stage& s : stages) json.field(s.name, s.total / frames);
      json.field("other", other / frames);
      json.endObject();
      json.field("target_fps_at_least", kTargetFps);
      json.field("pass", pass);
      json.endObject();
      const std::string text = std::move(json).finish();
      std::fwrite(text.data(), 1, text.size(), stdout);
    } else {
      std::printf(
          "player on %s: %d frames at %dx%d, up to %d tear particles (rig built in %.0f ms)\n",
          demo.c_str(), frames, o.width, o.height, peakParticles, rigMs);
      std::printf("  %-12s %10s %8s\n", "stage", "ms/frame", "share");
      for (const Stage& s : stages)
        std::printf("  %-12s %10.2f %7.1f%%\n", s.name, s.total / frames, 100.0 * s.total / wallMs);
      std::printf("  %-12s %10.2f %7.1f%%\n", "other", other / frames, 100.0 * other / wallMs);
      std::printf("  %-12s %10.2f   (median %.2f, max %.2f)\n", "whole frame", wallMs / frames,
                  median, worst);
      constexpr double kMiB = 1 << 20;
      std::printf("checkpoints: %d, %.1f MiB (budget %.0f MiB)\n", playback.checkpointCount(),
                  playback.checkpointBytes() / kMiB, playback::Playback::kCheckpointBudget / kMiB);
      std::printf("frames per second: %.1f  (target >= %.0f: %s)\n", fps, kTargetFps,
                  pass ? "met" : "NOT MET");
    }
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "lacrima-bench player: %s\n", e.what());
    return 1;
  }
}

}  // namespace lacrima::bench
