// A project that names its own head, in the editor: the preview rigs that head in the
// background and animates it; a missing head file leaves the project open with a clear
// message and a head reference that saving keeps; File > Choose head (setHead) is one undoable
// edit. Runs under xvfb-run (OGRE needs X); skips without ../shared (the ICT-FaceKit head).
#include "../support/ChangedPixels.h"
#include "../support/MissingData.h"

#include <lacrima/common/FapTable.h>
#include <lacrima/editing/EditorModel.h>
#include <lacrima/editor/MainWindow.h>
#include <lacrima/editor/PreviewPanel.h>
#include <lacrima/rigging/DefaultHead.h>
#include <lacrima/rigging/MeshImport.h>
#include <lacrima/scene/OrbitView.h>
#include <lacrima/viewport/FaceViewport.h>
#include <lacrima/viewport/WarningsButton.h>

#include "IctProject.h"

#include <Eigen/Geometry>
#include <QDialog>
#include <QImage>
#include <QPlainTextEdit>
#include <QScreen>
#include <QTemporaryDir>
#include <QUndoStack>
#include <QtTest>

using namespace lacrima;
using namespace lacrima::editor;

using lacrima::testsupport::changedFraction;

namespace {

QString readText(const QString& path) {
  QFile file(path);
  return file.open(QIODevice::ReadOnly) ? QString::fromUtf8(file.readAll()) : QString();
}

// One key with the jaw closed.
const QByteArray kKeys = R"([{"time": 0, "values": {"open_jaw": 0}}])";

}  // namespace

class EditorProjectHeadTest : public QObject {
  Q_OBJECT

 private:
  QTemporaryDir recovery_;
  int ictVertices_ = 0;

  EditorOptions options() const {
    EditorOptions o;
    o.interactive = false;
    o.offerRecovery = false;
    o.recoveryDirectory = recovery_.path();
    return o;
  }

 private slots:
  void initTestCase() {
    QStandardPaths::setTestModeEnabled(true);
    LACRIMA_REQUIRE_SHARED(rigtest::kIctMesh);
    // Counted by the importer itself, not by the preview under test.
    ictVertices_ = rigging::importHeadMesh(rigtest::kIctMesh.toStdString()).vertexCount();
    QVERIFY(ictVertices_ > 0);
  }

  void theProjectsHeadIsShownAndPosed() {
    QTemporaryDir folder;
    const QString project = rigtest::writeIctProject(folder.path(), kKeys);
    QVERIFY(!project.isEmpty());
    MainWindow window(options());
    window.resize(1280, 800);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QVERIFY2(window.openFile(project), qPrintable(window.lastError()));
    QVERIFY2(window.preview()->loadHead(), qPrintable(window.preview()->messageText()));
    QCOMPARE(window.preview()->headVertexCount(), ictVertices_);
    QVERIFY(window.preview()->statusText().contains(QLatin1String("ict.obj")));
    const QImage neutral = window.preview()->grabFrame();
    QVERIFY(!neutral.isNull());
    window.model().setChannel(3, 900);  // open_jaw
    const QImage open = window.preview()->grabFrame();
    const double changed = changedFraction(neutral, open);
    qInfo("open_jaw 900 on the ICT head changes %.2f%% of the preview's pixels", 100 * changed);
    QVERIFY2(changed > 0.002, "the ICT head's jaw did not move in the preview");
    // Tears run on this head: the tear sources come from its own rig.
    window.model().setChannels({{kTearLeftFap, 60}, {kTearRightFap, 60}}, QStringLiteral("tears"));
    for (int i = 0; i < 10; ++i) window.preview()->step(window.model().frameDuration());
    window.preview()->waitForTears();  // the tears are stepped on a worker thread
    QVERIFY(window.preview()->particleCount() > 0);
    window.model().markSaved();
  }

