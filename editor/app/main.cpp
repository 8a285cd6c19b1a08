// lacrima-editor: keyframe MPEG-4 facial animation with tears.
//
//   lacrima-editor [FILE]                 a project (.lacrima, .json) or a FAP file to import
//   lacrima-editor FILE --screenshot PNG  render the window (with the preview) to PNG and exit
//   lacrima-editor --head MESH [--points FDP] [--propose]
//                                         the Head workspace on MESH (bring your own head)
// Exit status: 0 on success, 1 when FILE or the screenshot cannot be read or written, 2 on
// wrong usage.
#include <lacrima/appsupport/ThreadsOption.h>
#include <lacrima/appsupport/WindowShot.h>
#include <lacrima/common/CommandLineNumbers.h>
#include <lacrima/common/FapChannels.h>
#include <lacrima/common/ImageSize.h>
#include <lacrima/common/Keyframes.h>
#include <lacrima/editing/EditorModel.h>
#include <lacrima/editor/EditorTheme.h>
#include <lacrima/editor/MainWindow.h>
#include <lacrima/editor/PresetPanel.h>
#include <lacrima/editor/PreviewPanel.h>
#include <lacrima/editor/SliderPanel.h>
#include <lacrima/editor/head/HeadWorkspace.h>

#include <QApplication>
#include <QCommandLineParser>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QImage>
#include <QLineEdit>
#include <QTimer>
#include <QTreeWidget>

#include <cstdio>
#include <optional>
#include <string>

using namespace lacrima::editor;
namespace appsupport = lacrima::appsupport;

namespace {

// --warm-up: ten minutes of frames at 22 fps is far more than any picture needs.
constexpr int kMaxWarmUpFrames = 13200;

// Runs the event loop until `signal` of `sender` fires (its first argument, when a bool, is
// the outcome) or `timeoutMs` passes; false on timeout or a false outcome.
template <typename Signal>
bool waitFor(const head::HeadWorkspace* sender, Signal signal, int timeoutMs = 60000) {
  QEventLoop loop;
  bool outcome = false;
  QObject::connect(sender, signal, &loop, [&](auto... args) {
    outcome = true;
    if constexpr (sizeof...(args) == 1) outcome = (args, ...);
    loop.quit();
  });
  QTimer::singleShot(timeoutMs, &loop, &QEventLoop::quit);
  loop.exec();
  return outcome;
}

// --head: the Head workspace on a mesh, with a points file and the proposal when asked. In a
// batch run (--screenshot) each step is waited for, so the picture shows the rigged head.
bool setUpHead(MainWindow& window, const QString& mesh, const QString& points, bool propose,
               bool batch) {
  head::HeadWorkspace& workspace = *window.headWorkspace();
  window.setWorkspace(MainWindow::Workspace::Head);
  workspace.importHead(mesh);
  if (!batch && points.isEmpty() && !propose) return true;
  if (!waitFor(&workspace, &head::HeadWorkspace::importFinished)) return false;
  if (!points.isEmpty() && !workspace.openPoints(points)) return false;
  if (propose) {
    workspace.proposePoints();
    if (!waitFor(&workspace, &head::HeadWorkspace::proposalFinished)) return false;
  }
  if (batch) {  // the rig starts after a short pause, or not at all while FAPU points miss
    QElapsedTimer waited;
    waited.start();
    while (workspace.rigging() && waited.elapsed() < 60000)
      QCoreApplication::processEvents(QEventLoop::AllEvents, 50);
    if (workspace.rigging()) return false;
  }
  return true;
}

QString headError(MainWindow& window) {
  const QString error = window.headWorkspace()->lastError();
  return error.isEmpty() ? QStringLiteral("the Head workspace did not finish within a minute")
                         : error;
}

}  // namespace

