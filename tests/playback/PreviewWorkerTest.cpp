// PreviewWorker on the real default head, offscreen (no OGRE, no display): its frames are the
// synchronous producer's bit for bit, stale requests are dropped rather than queued, tears set
// to 0 vanish at once even while a step runs, and destroying it mid-step is clean. A step is
// held "running" with the test hook (setBeforeStep), so nothing here depends on timing.
// Skipped when the default head has not been fetched.
#include "PlaybackTestSupport.h"

#include <lacrima/playback/PreviewWorker.h>
#include <lacrima/rigging/DefaultHead.h>

#include <QtTest>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <mutex>

using namespace lacrima;
using namespace lacrima::playback;
using namespace lacrima::playback::test;

namespace {

// Holds the worker's next step at its start until released: the test knows a step is running.
class StepGate {
 public:
  std::function<void()> hook() {
    return [this] {
      std::unique_lock lock(mutex_);
      ++entered_;
      changed_.notify_all();
      changed_.wait(lock, [this] { return released_ >= entered_; });
    };
  }
  // Waits until `n` steps have started (and are held).
  bool waitEntered(int n) {
    std::unique_lock lock(mutex_);
    return changed_.wait_for(lock, std::chrono::seconds(60), [&] { return entered_ >= n; });
  }
  void releaseAll() {
    const std::lock_guard lock(mutex_);
    released_ = 1 << 30;
    changed_.notify_all();
  }

 private:
  std::mutex mutex_;
  std::condition_variable changed_;
  int entered_ = 0, released_ = 0;
};

FapValues crying(int frame, int perEye) {
  FapValues v{};
  channel(v, "open_jaw") = static_cast<float>(std::round(300.0 * std::sin(frame * 0.15)));
  channel(v, "tears_l_eye") = static_cast<float>(perEye);
  channel(v, "tears_r_eye") = static_cast<float>(perEye);
  return v;
}

PreviewRequest requestAt(int frame, int perEye) {
  return {crying(frame, perEye), 1.0 / kFps, frame / 100.0};
}

bool sameSurface(const tears::TearSurface& a, const tears::TearSurface& b) {
  return a.vertexCount() == b.vertexCount() && a.triangleCount() == b.triangleCount() &&
         a.positions() == b.positions() && a.triangles() == b.triangles();
}

}  // namespace

class PreviewWorkerTest : public QObject {
  Q_OBJECT

  std::shared_ptr<const HeadRig> rig_;

  static SceneSettings withSpheres() {
    SceneSettings scene;
    scene.particles = true;  // frames then carry the particles themselves
    return scene;
  }

 private slots:
  void initTestCase() { LOAD_DEFAULT_HEAD_RIG(rig_); }

  // Answering every request in turn (waiting between them) is the producer called directly:
  // particles, surface and overlays bit for bit, frame after frame.
  void framesMatchTheSynchronousProducer() {
    PreviewWorker worker(rig_, withSpheres(), {});
    FrameProducer direct(*rig_, withSpheres());
    for (int f = 0; f < 16; ++f) {
      worker.request(requestAt(f, 30));
      worker.waitIdle();
      const FrameView& expected = direct.produce(crying(f, 30), 1.0 / kFps, f / 100.0);
      const auto frame = worker.currentFrame();
      QVERIFY(frame);
      QCOMPARE(frame->request, static_cast<long long>(f + 1));
      QCOMPARE(frame->particleCount, direct.particleCount());
      QVERIFY(expected.particles && frame->particles);
      QVERIFY2(sameParticles(*frame->particles, *expected.particles),
               qPrintable(QString::number(f)));
      QCOMPARE(frame->surface.has_value(), expected.surface != nullptr);
      if (expected.surface) QVERIFY(sameSurface(*frame->surface, *expected.surface));
      QVERIFY(frame->overlays == expected.overlays);
    }
    QCOMPARE(direct.particleCount(), 60);
    const PreviewWorkerCounters c = worker.counters();
    QCOMPARE(c.steps, 16LL);
    QCOMPARE(c.dropped, 0LL);
    QCOMPARE(c.discarded, 0LL);
  }

  // Ten requests while one step runs: one of them (the newest) runs next, nine are dropped.
  void dropsStaleRequests() {
    PreviewWorker worker(rig_, {}, {});
    StepGate gate;
    worker.setBeforeStep(gate.hook());
    std::atomic<int> ready{0};
    worker.setFrameReady([&] { ++ready; });
    worker.request(requestAt(0, 20));
    QVERIFY(gate.waitEntered(1));
    for (int f = 1; f <= 10; ++f) worker.request(requestAt(f, 20));
    QVERIFY(worker.busy());
    gate.releaseAll();
    worker.waitIdle();
    const PreviewWorkerCounters c = worker.counters();
    QCOMPARE(c.requests, 11LL);
    QCOMPARE(c.steps, 2LL);
    QCOMPARE(c.dropped, 9LL);
    const auto frame = worker.currentFrame();
    QVERIFY(frame);
    QCOMPARE(frame->request, 11LL);  // the newest request, not a queued older one
    QCOMPARE(frame->particleCount, 40);
    QCOMPARE(ready.load(), 2);
  }

