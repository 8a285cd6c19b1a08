// lacrima-batch on a real Slurm: a one-node cluster of this machine (Debian's slurm-wlm and
// munge, started by one-node-slurm.sh), the job array submitted with --slurm --submit --wait,
// its results compared byte for byte with the same manifest run locally. Skips where Slurm
// cannot run (not installed, not root); under CI=true that is a failure.
#include "BatchTestSupport.h"

#include <QStandardPaths>
#include <QTemporaryDir>
#include <QtTest>

#include <unistd.h>

using namespace lacrima::batch::test;

namespace {

const QString kCluster = QStringLiteral(LACRIMA_SOURCE_DIR "/tests/batch/one-node-slurm.sh");

QString clusterScript(const QString& mode, const QString& dir, QByteArray* out = nullptr) {
  QProcess p;
  p.start(QStringLiteral("bash"), {kCluster, mode, dir});
  if (!p.waitForFinished(60000)) {
    p.kill();
    p.waitForFinished();
    return QStringLiteral("timed out");
  }
  if (out) *out = p.readAllStandardOutput().trimmed();
  return p.exitCode() == 0 ? QString() : QString::fromUtf8(p.readAllStandardError());
}

}  // namespace

class BatchSlurmTest : public QObject {
  Q_OBJECT

  QTemporaryDir dir_;
  QString slurmConf_;

 private slots:
  void initTestCase() {
    QString missing;
    for (const char* program : {"munged", "mungekey", "slurmctld", "slurmd", "sbatch"})
      if (QStandardPaths::findExecutable(QString::fromLatin1(program)).isEmpty())
        missing =
            QString::fromLatin1(program) + " is not installed (apt-get install slurm-wlm munge)";
    if (missing.isEmpty() && geteuid() != 0) missing = "a one-node Slurm needs root";
    if (!missing.isEmpty()) {
      if (qgetenv("CI") == "true") QFAIL(qPrintable("CI=true and " + missing));
      QSKIP(qPrintable(missing));
    }
    QByteArray conf;
    const QString error = clusterScript("start", dir_.filePath("cluster"), &conf);
    QVERIFY2(error.isEmpty(), qPrintable(error));
    slurmConf_ = QString::fromUtf8(conf);
  }

  void jobArrayMatchesTheLocalRun() {
    const QString manifest = dir_.filePath("pair.json");
    QVERIFY(writeFile(manifest, R"({
      "defaults": { "size": "160x90", "frames": "136-141", "seconds": 7,
                    "outputs": ["frames", "masks"] },
      "jobs": [ { "mood": "sadness=1", "seed": 4 } ], "paired": true })"));
    const QString local = dir_.filePath("local");
    const auto here = runBatch({manifest, "--out", local});
    QVERIFY2(here.exitCode == 0, here.err.toLocal8Bit().constData());

    QProcessEnvironment cluster = withoutDisplay();
    cluster.insert("SLURM_CONF", slurmConf_);
    const QString out = dir_.filePath("on-slurm");
    const auto run =
        runBatch({"--slurm", manifest, "--out", out, "--array-size", "2", "--cpus-per-task", "1",
                  "--mem-mib", "1024", "--minutes-per-job", "5", "--submit", "--wait"},
                 300000, cluster);
    QVERIFY2(run.exitCode == 0, run.err.toLocal8Bit().constData());
    // Two array tasks and the summary job ran, each with its log.
    const QStringList logs = QDir(out + "/slurm").entryList({"*.out"}, QDir::Files);
    QCOMPARE(logs.size(), 3);
    QVERIFY(logs.contains("summary.out"));
    QCOMPARE(firstDifference(local, out), QString());
    QFile a(local + "/summary.csv"), b(out + "/summary.csv");
    QVERIFY(a.open(QIODevice::ReadOnly) && b.open(QIODevice::ReadOnly));
    const QByteArray summary = a.readAll();
    QCOMPARE(b.readAll(), summary);
    QCOMPARE(summary.count(",done,"), 2);
  }

  void cleanupTestCase() {
    if (!slurmConf_.isEmpty()) {
      const QString error = clusterScript("stop", dir_.filePath("cluster"));
      QVERIFY2(error.isEmpty(), qPrintable(error));
    }
  }
};

QTEST_GUILESS_MAIN(BatchSlurmTest)
#include "BatchSlurmTest.moc"