  // Opening a project without a head goes back to the default head; opening the ICT project
  // again replaces it.
  void openingAnotherProjectReplacesTheHead() {
    if (!rigging::defaultHeadAvailable()) LACRIMA_SKIP_WITHOUT_DEFAULT_HEAD();
    QTemporaryDir folder;
    const QString ict = rigtest::writeIctProject(folder.path(), kKeys);
    const QString plain = folder.filePath("plain.json");
    QFile file(plain);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write("{\"format\": \"lacrima-project\", \"version\": 1, \"keys\": []}");
    file.close();
    MainWindow window(options());
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QVERIFY(window.preview()->loadHead());
    const int defaultVertices = window.preview()->headVertexCount();
    QVERIFY(defaultVertices > 0 && defaultVertices != ictVertices_);
    QVERIFY(window.openFile(ict));
    QVERIFY(window.preview()->loadHead());
    QCOMPARE(window.preview()->headVertexCount(), ictVertices_);
    QVERIFY(window.openFile(plain));
    QVERIFY(window.preview()->loadHead());
    QCOMPARE(window.preview()->headVertexCount(), defaultVertices);
  }

  // The mesh moved away: the project opens, the preview names the missing file and the way
  // out, and saving (also elsewhere) keeps the head entry. Choosing the head again is one
  // undoable edit that marks the document modified.
  void aMovedMeshKeepsTheProjectAndItsHead() {
    QTemporaryDir folder;
    const QString project = rigtest::writeIctProject(folder.path(), kKeys);
    const QString moved = folder.filePath("elsewhere.obj");
    QVERIFY(QFile::rename(folder.filePath("heads/ict.obj"), moved));
    MainWindow window(options());
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QVERIFY2(window.openFile(project), qPrintable(window.lastError()));
    QVERIFY(!window.preview()->loadHead());
    const QString message = window.preview()->messageText();
    QVERIFY2(message.contains(QLatin1String("head.mesh: no file at ") +
                              QDir::cleanPath(folder.filePath("heads/ict.obj"))),
             qPrintable(message));
    QVERIFY2(message.contains(QLatin1String("Choose head")), qPrintable(message));
    QCOMPARE(window.preview()->headVertexCount(), 0);
    QVERIFY(!window.model().isModified());

    // Saved beside the original and in another folder: the entry names the same files.
    QVERIFY(window.saveTo(project));
    QVERIFY(readText(project).contains(R"("mesh": "heads/ict.obj")"));
    QDir(folder.path()).mkpath("copies");
    QVERIFY(window.saveTo(folder.filePath("copies/project.json")));
    QVERIFY(
        readText(folder.filePath("copies/project.json")).contains(R"("mesh": "../heads/ict.obj")"));

    // File > Choose head: a missing file is refused, the moved one accepted (undoably).
    QVERIFY(!window.setHead(folder.filePath("nothing.obj"), folder.filePath("heads/ict.fdp.json")));
    QVERIFY(!window.model().isModified());
    QVERIFY(window.setHead(moved, folder.filePath("heads/ict.fdp.json")));
    QVERIFY(window.model().isModified());
    QCOMPARE(QString::fromStdString(window.model().document().head->mesh), moved);
    QVERIFY2(window.preview()->loadHead(), qPrintable(window.preview()->messageText()));
    QCOMPARE(window.preview()->headVertexCount(), ictVertices_);
    QVERIFY(window.preview()->messageText().isEmpty());
    window.model().undoStack()->undo();
    QCOMPARE(QString::fromStdString(window.model().document().head->mesh),
             QDir::cleanPath(folder.filePath("heads/ict.obj")));
    QVERIFY(!window.model().isModified());
    QVERIFY(!window.preview()->loadHead());  // back to the missing file
    QVERIFY(window.preview()->messageText().contains(QLatin1String("head.mesh")));

    // The file is put back and the project opened again: the preview tries again and shows it.
    QVERIFY(QFile::rename(moved, folder.filePath("heads/ict.obj")));
    QVERIFY(window.openFile(project));
    QVERIFY2(window.preview()->loadHead(), qPrintable(window.preview()->messageText()));
    QCOMPARE(window.preview()->headVertexCount(), ictVertices_);
  }

