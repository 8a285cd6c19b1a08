// LiveSource: a stream on the default head. The newest frame wins (the others are counted as
// dropped), the face follows it at once, the tears step on a worker at the display's pace
// between frames and after the stream stops, a new frame is shown while a tear step is still
// running, the tears are the same as on the caller's thread for any thread count, and streams
// without tear channels weep what the player sets. Moods drive the face through the crying
// generator, easing in, with no tears simulated before its onset.
#include "PlaybackTestSupport.h"

#include <lacrima/common/mood/MoodGenerator.h>

#include <lacrima/playback/LivePacer.h>
#include <lacrima/playback/LiveSource.h>

#include <chrono>
#include <cmath>
#include <condition_variable>
#include <mutex>
#include <thread>

using namespace lacrima;
using namespace lacrima::playback;
using namespace lacrima::playback::test;

namespace {

ChannelMask maskOf(std::initializer_list<const char*> names) {
  ChannelMask mask;
  for (const char* name : names) mask.set(static_cast<std::size_t>(channelIndex(*fapByName(name))));
  return mask;
}

double largestMove(const FrameView& view, const HeadMesh& neutral) {
  return double(((*view.positions) - neutral.positions).colwise().norm().maxCoeff());
}

// The stream of the determinism test: the jaw moves, 60 tears an eye (from the frames).
FapValues streamFrame(int i) {
  FapValues v{};
  channel(v, "open_jaw") = static_cast<float>(20 * (i % 15));
  channel(v, "tears_l_eye") = 60;
  channel(v, "tears_r_eye") = 60;
  return v;
}

SceneSettings withSpheres() {
  SceneSettings scene;
  scene.redness = SceneSettings::Redness::Tears;
  scene.particles = true;  // the tear frames then carry the particles themselves
  return scene;
}

constexpr int kSteps = 40;
constexpr double kTick = 1.0 / 64;  // exact in binary: every dt is the same double

// A gate a test holds a tear step at: the worker waits in it until the test opens it.
struct Gate {
  std::mutex mutex;
  std::condition_variable changed;
  bool held = false, open = false, onCaller = false;
  std::thread::id caller = std::this_thread::get_id();

  void enter() {
    std::unique_lock lock(mutex);
    if (std::this_thread::get_id() == caller) {
      onCaller = true;  // a step on the display's thread: nothing to hold, the test fails
      return;
    }
    held = true;
    changed.notify_all();
    // Bounded, so that a display that waits for the step fails the test instead of hanging.
    changed.wait_for(lock, std::chrono::seconds(30), [this] { return open; });
  }
  bool waitHeld() {
    std::unique_lock lock(mutex);
    return changed.wait_for(lock, std::chrono::seconds(30), [this] { return held; });
  }
  void release() {
    const std::lock_guard lock(mutex);
    open = true;
    changed.notify_all();
  }
};

}  // namespace

class LiveSourceTest : public QObject {
  Q_OBJECT
  std::unique_ptr<HeadRig> rig_;

 private slots:
  void initTestCase() { LOAD_DEFAULT_HEAD_RIG(rig_); }

  void newestFrameWinsAndTheHeadTurns() {
    LiveSource live(*rig_);
    QVERIFY(!live.seekable());
    QCOMPARE(live.duration(), 0.0);
    FapValues a{}, b{};
    channel(a, "open_jaw") = 200;
    channel(b, "head_yaw") = 20000;
    live.push(a, maskOf({"open_jaw"}), 1.0);
    live.push(b, maskOf({"head_yaw"}), 1.01);  // before any display: a is dropped
    const FrameView& view = live.seek(0.0);
    QCOMPARE(live.framesReceived(), 2LL);
    QCOMPARE(live.framesDropped(), 1LL);
    QCOMPARE(live.shownArrival(), 1.01);
    QCOMPARE(live.shownValues()[channelIndex(49)], 20000.0F);
    QCOMPARE(live.shownValues()[channelIndex(3)], 0.0F);
    QVERIFY(largestMove(view, rig_->head) > 1e-3);  // the head turned
    const auto revision = view.revision;
    live.seek(0.001);  // nothing new, no tears: the same picture
    QCOMPARE(live.view().revision, revision);
    QCOMPARE(live.shownArrival(), -1.0);
    live.seek(1.0);  // no tears ever: nothing is simulated
    QCOMPARE(live.tearStepsRequested(), 0LL);
  }

