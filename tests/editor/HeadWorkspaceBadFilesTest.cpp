// The Head workspace (offscreen) importing damaged head files a user might get from the
// internet (DamagedHeadFiles.h: files that hang, abort or crash assimp, or ask it for gigabytes).
// Each import ends in a failure naming the file and what happened, within its time limit; the
// editor goes on, with the head it had and the project as it was; a hanging import can be
// cancelled at once and a good head imported right after.
#include "../rigging/DamagedHeadFiles.h"
#include "../support/GeneratedHead.h"

#include <lacrima/editing/EditorModel.h>
#include <lacrima/editing/HeadSetup.h>
#include <lacrima/editor/MainWindow.h>
#include <lacrima/editor/head/HeadWorkspace.h>

#include <QElapsedTimer>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QToolButton>
#include <QtTest>

using namespace lacrima;
using namespace lacrima::editor;
using lacrima::rigtest::Outcome;

namespace {

// The time limit the hanging file gets here: it waits this long.
constexpr double kLimitSeconds = 1.0;

}  // namespace

class HeadWorkspaceBadFilesTest : public QObject {
  Q_OBJECT

  QTemporaryDir dir_;

  EditorOptions options() const {
    EditorOptions o;
    o.preview = false;
    o.interactive = false;
    o.offerRecovery = false;
    o.recoveryDirectory = dir_.filePath(QStringLiteral("recovery"));
    return o;
  }

  // Imports `path`; whether it succeeded, or nullopt when nothing came within `timeoutMs`.
  static std::optional<bool> importInto(head::HeadWorkspace& ws, const QString& path,
                                        int timeoutMs = 30000) {
    QSignalSpy done(&ws, &head::HeadWorkspace::importFinished);
    ws.importHead(path);
    if (!done.wait(timeoutMs)) return std::nullopt;
    return done.front().front().toBool();
  }

 private slots:
  void initTestCase() { QVERIFY(dir_.isValid()); }

  void damagedFilesFailClearlyAndChangeNothing() {
    MainWindow window(options());
    window.setWorkspace(MainWindow::Workspace::Head);
    head::HeadWorkspace& ws = *window.headWorkspace();
    const QString good = dir_.filePath(QStringLiteral("good-head.obj"));
    QVERIFY(testsupport::writeObj(testsupport::generatedHead(), good));
    QVERIFY2(importInto(ws, good) == std::optional<bool>(true), qPrintable(ws.lastError()));
    const std::shared_ptr<const HeadMesh> head = ws.setup().sharedMesh();
    window.model().setChannel(3, 400);  // the project has an edit of its own
    const int edits = window.model().undoStack()->count();
    const float jaw = window.model().currentValue(3);

    const QDir dir(dir_.path());
    const auto files = rigtest::damagedHeadFiles(dir);
    QVERIFY(files.size() >= 9);
    for (const rigtest::DamagedFile& file : files) {
      const QString path = rigtest::writeDamagedFile(dir, file);
      QVERIFY(!path.isEmpty());
      // Only the hanging file waits for the short limit; on a busy machine the others keep the
      // default, so that a slow start is not taken for a hang.
      ws.setImportTimeLimit(file.outcome == Outcome::Hang ? kLimitSeconds : 0);
      QElapsedTimer timer;
      timer.start();
      QCOMPARE(importInto(ws, path), std::optional<bool>(false));
      QVERIFY2(timer.elapsed() < 30000, qPrintable(file.name));  // generous: see above
      const QString error = ws.lastError();
      QVERIFY2(error.startsWith(path + ": "), qPrintable(error));
      const char* cause = file.outcome == Outcome::Hang          ? "did not finish reading it"
                          : file.outcome == Outcome::Crash       ? "assimp crashed reading it"
                          : file.outcome == Outcome::OutOfMemory ? "of memory"
                                                                 : "assimp cannot read it";
      QVERIFY2(error.contains(cause), qPrintable(error));
      QVERIFY2(ws.statusText().contains(file.name), qPrintable(ws.statusText()));
      // The workspace keeps its head, the project its edit.
      QCOMPARE(ws.setup().sharedMesh(), head);
      QCOMPARE(ws.setup().meshPath(), good);
      QCOMPARE(window.model().undoStack()->count(), edits);
      QCOMPARE(window.model().currentValue(3), jaw);
    }
    window.model().markSaved();
  }

  void aHangingImportIsCancelledAtOnce() {
    MainWindow window(options());
    window.setWorkspace(MainWindow::Workspace::Head);
    head::HeadWorkspace& ws = *window.headWorkspace();
    ws.setImportTimeLimit(600);  // only the cancel can stop it
    const QDir dir(dir_.path());
    const rigtest::DamagedFile hang = rigtest::damagedHeadFiles(dir).front();
    QCOMPARE(hang.outcome, Outcome::Hang);
    const QString path = rigtest::writeDamagedFile(dir, hang);

    QSignalSpy done(&ws, &head::HeadWorkspace::importFinished);
    ws.importHead(path);
    QVERIFY(ws.importing());
    auto* cancel = ws.findChild<QToolButton*>(QStringLiteral("head.cancelImport"));
    QVERIFY(cancel && cancel->isVisibleTo(&ws));
    QTest::qWait(200);
    QVERIFY(done.isEmpty());
    QElapsedTimer timer;
    timer.start();
    cancel->click();
    QVERIFY(done.wait(5000));
    QVERIFY2(timer.elapsed() < 5000, "the cancel took seconds");
    QCOMPARE(done.front().front().toBool(), false);
    QVERIFY(!ws.importing());
    QVERIFY(!cancel->isVisibleTo(&ws));
    QVERIFY2(ws.statusText().contains("cancelled"), qPrintable(ws.statusText()));
    QVERIFY(!ws.setup().hasMesh());

    // The next import works.
    const QString good = dir_.filePath(QStringLiteral("after-cancel.obj"));
    QVERIFY(testsupport::writeObj(testsupport::generatedHead(), good));
    ws.setImportTimeLimit(0);
    QVERIFY2(importInto(ws, good) == std::optional<bool>(true), qPrintable(ws.lastError()));
    QCOMPARE(ws.setup().meshPath(), good);
  }
};

QTEST_MAIN(HeadWorkspaceBadFilesTest)
#include "HeadWorkspaceBadFilesTest.moc"
