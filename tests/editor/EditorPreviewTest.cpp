// The live preview in the editor window: the shared viewport on the default head, posed by
// the sliders, with tears simulated while paused (tear preview) and while playing. Runs under
// xvfb-run (OGRE needs X); skips when the default head is not fetched.
#include "../support/ChangedPixels.h"
#include "../support/MissingData.h"
#include "IctProject.h"

#include <lacrima/common/FapTable.h>
#include <lacrima/editing/EditorModel.h>
#include <lacrima/editing/FrameStepClock.h>
#include <lacrima/editor/MainWindow.h>
#include <lacrima/editor/PreviewPanel.h>
#include <lacrima/rigging/DefaultHead.h>
#include <lacrima/viewport/EffectsPanel.h>

#include <algorithm>

#include <QAction>
#include <QApplication>
#include <QDialog>
#include <QFileDialog>
#include <QImage>
#include <QLabel>
#include <QScreen>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTimer>
#include <QToolButton>
#include <QUndoStack>
#include <QtTest>

using namespace lacrima;
using namespace lacrima::editor;

using lacrima::testsupport::changedFraction;

class EditorPreviewTest : public QObject {
  Q_OBJECT

 private:
  QTemporaryDir recovery_;

  EditorOptions options() const {
    EditorOptions o;
    o.interactive = false;
    o.offerRecovery = false;
    o.recoveryDirectory = recovery_.path();
    return o;
  }

 private slots:
  void initTestCase() { QStandardPaths::setTestModeEnabled(true); }

  void slidersPoseTheFace() {
    if (!rigging::defaultHeadAvailable()) LACRIMA_SKIP_WITHOUT_DEFAULT_HEAD();
    MainWindow window(options());
    window.resize(1280, 800);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QVERIFY2(window.preview()->loadHead(), qPrintable(window.preview()->statusText()));
    QVERIFY(window.preview()->viewportWidget());
    const QImage neutral = window.preview()->grabFrame();
    QVERIFY(!neutral.isNull());
    window.model().setChannel(3, 900);  // open_jaw: the paused face follows the slider
    const QImage open = window.preview()->grabFrame();
    QVERIFY2(changedFraction(neutral, open) > 0.002, "the jaw did not move in the preview");
    QCOMPARE(window.preview()->particleCount(), 0);  // no tear channel: nothing simulated
    window.model().markSaved();
  }

  void tearPreviewRunsWhilePausedAndPlaybackStepsTears() {
    if (!rigging::defaultHeadAvailable()) LACRIMA_SKIP_WITHOUT_DEFAULT_HEAD();
    MainWindow window(options());
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QVERIFY(window.preview()->loadHead());
    window.model().setChannels({{kTearLeftFap, 40}, {kTearRightFap, 30}}, QStringLiteral("tears"));
    QVERIFY(window.preview()->tearPreview());
    QTRY_VERIFY(window.preview()->particleCount() > 0);  // the idle timer simulates
    // Live tears while paused are not the animation's: the bar says so, and not once off.
    QVERIFY(window.preview()->showsLiveTears());
    window.preview()->setTearPreview(false);
    QVERIFY(!window.preview()->showsLiveTears());
    window.preview()->waitForTears();  // a step may still be running on the worker
    const int frozen = window.preview()->particleCount();
    QTest::qWait(200);
    QCOMPARE(window.preview()->particleCount(), frozen);
    // Playing steps them once per playback frame.
    window.model().setCurrentTime(2.0);
    window.model().setChannels({{kTearLeftFap, 80}, {kTearRightFap, 80}},
                               QStringLiteral("more tears"));
    window.model().setCurrentTime(0.0);
    window.clock().play();
    QVERIFY(!window.preview()->showsLiveTears());  // playing shows the animation's
    QTRY_VERIFY(window.model().currentTime() > 0.5);
    window.clock().pause();
    QVERIFY(window.preview()->particleCount() > frozen);
    window.model().markSaved();
  }