int main(int argc, char** argv) {
  QApplication app(argc, argv);
  QApplication::setApplicationName(QStringLiteral("lacrima-editor"));
  QApplication::setOrganizationName(QStringLiteral("lacrima"));
  QApplication::setApplicationVersion(QStringLiteral(LACRIMA_VERSION));

  QCommandLineParser parser;
  parser.setApplicationDescription(
      QStringLiteral("Keyframe MPEG-4 facial animation with real-time tears."));
  parser.addHelpOption();
  parser.addVersionOption();
  parser.addPositionalArgument(
      QStringLiteral("file"),
      QStringLiteral("A project (.lacrima or .json) to open or a FAP file to import."),
      QStringLiteral("[file]"));
  const QCommandLineOption screenshot(QStringLiteral("screenshot"),
                                      QStringLiteral("Save the window as PNG to <file> and exit."),
                                      QStringLiteral("file"));
  const QCommandLineOption size(QStringLiteral("size"),
                                QStringLiteral("Window size for --screenshot (default 1440x900)."),
                                QStringLiteral("WxH"), QStringLiteral("1440x900"));
  const QCommandLineOption time(QStringLiteral("time"),
                                QStringLiteral("Start at this time in seconds."),
                                QStringLiteral("seconds"));
  const QCommandLineOption filter(QStringLiteral("filter"),
                                  QStringLiteral("Start with this channel filter."),
                                  QStringLiteral("text"));
  const QCommandLineOption focus(QStringLiteral("focus"),
                                 QStringLiteral("Draw this channel's curve in the timeline."),
                                 QStringLiteral("fap"));
  const QCommandLineOption presets(
      QStringLiteral("presets"),
      QStringLiteral("Use this presets file instead of the built-in one."), QStringLiteral("file"));
  const QCommandLineOption noPreview(QStringLiteral("no-preview"),
                                     QStringLiteral("Do not load the head (no 3D preview)."));
  const QCommandLineOption warm(
      QStringLiteral("warm-up"),
      QStringLiteral("For --screenshot: simulate this many frames of tears first."),
      QStringLiteral("frames"), QStringLiteral("0"));
  const QCommandLineOption headMesh(
      QStringLiteral("head"),
      QStringLiteral("Open the Head workspace and import this mesh (any format assimp reads)."),
      QStringLiteral("mesh"));
  const QCommandLineOption headPoints(
      QStringLiteral("points"),
      QStringLiteral("With --head: open this feature-point file (complete or partial)."),
      QStringLiteral("fdp"));
  const QCommandLineOption propose(
      QStringLiteral("propose"),
      QStringLiteral("With --head: propose every feature point not placed by hand."));
  const QCommandLineOption view(
      QStringLiteral("view"),
      QStringLiteral("Show this animation view under the transport: keys, dope, graph or moods."),
      QStringLiteral("name"), QStringLiteral("keys"));
  const QCommandLineOption threads =
      appsupport::threadsOption(QStringLiteral("the preview's tear simulation"));
  parser.addOptions({screenshot, size, time, filter, focus, presets, noPreview, warm, headMesh,
                     headPoints, propose, view, threads});
  parser.process(app);
  const std::optional<int> threadCount = appsupport::threadsFrom(parser, "lacrima-editor");
  if (!threadCount) return 2;

  // Numbers are checked before any window exists: a wrong one is a usage error, not a value
  // quietly read as 0.
  std::string error;
  const auto usage = [&error] {
    std::fprintf(stderr, "lacrima-editor: %s\n", error.c_str());
    return 2;
  };
  std::optional<double> startTime;
  if (parser.isSet(time) &&
      !(startTime = lacrima::readNumberOption("--time", "seconds", parser.value(time).toStdString(),
                                              0, lacrima::kMaxKeyTime, error)))
    return usage();
  std::optional<int> focusFap;
  if (parser.isSet(focus) && !(focusFap = lacrima::readWholeNumberOption(
                                   "--focus", "a FAP number", parser.value(focus).toStdString(), 1,
                                   lacrima::kChannelCount, error)))
    return usage();
  const std::optional<int> warmUpFrames = lacrima::readWholeNumberOption(
      "--warm-up", "frames", parser.value(warm).toStdString(), 0, kMaxWarmUpFrames, error);
  if (!warmUpFrames) return usage();

  const bool batch = parser.isSet(screenshot);
  theme::apply(app);  // screenshots show the editor as people see it

  const QStringList files = parser.positionalArguments();
  if (files.size() > 1) {
    std::fprintf(stderr, "lacrima-editor: one file at a time\n");
    return 2;
  }

  EditorOptions options;
  options.preview = !parser.isSet(noPreview);
  options.interactive = !batch;
  options.offerRecovery = !batch;
  options.presetsPath = parser.value(presets);
  options.simulationThreads = *threadCount;
  MainWindow window(options);
  if (!window.lastError().isEmpty())
    std::fprintf(stderr, "lacrima-editor: %s\n", qPrintable(window.lastError()));

  if (!files.isEmpty() && !window.openFile(files.front())) {
    std::fprintf(stderr, "lacrima-editor: %s\n", qPrintable(window.lastError()));
    if (batch) return 1;
  }
  if ((parser.isSet(headPoints) || parser.isSet(propose)) && !parser.isSet(headMesh)) {
    std::fprintf(stderr, "lacrima-editor: --points and --propose need --head MESH\n");
    return 2;
  }
  if (startTime) window.model().setCurrentTime(*startTime);
  if (parser.isSet(filter)) window.sliders()->setFilterText(parser.value(filter));
  if (focusFap) window.model().setFocusChannel(*focusFap);
  if (!window.showAnimationView(parser.value(view))) {
    std::fprintf(stderr, "lacrima-editor: --view: expected keys, dope, graph or moods, got %s\n",
                 qPrintable(parser.value(view)));
    return 2;
  }

  if (!batch) {
    window.show();
    if (parser.isSet(headMesh) &&
        !setUpHead(window, parser.value(headMesh), parser.value(headPoints), parser.isSet(propose),
                   false))
      std::fprintf(stderr, "lacrima-editor: %s\n", qPrintable(headError(window)));
    return app.exec();
  }

  const lacrima::ParsedImageSize windowSize =
      lacrima::parseImageSize(parser.value(size).toStdString());
  if (!windowSize.error.empty()) {
    std::fprintf(stderr, "lacrima-editor: --size: %s\n", windowSize.error.c_str());
    return 2;
  }
  window.resize(windowSize.size);
  window.show();
  // Let the window lay out and the head load before grabbing.
  QElapsedTimer settle;
  settle.start();
  while (settle.elapsed() < 300) app.processEvents(QEventLoop::AllEvents, 50);
  if (parser.isSet(headMesh)) {
    if (!setUpHead(window, parser.value(headMesh), parser.value(headPoints), parser.isSet(propose),
                   true)) {
      std::fprintf(stderr, "lacrima-editor: %s\n", qPrintable(headError(window)));
      return 1;
    }
  } else {
    window.preview()->loadHead();
  }
  // The preview steps its tears on a worker; a warm-up waits for each step so the picture shows
  // exactly that many frames of tears.
  for (int i = 0; i < *warmUpFrames; ++i) {
    window.preview()->step(window.model().frameDuration());
    window.preview()->waitForTears();
  }
  settle.restart();
  while (settle.elapsed() < 300) app.processEvents(QEventLoop::AllEvents, 50);
  const QImage image = appsupport::grabWindowWithViewports(window);
  // Quality 0 is zlib level 9 for PNG: the smallest file, same pixels.
  if (image.isNull() || !image.save(parser.value(screenshot), "PNG", 0)) {
    std::fprintf(stderr, "lacrima-editor: cannot write %s\n", qPrintable(parser.value(screenshot)));
    return 1;
  }
  std::printf("%s: %dx%d\n", qPrintable(parser.value(screenshot)), image.width(), image.height());
  return 0;
}
