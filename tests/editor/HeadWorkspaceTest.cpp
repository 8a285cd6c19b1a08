// The Head workspace driven like a user, under xvfb-run: import the ICT head, fix a part's role
// in the table, click the 8 anchors where the viewport shows them, propose the rest, drag a
// point, undo, save; the saved file rigs, and a FAP slider re-poses the rigged head at once. A
// small head generated in the test runs the import and a clicked anchor without ../shared. Bad
// input (a missing file, a mesh with no faces) gives a clear message and leaves the workspace as it
// was. Also measures the longest event-loop stall from import to a rigged head (printed; a figure,
// not an assertion).
#include "../rigging/TestHeadFiles.h"
#include "../support/ChangedPixels.h"
#include "../support/GeneratedHead.h"
#include "../support/MissingData.h"

#include <lacrima/common/AtomicSave.h>
#include <lacrima/common/FdpTable.h>
#include <lacrima/editing/EditorModel.h>
#include <lacrima/editing/HeadSetup.h>
#include <lacrima/editor/MainWindow.h>
#include <lacrima/editor/head/HeadWorkspace.h>
#include <lacrima/editor/head/PartsTableModel.h>
#include <lacrima/editor/head/PointListModel.h>
#include <lacrima/playback/HeadRig.h>
#include <lacrima/rigging/DefaultHead.h>
#include <lacrima/rigging/FeaturePointProposal.h>
#include <lacrima/viewport/FaceViewport.h>

#include <QColor>
#include <QComboBox>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QImage>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLabel>
#include <QListWidget>
#include <QProcess>
#include <QSignalSpy>
#include <QTableView>
#include <QTemporaryDir>
#include <QTimer>
#include <QToolButton>
#include <QtTest>

using namespace lacrima;
using namespace lacrima::editor;
using namespace lacrima::rigtest;

using lacrima::testsupport::changedFraction;

namespace {

// The longest gap between two ticks of a 1 ms timer while it runs: how long the event loop
// was blocked at worst.
// Only the waits are measured (start() before, stop() after): the test's own code between them
// runs outside the event loop by design.
class StallMeter : public QObject {
 public:
  StallMeter() {
    timer_.setInterval(1);
    connect(&timer_, &QTimer::timeout, this, [this] {
      longest_ = std::max(longest_, clock_.nsecsElapsed() / 1e6);
      clock_.restart();
    });
  }
  void start() {
    clock_.start();
    timer_.start();
  }
  void stop() {
    longest_ = std::max(longest_, clock_.nsecsElapsed() / 1e6);
    timer_.stop();
  }
  double longestMilliseconds() const { return longest_; }

 private:
  QTimer timer_;
  QElapsedTimer clock_;
  double longest_ = 0;
};

int rowNamed(const HeadMesh& mesh, const std::string& name) {
  for (std::size_t i = 0; i < mesh.submeshes.size(); ++i)
    if (mesh.submeshes[i].name == name) return static_cast<int>(i);
  return -1;
}

}  // namespace

class HeadWorkspaceTest : public QObject {
  Q_OBJECT

  QTemporaryDir dir_;

  EditorOptions options() const {
    EditorOptions o;
    o.preview = false;  // the Animate preview is not under test here
    o.interactive = false;
    o.offerRecovery = false;
    o.recoveryDirectory = dir_.filePath(QStringLiteral("recovery"));
    return o;
  }

  static bool importInto(head::HeadWorkspace& ws, const QString& path) {
    QSignalSpy done(&ws, &head::HeadWorkspace::importFinished);
    ws.importHead(path);
    if (!done.wait(30000)) return false;
    return done.front().front().toBool();
  }

 private slots:
  void initTestCase() {
    QStandardPaths::setTestModeEnabled(true);
    QVERIFY(dir_.isValid());
  }

