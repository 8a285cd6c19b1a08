// lacrima-bench preview: does the editor's live preview keep the window responsive with many
// tear particles? The editor window runs as an animator uses it: paused, tear preview on, the
// tear channels set to ask for N particles. A 5 ms timer on the UI thread records the largest
// gap between its ticks (the longest event-loop stall) while the preview runs for a few
// seconds; the tear simulation's own step time is printed beside it, since that is what a
// preview on the UI thread would stall for. Then the tear channels go back to 0 and the time
// until the panel shows no particles is measured (it should be at once, not after the running
// step). Target: longest stall <= 50 ms.
#include "BenchCommandLine.h"
#include "BenchEditorApp.h"

#include <lacrima/common/FapTable.h>
#include <lacrima/common/JsonWriter.h>
#include <lacrima/editing/EditorModel.h>
#include <lacrima/editor/MainWindow.h>
#include <lacrima/editor/PreviewPanel.h>
#include <lacrima/viewport/FaceViewport.h>

#include <QElapsedTimer>
#include <QTimer>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace lacrima::bench {

namespace {

constexpr double kStallTargetMs = 50;
constexpr int kTickMs = 5;

struct Options {
  std::vector<int> particles;  // empty: 10,000 and 100,000
  double seconds = 4;
  double maxSeconds = 120;  // a slow count runs on until two tear frames have shown
  int width = 1440, height = 900;
  bool json = false;
};

std::optional<int> parseOptions(int argc, char** argv, Options& options) {
  BenchCommandLine line(
      "preview",
      "The longest event-loop stall of the editor's live preview while it simulates N tear\n"
      "particles (paused, tear preview on), beside the simulation's step time; then how long\n"
      "the preview takes to show no particles once the tear channels go back to 0.\n"
      "Needs an X display and the default head:\n"
      "  xvfb-run -a -s \"-screen 0 1280x1024x24\" lacrima-bench preview");
  line.option("particles", "N",
              "Particles asked for by the tear channels (repeatable; default 10000 and 100000).",
              [&](const QString& value) -> std::string {
                bool ok = false;
                const int n = value.toInt(&ok);
                if (!ok || n < 2 || n > 199998)
                  return "expected a whole number of particles from 2 to 199998";
                options.particles.push_back(n);
                return {};
              });
  line.number("seconds", "S",
              "How long the preview runs per count (default 4), longer until two tear frames "
              "have shown (at most --max-seconds).",
              0.2, 600, options.seconds);
  line.number("max-seconds", "S", "Longest run per count (default 120).", 0.2, 3600,
              options.maxSeconds);
  line.imageSize("size", "Editor window size (default 1440x900).", options.width, options.height);
  line.flag("json", "One JSON object instead of the table.", options.json);
  const std::optional<int> status = line.parse(argc, argv);
  if (options.particles.empty()) options.particles = {10000, 100000};
  return status;
}

struct Run {
  int requested = 0;
  bool ran = false;
  std::string note;
  double stallMs = 0;            // largest gap between ticks of the 5 ms timer
  double tickMedianMs = 0;       // the typical gap (5 ms when nothing stalls)
  double stepMs = 0;             // the preview's longest tear step (what a UI thread would stall)
  double firstParticlesMs = -1;  // from setting the channels until particles show
  int particles = 0;             // shown at the end of the run
  double clearMs = -1;           // tear channels to 0 -> no particles shown (-1: not within 2 s)
  double closeMs = 0;            // destroying the window (the preview stops its work)
  int tearFrames = 0;            // tear frames that reached the panel during the run
  double renderMaxMs = 0;        // the viewport's slowest render (on the UI thread by necessity)
  double seconds = 0;            // how long the preview ran
};

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

Run runOne(const editor::EditorOptions& editorOptions, const Options& options, int requested) {
  Run run;
  run.requested = requested;
  QElapsedTimer closing;
  {
    editor::MainWindow window(editorOptions);
    window.resize(options.width, options.height);
    window.show();
    editor::PreviewPanel& preview = *window.preview();
    if (!preview.loadHead() || !preview.viewportWidget()) {
      run.note = "no preview: " + preview.statusText().toStdString();
      window.model().markSaved();
      return run;
    }
    QElapsedTimer settle;
    settle.start();
    while (settle.elapsed() < 300) QCoreApplication::processEvents(QEventLoop::AllEvents, 20);

    editing::EditorModel& model = window.model();
    if (auto* viewport = qobject_cast<viewport::FaceViewport*>(preview.viewportWidget()))
      QObject::connect(viewport, &viewport::FaceViewport::rendered,
                       [&](double ms) { run.renderMaxMs = std::max(run.renderMaxMs, ms); });
    double lastStepMs = 0;
    std::vector<double> gaps;
    QElapsedTimer sinceTick, wall;
    QTimer tick;
    tick.setTimerType(Qt::PreciseTimer);
    tick.setInterval(kTickMs);
    QObject::connect(&tick, &QTimer::timeout, [&] {
      gaps.push_back(sinceTick.nsecsElapsed() / 1e6);
      sinceTick.restart();
      if (run.firstParticlesMs < 0 && preview.particleCount() > 0)
        run.firstParticlesMs = wall.nsecsElapsed() / 1e6;
      // A new tear frame shows as a new step time (works for a preview stepping on the UI
      // thread as well as for one with a worker).
      const double stepMs = preview.lastProduceMilliseconds();
      if (stepMs > 0 && stepMs != lastStepMs) {
        ++run.tearFrames;
        lastStepMs = stepMs;
        run.stepMs = std::max(run.stepMs, stepMs);
      }
    });
    preview.setTearPreview(true);
    wall.start();
    sinceTick.start();
    tick.start();
    model.setChannels({{kTearLeftFap, static_cast<float>(requested / 2)},
                       {kTearRightFap, static_cast<float>(requested - requested / 2)}},
                      QStringLiteral("bench tears"));
    const auto elapsedS = [&] { return wall.nsecsElapsed() / 1e9; };
    while (elapsedS() < options.seconds ||
           (run.tearFrames < 2 && elapsedS() < std::max(options.seconds, options.maxSeconds)))
      QCoreApplication::processEvents(QEventLoop::WaitForMoreEvents, kTickMs);
    run.seconds = elapsedS();
    run.particles = preview.particleCount();

    // Tears off: the panel should show none at once.
    QElapsedTimer clearing;
    clearing.start();
    model.setChannels({{kTearLeftFap, 0.0f}, {kTearRightFap, 0.0f}}, QStringLiteral("dry"));
    while (clearing.elapsed() < 2000) {
      if (preview.particleCount() == 0) {
        run.clearMs = clearing.nsecsElapsed() / 1e6;
        break;
      }
      QCoreApplication::processEvents(QEventLoop::WaitForMoreEvents, kTickMs);
    }
    tick.stop();
    if (!gaps.empty()) {
      run.stallMs = *std::max_element(gaps.begin(), gaps.end());
      run.tickMedianMs = median(gaps);
    }
    run.ran = true;
    model.markSaved();
    closing.start();
  }
  run.closeMs = closing.nsecsElapsed() / 1e6;
  return run;
}

}  // namespace

