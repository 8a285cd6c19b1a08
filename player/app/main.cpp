// lacrima-player: plays MPEG-4 facial animation (FAP files and Lacrima projects) on a rigged
// head with real-time tears, or renders it to images (--render). Exit codes as the other
// tools: 0 success, 1 bad input or a failed write, 2 wrong usage.
#include <lacrima/appsupport/ThreadsOption.h>
#include <lacrima/appsupport/WindowShot.h>
#include <lacrima/player/BatchRender.h>
#include <lacrima/player/ErrorReport.h>
#include <lacrima/player/PlayerWindow.h>
#include <lacrima/player/ProjectHead.h>

#include <lacrima/common/AtomicSave.h>
#include <lacrima/common/CommandLineNumbers.h>
#include <lacrima/common/Diagnostics.h>
#include <lacrima/common/ImageSize.h>
#include <lacrima/common/Keyframes.h>
#include <lacrima/common/TearQuality.h>
#include <lacrima/common/mood/Moods.h>
#include <lacrima/export/GltfAnimationExport.h>
#include <lacrima/export/RunStatistics.h>
#include <lacrima/export/TearMeshExport.h>
#include <lacrima/export/VideoExport.h>
#include <lacrima/live/ListenUrl.h>
#include <lacrima/live/LiveMoodFeed.h>
#include <lacrima/live/LiveSession.h>
#include <lacrima/playback/HeadRig.h>
#include <lacrima/player/HeadViews.h>
#include <lacrima/scene/CameraPreset.h>
#include <lacrima/viewport/DarkTheme.h>

#include <QApplication>
#include <QCommandLineParser>
#include <QDir>
#include <QFileInfo>
#include <QTimer>

#include <unistd.h>
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <functional>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

using namespace lacrima;

namespace {

constexpr int kExitOk = 0;
constexpr int kExitBadInput = 1;
constexpr int kExitUsage = 2;

bool hasOption(int argc, char** argv, const char* name) {
  for (int i = 1; i < argc; ++i)
    if (std::strcmp(argv[i], name) == 0 || std::strncmp(argv[i], name, std::strlen(name)) == 0)
      return true;
  return false;
}

// The head to animate: --mesh/--fdp, else the project's own head ("head" in FILE), else the
// default head. `fixed`: given on the command line, so opening another project keeps it.
struct HeadChoice {
  std::optional<HeadFiles> files;  // nullopt: the default head
  bool fixed = false;
};

HeadChoice chooseHead(const QCommandLineParser& parser) {
  if (parser.isSet("mesh"))
    return {HeadFiles{parser.value("mesh").toStdString(), parser.value("fdp").toStdString()}, true};
  const QStringList files = parser.positionalArguments();
  if (files.size() != 1) return {};
  return {player::headOfFile(files.front().toStdString()), false};
}

// Throws FileError naming the project, its JSON path and the file when a project's head file
// is missing.
std::unique_ptr<playback::HeadRig> loadRig(const QCommandLineParser& parser,
                                           const HeadChoice& head) {
  if (head.fixed) return playback::loadHeadRig(head.files->mesh, head.files->fdp);
  return player::loadHeadFor(head.files, parser.positionalArguments().value(0).toStdString());
}

// One line per step on a log, a bar redrawn in place on a terminal.
void showProgress(int done, int total, const char* verb = "rendered") {
  static const bool terminal = isatty(fileno(stderr));
  if (terminal) {
    const int width = 40, filled = done * width / std::max(1, total);
    std::fprintf(stderr, "\rlacrima-player: [%.*s%*s] frame %d/%d", filled,
                 "########################################", width - filled, "", done, total);
    if (done == total) std::fputc('\n', stderr);
  } else if (done == total || done % std::max(1, total / 10) == 0) {
    std::fprintf(stderr, "lacrima-player: %s %d/%d frames\n", verb, done, total);
  }
}

// --view, or nullopt after saying what it takes.
std::optional<scene::CameraPreset> cameraPreset(const QCommandLineParser& parser) {
  const std::string viewName = parser.value("view").toStdString();
  const std::optional<scene::CameraPreset> view = scene::parseCameraPreset(viewName);
  if (!view)
    std::fprintf(stderr, "lacrima-player: --view: expected one of %s, not '%s'\n",
                 std::string(scene::cameraPresetNames()).c_str(), viewName.c_str());
  return view;
}

// What the options other than the file and the head ask of either mode.
struct ModeOptions {
  std::optional<TearQuality> quality;  // --quality
  int threads = 0;                     // --threads
  bool tears = true;                   // --no-tears: false
  QString stats;                       // --stats FILE.json
  std::optional<MoodLevels> moods;     // --mood
  std::uint64_t seed = 1;              // --seed
};

// --stats: what the run simulated (RunStatistics), gathered frame by frame by the observer it
// hands to an export, and written when the export has finished.
class StatsRecorder {
 public:
  explicit StatsRecorder(QString path) : path_(std::move(path)) {}
  std::function<void(const playback::Playback&)> observer() {
    if (path_.isEmpty()) return {};
    return [statistics = statistics_](const playback::Playback& p) { statistics->add(p); };
  }
  void write() const {
    if (!path_.isEmpty()) saveAtomically(path_.toStdString(), statistics_->toJson());
  }