  void importPlaceProposeDragUndoSave() {
    LACRIMA_REQUIRE_SHARED(kIctMesh);
    if (!rigging::defaultHeadAvailable()) LACRIMA_SKIP_WITHOUT_DEFAULT_HEAD();
    MainWindow window(options());
    window.resize(1280, 860);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    // Switching to the workspace starts its viewport (OGRE's window and shaders): once.
    QElapsedTimer wall;
    wall.start();
    window.action(QStringLiteral("view.head"))->trigger();
    QCOMPARE(window.workspace(), MainWindow::Workspace::Head);
    head::HeadWorkspace& ws = *window.headWorkspace();
    QVERIFY(ws.isVisible());
    editing::HeadSetup& setup = ws.setup();
    viewport::FaceViewport* view = ws.viewport();
    if (!view->usesOgre()) QSKIP("no OGRE viewport (needs an X display)");
    QTRY_VERIFY(view->renderCount() > 0);
    const double startMs = wall.nsecsElapsed() / 1e6;

    // --- import -> rigged, with the event loop watched ------------------------------------
    StallMeter meter;
    wall.restart();
    meter.start();
    QVERIFY2(importInto(ws, kIctMesh), qPrintable(ws.lastError()));
    meter.stop();
    const double importStall = meter.longestMilliseconds();
    const double importMs = wall.nsecsElapsed() / 1e6;
    const HeadMesh& mesh = setup.mesh();
    QCOMPARE(ws.partsView()->model()->rowCount(), static_cast<int>(mesh.submeshes.size()));

    // The reference picture and description of the point to place first.
    QCOMPARE(ws.currentPoint(), head::PointListModel::anchorOrder().front());
    QSignalSpy shown(&ws, &head::HeadWorkspace::referenceShown);
    QVERIFY(shown.wait(30000));
    QVERIFY(!ws.referencePicture().isNull());
    const QString description = QString::fromUtf8(fdpDescription(ws.currentPoint()).data());
    QVERIFY(!description.isEmpty());
    QVERIFY(
        ws.findChild<QLabel*>(QStringLiteral("head.referenceText"))->text().contains(description));

    // Assign: the teeth to the jaw through the table's combo box, then back with undo.
    const int teeth = rowNamed(mesh, "M_Teeth");
    const QModelIndex roleCell = ws.partsView()->model()->index(teeth, head::PartsTableModel::Role);
    ws.partsView()->edit(roleCell);
    auto* combo = ws.partsView()->findChild<QComboBox*>();
    QVERIFY(combo);
    combo->setCurrentIndex(combo->findData(static_cast<int>(editing::PartRole::TeethLower)));
    emit combo->activated(combo->currentIndex());
    QCOMPARE(setup.role(teeth), editing::PartRole::TeethLower);
    QCOMPARE(roleCell.data().toString(),
             head::PartsTableModel::roleLabel(int(editing::PartRole::TeethLower)));
    // The viewport draws the head with the role it now has (an untextured part's look follows it).
    QCOMPARE(view->head()->submeshes.at(static_cast<std::size_t>(teeth)).role, std::string("jaw"));
    ws.findChild<QAction*>(QStringLiteral("head.undo"))->trigger();
    QCOMPARE(setup.role(teeth), editing::PartRole::TeethUpper);
    QCOMPARE(view->head()->submeshes.at(static_cast<std::size_t>(teeth)).role,
             std::string("rigid"));

    // Click the anchors where the hand-made file has them; the workspace steps to the next one.
    const rigging::FeaturePointFile hand = rigging::readFeaturePointFile(kIctFdp.toStdString());
    QTRY_VERIFY(view->project(Eigen::Vector3d::Zero()).has_value());
    const double es0 = (rigging::surfacePosition(hand.points.at("3.5").at, mesh) -
                        rigging::surfacePosition(hand.points.at("3.6").at, mesh))
                           .norm();
    double worst = 0;
    for (const std::string& id : head::PointListModel::anchorOrder()) {
      QCOMPARE(ws.currentPoint(), id);
      const Eigen::Vector3d target = rigging::surfacePosition(hand.points.at(id).at, mesh);
      const QPoint pixel = view->project(target)->toPoint();
      QTest::mouseClick(view, Qt::LeftButton, {}, pixel);
      const editing::PlacedPoint* placed = setup.point(id);
      QVERIFY2(placed && placed->byHand(), id.c_str());
      // It lands at the anchor, on the part the hand-made file has it on (the skin), not on
      // the eyeball, lashes or tear films in front of the eye corners.
      QVERIFY2(placed->spec.at.submesh == hand.points.at(id).at.submesh,
               qPrintable(QStringLiteral("%1 on %2")
                              .arg(QString::fromStdString(id),
                                   QString::fromStdString(placed->spec.at.submesh))));
      // Where the skin was under the mouse, it lands under the mouse (the mouth corner's vertex
      // sits in a fold, so the skin in front of it is hit); where the eyeball was in front of
      // the eye corner, it lands on the closest skin point.
      const auto hit = view->pick(pixel);
      QVERIFY(hit);
      if (mesh.submeshes[static_cast<std::size_t>(hit->submesh)].name == placed->spec.at.submesh) {
        const double pixels = QLineF(*view->project(*setup.position(id)), pixel).length();
        QVERIFY2(
            pixels < 1.5,
            qPrintable(
                QStringLiteral("%1 landed %2 px off").arg(QString::fromStdString(id)).arg(pixels)));
      } else {
        const double off = (*setup.position(id) - target).norm() / es0;
        QVERIFY2(
            off < 0.1,
            qPrintable(
                QStringLiteral("%1 snapped %2 ES0 off").arg(QString::fromStdString(id)).arg(off)));
      }
      worst = std::max(worst, (*setup.position(id) - target).norm() / es0);
    }
    qInfo("anchors clicked at their projected vertices: worst %.3f ES0 from the vertex", worst);

    // Propose from the toolbar; the rig follows on its own.
    QSignalSpy proposed(&ws, &head::HeadWorkspace::proposalFinished);
    QSignalSpy rigged(&ws, &head::HeadWorkspace::rigFinished);
    meter.start();
    ws.findChild<QToolButton*>(QStringLiteral("head.propose"))->click();
    QVERIFY(proposed.wait(30000));
    QVERIFY2(proposed.front().front().toBool(), qPrintable(ws.lastError()));
    QVERIFY(setup.points().size() >= hand.points.size());
    QVERIFY2(rigged.wait(30000), qPrintable(ws.statusText()));
    meter.stop();
    const double riggedMs = wall.nsecsElapsed() / 1e6;
    QVERIFY(ws.rig());
    qInfo("Head workspace shown (viewport started) in %.0f ms", startMs);
    qInfo(
        "ICT head: imported in %.0f ms (longest event-loop stall %.1f ms); import -> anchors "
        "clicked -> proposed -> rigged in %.0f ms; longest stall while importing, proposing "
        "and rigging %.1f ms",
        importMs, importStall, riggedMs, meter.longestMilliseconds());
    // The checks ran on the rig: the list shows each with the points it names, then the rig's
    // and the proposal's warnings (or that nothing was found); a click selects a line's point.
    QVERIFY(ws.checksView()->count() >= std::max<int>(1, int(ws.checks().size())));
    for (std::size_t i = 0; i < ws.checks().size(); ++i) {
      const rigging::RigCheck& check = ws.checks()[i];
      qInfo("check: %s", rigging::toString(check).c_str());
      const QString line = ws.checksView()->item(static_cast<int>(i))->text();
      for (const std::string& id : check.points)
        QVERIFY2(line.contains(QString::fromStdString(id)), qPrintable(line));
    }
    const std::string current = ws.currentPoint();
    for (int row = 0; row < ws.checksView()->count(); ++row) {
      QListWidgetItem* item = ws.checksView()->item(row);
      const QStringList ids = item->data(Qt::UserRole).toStringList();
      if (ids.isEmpty()) continue;
      ws.checksView()->scrollToItem(item);
      QTest::mouseClick(ws.checksView()->viewport(), Qt::LeftButton, {},
                        ws.checksView()->visualItemRect(item).center());
      QCOMPARE(QString::fromStdString(ws.currentPoint()), ids.front());
      break;
    }
    ws.setCurrentPoint(current);

    // A slider poses the rigged head at once.
    const QImage neutral = view->grabFrame();
    window.model().setChannel(3, 900);  // open_jaw
    const QImage open = view->grabFrame();
    QVERIFY2(changedFraction(neutral, open) > 0.002, "the jaw did not move in the Head viewport");
    window.model().setChannel(3, 0);

    // Drag a proposed point: press on its marker, move, release; it becomes a hand point.
    const std::string dragged = "8.1";
    QVERIFY(!setup.point(dragged)->byHand());
    const Eigen::Vector3d before = *setup.position(dragged);
    const QPoint from = view->project(before)->toPoint();
    const QPoint to = from + QPoint(0, -12);
    QTest::mousePress(view, Qt::LeftButton, {}, from);
    QTest::mouseMove(view, from + QPoint(0, -6));
    QTest::mouseMove(view, to);
    QTest::mouseRelease(view, Qt::LeftButton, {}, to);
    QVERIFY(setup.point(dragged)->byHand());
    const Eigen::Vector3d after = *setup.position(dragged);
    QVERIFY((after - before).norm() > 0.01 * es0);
    QCOMPARE(ws.currentPoint(), dragged);
    // Edit ▸ Undo (Ctrl+Z) undoes head edits while the workspace is shown; the workspace's own
    // Redo button redoes them.
    window.action(QStringLiteral("edit.undo"))->trigger();
    QVERIFY(!setup.point(dragged)->byHand());
    QVERIFY((*setup.position(dragged) - before).norm() < 1e-9);
    ws.findChild<QAction*>(QStringLiteral("head.redo"))->trigger();
    QVERIFY((*setup.position(dragged) - after).norm() < 1e-9);

    // Save; the file rigs on its own.
    const QString saved = dir_.filePath(QStringLiteral("ict.fdp.json"));
    QVERIFY2(ws.saveTo(saved), qPrintable(ws.lastError()));
    const rigging::FeaturePointFile file = rigging::readFeaturePointFile(saved.toStdString());
    const auto rig = playback::rigHead(HeadMesh(mesh), file);
    QVERIFY(rig->rig.fapu.es0 > 0);
    QVERIFY(file.points.at(dragged).placedByHand);

    // Use in project: the project names the head; the Animate workspace comes back.
    ws.findChild<QToolButton*>(QStringLiteral("head.use"))->click();
    QVERIFY(window.model().document().head.has_value());
    QCOMPARE(QString::fromStdString(window.model().document().head->fdp), saved);
    QCOMPARE(window.workspace(), MainWindow::Workspace::Animate);
    window.setWorkspace(MainWindow::Workspace::Head);

    // Bad input: the workspace keeps its head and points, and says what went wrong.
    const std::size_t points = setup.points().size();
    const QString missing = dir_.filePath(QStringLiteral("no-such-head.obj"));
    QVERIFY(!importInto(ws, missing));
    QVERIFY2(ws.lastError().contains(missing), qPrintable(ws.lastError()));
    QCOMPARE(setup.meshPath(), kIctMesh);
    QCOMPARE(setup.points().size(), points);
    const QString noFaces = dir_.filePath(QStringLiteral("points-only.obj"));
    saveAtomically(noFaces.toStdString(), "v 0 0 0\nv 1 0 0\nv 0 1 0\n");
    QVERIFY(!importInto(ws, noFaces));
    QVERIFY2(ws.lastError().contains(noFaces), qPrintable(ws.lastError()));
    QCOMPARE(setup.meshPath(), kIctMesh);
    QCOMPARE(setup.points().size(), points);
    QVERIFY(ws.rig());
    window.model().markSaved();
  }

