// lacrima-scene-shots: renders the default head crying at 1280x720 into PNGs (for judging the
// look) and measures how long a render takes at 1280x720 and 640x480. Needs an X display
// (xvfb-run -a). Usage:
//   lacrima-scene-shots [OUT_DIR] [--timing | --quick-timing] [--close] [--particles]
//                       [--no-trails] [--no-surface] [--simulate N]
// OUT_DIR defaults to the current folder. The tears are SyntheticTears (drops and trails placed
// on the cheeks); --simulate N runs the tear simulation instead for N frames at 22 fps with 100
// particles per eye. --particles also draws the particle spheres. --timing prints ms per frame
// of the off-screen renderer (with and without 4x multisampling) and of the on-screen viewport
// (render and buffer swap) at 1280x720 and 640x480; --quick-timing only the renderer at 1280x720.
// The renderer is timed with the framing camera, or with --close with the camera of
// crying-close.png (the skin fills the frame and gets its fine relief).
#include "SyntheticTears.h"

#include <lacrima/rigging/DefaultHead.h>
#include <lacrima/scene/FaceRenderer.h>
#include <lacrima/scene/OgreRuntime.h>
#include <lacrima/viewport/FaceViewport.h>

#include <QApplication>
#include <QDir>
#include <QElapsedTimer>

#include <algorithm>
#include <cstdio>
#include <ctime>
#include <vector>

using namespace lacrima;

namespace {

// CPU time of the whole process (every thread, the rasteriser's included), in ms: on a machine
// shared with other work the wall time says more about the neighbours than about the render.
double processCpuMilliseconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return 1e3 * double(t.tv_sec) + 1e-6 * double(t.tv_nsec);
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0 : v[v.size() / 2];
}

void measure(scene::FaceRenderer& renderer, const playback::FrameView& frame, QSize size,
             int samples, int runs = 15) {
  renderer.resize(size);
  renderer.setSamples(samples);
  std::vector<double> total, render, readback, upload;
  playback::FrameView view = frame;
  renderer.show(view);
  renderer.render();  // warm-up: shader variants are compiled on first use
  const double cpuStart = processCpuMilliseconds();
  for (int i = 0; i < runs; ++i) {
    view.revision = i + 100;
    renderer.show(view);
    renderer.render();
    const auto& t = renderer.lastTimes();
    upload.push_back(t.upload);
    render.push_back(t.render);
    readback.push_back(t.readback);
    total.push_back(t.upload + t.render + t.readback);
  }
  const double cpu = (processCpuMilliseconds() - cpuStart) / runs;
  std::printf(
      "%dx%d, %dx MSAA: %.1f ms per frame wall (upload %.2f, render %.1f, read-back %.1f; medians "
      "of %d), "
      "%.1f ms CPU per frame (all threads)\n",
      size.width(), size.height(), samples, median(total), median(upload), median(render),
      median(readback), runs, cpu);
}

// The viewport widget at `size`: each frame a new revision is shown and the event loop runs
// until the widget has rendered it (upload, render and buffer swap: what the player pays).
void measureViewport(const playback::FrameView& frame, QSize size, int runs = 40) {
  viewport::FaceViewport widget;
  widget.resize(size);
  widget.show();
  QElapsedTimer settle;
  settle.start();
  while (settle.elapsed() < 500) QCoreApplication::processEvents();
  playback::FrameView view = frame;
  std::vector<double> render;
  const double cpuStart = processCpuMilliseconds();
  const long long rendersBefore = widget.renderCount();
  for (int i = 0; i < runs; ++i) {
    view.revision = 1000 + i;
    const long long before = widget.renderCount();
    widget.showFrame(view);
    while (widget.renderCount() == before)
      QCoreApplication::processEvents(QEventLoop::AllEvents, 5);
    render.push_back(widget.lastRenderMilliseconds());
  }
  const double cpu = (processCpuMilliseconds() - cpuStart) / runs;
  std::printf(
      "viewport %dx%d: %.1f ms per frame wall (render + swap, median of %d), %.1f ms CPU per "
      "frame, %lld renders\n",
      size.width(), size.height(), median(render), runs, cpu, widget.renderCount() - rendersBefore);
}

// The real simulation, surface and trails after `frames` frames.
struct SimulatedTears {
  std::unique_ptr<tears::TearSimulation> simulation;
  std::unique_ptr<tears::TrailBuilder> trails;
  tears::SurfaceMesher mesher;
  SimulatedTears(const HeadMesh& head, int frames) {
    simulation = tears::TearSimulation::forHead(head);
    trails = std::make_unique<tears::TrailBuilder>(head.findSubmesh("skin")->triangles);
    for (int f = 0; f < frames; ++f) {
      simulation->step(head.positions, 100, 100, 1.0 / 22.0);
      trails->update(*simulation, head.positions, 1.0 / 22.0);
    }
    mesher.update(*simulation);
  }
};

}  // namespace