 private:
  QString path_;
  std::shared_ptr<exporting::RunStatistics> statistics_ =
      std::make_shared<exporting::RunStatistics>();
};

// --mood and --seed into `mode`; false after saying what is wrong (a usage error).
bool readMoodOptions(const QCommandLineParser& parser, ModeOptions& mode) {
  if (parser.isSet("seed") && !parser.isSet("mood")) {
    std::fprintf(stderr, "lacrima-player: --seed goes with --mood\n");
    return false;
  }
  if (!parser.isSet("mood")) return true;
  if (!parser.positionalArguments().isEmpty()) {
    std::fprintf(stderr,
                 "lacrima-player: --mood plays the crying generator with no FILE; give one or "
                 "the other\n");
    return false;
  }
  for (const char* other :
       {"render", "video", "export-gltf", "export-tears", "no-window", "screenshot"}) {
    if (!parser.isSet(other)) continue;
    std::fprintf(stderr,
                 "lacrima-player: --mood plays live in the window; for --%s write a take first: "
                 "lacrima-fap generate --mood ... --seconds S -o take.lacrima\n",
                 other);
    return false;
  }
  try {
    mode.moods = parseMoodLevels(parser.value("mood").toStdString());
  } catch (const std::invalid_argument& e) {
    std::fprintf(stderr, "lacrima-player: --mood: %s\n", e.what());
    return false;
  }
  if (parser.isSet("seed")) {
    bool ok = false;
    mode.seed = parser.value("seed").toULongLong(&ok);
    if (!ok) {
      std::fprintf(stderr,
                   "lacrima-player: --seed: expected a whole number from 0 to "
                   "18446744073709551615, got '%s'\n",
                   parser.value("seed").toLocal8Bit().constData());
      return false;
    }
  }
  return true;
}

// --listen, --record, --record-rate, --mapping, --exit-when-idle: the live options.
struct LiveOptions {
  std::vector<live::ListenUrl> urls;
  QString record;
  std::optional<double> recordRate;
  std::optional<LiveLinkMapping> mapping;
  std::optional<double> exitWhenIdle;
};

// The live options, or nullopt after saying what is wrong (a usage error).
std::optional<LiveOptions> liveOptions(const QCommandLineParser& parser) {
  LiveOptions options;
  for (const QString& text : parser.values("listen")) {
    QString error;
    const std::optional<live::ListenUrl> url = live::parseListenUrl(text, error);
    if (!url) {
      std::fprintf(stderr, "lacrima-player: --listen: %s\n", error.toLocal8Bit().constData());
      return std::nullopt;
    }
    options.urls.push_back(*url);
  }
  // A number option when given; a bad one is said and makes the whole answer nullopt.
  bool failed = false;
  const auto number = [&](const char* name, const char* what, double low,
                          double high) -> std::optional<double> {
    if (!parser.isSet(name)) return std::nullopt;
    std::string error;
    const std::optional<double> value = readNumberOption(
        std::string("--") + name, what, parser.value(name).toStdString(), low, high, error);
    if (!value) {
      std::fprintf(stderr, "lacrima-player: %s\n", error.c_str());
      failed = true;
    }
    return value;
  };
  options.recordRate = number("record-rate", "frames per second", 1, 1000);
  options.exitWhenIdle = number("exit-when-idle", "seconds", 0.01, 86400);
  if (failed) return std::nullopt;
  options.record = parser.value("record");
  if ((!options.record.isEmpty() || options.exitWhenIdle) && options.urls.empty()) {
    std::fprintf(stderr, "lacrima-player: --record and --exit-when-idle need --listen URL\n");
    return std::nullopt;
  }
  return options;
}

// Starts the inputs and the recording, saying where each listens on stdout (a port of 0 is
// the one the system chose). Throws std::runtime_error when an input cannot be opened.
void startLive(live::LiveSession& session, const LiveOptions& options,
               const std::function<void(const live::ListenUrl&)>& listen) {
  if (options.mapping) session.setMapping(*options.mapping);
  if (!options.record.isEmpty())
    session.startRecording(options.record.toStdString(), options.recordRate);
  for (const live::ListenUrl& url : options.urls) listen(url);
  for (const auto& input : session.inputs())
    std::printf("listening on %s\n", input->url().toString().toLocal8Bit().constData());
  std::fflush(stdout);
}

// Ends the recording, saying where it went; false when the file could not be written.
bool finishRecording(live::LiveSession& session) {
  if (!session.recorder()) return true;
  const std::string path = session.recorder()->path();
  const int frames = session.recorder()->frameCount();
  const double rate = session.recorder()->rate();
  try {
    if (session.stopRecording())
      std::fprintf(stderr, "lacrima-player: recorded %d frames at %g fps to %s\n", frames, rate,
                   path.c_str());
    else
      std::fprintf(stderr, "lacrima-player: nothing arrived; %s not written\n", path.c_str());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "lacrima-player: %s\n", e.what());
    return false;
  }
  return true;
}

