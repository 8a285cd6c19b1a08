// lacrima-bench editor: what the editor costs while an animator works. The live preview of the
// face with 500 tear particles (target >= 30 fps, measured through the editor's own preview
// panel: FrameProducer::produce, then the viewport's render), and the widget costs behind
// "instant": building the window and the 70 sliders, refreshing all sliders on a time change,
// one slider drag step (an undo command merged into the drag), and painting the timeline of a
// long animation. And the Head workspace: the ICT head from file to rigged, posable head with
// its hand-made feature points (import and rig on worker threads), timed on the wall clock with
// the longest event-loop stall (the largest gap between ticks of a 1 ms timer).
#include "BenchCommandLine.h"
#include "BenchEditorApp.h"
#include "BenchSupport.h"
#include "RealHeads.h"

#include <lacrima/common/FapTable.h>
#include <lacrima/common/JsonWriter.h>
#include <lacrima/editing/EditorModel.h>
#include <lacrima/editing/FapTransfer.h>
#include <lacrima/editor/DopeSheetView.h>
#include <lacrima/editor/MainWindow.h>
#include <lacrima/editor/PreviewPanel.h>
#include <lacrima/editor/SliderPanel.h>
#include <lacrima/editor/TimelineWidget.h>
#include <lacrima/editor/head/HeadWorkspace.h>
#include <lacrima/viewport/FaceViewport.h>

#include <QElapsedTimer>
#include <QFileInfo>
#include <QTimer>
#include <QWindow>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace lacrima::bench {

namespace {

constexpr double kPreviewTargetFps = 30;
constexpr int kTearsPerEye = 250;  // 500 particles in all

struct Options {
  int frames = 110;  // timed preview frames (5 s at 22 fps)
  int warmUp = 44;   // frames before timing: the tears reach their count and start running
  int width = 1440, height = 900;  // the editor window; the viewport gets what the docks leave
  bool json = false;
};

std::optional<int> parseOptions(int argc, char** argv, Options& options) {
  BenchCommandLine line(
      "editor",
      QString("Times the editor's widgets and its live preview with %1 tear particles.\n"
              "The preview needs an X display (OGRE is GLX only): run under\n"
              "  xvfb-run -a -s \"-screen 0 1280x1024x24\" lacrima-bench editor\n"
              "Without a display or without the default head, only the widget figures are printed.")
          .arg(2 * kTearsPerEye));
  line.wholeNumber("frames", "N", "Timed preview frames (default 110).", 1, 100000, options.frames);
  line.wholeNumber("warm-up", "N", "Preview frames before timing (default 44).", 0, 100000,
                   options.warmUp);
  line.imageSize("size", "Editor window size (default 1440x900: a 628x598 viewport).",
                 options.width, options.height);
  line.flag("json", "One JSON object instead of the table.", options.json);
  return line.parse(argc, argv);
}

// Two full poses a second apart: every slider changes between them.
ProjectDocument twoPoses() {
  ProjectDocument doc;
  for (int k = 0; k < 2; ++k) {
    Keyframe key;
    key.time = k;
    for (int fap = 3; fap <= kChannelCount; ++fap) {
      const FapInfo& info = fapInfo(fap);
      key.set(fap, static_cast<float>(k == 0 ? info.sliderMin / 3 : info.sliderMax / 3));
    }
    doc.keys.insert(key);
  }
  return doc;
}

// Two minutes of smooth motion on every channel, imported as one key per frame.
ProjectDocument longAnimation() {
  FapAnimation animation;
  animation.fps = 22;
  animation.frames.assign(2640, FapValues{});
  for (std::size_t i = 0; i < animation.frames.size(); ++i)
    for (int fap = 3; fap <= kChannelCount; ++fap)
      animation.frames[i][static_cast<std::size_t>(channelIndex(fap))] =
          static_cast<float>(std::lround(std::max(0.0, 200 * std::sin(0.05 * i + fap))));
  for (int fap = 3; fap <= kChannelCount; ++fap)
    animation.animated.set(static_cast<std::size_t>(channelIndex(fap)));
  return editing::importAnimation(animation).document;
}

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

}  // namespace