  // The tear quality is a project setting: one undo step, and the preview's tears restart
  // with it (the settings dialog's Scene panel shows the preview's tearsStepped() cost).
  void qualityIsAnUndoableSetting() {
    if (!rigging::defaultHeadAvailable()) LACRIMA_SKIP_WITHOUT_DEFAULT_HEAD();
    MainWindow window(options());
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QVERIFY(window.preview()->loadHead());
    QSignalSpy stepped(window.preview(), &PreviewPanel::tearsStepped);
    window.model().setChannels({{kTearLeftFap, 20}, {kTearRightFap, 20}}, QStringLiteral("tears"));
    QTRY_VERIFY(window.preview()->particleCount() > 0);
    QTRY_VERIFY(!stepped.isEmpty());
    QVERIFY(stepped.last().at(1).toLongLong() > 0);  // sub-steps of a real step

    const int undoSteps = window.model().undoStack()->count();
    ProjectDocument settings = window.model().document();
    settings.scene.quality.level = TearQuality::Reference;
    settings.scene.quality.tension = "akinci";
    window.model().setSettings(settings, QStringLiteral("Project settings"));
    QCOMPARE(window.model().undoStack()->count(), undoSteps + 1);
    QVERIFY(window.model().document().scene.quality == settings.scene.quality);
    window.preview()->waitForTears();
    stepped.clear();
    QTRY_VERIFY(!stepped.isEmpty());  // the preview goes on at the new quality
    QVERIFY(window.preview()->particleCount() > 0);

    window.model().undoStack()->undo();
    QVERIFY(window.model().document().scene.quality == TearQualitySettings{});
    window.model().undoStack()->redo();
    QVERIFY(window.model().document().scene.quality == settings.scene.quality);
    window.model().markSaved();
  }

  // Project settings show the preview's live cost beside the tear quality: the Effects panel's
  // label is the mean of what the preview measured (tearsStepped) since the dialog opened, and
  // it follows new measurements while the dialog is open; not a fixed text.
  void settingsDialogShowsThePreviewsLiveCost() {
    if (!rigging::defaultHeadAvailable()) LACRIMA_SKIP_WITHOUT_DEFAULT_HEAD();
    EditorOptions o = options();
    o.interactive = true;  // the settings dialog opens only then
    MainWindow window(o);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QVERIFY(window.preview()->loadHead());
    QSignalSpy stepped(window.preview(), &PreviewPanel::tearsStepped);
    window.model().setChannels({{kTearLeftFap, 30}, {kTearRightFap, 30}}, QStringLiteral("tears"));
    QTRY_VERIFY(!stepped.isEmpty());
    auto* settings = window.findChild<QAction*>(QStringLiteral("edit.settings"));
    QVERIFY(settings);

    // The text the panel must show for the preview's frames since `from` (its last
    // kCostFrames), formatted as EffectsPanel::showCost does.
    const auto expected = [&stepped](qsizetype from) {
      from = std::max(from, stepped.count() - qsizetype(viewport::EffectsPanel::kCostFrames));
      double milliseconds = 0, substeps = 0;
      for (qsizetype i = from; i < stepped.count(); ++i) {
        milliseconds += stepped.at(i).at(0).toDouble();
        substeps += double(stepped.at(i).at(1).toLongLong());
      }
      const double n = double(stepped.count() - from);
      return QStringLiteral("%1 ms per frame, %2 sub-steps")
          .arg(milliseconds / n, 0, 'f', 1)
          .arg(substeps / n, 0, 'f', 0);
    };
    // Nothing runs the event loop between the trigger and the panel's connection, so the
    // panel sees exactly the frames the spy records from here on.
    const qsizetype opened = stepped.count();
    QStringList shown;
    bool seen = false;
    QTimer::singleShot(0, [&] {
      auto* dialog = qobject_cast<QDialog*>(QApplication::activeModalWidget());
      QVERIFY(dialog);
      struct Closer {
        QDialog* dialog;
        ~Closer() { dialog->reject(); }  // also when a check below fails
      } closer{dialog};
      auto* panel = dialog->findChild<viewport::EffectsPanel*>();
      QVERIFY(panel);
      for (qsizetype frames : {opened + 2, opened + 5}) {
        QTRY_VERIFY_WITH_TIMEOUT(stepped.count() >= frames, 30000);
        QVERIFY(stepped.last().at(0).toDouble() > 0);  // a measured time
        QCOMPARE(panel->cost()->text(), expected(opened));
        shown << panel->cost()->text();
      }
      seen = true;
    });
    settings->trigger();
    QVERIFY2(seen, "the settings dialog did not open, or its checks failed");
    QCOMPARE(shown.size(), 2);
    qInfo() << "the dialog showed" << shown;
    window.model().markSaved();
  }