// --exit-when-idle: quits the application after that long without a frame.
void quitWhenIdle(QCoreApplication& app, live::LiveSession& session,
                  std::optional<double> seconds) {
  if (!seconds) return;
  auto* timer = new QTimer(&session);
  timer->setInterval(std::clamp(static_cast<int>(*seconds * 250), 10, 500));
  QObject::connect(timer, &QTimer::timeout, &app, [&app, &session, limit = *seconds] {
    if (session.idleSeconds() >= limit) app.quit();
  });
  timer->start();
}

// --no-window: the inputs and the recording without a window; mood lines drive the crying
// generator, whose frames are recorded as the stream's would be. With --render DIR the take is
// then rendered as --render renders a file (the tears simulated on the recorded frames);
// without --record it is kept as DIR/take.fap.
int headlessMode(QCoreApplication& app, const QCommandLineParser& parser, LiveOptions options,
                 const QSize& size, const ModeOptions& mode) {
  const bool render = parser.isSet("render");
  if (options.urls.empty() || (options.record.isEmpty() && !render)) {
    std::fprintf(stderr,
                 "lacrima-player: --no-window needs --listen URL and --record OUT.fap and/or "
                 "--render DIR\n");
    return kExitUsage;
  }
  if (options.record.isEmpty()) {
    QDir().mkpath(parser.value("render"));
    options.record = QDir(parser.value("render")).filePath(QStringLiteral("take.fap"));
  }
  live::LiveSession session;
  const live::LiveMoodFeed moods(session,
                                 options.recordRate.value_or(live::LiveRecorder::kDefaultRate));
  startLive(session, options, [&](const live::ListenUrl& url) { session.listen(url); });
  quitWhenIdle(app, session, options.exitWhenIdle);
  app.exec();
  std::fprintf(stderr, "lacrima-player: %s\n", session.statusText().toLocal8Bit().constData());
  if (!finishRecording(session)) return kExitBadInput;
  if (!render || !QFileInfo::exists(options.record)) return kExitOk;
  const std::optional<scene::CameraPreset> view = cameraPreset(parser);
  if (!view) return kExitUsage;
  const auto rig = loadRig(parser, chooseHead(parser));
  player::BatchRenderOptions batch;
  batch.input = options.record;
  batch.outputDir = parser.value("render");
  batch.size = size;
  batch.view = *view;
  batch.progress = [](int done, int total) { showProgress(done, total); };
  batch.quality = mode.quality;
  batch.threads = mode.threads;
  const player::BatchRenderResult result = player::renderAnimation(*rig, batch);
  std::printf("%s/frame_0000.png ... frame_%04d.png and %s\n",
              QDir(batch.outputDir).absolutePath().toLocal8Bit().constData(), result.frames - 1,
              QFileInfo(result.contactSheet).absoluteFilePath().toLocal8Bit().constData());
  return kExitOk;
}