int main(int argc, char** argv) {
  QApplication app(argc, argv);
  const QStringList args = app.arguments().mid(1);
  QString out = QStringLiteral(".");
  bool timing = false, quick = false, viewportOnly = false, close = false, particles = false,
       noTrails = false, noSurface = false;
  int simulate = 0, runs = 80;
  for (int i = 0; i < args.size(); ++i) {
    if (args[i] == QLatin1String("--timing"))
      timing = true;
    else if (args[i] == QLatin1String("--quick-timing"))
      timing = quick = true;
    else if (args[i] == QLatin1String("--viewport-timing"))
      timing = viewportOnly = true;
    else if (args[i] == QLatin1String("--close"))
      close = true;
    else if (args[i] == QLatin1String("--particles"))
      particles = true;
    else if (args[i] == QLatin1String("--no-trails"))
      noTrails = true;
    else if (args[i] == QLatin1String("--no-surface"))
      noSurface = true;
    else if (args[i] == QLatin1String("--simulate") && i + 1 < args.size())
      simulate = args[++i].toInt();
    else if (args[i] == QLatin1String("--runs") && i + 1 < args.size())
      runs = std::max(1, args[++i].toInt());
    else
      out = args[i];
  }
  QDir().mkpath(out);
  if (!rigging::defaultHeadAvailable()) {
    std::fprintf(stderr, "default head not fetched (packaging/fetch-default-head.sh)\n");
    return 1;
  }
  const HeadMesh head = rigging::loadDefaultHead();
  const scenetest::SyntheticTears synthetic(head);
  std::unique_ptr<SimulatedTears> simulated;
  playback::FrameView frame = synthetic.view();
  frame.particleRadius = synthetic.particleRadius();
  const tears::ParticleSet* particleSet = &synthetic.particles();
  if (simulate > 0) {
    simulated = std::make_unique<SimulatedTears>(head, simulate);
    frame.surface = simulated->mesher.surface().empty() ? nullptr : &simulated->mesher.surface();
    frame.trails = simulated->trails->mesh().empty() ? nullptr : &simulated->trails->mesh();
    frame.particleRadius = simulated->simulation->particleRadius();
    particleSet = &simulated->simulation->particles();
  }
  if (particles) frame.particles = particleSet;
  if (noTrails) frame.trails = nullptr;
  if (noSurface) frame.surface = nullptr;
  std::printf("tears: %d particles, surface %d triangles, trails %d triangles\n",
              particleSet->size(), frame.surface ? frame.surface->triangleCount() : 0,
              frame.trails ? frame.trails->triangleCount() : 0);

  QElapsedTimer startup;
  startup.start();
  const auto runtime = scene::OgreRuntime::acquire();
  const qint64 ogreMs = startup.elapsed();
  scene::FaceRenderer renderer(head, QSize(1280, 720));
  std::printf(
      "start-up: OGRE and the shaders %lld ms, the head (textures, masks, layers, buffers) %lld "
      "ms\n",
      ogreMs, startup.elapsed() - ogreMs);
  renderer.setSamples(4);
  frame.overlays.redness = 1.0;
  frame.overlays.wetEyes = {1.0, 1.0};
  frame.overlays.blush = 0.35;
  renderer.show(frame);
  const QString first = out + QStringLiteral("/crying-front.png");
  renderer.render().save(first);

  auto closeUp = [&renderer] {
    renderer.resetView();
    renderer.orbit(24, -2);
    renderer.zoom(0.5);
    renderer.pan(0.06, -0.12);
  };
  closeUp();
  const QString second = out + QStringLiteral("/crying-close.png");
  renderer.render().save(second);

  renderer.resetView();
  playback::FrameView calm;
  calm.neutral = &head;
  renderer.show(calm);
  const QString third = out + QStringLiteral("/neutral.png");
  renderer.render().save(third);
  if (!quick)
    std::printf("wrote %s, %s, %s\n", qPrintable(first), qPrintable(second), qPrintable(third));

  if (!timing) return 0;
  renderer.resetView();
  if (close) closeUp();
  if (viewportOnly) {
    measureViewport(frame, QSize(1280, 720), runs);
    return 0;
  }
  if (quick) {
    measure(renderer, frame, QSize(1280, 720), 0, runs);
    return 0;
  }
  for (int samples : {0, 4})
    for (QSize size : {QSize(1280, 720), QSize(640, 480)}) measure(renderer, frame, size, samples);
  for (QSize size : {QSize(1280, 720), QSize(640, 480)}) measureViewport(frame, size);
  return 0;
}
