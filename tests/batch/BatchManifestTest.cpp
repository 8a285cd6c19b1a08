// The batch manifest, job ids, shards, job records and the Slurm script: lacrima-batch's logic
// without running a job. Manifests come from users, so their errors name file, line and what
// was expected, and their sizes are bounded before anything is allocated.
#include <lacrima/batch/BatchManifest.h>
#include <lacrima/batch/BatchRun.h>
#include <lacrima/batch/JobRecord.h>
#include <lacrima/batch/SlurmScript.h>

#include <lacrima/common/Diagnostics.h>

#include <QFile>
#include <QTemporaryDir>
#include <QtTest>

#include <set>

using namespace lacrima;
using namespace lacrima::batch;

namespace {

void write(const QString& path, const QByteArray& bytes) {
  QFile f(path);
  QVERIFY(f.open(QIODevice::WriteOnly));
  f.write(bytes);
}

// The FileError's message for `json` as a manifest in `dir`, or "" when it reads.
QString manifestError(const QTemporaryDir& dir, const QByteArray& json) {
  const QString path = dir.filePath("m.json");
  write(path, json);
  try {
    readManifest(path.toStdString());
    return {};
  } catch (const FileError& e) {
    return QString::fromStdString(e.what());
  }
}

}  // namespace

class BatchManifestTest : public QObject {
  Q_OBJECT