// --frames FIRST-LAST (frame numbers, both included), or nullopt after saying what it takes.
std::optional<std::pair<int, int>> frameRange(const QCommandLineParser& parser) {
  if (!parser.isSet("frames")) return std::pair{0, -1};
  const QStringList ends = parser.value("frames").split('-');
  bool firstOk = false, lastOk = false;
  const int first = ends.value(0).toInt(&firstOk), last = ends.value(1).toInt(&lastOk);
  if (ends.size() != 2 || !firstOk || !lastOk || first < 0 || last < first) {
    std::fprintf(stderr,
                 "lacrima-player: --frames: expected FIRST-LAST with 0 <= FIRST <= LAST, "
                 "not '%s'\n",
                 parser.value("frames").toLocal8Bit().constData());
    return std::nullopt;
  }
  return std::pair{first, last};
}

int renderMode(const QCommandLineParser& parser, const QSize& size, const ModeOptions& mode) {
  const QStringList files = parser.positionalArguments();
  if (files.size() != 1) {
    std::fprintf(stderr, "lacrima-player: --render needs exactly one FILE to render\n");
    return kExitUsage;
  }
  const std::optional<scene::CameraPreset> view = cameraPreset(parser);
  if (!view) return kExitUsage;
  const auto rig = loadRig(parser, chooseHead(parser));
  for (const std::string& w : rig->warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());
  player::BatchRenderOptions options;
  options.input = files.front();
  options.outputDir = parser.value("render");
  options.size = size;
  options.view = *view;
  options.progress = [](int done, int total) { showProgress(done, total); };
  const std::optional<std::pair<int, int>> range = frameRange(parser);
  if (!range) return kExitUsage;
  options.firstFrame = range->first;
  options.lastFrame = range->second;
  options.alpha = parser.isSet("alpha");
  options.masks = parser.isSet("masks");
  options.quality = mode.quality;
  options.threads = mode.threads;
  options.tears = mode.tears;
  StatsRecorder stats(mode.stats);
  options.frameShown = stats.observer();
  const player::BatchRenderResult result = player::renderAnimation(*rig, options);
  stats.write();
  std::fprintf(stderr, "lacrima-player: %d frames in %.1f s\n", result.frames, result.seconds);
  std::printf("%s/frame_%04d.png ... frame_%04d.png and %s\n",
              QDir(options.outputDir).absolutePath().toLocal8Bit().constData(), result.firstFrame,
              result.firstFrame + result.frames - 1,
              QFileInfo(result.contactSheet).absoluteFilePath().toLocal8Bit().constData());
  return kExitOk;
}

// The options every export takes from the command line; nullopt after a usage error.
std::optional<exporting::ExportOptions> exportOptions(const QCommandLineParser& parser,
                                                      const QString& option,
                                                      const ModeOptions& mode) {
  const QStringList files = parser.positionalArguments();
  if (files.size() != 1) {
    std::fprintf(stderr, "lacrima-player: --%s needs exactly one FILE to export\n",
                 option.toLocal8Bit().constData());
    return std::nullopt;
  }
  const std::optional<std::pair<int, int>> range = frameRange(parser);
  if (!range) return std::nullopt;
  exporting::ExportOptions options;
  options.input = files.front().toStdString();
  options.output = parser.value(option).toStdString();
  options.quality = mode.quality;
  options.threads = mode.threads;
  options.firstFrame = range->first;
  options.lastFrame = range->second;
  options.tears = mode.tears;
  options.progress = [](int done, int total) {
    showProgress(done, total, "exported");
    return true;
  };
  return options;
}

// The rig of an export's FILE, its warnings said on stderr.
std::unique_ptr<playback::HeadRig> exportRig(const QCommandLineParser& parser) {
  auto rig = loadRig(parser, chooseHead(parser));
  for (const std::string& w : rig->warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());
  return rig;
}