  // Warnings from rigging the project's head reach the status line. Here the left iris is
  // demoted to an attached part, so feature point 3.5 on it moves nothing.
  void rigWarningsShowInTheStatus() {
    QFile hand(rigtest::kIctFdp);
    QVERIFY(hand.open(QIODevice::ReadOnly));
    QByteArray fdp = hand.readAll();
    const QByteArray eye = R"("eye_left": ["M_ScleraLeft", "M_IrisLeft"])";
    const QByteArray attached = R"("attached": [)";
    QVERIFY(fdp.contains(eye) && fdp.contains(attached));
    fdp.replace(eye, R"("eye_left": ["M_IrisLeft"])");
    fdp.replace(attached, R"("attached": ["M_ScleraLeft", )");
    QTemporaryDir folder;
    const QString project = rigtest::writeIctProject(folder.path(), kKeys, fdp);
    MainWindow window(options());
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QVERIFY(window.openFile(project));
    QVERIFY2(window.preview()->loadHead(), qPrintable(window.preview()->messageText()));
    const QStringList warnings = window.preview()->headWarnings();
    QVERIFY2(
        warnings.filter(QLatin1String(
                            "feature point 3.5: sub-mesh \"M_ScleraLeft\" has no deforming role"))
                .size() == 1,
        qPrintable(warnings.join('\n')));
    // The status line counts them and shows the first; the button beside it lists them all,
    // in full, in a window of its own.
    const QString status = window.preview()->statusText();
    QVERIFY2(status.contains(QStringLiteral("%1 warning").arg(warnings.size())) &&
                 status.contains(warnings.front()),
             qPrintable(status));
    viewport::WarningsButton* button = window.preview()->warningsButton();
    QVERIFY(button->isVisible());
    QCOMPARE(button->warnings(), warnings);
    QTest::mouseClick(button, Qt::LeftButton);
    QVERIFY(button->list() && button->list()->isVisible());
    const QString listed = button->list()->findChild<QPlainTextEdit*>()->toPlainText();
    for (const QString& w : warnings) QVERIFY2(listed.contains(w), qPrintable(w));
    button->list()->close();
    // However long the status, no text widens the window: it needs no more width than a
    // window with no head at all.
    MainWindow plain(options());
    QVERIFY2(window.minimumSizeHint().width() <= plain.minimumSizeHint().width(),
             qPrintable(QStringLiteral("%1 > %2")
                            .arg(window.minimumSizeHint().width())
                            .arg(plain.minimumSizeHint().width())));
  }

  // Untextured eyes (the ICT head's) show an iris and a pupil where they look: the pupil's
  // pixel, straight in front of the eye, is much darker than the sclera beside the iris.
  void anUntexturedEyeHasAPupil() {
    QTemporaryDir folder;
    const QString project = rigtest::writeIctProject(folder.path(), kKeys);
    MainWindow window(options());
    window.resize(1280, 800);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QVERIFY(window.openFile(project));
    QVERIFY2(window.preview()->loadHead(), qPrintable(window.preview()->messageText()));
    auto* view = window.findChild<viewport::FaceViewport*>(QStringLiteral("faceViewport"));
    QVERIFY(view && view->head());
    const HeadMesh& head = *view->head();
    const HeadSubmesh* iris = head.findSubmesh("M_IrisLeft");
    const HeadSubmesh* sclera = head.findSubmesh("M_ScleraLeft");
    QVERIFY(iris && sclera);
    Eigen::AlignedBox3f box;
    for (const HeadSubmesh* part : {iris, sclera})
      for (int v = part->firstVertex; v < part->firstVertex + part->vertexCount; ++v)
        box.extend(head.positions.col(v));
    const Eigen::Vector3d centre = box.center().cast<double>();
    const double radius = 0.25 * (box.sizes().x() + box.sizes().y());
    const Eigen::Vector3d front = centre + Eigen::Vector3d(0, 0, radius);
    const Eigen::Vector3d side = centre + Eigen::Vector3d(0.65 * radius, 0, 0.76 * radius);
    // Straight on, the eye filling a good part of the view.
    scene::OrbitView close;
    close.target = centre;
    close.distance = 12 * radius;
    close.minDistance = radius;
    close.maxDistance = 100 * radius;
    view->setView(close);
    const QImage picture = window.preview()->grabFrame();
    QVERIFY(!picture.isNull());
    const auto pupil = view->project(front), white = view->project(side);
    QVERIFY(pupil && white);
    const double ratio = picture.devicePixelRatio();
    const auto lightness = [&](const QPointF& at) {
      return picture.pixelColor((at * ratio).toPoint()).lightnessF();
    };
    QVERIFY2(
        lightness(*pupil) + 0.25 < lightness(*white),
        qPrintable(
            QStringLiteral("pupil %1, sclera %2").arg(lightness(*pupil)).arg(lightness(*white))));
  }
};

QTEST_MAIN(EditorProjectHeadTest)
#include "EditorProjectHeadTest.moc"