int runEditor(int argc, char** argv) {
  Options options;
  if (const std::optional<int> status = parseOptions(argc, argv, options)) return *status;

  BenchEditorApp app;
  const bool display = app.hasDisplay();
  editor::EditorOptions editorOptions = app.editorOptions(false);

  // Building: the whole window without the head, and the 70-slider panel alone.
  const Timing windowBuild = timeRuns(5, [&] { editor::MainWindow window(editorOptions); });
  editing::EditorModel panelModel;
  const Timing panelBuild = timeRuns(10, [&] { editor::SliderPanel panel(panelModel); });

  editing::EditorModel model;
  model.resetDocument(twoPoses(), true);
  editor::SliderPanel panel(model);
  panel.resize(460, 900);
  panel.show();
  // A time change refreshes every slider (values, key marks, group counts).
  int flip = 0;
  const Timing sliderRefresh =
      timeRuns(200, [&] { model.setCurrentTime((flip++ % 2) ? 1.0 : 0.5); });
  // One step of a slider drag: a command pushed and merged into the drag, then the refresh.
  const int session = model.beginDragSession();
  int value = 0;
  const Timing dragStep =
      timeRuns(200, [&] { model.setChannel(3, (value++ % 500) + 10, session); });

  // The timeline of a two-minute, 68-channel animation (2,640 keys), whole and zoomed in.
  editing::EditorModel longModel;
  longModel.resetDocument(longAnimation(), true);
  editor::TimelineWidget timeline(longModel);
  timeline.resize(1400, 200);
  timeline.show();
  QElapsedTimer exposing;
  exposing.start();
  while (!(timeline.windowHandle() && timeline.windowHandle()->isExposed()) &&
         exposing.elapsed() < 2000)
    QCoreApplication::processEvents(QEventLoop::AllEvents, 20);
  QCoreApplication::processEvents();
  // repaint() paints now, through the window's backing store, as a real update does.
  timeline.fitAll();
  const Timing paintAll = timeRuns(30, [&] { timeline.repaint(); });
  timeline.setView(30.0, 200.0);
  const Timing paintZoomed = timeRuns(30, [&] { timeline.repaint(); });
  int scrubFrame = 0;
  const Timing scrub = timeRuns(60, [&] {
    longModel.setCurrentTime(30.0 + (scrubFrame++ % 100) / 22.0);
    timeline.repaint();
  });

  // The dope sheet of the same animation: 68 channel rows (as many as fit are drawn), whole
  // and zoomed in; selecting every channel key (179,520) and moving them all by a frame, as
  // one undo step (plan, apply and repaint), then undoing it.
  editor::DopeSheetView dopeSheet(longModel);
  dopeSheet.resize(1400, 400);
  dopeSheet.show();
  QCoreApplication::processEvents();
  dopeSheet.fitAll();
  const Timing dopePaintAll = timeRuns(30, [&] { dopeSheet.repaint(); });
  dopeSheet.setView(30.0, 200.0);
  const Timing dopePaintZoomed = timeRuns(30, [&] { dopeSheet.repaint(); });
  dopeSheet.fitAll();
  const Timing dopeSelectAll = timeRuns(5, [&] {
    dopeSheet.clearSelection();
    dopeSheet.selectAll();
  });
  const int dopeChannelKeys = static_cast<int>(longModel.channelKeySelection().keys().size());
  const Timing dopeMoveAll = timeRuns(3, [&] {
    const editing::ChannelKeyEdit edit =
        editing::moveChannelKeys(longModel.document().keys, longModel.channelKeySelection().keys(),
                                 1, longModel.document().fps);
    longModel.editKeys(edit.change, QStringLiteral("bench move"));
    dopeSheet.repaint();
    longModel.undoStack()->undo();
  });

  // The live preview with 500 tear particles, in a full editor window.
  editorOptions.preview = true;
  bool previewRan = false;
  QString previewNote;
  double frameMs = 0, produceMs = 0, renderMs = 0, fps = 0;
  int viewportWidth = 0, viewportHeight = 0;
  int particles = 0;
  {
    editor::MainWindow window(editorOptions);
    window.resize(options.width, options.height);
    window.show();
    QElapsedTimer settle;
    settle.start();
    while (settle.elapsed() < 200) QCoreApplication::processEvents(QEventLoop::AllEvents, 20);
    if (!display) {
      previewNote = QStringLiteral("no X display: the viewport needs one (run under xvfb-run)");
    } else if (!window.preview()->loadHead() || !window.preview()->viewportWidget()) {
      previewNote = QStringLiteral("no preview: ") + window.preview()->statusText();
    } else {
      editing::EditorModel& m = window.model();
      m.setChannels({{kTearLeftFap, kTearsPerEye},
                     {kTearRightFap, kTearsPerEye},
                     {3, 200},
                     {31, 220},
                     {32, 220}},
                    QStringLiteral("bench"));
      window.preview()->setTearPreview(false);  // the benchmark steps the tears itself
      const double dt = 1.0 / 22.0;
      // Each frame waits for its tear step (the preview's worker): every frame is simulated,
      // as in the player, and the figure is the whole frame's cost.
      for (int i = 0; i < options.warmUp; ++i) {
        window.preview()->step(dt);
        window.preview()->waitForTears();
        QCoreApplication::processEvents();
      }
      auto* viewport = qobject_cast<viewport::FaceViewport*>(window.preview()->viewportWidget());
      std::vector<double> frames, produce, render;
      QElapsedTimer total;
      total.start();
      for (int i = 0; i < options.frames; ++i) {
        QElapsedTimer frame;
        frame.start();
        window.preview()->step(dt);
        window.preview()->waitForTears();
        QCoreApplication::processEvents();  // the viewport renders on its deferred request
        frames.push_back(frame.nsecsElapsed() / 1e6);
        produce.push_back(window.preview()->lastProduceMilliseconds());
        if (viewport) render.push_back(viewport->lastRenderMilliseconds());
      }
      renderMs = median(render);
      viewportWidth = window.preview()->viewportWidget()->width();
      viewportHeight = window.preview()->viewportWidget()->height();
      const double elapsed = total.nsecsElapsed() / 1e6;
      frameMs = median(frames);
      produceMs = median(produce);
      fps = options.frames * 1000.0 / elapsed;
      particles = window.preview()->particleCount();
      previewRan = true;
    }
    window.model().markSaved();
  }
  const bool previewPass = previewRan && fps >= kPreviewTargetFps;

  // The Head workspace: import the ICT head, open its feature points, wait for the rig.
  bool headRan = false;
  QString headNote;
  double headImportMs = 0, headRiggedMs = 0, headStallMs = 0;
  if (!display) {
    headNote = QStringLiteral("no X display: the viewport needs one (run under xvfb-run)");
  } else if (!QFileInfo::exists(QString::fromStdString(ictHeadSpec().meshPath))) {
    headNote = QStringLiteral("the ICT-FaceKit head is not on this machine");
  } else {
    editorOptions.preview = false;
    editor::MainWindow window(editorOptions);
    window.resize(options.width, options.height);
    window.show();
    window.setWorkspace(editor::MainWindow::Workspace::Head);
    editor::head::HeadWorkspace& ws = *window.headWorkspace();
    QElapsedTimer settle;
    settle.start();
    while (settle.elapsed() < 500)
      QCoreApplication::processEvents(QEventLoop::AllEvents, 20);  // OGRE up
    bool imported = false, rigged = false, failed = false;
    QObject::connect(&ws, &editor::head::HeadWorkspace::importFinished,
                     [&](bool ok) { (ok ? imported : failed) = true; });
    QObject::connect(&ws, &editor::head::HeadWorkspace::rigFinished, [&] { rigged = true; });
    QObject::connect(&ws, &editor::head::HeadWorkspace::rigFailed, [&] { failed = true; });
    QTimer tick;
    tick.setInterval(1);
    QElapsedTimer sinceTick, wall;
    QObject::connect(&tick, &QTimer::timeout, [&] {
      headStallMs = std::max(headStallMs, sinceTick.nsecsElapsed() / 1e6);
      sinceTick.restart();
    });
    wall.start();
    sinceTick.start();
    tick.start();
    ws.importHead(QString::fromStdString(ictHeadSpec().meshPath));
    while (!imported && !failed && wall.elapsed() < 60000)
      QCoreApplication::processEvents(QEventLoop::WaitForMoreEvents);
    headImportMs = wall.nsecsElapsed() / 1e6;
    if (imported && ws.openPoints(QString::fromStdString(ictHeadSpec().fdpPath))) {
      while (!rigged && !failed && wall.elapsed() < 60000)
        QCoreApplication::processEvents(QEventLoop::WaitForMoreEvents);
    }
    tick.stop();
    headRiggedMs = wall.nsecsElapsed() / 1e6;
    headRan = rigged;
    if (!rigged) headNote = QStringLiteral("not rigged: ") + ws.lastError();
    window.model().markSaved();
  }

  if (options.json) {
    JsonWriter json(JsonWriter::Layout::Compact);
    json.beginObject();
    json.field("benchmark", "editor");
    writeTiming(json, "window_build_ms", windowBuild);
    writeTiming(json, "slider_panel_build_ms", panelBuild);
    writeTiming(json, "slider_refresh_ms", sliderRefresh);
    writeTiming(json, "slider_drag_step_ms", dragStep);
    writeTiming(json, "timeline_paint_all_ms", paintAll);
    writeTiming(json, "timeline_paint_zoomed_ms", paintZoomed);
    writeTiming(json, "timeline_scrub_ms", scrub);
    json.field("timeline_keys", static_cast<int>(longModel.document().keys.keys().size()));
    writeTiming(json, "dope_sheet_paint_all_ms", dopePaintAll);
    writeTiming(json, "dope_sheet_paint_zoomed_ms", dopePaintZoomed);
    writeTiming(json, "dope_sheet_select_all_ms", dopeSelectAll);
    writeTiming(json, "dope_sheet_move_all_ms", dopeMoveAll);
    json.field("dope_sheet_channel_keys", dopeChannelKeys);
    json.key("preview");
    json.beginObject();
    json.field("ran", previewRan);
    if (!previewRan) json.field("note", previewNote.toStdString());
    json.field("particles", particles);
    json.field("frames", options.frames);
    json.field("fps", fps);
    json.field("frame_ms_median", frameMs);
    json.field("produce_ms_median", produceMs);
    json.field("render_ms_median", renderMs);
    json.field("viewport_width", viewportWidth);
    json.field("viewport_height", viewportHeight);
    json.field("target_fps_at_least", kPreviewTargetFps);
    json.field("pass", previewPass);
    json.endObject();
    json.field("pass", previewPass);
    json.key("head_workspace");
    json.beginObject();
    json.field("ran", headRan);
    if (!headRan) json.field("note", headNote.toStdString());
    json.field("import_ms", headImportMs);
    json.field("import_to_rigged_ms", headRiggedMs);
    json.field("longest_stall_ms", headStallMs);
    json.endObject();
    json.endObject();
    std::fputs(std::move(json).finish().c_str(), stdout);
    return 0;
  }

  std::printf("editor widgets (median of runs)\n");
  std::printf("  build window (no head)           %8.2f ms\n", windowBuild.medianMs);
  std::printf("  build 70-slider panel            %8.2f ms\n", panelBuild.medianMs);
  std::printf("  refresh all sliders (time step)  %8.3f ms\n", sliderRefresh.medianMs);
  std::printf("  slider drag step (undo + merge)  %8.3f ms\n", dragStep.medianMs);
  std::printf("  timeline paint, %d keys, all    %8.2f ms\n",
              static_cast<int>(longModel.document().keys.keys().size()), paintAll.medianMs);
  std::printf("  timeline paint, zoomed in        %8.2f ms\n", paintZoomed.medianMs);
  std::printf("  timeline scrub step + paint      %8.2f ms\n", scrub.medianMs);
  std::printf("  dope sheet paint, all            %8.2f ms\n", dopePaintAll.medianMs);
  std::printf("  dope sheet paint, zoomed in      %8.2f ms\n", dopePaintZoomed.medianMs);
  std::printf("  dope sheet select all (%d)   %8.2f ms\n", dopeChannelKeys, dopeSelectAll.medianMs);
  std::printf("  dope sheet move all + undo       %8.2f ms\n", dopeMoveAll.medianMs);
  if (previewRan) {
    std::printf("preview, face + %d tear particles, %d frames, viewport %dx%d\n", particles,
                options.frames, viewportWidth, viewportHeight);
    std::printf("  %.1f fps   target >= %g fps: %s\n", fps, kPreviewTargetFps,
                previewPass ? "PASS" : "MISS");
    std::printf(
        "  frame %.1f ms median: produce %.1f ms (blend + tears), render %.1f ms, the rest is Qt "
        "events\n",
        frameMs, produceMs, renderMs);
  } else {
    std::printf("preview: skipped (%s)\n", qPrintable(previewNote));
  }
  if (headRan) {
    std::printf("Head workspace, ICT head with its feature-point file\n");
    std::printf("  imported (worker thread)         %8.0f ms\n", headImportMs);
    std::printf("  import -> rigged, posable        %8.0f ms\n", headRiggedMs);
    std::printf("  longest event-loop stall         %8.1f ms\n", headStallMs);
  } else {
    std::printf("Head workspace: skipped (%s)\n", qPrintable(headNote));
  }
  return 0;
}

}  // namespace lacrima::bench
