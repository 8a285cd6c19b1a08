// lacrima-batch as a lab runs it, on a machine without a display: a four-job dataset in one go
// and as two shards (the same bytes and summary), killed mid-way and rerun (finished jobs kept,
// the result identical), failing jobs recorded while the batch goes on, a bad option stopping it.
#include "BatchTestSupport.h"

#include <QImage>
#include <QTemporaryDir>
#include <QtTest>

using namespace lacrima::batch::test;

namespace {

// Pixels of value `v` in a grey mask.
int count(const QString& png, int v) {
  const QImage mask = QImage(png).convertToFormat(QImage::Format_Grayscale8);
  int n = 0;
  for (int y = 0; y < mask.height(); ++y)
    for (int x = 0; x < mask.width(); ++x) n += mask.constScanLine(y)[x] == v ? 1 : 0;
  return n;
}

QStringList summaryRows(const QString& out) {
  QFile f(QDir(out).filePath("summary.csv"));
  if (!f.open(QIODevice::ReadOnly)) return {};
  return QString::fromUtf8(f.readAll()).split('\n', Qt::SkipEmptyParts).mid(1);
}

}  // namespace

class BatchCliTest : public QObject {
  Q_OBJECT

  QTemporaryDir dir_;
  QString manifest_, oneGo_;

 private slots:
  void initTestCase() {
    QVERIFY(dir_.isValid());
    manifest_ = dir_.filePath("dataset.json");
    QVERIFY(writeFile(manifest_, fourJobManifest()));
  }

  void oneGoAndShardsGiveTheSameBytes() {
    oneGo_ = dir_.filePath("one-go");
    const auto all = runBatch({manifest_, "--out", oneGo_, "--jobs", "2"});
    QVERIFY2(all.exitCode == 0, all.err.toLocal8Bit().constData());
    const QStringList rows = summaryRows(oneGo_);
    QCOMPARE(rows.size(), 4);
    for (const QString& row : rows) {
      QVERIFY2(row.contains(",done,"), qPrintable(row));
      const QStringList f = row.split(',');
      // frames_with_tears: every frame with tears, none without; the masks say the same.
      const bool tears = row.contains(",yes,");
      QCOMPARE(f.at(f.size() - 5), tears ? QString("12") : QString("0"));
      const QString mask = QDir(oneGo_).filePath(f.at(0) + "/frames/mask_0141.png");
      if (tears)
        QVERIFY2(count(mask, 255) > 0, qPrintable(mask));
      else
        QCOMPARE(count(mask, 255) + count(mask, 128), 0);
    }

    const QString sharded = dir_.filePath("sharded");
    const auto first = runBatch({manifest_, "--out", sharded, "--shard", "1/2", "--threads", "1"});
    QVERIFY2(first.exitCode == 0, first.err.toLocal8Bit().constData());
    QCOMPARE(summaryRows(sharded).filter(",pending,").size(), 2);
    const auto second = runBatch({manifest_, "--out", sharded, "--shard", "2/2", "--threads", "2"});
    QVERIFY2(second.exitCode == 0, second.err.toLocal8Bit().constData());
    QCOMPARE(firstDifference(oneGo_, sharded), QString());
    QCOMPARE(summaryRows(sharded), rows);

    // Everything is done: a rerun runs nothing.
    const auto again = runBatch({manifest_, "--out", sharded});
    QVERIFY2(again.err.contains("4 already done, 0 done now"), again.err.toLocal8Bit().constData());
  }

  void aKilledBatchResumesToTheSameResult() {
    QVERIFY(!oneGo_.isEmpty());
    const QString out = dir_.filePath("killed");
    QProcess batch;
    batch.setProcessEnvironment(withoutDisplay());
    batch.start(kBatch, {manifest_, "--out", out});
    QVERIFY(batch.waitForStarted());
    // Killed while its second job runs: one job done, one in its scratch folder.
    QTRY_VERIFY_WITH_TIMEOUT(QDir(out).entryList(QDir::Dirs | QDir::NoDotAndDotDot).size() >= 2 &&
                                 !QDir(out + "/.partial").isEmpty(),
                             120000);
    batch.kill();  // SIGKILL: no chance to tidy up
    batch.waitForFinished();
    const auto rerun = runBatch({manifest_, "--out", out});
    QVERIFY2(rerun.exitCode == 0, rerun.err.toLocal8Bit().constData());
    QVERIFY2(rerun.err.contains("1 already done, 3 done now") ||
                 rerun.err.contains("2 already done, 2 done now"),
             rerun.err.toLocal8Bit().constData());
    QVERIFY(QDir(out + "/.partial").isEmpty());
    QCOMPARE(firstDifference(oneGo_, out), QString());
    QCOMPARE(summaryRows(out), summaryRows(oneGo_));
  }

  // A damaged animation fails its job alone; the summary and the exit status say so.
  void aFailingJobIsRecordedAndTheBatchGoesOn() {
    QVERIFY(writeFile(dir_.filePath("broken.fap"), "2.1 broken 22 2\n1 1\nnot a number\n"));
    QVERIFY(writeFile(dir_.filePath("mixed.json"), R"({
      "defaults": { "size": "160x90", "frames": "0-1", "outputs": ["gltf"] },
      "jobs": [ { "animation": "broken.fap" }, { "mood": "joy=1", "seconds": 1 } ] })"));
    const QString out = dir_.filePath("mixed");
    const auto run = runBatch({dir_.filePath("mixed.json"), "--out", out});
    QCOMPARE(run.exitCode, 1);
    QVERIFY2(run.err.contains("failed: ") && run.err.contains("broken.fap"),
             run.err.toLocal8Bit().constData());
    const QStringList rows = summaryRows(out);
    QCOMPARE(rows.size(), 2);
    QCOMPARE(rows.filter(",done,").size(), 1);
    const QStringList failed = rows.filter(",failed,");
    QCOMPARE(failed.size(), 1);
    QVERIFY2(failed.front().contains("broken.fap:2:5: expected a mask line"),
             qPrintable(failed.front()));
  }

  // An option every job shares and the player refuses: the batch stops at once.
  void aRefusedOptionStopsTheBatch() {
    QVERIFY(writeFile(dir_.filePath("sideways.json"), R"({
      "grid": { "mood": ["joy=1", "anger=1", "sadness=1"] },
      "defaults": { "seconds": 1, "size": "160x90", "view": "sideways" } })"));
    const auto run = runBatch({dir_.filePath("sideways.json"), "--out", dir_.filePath("sideways")});
    QCOMPARE(run.exitCode, 2);
    QVERIFY2(run.err.contains("--view") && run.err.contains("fix the manifest"),
             run.err.toLocal8Bit().constData());
    QVERIFY2(run.err.contains("1 done now") == false, run.err.toLocal8Bit().constData());
  }
};

QTEST_GUILESS_MAIN(BatchCliTest)
#include "BatchCliTest.moc"
