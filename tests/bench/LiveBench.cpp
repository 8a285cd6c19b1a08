// lacrima-bench live: latency of the live player, from a frame's arrival (decoded by a real
// fap+udp input on loopback) to the end of the render that shows it, at 22, 60 and 120 frames
// per second of input with 100 and 2,000 tear particles. A sender thread streams FAP frames
// (70-token masks carrying the tear counts) through a real socket; the main loop is the
// player's: the event loop delivers the frames to a LiveSource, which poses the newest frame at
// once and steps the tears on its worker; a display tick every 16 ms and at once when a frame
// arrives (or later, when a render takes longer) renders with FaceRenderer when the face or the
// tears changed, when the player's LivePacer says so (--no-pacing: at every tick, as before the
// pacer). A frame's arrival is when its datagram was sent (on loopback, when
// it reached the player's socket), so the time it waits for the UI thread counts. Frames
// dropped are those replaced before a render showed them, plus any the socket lost. Target:
// median latency <= one render (from the tick to its end, the mean of the case) + 5 ms. Needs
// an X display: run under xvfb-run.
#include "BenchCommandLine.h"
#include "BenchGuiApp.h"
#include "BenchSupport.h"

#include <lacrima/common/JsonWriter.h>
#include <lacrima/common/Milliseconds.h>
#include <lacrima/live/LiveSession.h>
#include <lacrima/playback/LivePacer.h>
#include <lacrima/playback/LiveSource.h>
#include <lacrima/scene/FaceRenderer.h>

#include <QCoreApplication>

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <string>
#include <thread>
#include <vector>