 private slots:
  void gridExpandsToTheProductWithPairs() {
    QTemporaryDir dir;
    write(dir.filePath("a.fap"), "2.1 demo 22 2\n");
    write(dir.filePath("m.json"), R"({
      "defaults": { "size": "160x90", "outputs": ["masks", "frames"] },
      "jobs": [ { "animation": "a.fap", "view": "front" } ],
      "grid": { "take": [ { "mood": "sadness=0.8", "seed": 3 }, { "mood": "joy=0.5" } ],
                "view": ["front", "profile", "close-left"] },
      "paired": true })");
    const BatchManifest m = readManifest(dir.filePath("m.json").toStdString());
    QCOMPARE(m.jobs.size(), std::size_t{2 * (1 + 2 * 3)});
    QVERIFY(m.jobs[0].animation && m.jobs[0].tears && !m.jobs[1].tears);
    QCOMPARE(m.jobs[0].width, 160);
    // Outputs keep their canonical order whatever order the manifest lists them in.
    QCOMPARE(m.jobs[0].outputs, (std::vector<Output>{Output::Frames, Output::Masks}));
    QCOMPARE(m.jobs[2].mood, std::string("sadness=0.8"));
    QCOMPARE(m.jobs[2].seed, std::uint64_t{3});
    QCOMPARE(m.jobs[2].view, std::string("front"));
    QCOMPARE(m.jobs[4].view, std::string("profile"));
    QCOMPARE(m.jobs[8].mood, std::string("joy=0.5"));
    QCOMPARE(m.jobs[8].seed, std::uint64_t{1});  // the default seed
  }

  void idsAreStableAndFollowContent() {
    QTemporaryDir dir;
    write(dir.filePath("a.fap"), "2.1 demo 22 2\n");
    write(dir.filePath("m.json"), R"({ "jobs": [ { "animation": "a.fap" }, { "animation": "a.fap" },
                                                { "animation": "a.fap", "tears": false } ] })");
    const BatchManifest m = readManifest(dir.filePath("m.json").toStdString());
    const std::vector<PlannedJob> first = planJobs(m);
    QCOMPARE(first.size(), std::size_t{2});  // the repeated job runs once
    QCOMPARE(planJobs(m)[0].id, first[0].id);
    QVERIFY(first[0].id < first[1].id);  // sorted: the order shards are cut from
    for (const PlannedJob& p : first) QCOMPARE(p.id.size(), std::size_t{16});
    // The file is named as written, not where it lies, and fingerprinted by its bytes.
    QVERIFY(first[0].canonical.find("\"file\": \"a.fap\"") != std::string::npos);
    QVERIFY(first[0].canonical.find(dir.path().toStdString()) == std::string::npos);
    write(dir.filePath("a.fap"), "2.1 demo 22 3\n");
    const std::vector<PlannedJob> changed = planJobs(m);
    QVERIFY(changed[0].id != first[0].id && changed[0].id != first[1].id);
  }

  void shardsPartitionTheJobs() {
    std::vector<PlannedJob> jobs(11);
    for (int k = 0; k < 11; ++k) jobs[static_cast<std::size_t>(k)].id = std::to_string(100 + k);
    std::multiset<std::string> seen;
    for (int i = 1; i <= 4; ++i) {
      const std::vector<PlannedJob> share = shardOf(jobs, i, 4);
      QVERIFY(share.size() == 2 || share.size() == 3);
      for (const PlannedJob& p : share) seen.insert(p.id);
    }
    QCOMPARE(seen.size(), std::size_t{11});
    QCOMPARE(std::set<std::string>(seen.begin(), seen.end()).size(), std::size_t{11});
    QCOMPARE(shardOf(jobs, 12, 12).size(), std::size_t{0});
  }

  void badManifestsNameLineAndWhatWasExpected_data() {
    QTest::addColumn<QByteArray>("json");
    QTest::addColumn<QString>("expected");
    QTest::newRow("unknown field")
        << QByteArray("{ \"jobs\": [\n { \"animaton\": \"a.fap\" } ] }") << "m.json:2:";
    QTest::newRow("bad mood") << QByteArray("{ \"jobs\": [\n { \"mood\": \"glee=2\" } ] }")
                              << "m.json:2:";
    QTest::newRow("missing file") << QByteArray(
                                         "{\n\"jobs\": [ { \"animation\": \"none.fap\" } ] }")
                                  << "no such file";
    QTest::newRow("mesh without fdp")
        << QByteArray("{ \"jobs\": [ { \"mood\": \"joy=1\", \"mesh\": \"m.json\" } ] }")
        << "go together";
    QTest::newRow("odd size")
        << QByteArray("{ \"jobs\": [ { \"mood\": \"joy=1\", \"size\": \"161x90\" } ] }") << "even";
    QTest::newRow("frames backwards")
        << QByteArray("{ \"jobs\": [ { \"mood\": \"joy=1\", \"frames\": \"9-3\" } ] }")
        << "FIRST <= LAST";
    QTest::newRow("frames past a take")
        << QByteArray(
               "{ \"jobs\": [ { \"mood\": \"joy=1\", \"seconds\": 1, \"frames\": \"0-40\" } ] }")
        << "past the end";
    QTest::newRow("no outputs") << QByteArray(
                                       "{ \"jobs\": [ { \"mood\": \"joy=1\", \"outputs\": [] } ] }")
                                << "at least one";
    QTest::newRow("no take") << QByteArray("{ \"jobs\": [ { \"view\": \"front\" } ] }")
                             << "neither \"animation\" nor \"mood\"";
    QTest::newRow("no jobs") << QByteArray("{ \"paired\": true }")
                             << "neither \"jobs\" nor \"grid\"";
    QTest::newRow("syntax") << QByteArray("{ \"jobs\": [\n\n  { \"mood\": } ] }") << "m.json:3:";
  }
  void badManifestsNameLineAndWhatWasExpected() {
    QFETCH(QByteArray, json);
    QFETCH(QString, expected);
    QTemporaryDir dir;
    const QString error = manifestError(dir, json);
    QVERIFY2(error.contains(expected), qPrintable(error));
  }

  // A grid of 10^3 x 10^3 values is refused from the axes' sizes, before any job is made.
  void hugeGridsAreRefusedBeforeExpanding() {
    QTemporaryDir dir;
    QByteArray axis = "[";
    for (int k = 0; k < 1000; ++k) axis += (k ? ",1" : "1");
    axis += "]";
    const QString error = manifestError(
        dir, "{ \"defaults\": { \"mood\": \"joy=1\" }, \"grid\": { \"seed\": " + axis +
                 ", \"seconds\": " + axis + " } }");
    QVERIFY2(error.contains("more than 100000 jobs"), qPrintable(error));
  }

  void recordsRoundTripAndProveCompleteness() {
    QTemporaryDir dir;
    QVERIFY(QDir(dir.path()).mkpath("job/frames"));
    write(dir.filePath("job/frames/frame_0000.png"), "picture");
    write(dir.filePath("job/statistics.json"), "{}");
    JobRecord r;
    r.id = "0123456789abcdef";
    r.done = true;
    r.job = "{}";
    r.label = "joy=1 seed 1";
    r.version = "test";
    r.host = "here";
    r.statistics = RunFigures{12, 10, 40, "00ff00ff00ff00ff"};
    r.outputs = listOutputs(dir.filePath("job").toStdString());
    QCOMPARE(r.outputs.size(), std::size_t{2});
    QCOMPARE(r.outputs[0].file, std::string("frames/frame_0000.png"));
    write(dir.filePath("job/job.json"), QByteArray::fromStdString(r.toJson()));
    const JobRecord back = JobRecord::read(dir.filePath("job/job.json").toStdString());
    QCOMPARE(back.outputs, r.outputs);
    QCOMPARE(back.statistics, r.statistics);
    const std::string folder = dir.filePath("job").toStdString();
    QVERIFY(isComplete(folder, r.id, true));
    QVERIFY(!isComplete(folder, "fedcba9876543210", false));  // another job's folder
    // Same size, other bytes: only a rehash sees it.
    write(dir.filePath("job/frames/frame_0000.png"), "PICTURE");
    QVERIFY(isComplete(folder, r.id, false));
    QVERIFY(!isComplete(folder, r.id, true));
    QFile::remove(dir.filePath("job/statistics.json"));
    QVERIFY(!isComplete(folder, r.id, false));
  }

  void recordsCannotPointOutsideTheirFolder() {
    QTemporaryDir dir;
    write(dir.filePath("job.json"), R"({ "format": "lacrima-job", "version": 1,
      "id": "0123456789abcdef", "status": "done", "label": "", "job": "{}", "lacrima": "x",
      "host": "h", "wall_seconds": 1,
      "outputs": [ { "file": "../../etc/passwd", "bytes": 1, "sha256": "00" } ] })");
    try {
      JobRecord::read(dir.filePath("job.json").toStdString());
      QFAIL("a record pointing outside its folder was read");
    } catch (const FileError& e) {
      QVERIFY2(QString(e.what()).contains("inside the job's folder"), e.what());
    }
  }

  void slurmScriptStatesItsShardsAndResources() {
    SlurmSettings s;
    s.batchProgram = "/opt/lacrima/bin/lacrima-batch";
    s.manifest = "/data/it's.json";
    s.outDir = "/shared/out";
    s.jobCount = 101;
    s.arraySize = 10;
    s.cpusPerTask = 4;
    s.memoryMiB = 3000;
    s.minutesPerJob = 7;
    s.partition = "render";
    const QString script = QString::fromStdString(slurmScript(s));
    QVERIFY(script.startsWith("#!/bin/bash\n"));
    QVERIFY(script.contains("#SBATCH --array=1-10\n"));
    QVERIFY(script.contains("#SBATCH --cpus-per-task=4\n"));
    QVERIFY(script.contains("#SBATCH --mem=3000M\n"));
    QVERIFY(script.contains("#SBATCH --time=0-01:17:00\n"));  // 11 jobs in the largest task
    QVERIFY(script.contains("#SBATCH --partition=render\n"));
    QVERIFY(script.contains("#SBATCH --output=/shared/out/slurm/%A_%a.out\n"));
    QVERIFY(script.contains("'/data/it'\\''s.json'"));
    QVERIFY(script.contains("--shard \"${SLURM_ARRAY_TASK_ID}/10\""));
    QCOMPARE(QString::fromStdString(slurmTime(3 * 1440 + 61)), QString("3-01:01:00"));
  }
};

QTEST_GUILESS_MAIN(BatchManifestTest)
#include "BatchManifestTest.moc"
