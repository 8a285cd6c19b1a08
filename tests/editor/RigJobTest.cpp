// RigJob: rigging on a worker thread with results on the GUI thread. Driven with small Work
// functions whose timing the test controls (semaphores), and once with a real head rigged while
// the event loop turns.
#include <lacrima/common/Diagnostics.h>
#include <lacrima/editor/HeadRigWork.h>
#include <lacrima/editor/RigJob.h>
#include <lacrima/playback/HeadRig.h>
#include <lacrima/rigging/DefaultHead.h>
#include <lacrima/rigging/MeshImport.h>

#include "../rigging/TestHeadFiles.h"

#include <QFileInfo>
#include <QSemaphore>
#include <QTimer>
#include <QtTest>

#include <atomic>
#include <thread>

using namespace lacrima;
using namespace lacrima::editor;

namespace {

// A rig the test can recognise: its only warning names the job that built it.
std::unique_ptr<playback::HeadRig> taggedRig(const std::string& tag) {
  auto rig = std::make_unique<playback::HeadRig>();
  rig->warnings.push_back(tag);
  return rig;
}

// Everything a RigJob emitted, in order.
struct Emitted {
  std::vector<std::string> finished;  // the tags of the rigs
  std::shared_ptr<playback::HeadRig> lastRig;
  QStringList failed;
  std::vector<std::pair<double, QString>> progress;
  bool allOnGuiThread = true;

  explicit Emitted(RigJob& job) {
    QObject::connect(&job, &RigJob::finished, [this](std::shared_ptr<playback::HeadRig> rig) {
      noteThread();
      finished.push_back(rig && !rig->warnings.empty() ? rig->warnings.front() : "");
      lastRig = rig;
    });
    QObject::connect(&job, &RigJob::failed, [this](const QString& message) {
      noteThread();
      failed << message;
    });
    QObject::connect(&job, &RigJob::progress, [this](double fraction, const QString& stage) {
      noteThread();
      progress.emplace_back(fraction, stage);
    });
  }
  void noteThread() {
    if (QThread::currentThread() != QCoreApplication::instance()->thread()) allOnGuiThread = false;
  }
  int total() const { return static_cast<int>(finished.size()) + failed.size(); }
};

}  // namespace

class RigJobTest : public QObject {
  Q_OBJECT

 private slots:
  void resultAndProgressArriveOnTheGuiThread() {
    RigJob job;
    Emitted emitted(job);
    std::atomic<bool> workedOffGuiThread{false};
    job.start([&](const auto& progress) {
      workedOffGuiThread = QThread::currentThread() != QCoreApplication::instance()->thread();
      progress(0.25, "reading");
      progress(0.75, "baking");
      return taggedRig("only");
    });
    QVERIFY(job.running());
    QTRY_COMPARE(emitted.total(), 1);
    QVERIFY(!job.running());
    QVERIFY(workedOffGuiThread);
    QVERIFY(emitted.allOnGuiThread);
    QCOMPARE(emitted.finished, std::vector<std::string>{"only"});
    QCOMPARE(emitted.progress.size(), std::size_t{2});
    QCOMPARE(emitted.progress[0].first, 0.25);
    QCOMPARE(emitted.progress[0].second, QStringLiteral("reading"));
    QCOMPARE(emitted.progress[1].second, QStringLiteral("baking"));
  }

  // The first job is held until the second has delivered; its result must never appear,
  // whether it finishes quietly or reports progress (which stops it early).
  void aSupersededJobNeverEmits() {
    for (const bool reportsProgress : {false, true}) {
      RigJob job;
      Emitted emitted(job);
      QSemaphore release;
      std::atomic<bool> oldJobCarriedOn{false};
      job.start([&](const auto& progress) {
        release.acquire();
        if (reportsProgress) progress(0.5, "old stage");
        oldJobCarriedOn = true;
        return taggedRig("old");
      });
      job.start([](const auto& progress) {
        progress(1.0, "new stage");
        return taggedRig("new");
      });
      QTRY_COMPARE(emitted.total(), 1);
      release.release();
      QTest::qWait(100);  // room for anything the old job might post
      QCOMPARE(emitted.finished, std::vector<std::string>{"new"});
      QVERIFY(emitted.failed.isEmpty());
      for (const auto& [fraction, stage] : emitted.progress)
        QCOMPARE(stage, QStringLiteral("new stage"));
      QCOMPARE(oldJobCarriedOn.load(), !reportsProgress);  // progress() stopped it
      QVERIFY(!job.running());
    }
  }