namespace lacrima::bench {

namespace {

constexpr double kTickSeconds = 0.016;  // the player's live display tick
constexpr double kTargetSlackMs = 5;
// The frame's number rides in pull_r_ear (an ear, barely seen), so the render that shows it
// knows when it was sent: on loopback, when it reached the player's socket.
constexpr int kNumberFap = 68;
constexpr int kNumbers = 1 << 20;

struct Options {
  int width = 1280, height = 720;
  double seconds = 4;  // measured per case, after a warm-up of as long
  bool json = false;
  bool pacing = true;
};

std::optional<int> parseOptions(int argc, char** argv, Options& o) {
  BenchCommandLine line(
      "live",
      "Streams FAP frames over UDP on loopback into the live player's input, source and\n"
      "renderer, and reports the latency from a frame's arrival to the end of the render that\n"
      "shows it (median, 99th percentile) and the frames dropped, at 22, 60 and 120 fps with\n"
      "100 and 2,000 tear particles. Needs an X display: run under xvfb-run.");
  line.imageSize("size", "Image size (default 1280x720).", o.width, o.height);
  line.number("seconds", "S", "Seconds measured per case, after as long a warm-up (default 4).",
              0.5, 600, o.seconds);
  line.flag("json", "One JSON object instead of the table.", o.json);
  bool noPacing = false;
  line.flag("no-pacing", "Render at every display tick, as the player did before pacing.",
            noPacing);
  if (const std::optional<int> status = line.parse(argc, argv)) return status;
  o.pacing = !noPacing;
  return std::nullopt;
}

// A frame as an agent sends it: the mask line (70 tokens) and the value line.
std::string frameText(int number, int particlesPerEye) {
  std::string mask, values = std::to_string(number);
  for (int fap = 1; fap <= kChannelCount; ++fap) {
    const bool set = fap == 3 || fap == 49 || fap == kNumberFap || fap == 69 || fap == 70;
    mask += set ? '1' : '0';
    mask += fap < kChannelCount ? ' ' : '\n';
  }
  const double phase = number * 0.1;
  values += ' ' + std::to_string(static_cast<int>(300 + 200 * std::sin(phase)));    // open_jaw
  values += ' ' + std::to_string(static_cast<int>(15000 * std::sin(phase * 0.5)));  // head_yaw
  values += ' ' + std::to_string(number % kNumbers);  // which frame this is, for its send time
  values += ' ' + std::to_string(particlesPerEye) + ' ' + std::to_string(particlesPerEye) + '\n';
  return mask + values;
}

struct Case {
  double rate = 0;
  int particles = 0;
  long long sent = 0, received = 0, shown = 0, dropped = 0;
  double medianMs = 0, p99Ms = 0, intervalMs = 0, meanParticles = 0, renderMs = 0;
  bool pass = false;
};

double percentile(std::vector<double> values, double p) {
  if (values.empty()) return 0;
  std::sort(values.begin(), values.end());
  const auto i = static_cast<std::size_t>(std::ceil(p * static_cast<double>(values.size()))) - 1;
  return values[std::min(i, values.size() - 1)];
}

Case runCase(const playback::HeadRig& rig, scene::FaceRenderer& renderer, double rate,
             int particles, double seconds, bool pacing) {
  Case c;
  c.rate = rate;
  c.particles = particles;
  playback::LiveSource live(rig);
  live::LiveSession session;
  playback::LivePacer pacer;
  session.setFrameHandler([&](const live::LiveFrame& f) {
    live.push(f.values, f.mask, f.arrival);
    pacer.frameArrived(f.arrival);
  });
  live::ListenUrl url;
  url.kind = live::StreamKind::FapUdp;
  const quint16 port = session.listen(url).url().port;

  std::atomic<bool> stop = false;
  std::atomic<long long> sent = 0;
  // Send times by frame number; a slot is written before the datagram leaves.
  std::vector<std::atomic<double>> sentAt(kNumbers);
  std::thread sender([&] {
    const int fd = ::socket(AF_INET, SOCK_DGRAM, 0);
    sockaddr_in to{};
    to.sin_family = AF_INET;
    to.sin_port = htons(port);
    to.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    const auto start = SteadyClock::now();
    for (long long k = 0; !stop; ++k) {
      const auto due = start + std::chrono::duration_cast<SteadyClock::duration>(
                                   std::chrono::duration<double>(k / rate));
      std::this_thread::sleep_until(due);
      const std::string text = frameText(static_cast<int>(k), particles / 2);
      sentAt[static_cast<std::size_t>(k % kNumbers)] = live::liveClockSeconds();
      ::sendto(fd, text.data(), text.size(), 0, reinterpret_cast<const sockaddr*>(&to), sizeof to);
      ++sent;
    }
    ::close(fd);
  });

  std::vector<double> latencies;
  double renderTotal = 0;
  long long renders = 0, particleSum = 0;
  const double begin = live::liveClockSeconds();
  const double measureFrom = begin + seconds;  // the warm-up lets the tears reach their count
  const double end = measureFrom + seconds;
  long long sentAtStart = 0, receivedAtStart = 0, droppedAtStart = 0, shownAtStart = 0;
  bool measuring = false;
  double nextTick = begin, lastTick = begin - 1;
  double firstRender = 0, lastRender = 0;
  long long receivedBefore = 0, shownRevision = -1;
  for (double now = begin; now < end; now = live::liveClockSeconds()) {
    QCoreApplication::processEvents(QEventLoop::AllEvents, 1);
    now = live::liveClockSeconds();
    // As the player: a tick every 16 ms, and at once when a frame arrives (at most one render
    // per LiveSource::kMinStep).
    const bool fresh = live.framesReceived() != receivedBefore;
    receivedBefore = live.framesReceived();
    if (fresh && now - lastTick >= playback::LiveSource::kMinStep)
      nextTick = std::min(nextTick, now);
    if (now < nextTick) {
      std::this_thread::sleep_for(std::chrono::microseconds(300));
      continue;
    }
    if (!measuring && now >= measureFrom) {
      measuring = true;
      sentAtStart = sent;
      receivedAtStart = live.framesReceived();
      droppedAtStart = live.framesDropped();
      shownAtStart = live.currentFrame();
      firstRender = -1;
    }
    if (pacing) {
      const playback::LivePacer::Decision wait = pacer.decide(now, live.frameWaiting());
      if (!wait.render) {
        nextTick = wait.wakeAt;  // or at once, when the frame waited for arrives
        continue;
      }
    }
    lastTick = now;
    nextTick = now + kTickSeconds;
    const auto t0 = SteadyClock::now();
    const playback::FrameView& view = live.seek(now);
    if (view.revision == shownRevision) continue;  // nothing new: the viewport draws nothing
    shownRevision = view.revision;
    renderer.show(view);
    renderer.render();
    const double done = live::liveClockSeconds();
    pacer.rendered(done - now);
    if (!measuring) continue;
    if (firstRender < 0) firstRender = now;  // the tick of the first render measured
    renderTotal += millisecondsSince(t0);
    ++renders;
    lastRender = done;
    particleSum += live.particleCount();
    if (live.shownArrival() >= 0) {
      const auto number = static_cast<std::size_t>(
          std::lround(live.shownValues()[static_cast<std::size_t>(channelIndex(kNumberFap))]));
      latencies.push_back((done - sentAt[number % kNumbers].load()) * 1000);
    }
  }
  stop = true;
  sender.join();
  QCoreApplication::processEvents();
  c.sent = sent - sentAtStart;
  c.received = live.framesReceived() - receivedAtStart;
  c.shown = live.currentFrame() - shownAtStart;
  c.dropped = (live.framesDropped() - droppedAtStart) + std::max(0LL, c.sent - c.received);
  c.medianMs = percentile(latencies, 0.5);
  c.p99Ms = percentile(latencies, 0.99);
  c.intervalMs =
      renders > 1 ? (lastRender - firstRender) * 1000 / static_cast<double>(renders - 1) : 0;
  c.renderMs = renders > 0 ? renderTotal / static_cast<double>(renders) : 0;
  c.meanParticles =
      renders > 0 ? static_cast<double>(particleSum) / static_cast<double>(renders) : 0;
  c.pass = c.medianMs <= c.renderMs + kTargetSlackMs;
  return c;
}

}  // namespace

int runLive(int argc, char** argv) {
  Options o;
  if (const std::optional<int> status = parseOptions(argc, argv, o)) return *status;
  if (const std::optional<int> status = missingDisplayOrHead("live")) return *status;
  const BenchGuiApp app;
  try {
    const auto rig = playback::loadDefaultHeadRig();
    scene::FaceRenderer renderer(rig->head, QSize(o.width, o.height));
    renderer.render();  // the first render compiles the shaders
    std::vector<Case> cases;
    for (const int particles : {100, 2000})
      for (const double rate : {22.0, 60.0, 120.0})
        cases.push_back(runCase(*rig, renderer, rate, particles, o.seconds, o.pacing));
    if (o.json) {
      JsonWriter json(JsonWriter::Layout::Compact);
      json.beginObject();
      json.field("benchmark", "live");
      json.field("width", o.width);
      json.field("height", o.height);
      json.field("seconds", o.seconds);
      json.field("pacing", o.pacing);
      json.key("cases");
      json.beginArray();
      for (const Case& c : cases) {
        json.beginObject();
        json.field("input_fps", c.rate);
        json.field("particles", c.particles);
        json.field("mean_particles_shown", c.meanParticles);
        json.field("frames_sent", c.sent);
        json.field("frames_received", c.received);
        json.field("frames_shown", c.shown);
        json.field("frames_dropped", c.dropped);
        json.field("render_interval_ms", c.intervalMs);
        json.field("render_ms", c.renderMs);
        json.field("latency_median_ms", c.medianMs);
        json.field("latency_p99_ms", c.p99Ms);
        json.field("target_median_ms_at_most", c.renderMs + kTargetSlackMs);
        json.field("pass", c.pass);
        json.endObject();
      }
      json.endArray();
      json.endObject();
      const std::string text = std::move(json).finish();
      std::fwrite(text.data(), 1, text.size(), stdout);
    } else {
      std::printf(
          "live: fap+udp on loopback -> LiveSource -> FaceRenderer %dx%d, %g s per case, %s\n",
          o.width, o.height, o.seconds, o.pacing ? "paced" : "rendering at every tick");
      std::printf("  %6s %9s %9s %8s %8s %8s %9s %9s %9s %9s  %s\n", "fps in", "particles",
                  "(shown)", "sent", "shown", "dropped", "interval", "render", "median", "p99",
                  "target: median <= render + 5 ms");
      for (const Case& c : cases)
        std::printf("  %6.0f %9d %9.0f %8lld %8lld %8lld %7.1fms %7.1fms %7.1fms %7.1fms  %s\n",
                    c.rate, c.particles, c.meanParticles, c.sent, c.shown, c.dropped, c.intervalMs,
                    c.renderMs, c.medianMs, c.p99Ms, c.pass ? "met" : "NOT MET");
    }
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "lacrima-bench live: %s\n", e.what());
    return 1;
  }
}

}  // namespace lacrima::bench
