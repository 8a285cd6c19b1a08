// The live preview in the editor window: the shared viewport on the default head, posed by
// the sliders, with tears simulated while paused (tear preview) and while playing. Runs under
// xvfb-run (OGRE needs X); skips when the default head is not fetched.
#include "../support/ChangedPixels.h"

#include <lacrima/common/FapTable.h>
#include <lacrima/editing/EditorModel.h>
#include <lacrima/editing/FrameStepClock.h>
#include <lacrima/editor/MainWindow.h>
#include <lacrima/editor/PreviewPanel.h>
#include <lacrima/rigging/DefaultHead.h>

#include <QImage>
#include <QTemporaryDir>
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
    if (!rigging::defaultHeadAvailable()) QSKIP("the default head is not fetched");
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
    if (!rigging::defaultHeadAvailable()) QSKIP("the default head is not fetched");
    MainWindow window(options());
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QVERIFY(window.preview()->loadHead());
    window.model().setChannels({{kTearLeftFap, 40}, {kTearRightFap, 30}}, QStringLiteral("tears"));
    QVERIFY(window.preview()->tearPreview());
    QTRY_VERIFY(window.preview()->particleCount() > 0);  // the idle timer simulates
    // Off: the tears stop advancing (the count stays what it was).
    window.preview()->setTearPreview(false);
    const int frozen = window.preview()->particleCount();
    QTest::qWait(200);
    QCOMPARE(window.preview()->particleCount(), frozen);
    // Playing steps them once per playback frame.
    window.model().setCurrentTime(2.0);
    window.model().setChannels({{kTearLeftFap, 80}, {kTearRightFap, 80}},
                               QStringLiteral("more tears"));
    window.model().setCurrentTime(0.0);
    window.clock().play();
    QTRY_VERIFY(window.model().currentTime() > 0.5);
    window.clock().pause();
    QVERIFY(window.preview()->particleCount() > frozen);
    window.model().markSaved();
  }
};

QTEST_MAIN(EditorPreviewTest)
#include "EditorPreviewTest.moc"