  // Without ../shared or the default head: a small head written in the test imports, shows
  // its part, takes a clicked anchor where the mouse was (undoable), and a bad import after it
  // leaves it as it was.
  void aGeneratedHeadImportsAndTakesAClickedAnchor() {
    const testsupport::GeneratedHead generated = testsupport::generatedHead();
    const QString path = dir_.filePath(QStringLiteral("generated-head.obj"));
    QVERIFY(testsupport::writeObj(generated, path));
    MainWindow window(options());
    window.resize(1280, 860);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    window.setWorkspace(MainWindow::Workspace::Head);
    head::HeadWorkspace& ws = *window.headWorkspace();
    editing::HeadSetup& setup = ws.setup();
    viewport::FaceViewport* view = ws.viewport();
    if (!view->usesOgre()) QSKIP("no OGRE viewport (needs an X display)");
    QVERIFY2(importInto(ws, path), qPrintable(ws.lastError()));
    const HeadMesh& mesh = setup.mesh();
    QCOMPARE(setup.meshPath(), path);
    QCOMPARE(mesh.vertexCount(), static_cast<int>(generated.positions.size()));
    QCOMPARE(mesh.triangleCount(), static_cast<int>(generated.triangles.size()));
    QCOMPARE(ws.partsView()->model()->rowCount(), 1);

    // The first anchor, clicked on the front of the head (its vertex furthest forward).
    const std::vector<std::string>& anchors = head::PointListModel::anchorOrder();
    QCOMPARE(ws.currentPoint(), anchors.front());
    Eigen::Index front = 0;
    mesh.positions.row(2).maxCoeff(&front);
    const Eigen::Vector3d target = mesh.positions.col(front).cast<double>();
    QTRY_VERIFY(view->project(target).has_value());
    QTest::mouseClick(view, Qt::LeftButton, {}, view->project(target)->toPoint());
    const editing::PlacedPoint* placed = setup.point(anchors.front());
    QVERIFY(placed && placed->byHand());
    const double off = (*setup.position(anchors.front()) - target).norm();
    QVERIFY2(off < 0.05 * generated.radii.z(), qPrintable(QString("%1 mm off").arg(off)));
    QCOMPARE(ws.currentPoint(), anchors[1]);
    ws.findChild<QAction*>(QStringLiteral("head.undo"))->trigger();
    QVERIFY(!setup.point(anchors.front()));

    const QString missing = dir_.filePath(QStringLiteral("no-such-head.obj"));
    QVERIFY(!importInto(ws, missing));
    QVERIFY2(ws.lastError().contains(missing), qPrintable(ws.lastError()));
    QCOMPARE(setup.meshPath(), path);
    QCOMPARE(setup.mesh().vertexCount(), static_cast<int>(generated.positions.size()));
    window.model().markSaved();
  }