void printPath(const std::string& path) {
  std::printf("%s\n",
              QFileInfo(QString::fromStdString(path)).absoluteFilePath().toLocal8Bit().constData());
}

int gltfMode(const QCommandLineParser& parser, const ModeOptions& mode) {
  std::optional<exporting::ExportOptions> options =
      exportOptions(parser, QStringLiteral("export-gltf"), mode);
  if (!options) return kExitUsage;
  StatsRecorder stats(mode.stats);
  options->frameShown = stats.observer();
  const exporting::GltfExportResult result =
      exporting::exportGltfAnimation(*exportRig(parser), *options);
  stats.write();
  std::fprintf(stderr,
               "lacrima-player: %d frames, %d morph targets, tears in %d frames, %.1f MB in "
               "%.1f s\n",
               result.frames, result.morphTargets, result.tearFrames,
               static_cast<double>(result.bytes) / 1e6, result.seconds);
  printPath(options->output);
  return kExitOk;
}

int tearsMode(const QCommandLineParser& parser, const ModeOptions& mode) {
  std::optional<exporting::ExportOptions> options =
      exportOptions(parser, QStringLiteral("export-tears"), mode);
  if (!options) return kExitUsage;
  StatsRecorder stats(mode.stats);
  options->frameShown = stats.observer();
  const exporting::TearMeshExportResult result =
      exporting::exportTearMeshes(*exportRig(parser), *options);
  stats.write();
  std::fprintf(stderr, "lacrima-player: %d PLY files, tears in %d, %.1f MB in %.1f s\n",
               result.frames, result.framesWithTears, static_cast<double>(result.bytes) / 1e6,
               result.seconds);
  printPath(options->output);
  return kExitOk;
}

int videoMode(const QCommandLineParser& parser, const QSize& size, const ModeOptions& mode) {
  std::optional<exporting::ExportOptions> options =
      exportOptions(parser, QStringLiteral("video"), mode);
  if (!options) return kExitUsage;
  const std::optional<scene::CameraPreset> view = cameraPreset(parser);
  if (!view) return kExitUsage;
  if (size.width() % 2 || size.height() % 2) {
    std::fprintf(stderr,
                 "lacrima-player: --size: H.264 video needs an even width and height, not %dx%d\n",
                 size.width(), size.height());
    return kExitUsage;
  }
  const auto rig = exportRig(parser);
  StatsRecorder stats(mode.stats);
  options->frameShown = stats.observer();
  const exporting::VideoExportResult result =
      exporting::exportVideo(*rig, *options, size, player::presetView(*rig, *view));
  stats.write();
  std::fprintf(stderr, "lacrima-player: %d frames at %g fps (H.264, %s) in %.1f s\n", result.frames,
               result.fps, result.encoder.c_str(), result.seconds);
  printPath(options->output);
  return kExitOk;
}