  // A stream without tear channels weeps what the player sets; the tears go on between frames
  // and after the stream stops, stepped by the display clock (capped per step).
  void tearsRunAtTheDisplaysPace() {
    LiveSource live(*rig_);
    live.setTears(40, 30);
    FapValues v{};
    channel(v, "open_jaw") = 100;
    live.push(v, maskOf({"open_jaw"}), 0);
    double t = 0;
    live.seek(t);
    for (int i = 0; i < 30; ++i) {
      live.seek(t += 1.0 / 60);
      live.waitForTears();
    }
    live.seek(t += 1.0 / 60);  // shows the last step
    QCOMPARE(live.shownValues()[channelIndex(kTearLeftFap)], 40.0F);
    QVERIFY2(live.particleCount() > 0, "no tears from the player's own counts");
    QVERIFY(live.hasTears());
    live.waitForTears();
    const long long steps = live.tearStepsRequested();
    live.seek(t += 5.0);  // a stalled display: one capped step, not five seconds at once
    live.waitForTears();
    QCOMPARE(live.tearStepsRequested(), steps + 1);
    QCOMPARE(live.tearStepsDone(), steps + 1);

    // A frame that carries tear channels wins over the player's counts.
    FapValues dry{};
    live.push(dry, maskOf({"open_jaw", "tears_l_eye", "tears_r_eye"}), 1);
    live.seek(t += 1.0 / 60);
    QCOMPARE(live.shownValues()[channelIndex(kTearLeftFap)], 0.0F);
    // As in a file, channels at 0 are stepped (the particles beyond the count leave, the wet
    // trails dry on); the editor's preview clears everything at once instead.
    live.waitForTears();
    live.seek(t += 1.0 / 60);
    QVERIFY2(live.tearFrame(), "the tears were cleared instead of stepped");
    QCOMPARE(live.tearFrame()->request, steps + 2);  // the step of the frame at 0

    live.reset();
    QCOMPARE(live.particleCount(), 0);
    QVERIFY(!live.tearFrame());
  }

  // The face of a new frame is shown while a tear step is in flight: the display never waits
  // for the tears. A gate holds the step on the worker (no timing involved); a step run on the
  // display's thread would pass the gate at once and fail the test.
  void aNewFrameIsShownWhileATearStepRuns() {
    Gate gate;
    LiveSource live(*rig_);
    // Opened whatever happens, before the source (which waits for its step) goes.
    const std::unique_ptr<Gate, void (*)(Gate*)> opener(&gate, [](Gate* g) { g->release(); });
    live.setBeforeTearStep([&gate] { gate.enter(); });
    live.setTears(40, 40);
    FapValues a{};
    channel(a, "open_jaw") = 100;
    live.push(a, maskOf({"open_jaw"}), 0);
    live.seek(0);
    live.seek(1.0 / 60);  // asks for a step: the gate holds it
    QVERIFY2(!gate.onCaller, "the tear step ran on the display's thread");
    QVERIFY2(gate.waitHeld(), "no tear step reached the worker");

    FapValues b{};
    channel(b, "head_yaw") = 20000;
    live.push(b, maskOf({"head_yaw"}), 1.0);
    const FrameView& view = live.seek(2.0 / 60);
    QCOMPARE(live.shownArrival(), 1.0);
    QCOMPARE(live.shownValues()[channelIndex(49)], 20000.0F);
    QVERIFY(largestMove(view, rig_->head) > 1e-3);  // the head turned, the step still held
    QCOMPARE(live.tearStepsDone(), 0LL);
    QCOMPARE(live.tearStepsRequested(), 1LL);  // the next step waits for this one
    QVERIFY(!live.tearFrame());

    gate.release();
    live.waitForTears();
    live.seek(3.0 / 60);  // shows the first step, asks for the second
    QVERIFY(live.tearFrame());
    QCOMPARE(live.tearFrame()->request, 1LL);
    QCOMPARE(live.tearStepsRequested(), 2LL);
  }