  // Tears set to 0 leave the view and the status line at once, not after a simulation step;
  // and a step never runs on the UI thread: step() returns before the tears exist.
  void tearsToZeroClearAtOnce() {
    if (!rigging::defaultHeadAvailable()) LACRIMA_SKIP_WITHOUT_DEFAULT_HEAD();
    MainWindow window(options());
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    PreviewPanel& preview = *window.preview();
    QVERIFY(preview.loadHead());
    preview.setTearPreview(false);  // this test steps the tears itself
    const QImage dry = preview.grabFrame();
    window.model().setChannels({{kTearLeftFap, 1000}, {kTearRightFap, 1000}},
                               QStringLiteral("tears"));
    preview.step(window.model().frameDuration());
    QCOMPARE(preview.particleCount(), 0);  // 2,000 particles: the step is on the worker
    preview.waitForTears();
    QCOMPARE(preview.particleCount(), 2000);
    QVERIFY(preview.statusText().startsWith(QStringLiteral("2000 particles")));
    for (int i = 0; i < 3; ++i) preview.step(window.model().frameDuration());
    const QImage wet = preview.grabFrame();
    QVERIFY2(changedFraction(dry, wet) > 0.001, "no tears drawn");

    preview.step(window.model().frameDuration());  // a step still running when...
    window.model().setChannels({{kTearLeftFap, 0}, {kTearRightFap, 0}}, QStringLiteral("dry"));
    QCOMPARE(preview.particleCount(), 0);  // ...the tears go to 0: gone before it ends
    QVERIFY(preview.statusText().startsWith(QStringLiteral("0 particles")));
    QCOMPARE(changedFraction(dry, preview.grabFrame()), 0.0);
    preview.waitForTears();  // the running step's result is thrown away
    QCOMPARE(preview.particleCount(), 0);
    QCOMPARE(changedFraction(dry, preview.grabFrame()), 0.0);
    window.model().markSaved();
  }

  // Another head while a tear step runs: the old head's worker is retired mid-step (the step
  // ends on its own thread), the new head previews at once, starts dry and weeps; closing the
  // window with a step in flight is clean.
  void headChangeWhileSteppingIsClean() {
    if (!rigging::defaultHeadAvailable()) LACRIMA_SKIP_WITHOUT_DEFAULT_HEAD();
    LACRIMA_REQUIRE_SHARED(rigtest::kIctMesh);
    QTemporaryDir folder;
    const QString project = rigtest::writeIctProject(folder.path(), "[]");
    QVERIFY(!project.isEmpty());
    MainWindow window(options());
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    PreviewPanel& preview = *window.preview();
    QVERIFY(preview.loadHead());
    const int defaultVertices = preview.headVertexCount();
    preview.setTearPreview(false);
    window.model().setChannels({{kTearLeftFap, 1000}, {kTearRightFap, 1000}},
                               QStringLiteral("tears"));
    preview.step(window.model().frameDuration());  // 2,000 particles: seconds on the worker
    window.model().markSaved();
    QVERIFY2(window.openFile(project), qPrintable(window.lastError()));
    QCOMPARE(preview.particleCount(), 0);  // the new document has no tears
    QVERIFY2(preview.loadHead(), qPrintable(preview.messageText()));
    QVERIFY(preview.headVertexCount() != defaultVertices);
    QCOMPARE(preview.particleCount(), 0);
    window.model().setChannels({{kTearLeftFap, 20}, {kTearRightFap, 20}}, QStringLiteral("tears"));
    preview.step(window.model().frameDuration());
    preview.waitForTears();
    QCOMPARE(preview.particleCount(), 40);
    window.model().setChannels({{kTearLeftFap, 1000}, {kTearRightFap, 1000}},
                               QStringLiteral("more"));
    preview.step(window.model().frameDuration());  // still running when the window goes
    window.model().markSaved();
  }