  // Tears to 0 while a step runs: no tears from that moment (the running step's result is
  // thrown away), and nothing is simulated for the request without tears.
  void tearsToZeroClearAtOnce() {
    PreviewWorker worker(rig_, {}, {});
    StepGate gate;
    worker.request(requestAt(0, 30));
    worker.waitIdle();
    QVERIFY(worker.currentFrame());
    QCOMPARE(worker.currentFrame()->particleCount, 60);

    worker.setBeforeStep(gate.hook());
    worker.request(requestAt(1, 30));
    QVERIFY(gate.waitEntered(1));
    worker.request(requestAt(2, 0));  // the animator sets the tears to 0
    QVERIFY(!worker.currentFrame());  // at once, while the step is still held
    gate.releaseAll();
    worker.waitIdle();
    QVERIFY(!worker.currentFrame());  // the held step finished and was discarded
    PreviewWorkerCounters c = worker.counters();
    QCOMPARE(c.steps, 2LL);
    QCOMPARE(c.discarded, 1LL);
    QCOMPARE(c.clears, 1LL);

    // More requests without tears simulate nothing.
    for (int f = 3; f < 8; ++f) worker.request(requestAt(f, 0));
    worker.waitIdle();
    c = worker.counters();
    QCOMPARE(c.steps, 2LL);
    QCOMPARE(c.clears, 1LL);

    // Tears again start from nothing: the same as a fresh producer's first frame.
    worker.setBeforeStep({});
    worker.request(requestAt(8, 10));
    worker.waitIdle();
    FrameProducer fresh(*rig_);
    fresh.produce(crying(8, 10), 1.0 / kFps, 0.08);
    QVERIFY(worker.currentFrame());
    QCOMPARE(worker.currentFrame()->particleCount, fresh.particleCount());
    QCOMPARE(worker.currentFrame()->particleCount, 20);
  }

  // clearTears() (the editor's Clear tears, a document reset) and a change of the simulation
  // parameters both end the current tears at once.
  void clearAndParameterChangeEndTheTears() {
    SceneSettings scene;
    PreviewWorker worker(rig_, scene, {});
    worker.request(requestAt(0, 25));
    worker.waitIdle();
    QVERIFY(worker.currentFrame());
    worker.clearTears();
    QVERIFY(!worker.currentFrame());
    worker.waitIdle();
    QVERIFY(!worker.currentFrame());

    worker.request(requestAt(1, 25));
    worker.waitIdle();
    QVERIFY(worker.currentFrame());
    scene.simulation["viscosity"] = 2.0;
    worker.setScene(scene);
    QVERIFY(!worker.currentFrame());
    worker.waitIdle();
    // Effects alone keep the tears and show them anew.
    worker.request(requestAt(2, 25));
    worker.waitIdle();
    QVERIFY(worker.currentFrame());
    QVERIFY(!worker.currentFrame()->particles);
    scene.particles = true;
    worker.setScene(scene);
    worker.waitIdle();
    QVERIFY(worker.currentFrame());
    QVERIFY(worker.currentFrame()->particles);
    QCOMPARE(worker.currentFrame()->particles->size(), 50);
  }

  // Destroying the worker while a step runs waits for that step, runs no other and calls no
  // callback afterwards.
  void destructionWhileSteppingIsClean() {
    std::atomic<int> ready{0};
    StepGate gate;
    std::thread releaser;
    {
      PreviewWorker worker(rig_, {}, {});
      worker.setBeforeStep(gate.hook());
      worker.setFrameReady([&] { ++ready; });
      worker.request(requestAt(0, 20));
      QVERIFY(gate.waitEntered(1));
      worker.request(requestAt(1, 20));  // pending: must never run
      releaser = std::thread([&] {
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
        gate.releaseAll();
      });
    }  // the destructor waits here for the held step
    releaser.join();
    QCOMPARE(ready.load(), 0);
    // stop() (a head change retires the worker): the held step ends, nothing else runs, the
    // thread ends by itself and the destructor then has nothing to wait for.
    {
      StepGate held;
      PreviewWorker worker(rig_, {}, {});
      worker.setBeforeStep(held.hook());
      worker.setFrameReady([&] { ++ready; });
      worker.request(requestAt(0, 20));
      QVERIFY(held.waitEntered(1));
      worker.request(requestAt(1, 20));
      worker.stop();
      QVERIFY(!worker.stopped());  // still in the held step
      held.releaseAll();
      QTRY_VERIFY(worker.stopped());
      QCOMPARE(worker.counters().steps, 1LL);
    }
    QCOMPARE(ready.load(), 0);
    // And with a real step in flight, no hook: destruction right after the request.
    for (int i = 0; i < 3; ++i) {
      PreviewWorker worker(rig_, {}, {});
      worker.setFrameReady([&] { ++ready; });
      worker.request(requestAt(0, 200));
    }
  }

  void noRigIsAnError() {
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, PreviewWorker(nullptr, {}, {}));
  }
};

QTEST_MAIN(PreviewWorkerTest)
#include "PreviewWorkerTest.moc"
