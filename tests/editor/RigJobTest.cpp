// RigJob: rigging on a worker thread with results on the GUI thread. Driven with small Work
// functions whose timing the test controls (semaphores), and once with a real head to measure
// how long the event loop stalls while a head is rigged in the background.
#include <lacrima/common/Diagnostics.h>
#include <lacrima/editor/RigJob.h>
#include <lacrima/playback/HeadRig.h>
#include <lacrima/rigging/DefaultHead.h>

#include "../rigging/TestHeadFiles.h"

#include <QElapsedTimer>
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
  QStringList failed;
  std::vector<std::pair<double, QString>> progress;
  bool allOnGuiThread = true;

  explicit Emitted(RigJob& job) {
    QObject::connect(&job, &RigJob::finished, [this](std::shared_ptr<playback::HeadRig> rig) {
      noteThread();
      finished.push_back(rig && !rig->warnings.empty() ? rig->warnings.front() : "");
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

  // The GUI thread keeps turning while a real head is rigged: a 1 ms timer measures the
  // longest gap between its ticks. The ICT head (about a second to rig) when ../shared is
  // there, otherwise the default head.
  void theEventLoopTurnsWhileAHeadIsRigged() {
    RigJob::Work work;
    QString which;
    if (QFileInfo::exists(rigtest::kIctMesh)) {
      which = QStringLiteral("ICT-FaceKit");
      work = [](const auto&) {
        return playback::loadHeadRig(rigtest::kIctMesh.toStdString(),
                                     rigtest::kIctFdp.toStdString());
      };
    } else if (rigging::defaultHeadAvailable()) {
      which = QStringLiteral("default");
      work = [](const auto&) { return playback::loadDefaultHeadRig(); };
    } else {
      QSKIP("neither ../shared nor the default head is available");
    }
    RigJob job;
    Emitted emitted(job);
    QTimer tick;
    tick.setInterval(1);
    tick.setTimerType(Qt::PreciseTimer);
    QElapsedTimer sinceTick;
    qint64 longestStall = 0;
    int ticks = 0;
    connect(&tick, &QTimer::timeout, [&] {
      longestStall = std::max(longestStall, sinceTick.restart());
      ++ticks;
    });
    QElapsedTimer rigTime;
    rigTime.start();
    sinceTick.start();
    tick.start();
    job.start(work);
    QTRY_VERIFY_WITH_TIMEOUT(emitted.total() == 1, 30000);
    const qint64 rigMs = rigTime.elapsed();
    tick.stop();
    QVERIFY2(emitted.failed.isEmpty(), qPrintable(emitted.failed.value(0)));
    qInfo(
        "%s head rigged in the background in %lld ms; timer ticks %d, longest event-loop stall "
        "%lld ms",
        qPrintable(which), static_cast<long long>(rigMs), ticks,
        static_cast<long long>(longestStall));
    // Rigging on the GUI thread would stall for the whole rig; allow the scheduling noise of a
    // busy 2-core machine.
    QVERIFY2(longestStall < 150, qPrintable(QStringLiteral("stalled %1 ms").arg(longestStall)));
    // ... and the timer kept firing through the rig (at least once per 20 ms on average).
    QVERIFY2(ticks >= rigMs / 20,
             qPrintable(QStringLiteral("%1 ticks in %2 ms").arg(ticks).arg(rigMs)));
  }
};

QTEST_MAIN(RigJobTest)
#include "RigJobTest.moc"