int windowMode(QApplication& app, const QCommandLineParser& parser, const QSize* size,
               const ModeOptions& mode, const LiveOptions& liveOptions) {
  const QStringList files = parser.positionalArguments();
  if (files.size() > 1) {
    std::fprintf(stderr, "lacrima-player: give at most one FILE to open\n");
    return kExitUsage;
  }
  const std::optional<scene::CameraPreset> view = cameraPreset(parser);
  if (!view) return kExitUsage;
  HeadChoice head;
  try {
    head = chooseHead(parser);
  } catch (const FileError&) {
    // An unreadable project: the window opens on the default head and openFile() reports the
    // problem the way it reports any file it cannot use.
  }
  viewport::applyDarkTheme(app);  // the editor's look: the suite is one
  player::PlayerWindow window(loadRig(parser, head));
  window.setHeadSource(head.files, head.fixed);
  window.setSimulationThreads(mode.threads);
  if (mode.quality) window.setTearQuality(*mode.quality);
  for (const std::string& w : window.rig().warnings)
    std::fprintf(stderr, "warning: %s\n", w.c_str());
  window.resize(size ? *size : QSize(1360, 820));
  if (*view != scene::CameraPreset::Framing) window.setCameraPreset(*view);
  const bool screenshot = parser.isSet("screenshot");
  if (screenshot) window.setErrorDialogsEnabled(false);
  window.show();
  if (!files.isEmpty() && !window.openFile(files.front()) && screenshot) return kExitBadInput;
  if (!screenshot) {
    window.loopAction()->setChecked(parser.isSet("loop"));
    if (parser.isSet("play")) window.play();
    startLive(window.liveSession(), liveOptions,
              [&](const live::ListenUrl& url) { window.listen(url); });
    if (mode.moods) {
      window.setMoodSeed(mode.seed);
      window.playMoods(*mode.moods);
    }
    quitWhenIdle(app, window.liveSession(), liveOptions.exitWhenIdle);
    const int status = app.exec();
    return finishRecording(window.liveSession()) ? status : kExitBadInput;
  }
  // --screenshot: pose the window at --at seconds, let it lay out and render, grab it.
  std::string error;
  const std::optional<double> at =
      readNumberOption("--at", "seconds", parser.value("at").toStdString(), 0, kMaxKeyTime, error);
  if (!at) {
    std::fprintf(stderr, "lacrima-player: %s\n", error.c_str());
    return kExitUsage;
  }
  int status = kExitOk;
  QTimer::singleShot(300, &window, [&] {
    window.seek(*at);
    QTimer::singleShot(300, &window, [&] {
      const QString path = parser.value("screenshot");
      if (!appsupport::grabWindowWithViewports(window).save(path)) {
        std::fprintf(stderr, "lacrima-player: cannot write %s\n", path.toLocal8Bit().constData());
        status = kExitBadInput;
      }
      app.quit();
    });
  });
  app.exec();
  return status;
}

}  // namespace