  // Every step asked for runs, in order, with the values and dt of its seek: the tears are bit
  // for bit those of a FrameProducer called on this thread, for 1 and 2 simulation threads.
  void tearsAreTheSameAsOnTheCallersThreadForAnyThreadCount() {
    FrameProducer reference(*rig_, withSpheres());
    reference.setSimulationThreads(1);
    for (int i = 1; i < kSteps; ++i) reference.produce(streamFrame(i), kTick, 0);
    const tears::ParticleSet* expected = reference.view().particles;
    QVERIFY(expected && expected->size() > 0);

    for (const int threads : {1, 2}) {
      LiveSource live(*rig_);
      live.setScene(withSpheres());
      live.setSimulationThreads(threads);
      for (int i = 0; i < kSteps; ++i) {
        live.push(streamFrame(i), maskOf({"open_jaw", "tears_l_eye", "tears_r_eye"}), 0);
        live.seek(i * kTick);
        live.waitForTears();
      }
      live.seek((kSteps - 1) * kTick + 1.0 / 512);  // shows the last step, too soon for another
      QCOMPARE(live.tearStepsDone(), static_cast<long long>(kSteps - 1));
      const auto frame = live.tearFrame();
      QVERIFY(frame && frame->particles);
      const tears::ParticleSet& got = *frame->particles;
      QCOMPARE(got.size(), expected->size());
      for (int p = 0; p < got.size(); ++p)
        QVERIFY2(got.position[static_cast<std::size_t>(p)] ==
                     expected->position[static_cast<std::size_t>(p)],
                 qPrintable(QStringLiteral("threads %1, particle %2").arg(threads).arg(p)));
    }
  }

  // The crying generator on the display's clock: a change of moods eases in (no jump), no tear
  // is simulated while it makes no tear channel, its tears come after the onset, its colours
  // replace the computed ones, and a frame takes the face back until the next moods.
  void moodsDriveTheFaceLive() {
    LiveSource live(*rig_);
    QVERIFY(!live.moodDriven());
    live.setMoods(MoodLevels{});
    QVERIFY(live.moodDriven());
    const auto brow = static_cast<std::size_t>(channelIndex(31));  // raise_l_i_eyebrow
    const auto tear = static_cast<std::size_t>(channelIndex(kTearLeftFap));
    double t = 0;
    const double step = 1.0 / 30;
    for (; t < 1.0; t += step) live.seek(t);
    const float neutral = live.shownValues()[brow];
    live.setMoods(MoodLevels{{0.8, 0, 0, 0}});
    QCOMPARE(live.moods()[Mood::Sadness], 0.8);
    live.seek(t += step);
    const float first = live.shownValues()[brow];
    double later = 0;
    int n = 0;
    for (; t < 2.5; t += step, ++n) {
      live.seek(t);
      later += live.shownValues()[brow];
      QCOMPARE(live.shownValues()[tear], 0.0F);  // before the onset: no tear channel
    }
    later /= n;
    QVERIFY2(later > neutral + 40, qPrintable(QString("brow %1 -> %2").arg(neutral).arg(later)));
    QVERIFY2(std::abs(first - neutral) < 0.2 * (later - neutral),
             qPrintable(QString("jumped %1 of %2").arg(first - neutral).arg(later - neutral)));
    QCOMPARE(live.tearStepsRequested(), 0LL);  // nothing asked for tears
    QVERIFY(!live.hasTears());
    for (; t < 6 && live.shownValues()[tear] < 1; t += step) live.seek(t);
    QVERIFY2(live.shownValues()[tear] >= 1, "the generator's tears never came");
    for (int i = 0; i < 5; ++i) {
      live.seek(t += step);
      live.waitForTears();  // every seek steps (the worker would otherwise be a step behind)
    }
    live.seek(t += step);
    QVERIFY(live.particleCount() > 0);
    QVERIFY(live.hasTears());
    QVERIFY(live.view().overlays.redness > 0);  // the generator's redness, after the tears

    // A frame takes the face back; the next moods take it again.
    FapValues jaw{};
    channel(jaw, "open_jaw") = 300;
    live.push(jaw, maskOf({"open_jaw"}), t);
    live.seek(t += step);
    QVERIFY(!live.moodDriven());
    QCOMPARE(live.shownValues()[channelIndex(3)], 300.0F);
    live.setMoods(MoodLevels{{0.8, 0, 0, 0}});
    live.seek(t += step);
    QVERIFY(live.moodDriven());
    QVERIFY(live.shownValues()[channelIndex(3)] != 300.0F);
  }

