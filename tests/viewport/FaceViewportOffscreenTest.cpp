// The viewport widget where there is no X display (the offscreen platform, as in the editor's
// headless tests): it must construct, show, take frames and be destroyed without ever starting
// OGRE, and say why there is no picture.
#include <lacrima/rigging/DefaultHead.h>
#include <lacrima/scene/OgreRuntime.h>
#include <lacrima/viewport/FaceViewport.h>

#include <QLabel>
#include <QtTest>

using namespace lacrima;

class FaceViewportOffscreenTest : public QObject {
  Q_OBJECT

 private slots:
  void initTestCase() {
    if (QGuiApplication::platformName() == QLatin1String("xcb"))
      QSKIP("checks the non-X11 fallback");
  }

  void neverTouchesOgre() {
    HeadMesh head;
    if (rigging::defaultHeadAvailable()) head = rigging::loadDefaultHead();
    {
      viewport::FaceViewport viewport;
      QVERIFY(!viewport.usesOgre());
      QCOMPARE(viewport.message(), QStringLiteral("3-D preview needs an X display"));
      viewport.resize(320, 240);
      viewport.setHead(head);
      playback::FrameView view;
      view.neutral = &head;
      view.revision = 1;
      viewport.showFrame(view);
      viewport.show();
      QVERIFY(QTest::qWaitForWindowExposed(&viewport));
      viewport.resetView();
      QTest::mouseDClick(&viewport, Qt::LeftButton);
      QTest::mousePress(&viewport, Qt::LeftButton, {}, QPoint(10, 10));
      QTest::mouseMove(&viewport, QPoint(60, 40));
      QTest::mouseRelease(&viewport, Qt::LeftButton, {}, QPoint(60, 40));
      // The Head workspace's calls: nothing to project or pick without a scene, no crash.
      viewport.setMarkers({viewport::Marker{}});
      viewport.setViewFrame(Eigen::Matrix3d::Identity());
      viewport.setPickableSubmeshes({true});
      QVERIFY(!viewport.project(Eigen::Vector3d::Zero()));
      QVERIFY(!viewport.rayAt(QPointF(100, 100)));
      QVERIFY(!viewport.pick(QPointF(100, 100)));
      viewport.update();
      QTest::qWait(50);
      QVERIFY(viewport.grabFrame().isNull());
      QCOMPARE(viewport.renderCount(), 0);
      QCOMPARE(viewport.lastRenderMilliseconds(), 0.0);
      QVERIFY(!scene::OgreRuntime::running());
      // The message is what the user sees, filling the widget.
      auto* label = viewport.findChild<QLabel*>();
      QVERIFY(label && label->isVisible());
      QCOMPARE(label->size(), viewport.size());
    }
    QVERIFY(!scene::OgreRuntime::running());
  }
};

QTEST_MAIN(FaceViewportOffscreenTest)
#include "FaceViewportOffscreenTest.moc"
