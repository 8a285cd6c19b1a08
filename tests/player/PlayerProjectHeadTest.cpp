// A project that names its own head, in the player: `lacrima-player --render` animates it on
// that head with its tears (a frame with tears against the same frame with the tear channels
// at zero), --mesh/--fdp override it, and a missing head file is a clear error (exit 1). The
// window plays a project on its head too. Runs under xvfb-run; skips without ../shared (the
// ICT-FaceKit head).
#include "../support/ChangedPixels.h"
#include "../support/MissingData.h"
#include "../support/RunProcess.h"

#include <lacrima/player/PlayerWindow.h>
#include <lacrima/player/ProjectHead.h>
#include <lacrima/rigging/DefaultHead.h>
#include <lacrima/rigging/MeshImport.h>
#include <lacrima/viewport/WarningsButton.h>

#include "../editor/IctProject.h"

#include <QImage>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QtTest>

using namespace lacrima;

using lacrima::testsupport::changedFraction;

namespace {

const QString kPlayer = QStringLiteral(LACRIMA_BIN_DIR "/lacrima-player");

// 0.6 s at 22 fps (14 frames): the jaw opens a little while both eyes shed `tears` particles.
QByteArray keysWithTears(int tears) {
  return QStringLiteral(
             R"([{"time": 0, "values": {"open_jaw": 0, "tears_l_eye": %1, "tears_r_eye": %1}},
                 {"time": 0.6, "values": {"open_jaw": 200, "tears_l_eye": %1, "tears_r_eye": %1}}])")
      .arg(tears)
      .toUtf8();
}

using Run = testsupport::ProcessRun;

Run run(const QStringList& arguments) {
  return testsupport::runProcess(kPlayer, arguments, 120000);
}

const QString kLastFrame = QStringLiteral("/frame_0013.png");

}  // namespace

class PlayerProjectHeadTest : public QObject {
  Q_OBJECT

  QTemporaryDir dir_;

 private slots:
  void initTestCase() {
    LACRIMA_REQUIRE_SHARED(rigtest::kIctMesh);
    QVERIFY(dir_.isValid());
  }

  void rendersTheProjectOnItsHeadWithTears() {
    const QString wet = rigtest::writeIctProject(dir_.filePath("wet"), keysWithTears(80));
    const QString dry = rigtest::writeIctProject(dir_.filePath("dry"), keysWithTears(0));
    QVERIFY(!wet.isEmpty() && !dry.isEmpty());
    const Run w = run({"--render", dir_.filePath("wet-out"), "--size", "320x240", wet});
    QVERIFY2(w.exitCode == 0, qPrintable(w.err));
    const Run d = run({"--render", dir_.filePath("dry-out"), "--size", "320x240", dry});
    QVERIFY2(d.exitCode == 0, qPrintable(d.err));
    const QImage withTears(dir_.filePath("wet-out") + kLastFrame);
    const QImage without(dir_.filePath("dry-out") + kLastFrame);
    QCOMPARE(withTears.size(), QSize(320, 240));
    const double changed = changedFraction(withTears, without);
    qInfo("tears change %.3f%% of the ICT head's last frame", 100 * changed);
    QVERIFY2(changed > 0.001, "no tears ran down the project's head");

    // It is the project's head: the same animation with the ICT head given explicitly (the
    // project now names a head that is not there, which --mesh/--fdp override) renders the
    // same picture.
    const QString named = dir_.filePath("wet/project.json");
    const QString movedFdp = dir_.filePath("wet/ict.fdp.json");
    QVERIFY(QFile::rename(dir_.filePath("wet/heads/ict.fdp.json"), movedFdp));
    const Run o = run({"--render", dir_.filePath("override-out"), "--size", "320x240", "--mesh",
                       dir_.filePath("wet/heads/ict.obj"), "--fdp", movedFdp, named});
    QVERIFY2(o.exitCode == 0, qPrintable(o.err));
    const QImage overridden(dir_.filePath("override-out") + kLastFrame);
    QCOMPARE(changedFraction(overridden, withTears), 0.0);
  }

  void aMissingHeadFileIsAClearError() {
    const QString project = rigtest::writeIctProject(dir_.filePath("moved"), keysWithTears(10));
    QVERIFY(QFile::remove(dir_.filePath("moved/heads/ict.fdp.json")));
    const QString out = dir_.filePath("moved-out");
    const Run r = run({"--render", out, project});
    QCOMPARE(r.exitCode, 1);
    const QString missing = QDir::cleanPath(dir_.filePath("moved/heads/ict.fdp.json"));
    QVERIFY2(r.err.contains(project + ": head.fdp: no file at " + missing), qPrintable(r.err));
    QVERIFY(!QFile::exists(out + "/frame_0000.png"));
  }

  // The window opens a project on the head it names, and refuses one whose head is missing
  // while the previous head and animation stay.
  void theWindowPlaysAProjectOnItsHead() {
    const QString project = rigtest::writeIctProject(dir_.filePath("window"), keysWithTears(20));
    const auto head = player::headOfFile(project.toStdString());
    QVERIFY(head);
    player::PlayerWindow window(player::loadHeadFor(head, project.toStdString()));
    window.setHeadSource(head, false);
    window.setErrorDialogsEnabled(false);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QVERIFY(window.openFile(project));
    const int ictVertices = window.rig().head.vertexCount();
    QCOMPARE(ictVertices, rigging::importHeadMesh(rigtest::kIctMesh.toStdString()).vertexCount());
    // The rig's warnings are in the window, in full, not only on stderr.
    QStringList warnings;
    for (const std::string& w : window.rig().warnings) warnings << QString::fromStdString(w);
    QCOMPARE(window.rigWarnings().warnings(), warnings);
    QCOMPARE(window.rigWarnings().isVisible(), !warnings.isEmpty());
    // The rig gives the scene each part's role (its untextured eyes and skin are drawn by it).
    const HeadSubmesh* face = window.rig().head.findSubmesh("M_Face");
    QVERIFY(face);
    QCOMPARE(face->role, std::string("skin"));
    QCOMPARE(window.rig().head.findSubmesh("M_IrisLeft")->role, std::string("eye_left"));
    window.seek(0.6);
    QVERIFY(window.playback().producer().particleCount() > 0);

    const QString broken = rigtest::writeIctProject(dir_.filePath("broken"), keysWithTears(0));
    QVERIFY(QFile::remove(dir_.filePath("broken/heads/ict.obj")));
    // Another head (the same mesh, but another file), which is missing: refused, nothing lost.
    QSignalSpy failed(&window, &player::PlayerWindow::openFailed);
    QVERIFY(!window.openFile(broken));
    QCOMPARE(failed.count(), 1);
    QVERIFY2(failed.front().front().toString().contains("head.mesh: no file at"),
             qPrintable(failed.front().front().toString()));
    QCOMPARE(window.rig().head.vertexCount(), ictVertices);
    QCOMPARE(window.playback().path(), project.toStdString());

    // A project without a head plays on the default head.
    if (!rigging::defaultHeadAvailable()) LACRIMA_SKIP_WITHOUT_DEFAULT_HEAD();
    const QString plain = dir_.filePath("plain.json");
    QFile file(plain);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write("{\"format\": \"lacrima-project\", \"version\": 1, \"keys\": " + keysWithTears(5) +
               "}");
    file.close();
    QVERIFY(window.openFile(plain));
    QVERIFY(window.rig().head.vertexCount() != ictVertices);
  }
};

QTEST_MAIN(PlayerProjectHeadTest)
#include "PlayerProjectHeadTest.moc"