  // A head exported Z-up (x, y, z) -> (x, -z, y): once the eye corners and the chin are placed,
  // the view turns to the face's frame (the face's up is the mesh's +z), before any rig.
  void zUpHeadStandsUpOnceTheAnchorsArePlaced() {
    LACRIMA_REQUIRE_SHARED(kIctMesh);
    MainWindow window(options());
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    window.setWorkspace(MainWindow::Workspace::Head);
    head::HeadWorkspace& ws = *window.headWorkspace();
    ws.setRigDelay(60000);  // not rigged: the anchors alone turn the view
    HeadMesh mesh = editing::HeadSetup::importMesh(kIctMesh);
    for (Eigen::Index i = 0; i < mesh.positions.cols(); ++i) {
      const Eigen::Vector3f p = mesh.positions.col(i);
      mesh.positions.col(i) = Eigen::Vector3f(p.x(), -p.z(), p.y());
    }
    mesh.computeNormals();
    ws.setup().setMesh(QStringLiteral("ict-z-up.obj"), std::move(mesh));
    QVERIFY(ws.viewport()->viewFrame().isIdentity());
    const rigging::FeaturePointFile hand = rigging::readFeaturePointFile(kIctFdp.toStdString());
    for (const std::string& id : rigging::proposalAnchors()) {
      const auto& at = hand.points.at(id).at;
      const HeadMesh& m = ws.setup().mesh();
      const HeadSubmesh& part = m.submeshes[static_cast<std::size_t>(rowNamed(m, at.submesh))];
      for (std::size_t t = 0; t < part.triangles.size(); ++t)
        for (int c = 0; c < 3; ++c)
          if (part.triangles[t][c] == part.firstVertex + at.vertex) {
            editing::SurfaceSpot spot{rowNamed(m, at.submesh), int(t), Eigen::Vector3d::Zero()};
            spot.barycentric[c] = 1;
            ws.setup().placePoint(id, spot);
            t = part.triangles.size();
            break;
          }
    }
    QVERIFY(!ws.rig());
    // Columns: the face's left, up and forward in mesh axes: +x, +z, -y.
    Eigen::Matrix3d expected;
    expected << 1, 0, 0, 0, 0, -1, 0, 1, 0;
    QVERIFY(ws.viewport()->viewFrame().isApprox(expected));
    window.model().markSaved();
  }