int runPreview(int argc, char** argv) {
  Options options;
  if (const std::optional<int> status = parseOptions(argc, argv, options)) return *status;

  BenchEditorApp app;
  const bool display = app.hasDisplay();
  const editor::EditorOptions editorOptions = app.editorOptions(true);

  std::vector<Run> runs;
  for (int requested : options.particles) {
    if (!display) {
      Run skipped;
      skipped.requested = requested;
      skipped.note = "no X display: the viewport needs one (run under xvfb-run)";
      runs.push_back(skipped);
      continue;
    }
    runs.push_back(runOne(editorOptions, options, requested));
  }
  bool pass = true;
  for (const Run& r : runs) pass = pass && r.ran && r.stallMs <= kStallTargetMs;

  if (options.json) {
    JsonWriter json(JsonWriter::Layout::Compact);
    json.beginObject();
    json.field("benchmark", "preview");
    json.field("seconds", options.seconds);
    json.field("tick_ms", kTickMs);
    json.field("target_stall_ms_at_most", kStallTargetMs);
    json.key("runs");
    json.beginArray();
    for (const Run& r : runs) {
      json.beginObject();
      json.field("requested_particles", r.requested);
      json.field("ran", r.ran);
      if (!r.ran) json.field("note", r.note);
      json.field("longest_stall_ms", r.stallMs);
      json.field("tick_median_ms", r.tickMedianMs);
      json.field("longest_step_ms", r.stepMs);
      json.field("first_particles_ms", r.firstParticlesMs);
      json.field("particles_shown", r.particles);
      json.field("clear_ms", r.clearMs);
      json.field("close_ms", r.closeMs);
      json.field("tear_frames", r.tearFrames);
      json.field("render_max_ms", r.renderMaxMs);
      json.field("seconds", r.seconds);
      json.field("pass", r.ran && r.stallMs <= kStallTargetMs);
      json.endObject();
    }
    json.endArray();
    json.field("pass", pass);
    json.endObject();
    std::fputs(std::move(json).finish().c_str(), stdout);
    return 0;
  }

  std::printf("editor preview, paused with tear preview on, %d ms timer on the UI thread\n",
              kTickMs);
  std::printf("  %9s  %11s  %8s  %10s  %6s  %10s  %8s  %10s  %9s  %8s  %9s\n", "requested",
              "stall (max)", "tick med", "step (max)", "frames", "first tear", "shown",
              "render max", "tears->0", "close", "ran");
  for (const Run& r : runs) {
    if (!r.ran) {
      std::printf("  %9d  skipped (%s)\n", r.requested, r.note.c_str());
      continue;
    }
    char clear[32];
    if (r.clearMs >= 0)
      std::snprintf(clear, sizeof clear, "%.1f ms", r.clearMs);
    else
      std::snprintf(clear, sizeof clear, "> 2 s");
    std::printf(
        "  %9d  %8.1f ms  %5.1f ms  %7.0f ms  %6d  %7.0f ms  %8d  %7.1f ms  %9s  %5.0f ms  %7.1f s "
        " "
        "%s\n",
        r.requested, r.stallMs, r.tickMedianMs, r.stepMs, r.tearFrames, r.firstParticlesMs,
        r.particles, r.renderMaxMs, clear, r.closeMs, r.seconds,
        r.stallMs <= kStallTargetMs ? "PASS" : "MISS");
  }
  std::printf("  target: longest stall <= %g ms: %s\n", kStallTargetMs, pass ? "PASS" : "MISS");
  return 0;
}

}  // namespace lacrima::bench
