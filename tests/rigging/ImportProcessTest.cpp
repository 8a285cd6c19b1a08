// Heads read in the importer process (ImportProcess.h). A good head comes back exactly as the
// in-process reader gives it. Damaged files made in the test (DamagedHeadFiles.h) that hang,
// abort, crash assimp or exhaust its memory become an ImportError naming the file and what
// happened, in about the time limit, and this process goes on; so does lacrima-rig, which
// exits 1 with the message. Stand-in importers (shell scripts) check the parent's side alone:
// each signal, a hang, a cancel (at once, also by an exception), a garbled answer, a missing
// program, and that the child inherits no descriptor but its pipes.
#include "../support/GeneratedHead.h"
#include "../support/RunProcess.h"
#include "DamagedHeadFiles.h"
#include "TestHeadFiles.h"

#include <lacrima/rigging/ImportProcess.h>
#include <lacrima/rigging/MeshImport.h>

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <QElapsedTimer>
#include <QFile>
#include <QTemporaryDir>
#include <QtTest>

#include <cerrno>

using namespace lacrima;
using namespace lacrima::rigtest;
using rigging::ImportError;
using rigging::ImportFailure;

Q_DECLARE_METATYPE(lacrima::rigtest::Outcome)

namespace {

// The failure and message of importing `path` with `options`, and how long it took.
struct Failed {
  bool threw = false;
  ImportFailure failure = ImportFailure::Refused;
  QString message;
  double seconds = 0;
};
Failed importFailure(const QString& path, const rigging::ImportOptions& options) {
  Failed f;
  QElapsedTimer timer;
  timer.start();
  try {
    (void)rigging::importHeadMeshIsolated(path.toStdString(), options);
  } catch (const ImportError& e) {
    f.threw = true;
    f.failure = e.failure();
    f.message = QString::fromStdString(e.what());
  }
  f.seconds = timer.nsecsElapsed() / 1e9;
  return f;
}

void compareHeads(const HeadMesh& a, const HeadMesh& b) {
  QCOMPARE(a.positions, b.positions);
  QCOMPARE(a.normals, b.normals);
  QCOMPARE(a.uvs, b.uvs);
  QCOMPARE(a.submeshes.size(), b.submeshes.size());
  for (std::size_t i = 0; i < a.submeshes.size(); ++i) {
    QCOMPARE(a.submeshes[i].name, b.submeshes[i].name);
    QCOMPARE(a.submeshes[i].material, b.submeshes[i].material);
    QCOMPARE(a.submeshes[i].firstVertex, b.submeshes[i].firstVertex);
    QCOMPARE(a.submeshes[i].vertexCount, b.submeshes[i].vertexCount);
    QVERIFY(a.submeshes[i].triangles == b.submeshes[i].triangles);
  }
  QCOMPARE(a.materials.size(), b.materials.size());
  for (std::size_t i = 0; i < a.materials.size(); ++i) {
    QCOMPARE(a.materials[i].name, b.materials[i].name);
    QCOMPARE(a.materials[i].diffuseTexture, b.materials[i].diffuseTexture);
    QCOMPARE(a.materials[i].diffuse, b.materials[i].diffuse);
    QCOMPARE(a.materials[i].specular, b.materials[i].specular);
    QCOMPARE(a.materials[i].shininess, b.materials[i].shininess);
    QCOMPARE(a.materials[i].transparent, b.materials[i].transparent);
  }
}

// Time limit for the damaged files: the hang waits this long.
constexpr double kLimit = 1.0;

}  // namespace

class ImportProcessTest : public QObject {
  Q_OBJECT

  QTemporaryDir dir_;