  // lacrima-editor --head MESH --points PARTIAL --propose --screenshot: the window comes up on
  // the Head workspace with the head imported, proposed and rigged; wrong usage and a missing
  // mesh are refused with their exit codes.
  void commandLineOpensTheHeadWorkspace() {
    LACRIMA_REQUIRE_SHARED(kIctMesh);
    if (!rigging::defaultHeadAvailable()) LACRIMA_SKIP_WITHOUT_DEFAULT_HEAD();
    // The 8 anchors of the hand-made file, as a user's partial file.
    QFile hand(kIctFdp);
    QVERIFY(hand.open(QIODevice::ReadOnly));
    QJsonObject fdp = QJsonDocument::fromJson(hand.readAll()).object();
    QJsonObject points = fdp.value("points").toObject(), anchors;
    for (const std::string& id : rigging::proposalAnchors()) {
      const QString key = QString::fromStdString(id);
      QVERIFY(points.contains(key));
      anchors.insert(key, points.value(key));
    }
    fdp.insert("points", anchors);
    fdp.remove("tear_sources");
    const QString partial = dir_.filePath(QStringLiteral("cli-anchors.fdp.json"));
    saveAtomically(partial.toStdString(), QJsonDocument(fdp).toJson().toStdString());

    const QString editor = QStringLiteral(LACRIMA_BIN_DIR "/lacrima-editor");
    const QString shot = dir_.filePath(QStringLiteral("cli-head.png"));
    auto run = [&](const QStringList& arguments) {
      QProcess process;
      process.start(editor, arguments);
      if (!process.waitForFinished(120000)) process.kill();
      return std::pair{process.exitCode(), QString::fromUtf8(process.readAllStandardError())};
    };
    const auto [code, err] = run({"--head", kIctMesh, "--points", partial, "--propose",
                                  "--screenshot", shot, "--size", "1440x900"});
    QVERIFY2(code == 0, qPrintable(err));
    const QImage image(shot);
    QCOMPARE(image.size(), QSize(1440, 900));  // the editor's default size fits the workspace
    // The head is drawn (light skin in the workspace's view), which grab() alone would leave
    // black: more than 3% of the window is light grey.
    int light = 0;
    for (int y = 0; y < image.height(); y += 2)
      for (int x = 0; x < image.width(); x += 2)
        light += qGray(image.pixel(x, y)) > 170 && QColor(image.pixel(x, y)).saturation() < 40;
    QVERIFY2(light * 4 > image.width() * image.height() * 3 / 100,
             qPrintable(QString("light pixels: %1").arg(light * 4)));

    const auto [usage, usageErr] = run({"--points", partial, "--screenshot", shot});
    QCOMPARE(usage, 2);
    QVERIFY2(usageErr.contains("--head"), qPrintable(usageErr));
    const QString missing = dir_.filePath(QStringLiteral("no-such-head.obj"));
    const auto [failed, failedErr] = run({"--head", missing, "--screenshot", shot});
    QCOMPARE(failed, 1);
    QVERIFY2(failedErr.contains("no-such-head.obj"), qPrintable(failedErr));
  }
};

QTEST_MAIN(HeadWorkspaceTest)
#include "HeadWorkspaceTest.moc"