  // The Tear preview button is checkable and looks it: on and off differ at a glance.
  void tearPreviewButtonShowsItsState() {
    if (!rigging::defaultHeadAvailable()) LACRIMA_SKIP_WITHOUT_DEFAULT_HEAD();
    MainWindow window(options());
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    auto* toggle = window.preview()->findChild<QToolButton*>(QStringLiteral("tearPreviewToggle"));
    QVERIFY(toggle);
    QVERIFY(toggle->isCheckable());
    QVERIFY(toggle->isChecked());
    QVERIFY(window.preview()->tearPreview());
    const QImage on = toggle->grab().toImage();
    toggle->click();
    QVERIFY(!toggle->isChecked());
    QVERIFY(!window.preview()->tearPreview());
    const QImage off = toggle->grab().toImage();
    QVERIFY2(changedFraction(on, off) > 0.4, "the button looks the same on and off");
    window.preview()->setTearPreview(true);
    QVERIFY(toggle->isChecked());
    window.model().markSaved();
  }

  // Behind a modal file dialog the preview stays as it was: what the X server shows of the
  // viewport where the dialog does not cover it is the picture from before the dialog.
  void fileDialogLeavesThePreviewAsItWas() {
    if (!rigging::defaultHeadAvailable()) LACRIMA_SKIP_WITHOUT_DEFAULT_HEAD();
    MainWindow window(options());
    window.resize(1280, 800);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QVERIFY(window.preview()->loadHead());
    QWidget* viewport = window.preview()->viewportWidget();
    QVERIFY(viewport);
    QTest::qWait(300);
    QScreen* screen = QGuiApplication::primaryScreen();
    const QImage before = screen->grabWindow(viewport->winId()).toImage();
    QImage during;
    QRect covered;
    QTimer::singleShot(600, [&] {
      for (QWidget* w : QApplication::topLevelWidgets()) {
        auto* dialog = qobject_cast<QFileDialog*>(w);
        if (!dialog || !dialog->isVisible()) continue;
        covered = QRect(viewport->mapFromGlobal(dialog->frameGeometry().topLeft()),
                        dialog->frameGeometry().size());
        during = screen->grabWindow(viewport->winId()).toImage();
        dialog->reject();
      }
    });
    QFileDialog::getOpenFileName(&window, QStringLiteral("Open project"), QString(),
                                 QStringLiteral("Projects (*.json)"), nullptr,
                                 QFileDialog::DontUseNativeDialog);
    QVERIFY2(!during.isNull(), "the file dialog did not open");
    // The band above the dialog (the crown of the head sits there when framed).
    const int band = std::min(covered.top(), before.height());
    QVERIFY2(band >= 20, "the dialog covers the whole viewport: move it in the test");
    const QRect strip(0, 0, before.width(), band);
    QCOMPARE(changedFraction(before.copy(strip), during.copy(strip)), 0.0);
    window.model().markSaved();
  }
};

QTEST_MAIN(EditorPreviewTest)
#include "EditorPreviewTest.moc"