  // The same seed gives the same take at the same display times; another seed another one.
  // The pacer (LivePacer.h) at 22 fps with 28 ms renders: a tears-only render starts only if it
  // ends before the next frame is due; a frame is shown at once; a late stream is not waited for.
  void pacingKeepsTheDisplayFreeForTheNextFrame() {
    LivePacer pacer;
    QVERIFY(pacer.decide(0, false).render);  // no stream yet
    const double gap = 1.0 / 22;
    for (int k = 0; k < 4; ++k) pacer.frameArrived(10 + k * gap);
    QVERIFY(pacer.decide(10.2, true).render);  // no render measured yet: nothing to pace by
    pacer.rendered(0.028);
    QCOMPARE(*pacer.streamInterval(), gap);
    const double last = 10 + 3 * gap, due = last + gap;
    QVERIFY(pacer.decide(last, true).render);           // a new frame: at once
    QVERIFY(pacer.decide(last + 0.010, false).render);  // ends at +39 ms, before +45
    const LivePacer::Decision wait = pacer.decide(last + 0.020, false);  // would end at +49
    QVERIFY(!wait.render);
    QCOMPARE(wait.wakeAt, due + LivePacer::tolerance(gap));
    QVERIFY(pacer.decide(wait.wakeAt + 0.001, false).render);  // late: the stream may be over

    // A pause starts the stream's line again.
    pacer.frameArrived(last + 10);
    QVERIFY(!pacer.streamInterval());
    QVERIFY(pacer.decide(last + 10.01, false).render);
  }

  // Frames that come during a render are read together after it: the pacer still finds the
  // stream's rate and when its newest frame came, from the least delayed reads.
  void pacingSeesThroughLateReads() {
    LivePacer pacer;
    const double gap = 1.0 / 60, render = 0.029;
    double sent = 0;
    for (int k = 0; k < 40; ++k) {
      sent = 5 + k * gap;
      const double read = 5 + std::ceil((sent - 5) / render) * render;  // at a render's end
      pacer.frameArrived(read);
    }
    QVERIFY(pacer.streamInterval());
    QVERIFY(std::abs(*pacer.streamInterval() - gap) < 0.05 * gap);
    QVERIFY(std::abs(pacer.newestArrival() - sent) < 0.002);
  }

  // At 60 fps with 29 ms renders a frame comes during every render: the one waiting is shown at
  // once when it is fresh, and replaced by the next when that is due sooner than it came.
  void pacingShowsTheFreshestFrame() {
    LivePacer pacer;
    const double gap = 1.0 / 60;
    for (int k = 0; k < 5; ++k) pacer.frameArrived(k * gap);
    pacer.rendered(0.029);
    const double last = 4 * gap, due = last + gap;
    QVERIFY(pacer.decide(last + 0.005, true).render);  // 5 ms old, the next in 11.7 ms
    const LivePacer::Decision wait = pacer.decide(last + 0.010, true);  // 10 ms old, next in 6.7
    QVERIFY(!wait.render);
    QVERIFY(wait.wakeAt > due);
    pacer.frameArrived(due);
    QVERIFY(pacer.decide(due + 0.0005, true).render);
    pacer.reset();
    QVERIFY(!pacer.streamInterval());
    QCOMPARE(pacer.renderSeconds(), 0.0);

    // The source says when a pushed frame has not been shown.
    LiveSource live(*rig_);
    QVERIFY(!live.frameWaiting());
    live.push(FapValues{}, ChannelMask{}, 1);
    QVERIFY(live.frameWaiting());
    live.seek(1);
    QVERIFY(!live.frameWaiting());
  }

  void moodSeedChoosesTheTake() {
    const auto take = [this](std::uint64_t seed) -> std::vector<FapValues> {
      LiveSource live(*rig_);
      live.setMoodSeed(seed);
      live.setMoods(MoodLevels{{0, 0.5, 0, 0.6}});
      std::vector<FapValues> frames;
      for (double t = 0; t < 2; t += 1.0 / 30) {
        live.seek(t);
        frames.push_back(live.shownValues());
      }
      if (live.moodSeed() != seed) return {};
      return frames;
    };
    QVERIFY(!take(7).empty());
    QVERIFY(take(7) == take(7));
    QVERIFY(take(7) != take(8));
  }
};

QTEST_GUILESS_MAIN(LiveSourceTest)
#include "LiveSourceTest.moc"