  // Superseded while the newer job is still running: the older one's failure is dropped too,
  // and running() stays true until the newest job delivers.
  void aSupersededFailureIsDropped() {
    RigJob job;
    Emitted emitted(job);
    QSemaphore releaseNew;
    job.start([](const auto&) -> std::unique_ptr<playback::HeadRig> {
      throw FileError({"old.obj", 1}, "old failure");
    });
    job.start([&](const auto&) {
      releaseNew.acquire();
      return taggedRig("new");
    });
    QTest::qWait(100);
    QCOMPARE(emitted.total(), 0);
    QVERIFY(job.running());
    releaseNew.release();
    QTRY_COMPARE(emitted.total(), 1);
    QCOMPARE(emitted.finished, std::vector<std::string>{"new"});
  }

  void exceptionsBecomeFailed() {
    RigJob job;
    Emitted emitted(job);
    job.start([](const auto&) -> std::unique_ptr<playback::HeadRig> {
      throw FileError({"heads/face.fdp.json", 12}, "expected a number");
    });
    QTRY_COMPARE(emitted.total(), 1);
    QCOMPARE(emitted.failed,
             QStringList{QStringLiteral("heads/face.fdp.json:12: expected a number")});
    // Anything thrown, and a Work function that returns nothing, fail with a message too.
    job.start([](const auto&) -> std::unique_ptr<playback::HeadRig> { throw 42; });
    QTRY_COMPARE(emitted.total(), 2);
    job.start([](const auto&) { return std::unique_ptr<playback::HeadRig>(); });
    QTRY_COMPARE(emitted.total(), 3);
    QCOMPARE(emitted.failed.size(), 3);
    for (const QString& message : emitted.failed) QVERIFY(!message.isEmpty());
    QVERIFY(emitted.finished.empty());
  }

  void theDestructorWaitsAndDropsTheResult() {
    std::atomic<bool> done{false};
    int emittedCount = 0;
    {
      RigJob job;
      connect(&job, &RigJob::finished, [&] { ++emittedCount; });
      connect(&job, &RigJob::failed, [&] { ++emittedCount; });
      job.start([&](const auto&) {
        std::this_thread::sleep_for(std::chrono::milliseconds(150));
        done = true;
        return taggedRig("late");
      });
    }
    QVERIFY(done);  // the destructor did not return before the work did
    QTest::qWait(50);
    QCOMPARE(emittedCount, 0);
  }

  // A real head rigged in the background: the GUI thread's event loop turns while the job runs
  // (the work starts rigging only once a GUI-thread timer has fired three times, which cannot
  // happen if start() blocks the GUI thread), the stages arrive on the GUI thread with their
  // fractions rising from 0 to 1, and the rig is the head's. The ICT head (about a second to
  // rig, several stages) when ../shared is there, otherwise the default head. How long the loop
  // stalls is a figure of `lacrima-bench worst-cases`, not a check: it depends on the load.
  void aRealHeadRigsWhileTheEventLoopTurns() {
    RigJob::Work work;
    int vertices = 0;
    if (QFileInfo::exists(rigtest::kIctMesh)) {
      work = headFilesWork(rigtest::kIctMesh.toStdString(), rigtest::kIctFdp.toStdString());
      vertices = rigging::importHeadMesh(rigtest::kIctMesh.toStdString()).vertexCount();
    } else if (rigging::defaultHeadAvailable()) {
      work = defaultHeadWork();
      vertices = rigging::loadDefaultHead().vertexCount();
    } else {
      LACRIMA_SKIP_WITHOUT_DEFAULT_HEAD();
    }
    RigJob job;
    Emitted emitted(job);
    QSemaphore ticked;
    int ticks = 0;
    QTimer tick;
    tick.setInterval(1);
    connect(&tick, &QTimer::timeout, [&] {
      if (++ticks == 3) ticked.release();
    });
    tick.start();
    job.start([&](const auto& progress) {
      if (!ticked.tryAcquire(1, 30000))
        throw FileError({"RigJobTest", 0}, "the GUI thread's timer never fired during the job");
      return work(progress);
    });
    QTRY_VERIFY_WITH_TIMEOUT(emitted.total() == 1, 60000);
    tick.stop();
    QVERIFY2(emitted.failed.isEmpty(), qPrintable(emitted.failed.value(0)));
    QCOMPARE(emitted.finished.size(), std::size_t{1});
    QVERIFY(emitted.allOnGuiThread);
    QVERIFY(!emitted.progress.empty());
    double last = 0;
    for (const auto& [fraction, stage] : emitted.progress) {
      QVERIFY2(fraction >= last && fraction <= 1, qPrintable(stage));
      QVERIFY(!stage.isEmpty());
      last = fraction;
    }
    QCOMPARE(emitted.lastRig->head.vertexCount(), vertices);
  }
};

QTEST_MAIN(RigJobTest)
#include "RigJobTest.moc"