  // A stand-in importer: a shell script with `body`.
  QString script(const QString& name, const QByteArray& body) {
    const QString path = dir_.filePath(name);
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly)) return {};
    file.write("#!/bin/sh\n" + body + "\n");
    file.close();
    file.setPermissions(QFile::ReadOwner | QFile::WriteOwner | QFile::ExeOwner);
    return path;
  }
  QString anyFile() {
    const QString path = dir_.filePath(QStringLiteral("any.obj"));
    testsupport::writeObj(testsupport::generatedHead(4, 6), path);
    return path;
  }

 private slots:
  void initTestCase() {
    QVERIFY(dir_.isValid());
    QVERIFY2(!rigging::importerProgram().empty(), "lacrima-import is not beside this test");
  }

  void aGoodHeadComesBackAsTheInProcessReaderGivesIt() {
    const QString path = dir_.filePath(QStringLiteral("generated.obj"));
    QVERIFY(testsupport::writeObj(testsupport::generatedHead(), path));
    compareHeads(rigging::importHeadMeshIsolated(path.toStdString()),
                 rigging::importHeadMesh(path.toStdString()));
    const std::string parts = LACRIMA_SOURCE_DIR "/tests/fuzz/corpus/mesh_obj/two-parts.obj";
    compareHeads(rigging::importHeadMeshIsolated(parts), rigging::importHeadMesh(parts));
  }

  void theIctHeadComesBackAsTheInProcessReaderGivesIt() {
    LACRIMA_REQUIRE_SHARED(kIctMesh);
    compareHeads(rigging::importHeadMeshIsolated(kIctMesh.toStdString()),
                 rigging::importHeadMesh(kIctMesh.toStdString()));
  }

  void aRefusalKeepsTheReadersMessage() {
    const QString path = dir_.filePath(QStringLiteral("points-only.obj"));
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write("v 0 0 0\nv 1 0 0\nv 0 1 0\n");
    file.close();
    const Failed f = importFailure(path, {});
    QVERIFY(f.threw);
    QCOMPARE(f.failure, ImportFailure::Refused);
    QVERIFY2(f.message.startsWith(path + ": no faces in it (3 vertices and no face)"),
             qPrintable(f.message));
    const Failed missing = importFailure(dir_.filePath(QStringLiteral("none.obj")), {});
    QVERIFY2(missing.message.endsWith("none.obj: no such file"), qPrintable(missing.message));
  }

  void damagedFilesGiveAClearError_data() {
    QTest::addColumn<QString>("path");
    QTest::addColumn<Outcome>("outcome");
    QTest::addColumn<QString>("signal");
    const auto files = damagedHeadFiles(QDir(dir_.path()));
    QVERIFY(files.size() >= 9);
    for (const DamagedFile& file : files)
      QTest::newRow(qPrintable(file.name))
          << writeDamagedFile(QDir(dir_.path()), file) << file.outcome << file.signal;
  }
  void damagedFilesGiveAClearError() {
    QFETCH(QString, path);
    QFETCH(Outcome, outcome);
    QFETCH(QString, signal);
    QVERIFY(!path.isEmpty());
    // Only the hanging file gets the short limit: on a busy machine a slow start of the others
    // must not be taken for a hang.
    rigging::ImportOptions options;
    if (outcome == Outcome::Hang) options.seconds = kLimit;
    const Failed f = importFailure(path, options);
    QVERIFY2(f.threw, "the damaged file was read");
    QVERIFY2(f.message.startsWith(path + ": "), qPrintable(f.message));
    // Generous: the hang stops at its limit, the others at once (their default limit is 10 s).
    QVERIFY2(f.seconds < 30, qPrintable(QString::number(f.seconds)));
    switch (outcome) {
      case Outcome::Hang:
        QCOMPARE(f.failure, ImportFailure::TimedOut);
        QVERIFY2(f.message.contains("did not finish reading it in 1 s"), qPrintable(f.message));
        break;
      case Outcome::Crash:
        QCOMPARE(f.failure, ImportFailure::Crashed);
        QVERIFY2(f.message.contains("assimp crashed reading it (" + signal), qPrintable(f.message));
        QVERIFY2(f.message.contains("the file may be damaged"), qPrintable(f.message));
        break;
      case Outcome::OutOfMemory:
        QCOMPARE(f.failure, ImportFailure::OutOfMemory);
        QVERIFY2(f.message.contains("needed more than 1024 MiB of memory"), qPrintable(f.message));
        break;
      case Outcome::Refusal:
        QCOMPARE(f.failure, ImportFailure::Refused);
        QVERIFY2(f.message.contains("assimp cannot read it"), qPrintable(f.message));
        break;
    }
  }

  // lacrima-rig --mesh on a hanging and a crashing file: exit 1 with the message, in seconds.
  void theRigToolReportsADamagedFile() {
    const QDir dir(dir_.path());
    for (const DamagedFile& file : damagedHeadFiles(dir)) {
      if (file.name != "cut-header.ply" && file.name != "nul-in-header.ply") continue;
      const QString path = writeDamagedFile(dir, file);
      QElapsedTimer timer;
      timer.start();
      QStringList arguments = {
          "--mesh", path, "--fdp", dir.filePath("none.fdp.json"), "-o", dir.filePath("rig")};
      if (file.outcome == Outcome::Hang)
        arguments << "--import-time-limit"
                  << "1";
      const testsupport::ProcessRun run = testsupport::runProcess(kRigTool, arguments, 30000);
      QCOMPARE(run.exitCode, 1);
      const QString expected = file.outcome == Outcome::Hang
                                   ? QStringLiteral(": assimp did not finish reading it in 1 s")
                                   : QStringLiteral(": assimp crashed reading it (SIGSEGV");
      QVERIFY2(run.err.contains(path + expected), qPrintable(run.err));
      QVERIFY2(timer.elapsed() < 20000, qPrintable(QString::number(timer.elapsed())));
    }
  }

  // --- the parent's side, with stand-in importers ------------------------------------------

  void eachSignalIsNamed_data() {
    QTest::addColumn<QString>("signal");
    QTest::addColumn<QString>("meaning");
    QTest::newRow("SEGV") << "SEGV"
                          << "a segmentation fault";
    QTest::newRow("ABRT") << "ABRT"
                          << "one of assimp's own checks failed";
    QTest::newRow("BUS") << "BUS"
                         << "a bus error";
    QTest::newRow("FPE") << "FPE"
                         << "an arithmetic fault";
  }
  void eachSignalIsNamed() {
    QFETCH(QString, signal);
    QFETCH(QString, meaning);
    rigging::ImportOptions options;
    options.importer =
        script("die-" + signal, "echo 'last words' >&2; kill -" + signal.toUtf8() + " $$")
            .toStdString();
    const Failed f = importFailure(anyFile(), options);
    QCOMPARE(f.failure, ImportFailure::Crashed);
    QVERIFY2(f.message.contains("assimp crashed reading it (SIG" + signal + ", " + meaning +
                                ") (it said: \"last words\"); the file may be damaged"),
             qPrintable(f.message));
  }

  void aHangStopsAtTheLimit() {
    rigging::ImportOptions options;
    options.importer = script("hang", "exec sleep 60").toStdString();
    options.seconds = 0.3;
    const Failed f = importFailure(anyFile(), options);
    QCOMPARE(f.failure, ImportFailure::TimedOut);
    QVERIFY2(f.message.contains("did not finish reading it in 0.3 s"), qPrintable(f.message));
    QVERIFY2(f.seconds < 5, qPrintable(QString::number(f.seconds)));
  }

  void aCancelKillsTheChildAtOnce() {
    const QString pidFile = dir_.filePath(QStringLiteral("cancelled.pid"));
    rigging::ImportOptions options;
    options.importer =
        script("hang-pid", "echo $$ > '" + pidFile.toUtf8() + "'; exec sleep 60").toStdString();
    QElapsedTimer timer;
    timer.start();
    options.cancelled = [&] { return timer.elapsed() > 200; };
    const Failed f = importFailure(anyFile(), options);
    QCOMPARE(f.failure, ImportFailure::Cancelled);
    QVERIFY2(f.message.endsWith(": import cancelled"), qPrintable(f.message));
    QVERIFY2(f.seconds < 5, qPrintable(QString::number(f.seconds)));
    QFile file(pidFile);
    QVERIFY(file.open(QIODevice::ReadOnly));
    const pid_t pid = file.readAll().trimmed().toInt();
    QVERIFY(pid > 0);
    QVERIFY(::kill(pid, 0) != 0 && errno == ESRCH);  // killed and reaped

    // A cancel check that throws stops it the same way, and its exception goes through.
    struct Stop {};
    options.cancelled = [&]() -> bool { throw Stop{}; };
    QVERIFY_THROWS_EXCEPTION(
        Stop, (void)rigging::importHeadMeshIsolated(anyFile().toStdString(), options));
  }

  void aGarbledAnswerIsRefused() {
    rigging::ImportOptions options;
    options.importer = script("garble", "printf 'LCRMESH hello' >&3").toStdString();
    const Failed f = importFailure(anyFile(), options);
    QCOMPARE(f.failure, ImportFailure::Malformed);
    QVERIFY2(f.message.contains("the importer's answer is malformed"), qPrintable(f.message));
    options.importer = script("exit7", "exit 7").toStdString();
    const Failed exited = importFailure(anyFile(), options);
    QCOMPARE(exited.failure, ImportFailure::Crashed);
    QVERIFY2(exited.message.contains("stopped with exit code 7"), qPrintable(exited.message));
  }

  void aMissingImporterIsNamed() {
    rigging::ImportOptions options;
    options.importer = dir_.filePath(QStringLiteral("no-such-importer")).toStdString();
    const Failed f = importFailure(anyFile(), options);
    QCOMPARE(f.failure, ImportFailure::NotStarted);
    QVERIFY2(
        f.message.contains("cannot start the importer " + QString::fromStdString(options.importer)),
        qPrintable(f.message));
  }

  void theChildInheritsNoOtherDescriptor() {
    // A descriptor without close-on-exec, as a library of the editor might leave one.
    const int opened = ::open("/dev/null", O_RDONLY);
    const int leaked = ::fcntl(opened, F_DUPFD, 50);
    ::close(opened);
    QVERIFY(leaked >= 50);
    const QString list = dir_.filePath(QStringLiteral("fds.txt"));
    rigging::ImportOptions options;
    options.importer =
        script("list-fds", "ls /proc/self/fd > '" + list.toUtf8() + "'").toStdString();
    (void)importFailure(anyFile(), options);
    ::close(leaked);
    QFile file(list);
    QVERIFY(file.open(QIODevice::ReadOnly));
    const QList<QByteArray> fds = file.readAll().split('\n');
    QVERIFY2(!fds.contains(QByteArray::number(leaked)), qPrintable(fds.join(' ')));
    QVERIFY2(fds.contains("3"), "the answer pipe is fd 3");
  }
};

QTEST_GUILESS_MAIN(ImportProcessTest)
#include "ImportProcessTest.moc"