int main(int argc, char** argv) {
  // OGRE on Debian renders through GLX: both modes need an X display. Say so before Qt would
  // abort on a missing one.
  const bool render = hasOption(argc, argv, "--render") || hasOption(argc, argv, "--video");
  const bool noWindow = hasOption(argc, argv, "--no-window");
  // Exports that draw nothing need no display, nor does a stream recorded without a window;
  // rendering its take does.
  const bool headless = !render && (noWindow || hasOption(argc, argv, "--export-gltf") ||
                                    hasOption(argc, argv, "--export-tears"));
  const bool help = hasOption(argc, argv, "--help") || hasOption(argc, argv, "-h") ||
                    hasOption(argc, argv, "--version");
  const bool haveX = !qEnvironmentVariableIsEmpty("DISPLAY");
  if (!haveX && !help && !headless) {
    if (render)
      std::fprintf(
          stderr,
          "lacrima-player: --render and --video need an X display (OGRE renders through GLX) and "
          "there is none;\n"
          "  run it under a virtual one: xvfb-run -a lacrima-player --render OUT_DIR FILE\n");
    else
      std::fprintf(stderr,
                   "lacrima-player: no X display to open a window on (DISPLAY is not set);\n"
                   "  render images instead: xvfb-run -a lacrima-player --render OUT_DIR FILE\n");
    return kExitBadInput;
  }
  // The OGRE viewport embeds a GLX window: use X even in a Wayland session (XWayland). Help
  // and version need no display at all.
  if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
    qputenv("QT_QPA_PLATFORM", haveX && !noWindow ? "xcb" : "offscreen");
  QApplication app(argc, argv);
  QCoreApplication::setApplicationName("lacrima-player");
  QCoreApplication::setApplicationVersion(LACRIMA_VERSION);
  QCommandLineParser parser;
  parser.setApplicationDescription(
      "Plays MPEG-4 facial animation with real-time tears: a FAP file (.fap) or a Lacrima project\n"
      "(.lacrima or .json) on the default head, on the head the project names (its \"head\"\n"
      "entry), or on your own (--mesh, --fdp, which override the project's head).\n\n"
      "Examples:\n"
      "  lacrima-player media/demo/crying.fap\n"
      "  xvfb-run -a lacrima-player --render out/ --size 1280x720 media/demo/crying.fap\n"
      "  xvfb-run -a lacrima-player --render close/ --view close-left media/demo/crying.fap\n"
      "  xvfb-run -a lacrima-player --render layers/ --alpha --masks media/demo/crying.fap\n"
      "  lacrima-player --export-gltf crying.glb media/demo/crying.fap\n"
      "  lacrima-player --export-tears tears/ media/demo/crying.fap\n"
      "  xvfb-run -a lacrima-player --video crying.mp4 --size 1280x720 media/demo/crying.fap\n"
      "  lacrima-player --mesh head.obj --fdp head.fdp.json animation.fap\n"
      "  lacrima-player my-character/project.lacrima\n\n"
      "Live (docs/live.md):\n"
      "  lacrima-player --listen fap+tcp://127.0.0.1:5555     # then: lacrima-send FILE --to ...\n"
      "  lacrima-player --listen livelink+udp://0.0.0.0:11111  # Live Link Face on a phone\n"
      "  lacrima-player --no-window --listen fap+tcp://:5555 --record take.fap --exit-when-idle "
      "2\n\n"
      "Crying on the fly (docs/mood.md):\n"
      "  lacrima-player --mood sadness=0.8,anger=0.2 --seed 4\n\n"
      "Keys: Space play/pause, Home reset, Left/Right one frame, L loop, V reset the view, Ctrl+O\n"
      "open.\n"
      "Mouse: left drag orbits, right drag pans, the wheel zooms, double-click frames the face.\n\n"
      "Exit codes: 0 success, 1 bad input or failed write, 2 wrong usage.");
  parser.addHelpOption();
  parser.addVersionOption();
  parser.addPositionalArgument(
      "FILE", "The animation: a .fap file or a project (.lacrima or .json).", "[FILE]");
  parser.addOptions({
      {"render",
       "Render every frame to OUT_DIR/frame_NNNN.png plus contact_sheet.png, then exit (needs an X "
       "display: run under xvfb-run).",
       "OUT_DIR"},
      {"alpha", "With --render: RGBA frames with a transparent background, for compositing."},
      {"masks",
       "With --render: beside each frame a mask_NNNN.png of the same render's tears (255 tear "
       "water, 128 wet trail, 0 the rest)."},
      {"export-gltf",
       "Export the animation with its tears as one binary glTF 2.0 file (head, morph targets "
       "named by FAP, eye and head joints, tears per frame), then exit. Needs no display.",
       "OUT.glb"},
      {"video",
       "Export the animation as an H.264 MP4 video (yuv420p, the file's frame rate) at --size "
       "from --view, then exit (needs an X display: run under xvfb-run).",
       "OUT.mp4"},
      {"export-tears",
       "Export the tear geometry of every frame (water and wet trails) as OUT_DIR/tears_NNNN.ply, "
       "then exit. Needs no display.",
       "OUT_DIR"},
      {"frames", "Frames to render or export, both included (default: all).", "FIRST-LAST"},
      {"size",
       "Image size for --render and --video, window size otherwise (default 1280x720 for "
       "--render and --video).",
       "WxH"},
      {"view",
       "Camera of --render, --screenshot and the window: framing (the viewport's reset view, "
       "the default), front, three-quarter, profile, close-left or close-right (a cheek and its "
       "tear filling the image), measured on the head shown.",
       "NAME", "framing"},
      {"mesh",
       "Your own head (any format assimp reads) instead of the default head or the project's; "
       "needs --fdp.",
       "FILE"},
      {"fdp", "The feature-point file (*.fdp.json) of --mesh.", "FILE"},
      {"play", "Start playing as soon as the file is open."},
      {"loop", "Play again from the start at the end (Playback > Loop, L)."},
      {"screenshot", "Grab the whole window to PNG after showing FILE at --at seconds, then exit.",
       "PNG"},
      {"at", "Time for --screenshot, in seconds (default 0).", "SECONDS", "0"},
      {"quality",
       "Tear quality, in place of the file's: preview (longer sub-steps, faster), balanced (the "
       "default) or reference (shorter sub-steps, closest to a fine reference).",
       "LEVEL"},
      appsupport::threadsOption(QStringLiteral("the tear simulation")),
      {"listen",
       "Play a live stream (repeatable): fap+tcp://HOST:PORT, fap+udp://HOST:PORT or "
       "livelink+udp://HOST:PORT. Without HOST only this machine can send (127.0.0.1).",
       "URL"},
      {"record",
       "Record what arrives, after retargeting, to a FAP file, written when the player ends.",
       "OUT.fap"},
      {"record-rate", "Frame rate of --record (default: the stream's, else 30).", "FPS"},
      {"mapping",
       "The Live Link mapping table (ARKit blendshapes to FAPs, with gains) in place of the "
       "shipped one (media/livelink-mapping.json).",
       "FILE"},
      {"no-window",
       "Run without a window (with --listen, and --record and/or --render: the take rendered "
       "when the stream ends): for scripts and tests. A stream's mood lines drive the crying "
       "generator, and --record keeps its frames."},
      {"exit-when-idle", "End after this long without a live frame or mood line.", "SECONDS"},
      {"no-tears",
       "With --render, --video or an export: the animation without its tear channels (69/70), "
       "the same face with no tear: the other half of a paired stimulus."},
      {"stats",
       "With --render, --video or an export: write what was simulated to FILE.json (frames, "
       "frames with tears, peak particles, a hash of the tears' state at every frame).",
       "FILE.json"},
      {"mood",
       "Play the crying generator live, with no file: moods sadness, anger, joy, shame, each "
       "0..1 (the Mood panel changes them).",
       "MOODS"},
      {"seed", "The generator's seed with --mood (default 1): another seed, another take.", "N"},
  });
  parser.process(app);
  const std::optional<int> threads = appsupport::threadsFrom(parser, "lacrima-player");
  if (!threads) return kExitUsage;
  ModeOptions mode;
  mode.threads = *threads;
  mode.tears = !parser.isSet("no-tears");
  mode.stats = parser.value("stats");
  const bool fileOutput = parser.isSet("render") || parser.isSet("video") ||
                          parser.isSet("export-gltf") || parser.isSet("export-tears");
  if ((parser.isSet("no-tears") || parser.isSet("stats")) && (!fileOutput || noWindow)) {
    std::fprintf(stderr,
                 "lacrima-player: --no-tears and --stats go with --render, --video, "
                 "--export-gltf or --export-tears on a FILE\n");
    return kExitUsage;
  }
  if (!readMoodOptions(parser, mode)) return kExitUsage;
  if (parser.isSet("mesh") != parser.isSet("fdp")) {
    std::fprintf(stderr,
                 "lacrima-player: --mesh and --fdp go together (a head and its feature points)\n");
    return kExitUsage;
  }
  if ((parser.isSet("alpha") || parser.isSet("masks")) && !parser.isSet("render")) {
    std::fprintf(stderr, "lacrima-player: --alpha and --masks go with --render OUT_DIR\n");
    return kExitUsage;
  }
  if (parser.isSet("quality")) {
    const std::string name = parser.value("quality").toStdString();
    mode.quality = parseTearQuality(name);
    if (!mode.quality) {
      std::fprintf(stderr,
                   "lacrima-player: --quality: expected preview, balanced or reference, not "
                   "'%s'\n",
                   name.c_str());
      return kExitUsage;
    }
  }
  QSize size(1280, 720);
  if (parser.isSet("size")) {
    const ParsedImageSize parsed = parseImageSize(parser.value("size").toStdString());
    if (!parsed.error.empty()) {
      std::fprintf(stderr, "lacrima-player: --size: %s\n", parsed.error.c_str());
      return kExitUsage;
    }
    size = parsed.size;
  }
  std::optional<LiveOptions> live = liveOptions(parser);
  if (!live) return kExitUsage;
  try {
    if (parser.isSet("mapping"))
      live->mapping = LiveLinkMapping::load(parser.value("mapping").toStdString());
    if (noWindow) return headlessMode(app, parser, *live, size, mode);
    if (parser.isSet("export-gltf")) return gltfMode(parser, mode);
    if (parser.isSet("export-tears")) return tearsMode(parser, mode);
    if (parser.isSet("video")) return videoMode(parser, size, mode);
    if (parser.isSet("render")) return renderMode(parser, size, mode);
    return windowMode(app, parser, parser.isSet("size") ? &size : nullptr, mode, *live);
  } catch (const std::exception& e) {
    const QString input = parser.positionalArguments().value(0);
    std::fprintf(stderr, "lacrima-player: %s\n",
                 player::describeError(e, input).oneLine.toLocal8Bit().constData());
    return kExitBadInput;
  }
}
