// lacrima-bench export: what each way out of Lacrima costs per frame, beside the plain render, on
// the demo (media/demo/crying.fap on the default head) at 1280x720 with its tear channels scaled
// so that at most 100 particles are present (--particles): the playback alone (pose blend and
// tears), the plain render (playback, upload, render, read back; no file), --render's PNG frames,
// --render --alpha --masks (a second, ID pass and twice the PNGs), the H.264 video (render,
// yuv420p conversion, libx264), the glTF file (playback, meshes, one .glb) and the PLY tear
// meshes. Each is its own run over the same frames through the code the command line runs, so
// each figure includes the playback it needs. Beside the time, what each writes (MB, the video's
// bitrate) and, for the video, its error: the PSNR of the decoded video against the PNG frames of
// the same render (Debian's ffmpeg, when installed). Needs an X display: run under xvfb-run.
#include "BenchCommandLine.h"
#include "BenchGuiApp.h"
#include "BenchSupport.h"

#include <lacrima/common/FapChannels.h>
#include <lacrima/common/FapReader.h>
#include <lacrima/common/FapWriter.h>
#include <lacrima/common/JsonWriter.h>
#include <lacrima/common/MediaFiles.h>
#include <lacrima/common/Milliseconds.h>
#include <lacrima/export/GltfAnimationExport.h>
#include <lacrima/export/TearMeshExport.h>
#include <lacrima/export/VideoExport.h>
#include <lacrima/playback/Playback.h>
#include <lacrima/player/BatchRender.h>
#include <lacrima/player/HeadViews.h>
#include <lacrima/scene/FaceRenderer.h>
#include <lacrima/scene/FaceScene.h>

#include <QDir>
#include <QFileInfo>
#include <QProcess>
#include <QRegularExpression>
#include <QStandardPaths>
#include <QTemporaryDir>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace lacrima::bench {

namespace {

struct Options {
  int width = 1280, height = 720;
  int frames = 0;  // 0: the whole demo
  int particles = 100;
  bool json = false;
};

std::optional<int> parseOptions(int argc, char** argv, Options& o) {
  BenchCommandLine line(
      "export",
      "Exports the demo (media/demo/crying.fap) on the default head every way Lacrima can and\n"
      "reports milliseconds per frame of each beside the plain render, with what each writes:\n"
      "playback alone, render, PNG frames, PNG with alpha and tear masks, H.264 video (with its\n"
      "bitrate and PSNR against the PNG frames), glTF, PLY tear meshes. Needs an X display: run\n"
      "under xvfb-run.");
  line.imageSize("size", "Image size of the renders and the video (default 1280x720).", o.width,
                 o.height);
  line.wholeNumber("frames", "N", "Frames from the start (default: the whole demo).", 1, 1000000,
                   o.frames);
  line.wholeNumber("particles", "N",
                   "Most tear particles present at once: the demo's tear channels are scaled to "
                   "it (default 100).",
                   2, kMaxTearParticles, o.particles);
  line.flag("json", "One JSON object instead of the table.", o.json);
  return line.parse(argc, argv);
}

struct Figure {
  const char* name;
  const char* what;
  double msPerFrame = 0;
  double megabytes = 0;  // written, 0 for none
};

double megabytesOfFile(const QString& path) {
  return static_cast<double>(QFileInfo(path).size()) / 1e6;
}

double megabytesOfFolder(const QString& path) {
  double bytes = 0;
  for (const QFileInfo& file : QDir(path).entryInfoList(QDir::Files))
    bytes += static_cast<double>(file.size());
  return bytes / 1e6;
}

// The demo with its tear channels scaled so that the frame with the most tear particles has
// `particles` of them (each eye's channel rounded to whole particles), written to `path`.
void writeScaledDemo(const std::string& demo, int particles, const std::string& path) {
  FapAnimation animation = FapReader::readFile(demo).animation;
  float most = 0;
  for (const FapValues& f : animation.frames)
    most = std::max(most, f[channelIndex(kTearLeftFap)] + f[channelIndex(kTearRightFap)]);
  if (most <= 0) throw std::runtime_error(demo + ": the demo has no tears");
  const float scale = static_cast<float>(particles) / most;
  for (FapValues& f : animation.frames)
    for (const int fap : {kTearLeftFap, kTearRightFap})
      f[channelIndex(fap)] = std::round(f[channelIndex(fap)] * scale);
  FapWriter::save(animation, path);
}

// PSNR in dB of the video against the PNG frames it should show (frame_0000.png, ...), from
// ffmpeg's psnr filter over every frame (luma and chroma, the video's yuv420p); nullopt
// without ffmpeg or when it fails.
std::optional<double> videoPsnr(const QString& video, const QString& pngFolder, double fps) {
  const QString ffmpeg = QStandardPaths::findExecutable("ffmpeg");
  if (ffmpeg.isEmpty()) return std::nullopt;
  QProcess process;
  process.start(ffmpeg,
                {"-hide_banner", "-nostats", "-i", video, "-framerate", QString::number(fps),
                 "-start_number", "0", "-i", QDir(pngFolder).filePath("frame_%04d.png"), "-lavfi",
                 "[0:v][1:v]psnr", "-f", "null", "-"});
  if (!process.waitForFinished(600000) || process.exitCode() != 0) return std::nullopt;
  const QString log = QString::fromUtf8(process.readAllStandardError());
  const QRegularExpressionMatch m = QRegularExpression("average:([0-9.]+|inf)").match(log);
  if (!m.hasMatch()) return std::nullopt;
  return m.captured(1) == "inf" ? INFINITY : m.captured(1).toDouble();
}

}  // namespace

