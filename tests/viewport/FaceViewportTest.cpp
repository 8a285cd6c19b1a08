// The viewport widget on a real (virtual) X display, the default head in it (skipped when it is
// not fetched): it renders once when shown, never again for the same frame or a bare update(),
// a drag orbits, the wheel zooms, a double-click frames the face again.
#include "../scene/ImageCompare.h"
#include "../support/MissingData.h"

#include <lacrima/rigging/DefaultHead.h>
#include <lacrima/scene/FaceRenderer.h>
#include <lacrima/scene/OgreRuntime.h>
#include <lacrima/viewport/FaceViewport.h>

#include <QtTest>

#include <memory>

using namespace lacrima;
using namespace lacrima::scenetest;

class FaceViewportTest : public QObject {
  Q_OBJECT

  std::unique_ptr<HeadMesh> head_;
  std::unique_ptr<viewport::FaceViewport> viewport_;

  playback::FrameView frame(long long revision) const {
    playback::FrameView v;
    v.neutral = head_.get();
    v.revision = revision;
    return v;
  }
  // Lets deferred render requests and window-system events run.
  static void settle() {
    for (int i = 0; i < 5; ++i) {
      QCoreApplication::processEvents();
      QTest::qWait(40);
    }
  }
  void send(QEvent::Type type, QPoint at, Qt::MouseButton button, Qt::MouseButtons buttons) {
    QMouseEvent event(type, QPointF(at), QPointF(viewport_->mapToGlobal(at)), button, buttons,
                      Qt::NoModifier);
    QCoreApplication::sendEvent(viewport_.get(), &event);
  }

 private slots:
  void initTestCase() {
    if (!rigging::defaultHeadAvailable()) LACRIMA_SKIP_WITHOUT_DEFAULT_HEAD();
    if (QGuiApplication::platformName() != QLatin1String("xcb"))
      QSKIP("needs the xcb platform (run under xvfb-run)");
    head_ = std::make_unique<HeadMesh>(rigging::loadDefaultHead());
  }

  void rendersOnceWhenShown() {
    viewport_ = std::make_unique<viewport::FaceViewport>();
    QVERIFY(viewport_->usesOgre());
    viewport_->resize(480, 360);
    viewport_->setHead(*head_);
    viewport_->showFrame(frame(1));
    viewport_->show();
    QVERIFY(QTest::qWaitForWindowExposed(viewport_.get()));
    QTRY_VERIFY(viewport_->renderCount() >= 1);
    settle();
    QVERIFY(scene::OgreRuntime::running());
    QVERIFY(viewport_->lastRenderMilliseconds() > 0);
  }

  void aStaticSceneIsNotRenderedAgain() {
    settle();
    const long long before = viewport_->renderCount();
    QSignalSpy rendered(viewport_.get(), &viewport::FaceViewport::rendered);
    for (int i = 0; i < 3; ++i) {
      viewport_->showFrame(frame(1));  // same revision
      viewport_->update();             // a paint request without an expose
      settle();
    }
    QCOMPARE(viewport_->renderCount(), before);
    QCOMPARE(rendered.count(), 0);
    // A new revision renders exactly once, however often it is shown.
    viewport_->showFrame(frame(2));
    viewport_->showFrame(frame(2));
    settle();
    QCOMPARE(viewport_->renderCount(), before + 1);
    QCOMPARE(rendered.count(), 1);
  }

  void dragOrbitsAndDoubleClickResets() {
    const QImage first = viewport_->grabFrame();
    QCOMPARE(first.size(), QSize(480, 360));
    // The face is there: the middle is much brighter than the backdrop in a corner.
    QVERIFY(meanColour(first, QPointF(240, 150), 4).luminance() >
            meanColour(first, QPointF(4, 4), 3).luminance() + 50);

    const long long before = viewport_->renderCount();
    send(QEvent::MouseButtonPress, QPoint(240, 180), Qt::LeftButton, Qt::LeftButton);
    send(QEvent::MouseMove, QPoint(300, 170), Qt::NoButton, Qt::LeftButton);
    send(QEvent::MouseMove, QPoint(340, 160), Qt::NoButton, Qt::LeftButton);
    send(QEvent::MouseButtonRelease, QPoint(340, 160), Qt::LeftButton, Qt::NoButton);
    QTRY_VERIFY(viewport_->renderCount() > before);
    settle();
    QVERIFY2(viewport_->renderCount() <= before + 2,
             "a drag of two moves rendered more than twice");
    const QImage turned = viewport_->grabFrame();
    QVERIFY2(differingPixels(first, turned, 10).size() > 2000,
             "orbiting did not change the picture");

    send(QEvent::MouseButtonDblClick, QPoint(240, 180), Qt::LeftButton, Qt::LeftButton);
    settle();
    const QImage reset = viewport_->grabFrame();
    QCOMPARE(differingPixels(first, reset, 0).size(), std::size_t{0});
  }