int runExport(int argc, char** argv) {
  Options o;
  if (const std::optional<int> status = parseOptions(argc, argv, o)) return *status;
  if (const std::optional<int> status = missingDisplayOrHead("export")) return *status;
  const BenchGuiApp app;

  try {
    const auto rig = playback::loadDefaultHeadRig();
    const std::string demo = findMediaFile("demo/crying.fap");
    const QSize size(o.width, o.height);
    QTemporaryDir out;
    if (!out.isValid()) throw std::runtime_error("cannot make a temporary folder");
    const std::string input = out.filePath("crying.fap").toStdString();
    writeScaledDemo(demo, o.particles, input);
    int frames = 0;
    double fps = 0;
    {
      playback::Playback probe(*rig);
      probe.open(input);
      frames = o.frames > 0 ? std::min(o.frames, probe.frameCount()) : probe.frameCount();
      fps = probe.frameRate();
    }
    exporting::ExportOptions options;
    options.input = input;
    options.lastFrame = frames - 1;

    scene::FaceRenderer renderer(rig->head, size);
    const scene::OrbitView view = player::presetView(*rig, scene::CameraPreset::Framing);
    renderer.scene().setView(view);
    renderer.render();  // warm-up: the first render compiles the shaders
    int peakParticles = 0;
    // One pass of the playback over the frames, `each` called on every frame shown.
    auto timedPlayback = [&](const std::function<void(const playback::FrameView&)>& each) {
      playback::Playback playback(*rig);
      playback.open(input);
      const auto start = SteadyClock::now();
      for (int f = 0; f < frames; ++f) {
        each(playback.seek(f / playback.frameRate()));
        peakParticles = std::max(peakParticles, playback.producer().particleCount());
      }
      return millisecondsSince(start) / frames;
    };
    auto timed = [&](const std::function<void()>& run) {
      const auto start = SteadyClock::now();
      run();
      return millisecondsSince(start) / frames;
    };
    auto renderOptions = [&](const QString& folder, bool layers) {
      player::BatchRenderOptions r;
      r.input = QString::fromStdString(input);
      r.outputDir = folder;
      r.size = size;
      r.lastFrame = frames - 1;
      r.alpha = r.masks = layers;
      return r;
    };

    std::vector<Figure> figures;
    figures.push_back({"playback", "pose blend, tears, surface, trails; nothing drawn",
                       timedPlayback([](const playback::FrameView&) {})});
    figures.push_back({"render", "playback, upload, render, read back; no file",
                       timedPlayback([&](const playback::FrameView& frame) {
                         renderer.show(frame);
                         renderer.render();
                       })});
    const QString pngs = out.filePath("png");
    figures.push_back({"png", "--render: a PNG per frame, the contact sheet",
                       timed([&] { player::renderAnimation(*rig, renderOptions(pngs, false)); }),
                       megabytesOfFolder(pngs)});
    const QString layers = out.filePath("layers");
    figures.push_back({"png+alpha+masks", "--render --alpha --masks: the ID pass, 2 PNGs a frame",
                       timed([&] { player::renderAnimation(*rig, renderOptions(layers, true)); }),
                       megabytesOfFolder(layers)});
    const QString video = out.filePath("demo.mp4");
    options.output = video.toStdString();
    figures.push_back({"video", "--video: the render, yuv420p, libx264 crf 18 into an MP4",
                       timed([&] { exporting::exportVideo(*rig, options, size, view); }),
                       megabytesOfFile(video)});
    const double kbitPerSecond = figures.back().megabytes * 8000.0 / (frames / fps);
    const std::optional<double> psnr = videoPsnr(video, pngs, fps);
    const QString glb = out.filePath("demo.glb");
    options.output = glb.toStdString();
    exporting::GltfExportResult gltf;
    figures.push_back({"gltf", "--export-gltf: playback, tear meshes, one .glb",
                       timed([&] { gltf = exporting::exportGltfAnimation(*rig, options); }),
                       megabytesOfFile(glb)});
    const QString ply = out.filePath("ply");
    options.output = ply.toStdString();
    figures.push_back({"ply", "--export-tears: playback, a PLY of the tears per frame",
                       timed([&] { exporting::exportTearMeshes(*rig, options); }),
                       megabytesOfFolder(ply)});

    const double render = figures[1].msPerFrame;
    if (o.json) {
      JsonWriter json(JsonWriter::Layout::Compact);
      json.beginObject();
      json.field("benchmark", "export");
      json.field("animation", demo);
      json.field("width", o.width);
      json.field("height", o.height);
      json.field("frames", frames);
      json.field("fps", fps);
      json.field("peak_particles", peakParticles);
      json.key("ms_per_frame");
      json.beginObject();
      for (const Figure& f : figures) json.field(f.name, f.msPerFrame);
      json.endObject();
      json.key("megabytes");
      json.beginObject();
      for (const Figure& f : figures)
        if (f.megabytes > 0) json.field(f.name, f.megabytes);
      json.endObject();
      json.field("video_kbit_per_s", kbitPerSecond);
      if (psnr && std::isfinite(*psnr)) json.field("video_psnr_db", *psnr);
      json.field("gltf_tear_frames", gltf.tearFrames);
      json.field("gltf_morph_targets", gltf.morphTargets);
      json.endObject();
      const std::string text = std::move(json).finish();
      std::fwrite(text.data(), 1, text.size(), stdout);
    } else {
      std::printf(
          "export of %s, tears scaled to %d particles: %d frames at %dx%d, %g fps, up to "
          "%d tear particles shown\n",
          demo.c_str(), o.particles, frames, o.width, o.height, fps, peakParticles);
      std::printf("  %-16s %9s %9s %9s  %s\n", "way", "ms/frame", "x render", "MB", "what");
      for (const Figure& f : figures)
        std::printf("  %-16s %9.2f %9.2f %9.2f  %s\n", f.name, f.msPerFrame, f.msPerFrame / render,
                    f.megabytes, f.what);
      std::printf("video: %.0f kbit/s", kbitPerSecond);
      if (psnr)
        std::printf(", PSNR %.2f dB against the PNG frames (ffmpeg psnr, yuv420p)\n", *psnr);
      else
        std::printf(", PSNR not measured (no ffmpeg)\n");
      std::printf("glTF: %d morph targets, tears in %d frames, %.1f KB a frame\n",
                  gltf.morphTargets, gltf.tearFrames, figures[5].megabytes * 1000.0 / frames);
    }
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "lacrima-bench export: %s\n", e.what());
    return 1;
  }
}

}  // namespace lacrima::bench