  void panAndZoomChangeThePicture() {
    const QImage first = viewport_->grabFrame();
    send(QEvent::MouseButtonPress, QPoint(240, 180), Qt::RightButton, Qt::RightButton);
    send(QEvent::MouseMove, QPoint(280, 180), Qt::NoButton, Qt::RightButton);
    send(QEvent::MouseButtonRelease, QPoint(280, 180), Qt::RightButton, Qt::NoButton);
    settle();
    QVERIFY(differingPixels(first, viewport_->grabFrame(), 10).size() > 2000);
    viewport_->resetView();
    settle();
    QWheelEvent wheel(QPointF(240, 180), QPointF(viewport_->mapToGlobal(QPoint(240, 180))),
                      QPoint(), QPoint(0, 240), Qt::NoButton, Qt::NoModifier, Qt::NoScrollPhase,
                      false);
    QCoreApplication::sendEvent(viewport_.get(), &wheel);
    settle();
    const QImage closer = viewport_->grabFrame();
    QVERIFY(differingPixels(first, closer, 10).size() > 2000);
    // Closer: the face fills more of the picture (a corner is no longer backdrop at the top... )
    // measured as more bright pixels.
    auto bright = [](const QImage& image) {
      int n = 0;
      for (int y = 0; y < image.height(); y += 4)
        for (int x = 0; x < image.width(); x += 4)
          n += meanColour(image, QPointF(x, y), 0).luminance() > 120;
      return n;
    };
    QVERIFY(bright(closer) > bright(first));
    viewport_->resetView();
    settle();
  }

  void resizingRendersAtTheNewSize() {
    const long long before = viewport_->renderCount();
    viewport_->resize(320, 240);
    QTRY_VERIFY(viewport_->renderCount() > before);
    QCOMPARE(viewport_->grabFrame().size(), QSize(320, 240));
  }

  // Resizes reach OGRE at once, whatever happens between them (a collapsed layout gives the
  // widget no height for a moment): a render right after a resize, with no event processed in
  // between, is at the new size and frames the head as a viewport made at that size does. A
  // stale size made the head fill the view (behind a file dialog).
  void resizesReachTheRenderAtOnce() {
    const QSize sizes[] = {{400, 300}, {400, 0}, {300, 420}, {200, 150}, {360, 270}};
    for (const QSize& size : sizes) {
      viewport_->resize(size);
      // No area is clamped by the widget's minimum size (64 x 48).
      QCOMPARE(viewport_->grabFrame().size(), size.expandedTo(viewport_->minimumSize()));
    }
    settle();
    const QImage resized = viewport_->grabFrame();
    viewport::FaceViewport fresh;
    fresh.resize(360, 270);
    fresh.setHead(*head_);
    fresh.showFrame(frame(1));
    fresh.show();
    QVERIFY(QTest::qWaitForWindowExposed(&fresh));
    settle();
    const QImage reference = fresh.grabFrame();
    QCOMPARE(reference.size(), resized.size());
    QVERIFY2(differingPixels(reference, resized, 12).size() < std::size_t(360 * 270 / 100),
             "after the resizes the head is not framed as in a viewport of that size");
  }

  void sharesOgreWithAnOffscreenRenderer() {
    // The player renders batches off screen while its window shows the viewport: one OGRE, two
    // GL contexts sharing buffers and textures.
    const QImage before = viewport_->grabFrame();
    {
      scene::FaceRenderer renderer(*head_, QSize(320, 240));
      playback::FrameView view = frame(7);
      renderer.show(view);
      const QImage offscreen = renderer.render();
      QVERIFY(meanColour(offscreen, QPointF(160, 100), 3).luminance() >
              meanColour(offscreen, QPointF(3, 3), 2).luminance() + 50);
      const QImage during = viewport_->grabFrame();
      QCOMPARE(differingPixels(before, during, 0).size(), std::size_t{0});
    }
    QVERIFY(scene::OgreRuntime::running());  // the viewport still holds it
    QCOMPARE(differingPixels(before, viewport_->grabFrame(), 0).size(), std::size_t{0});
  }

  void cleanupTestCase() {
    viewport_.reset();
    QVERIFY(!scene::OgreRuntime::running());
  }
};

QTEST_MAIN(FaceViewportTest)
#include "FaceViewportTest.moc"
