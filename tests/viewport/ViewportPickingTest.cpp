// What the Head workspace asks of the viewport, on a real (virtual) X display:
// project() and pick() agree on the default head from several orbit angles and on a deformed
// frame, a pixel off the head picks nothing; markers take their colour on screen and leave the
// picture as it was when cleared; a head in millimetres with +z up is framed whole, and its view
// frame puts its up on the screen's up. Skipped without the default head (the ICT head's case
// without /work/shared).
#include "../rigging/TestHeadFiles.h"
#include "../scene/ImageCompare.h"
#include "../support/MissingData.h"

#include <lacrima/common/Milliseconds.h>
#include <lacrima/rigging/DefaultHead.h>
#include <lacrima/rigging/MeshImport.h>
#include <lacrima/scene/FaceRenderer.h>
#include <lacrima/scene/FaceScene.h>
#include <lacrima/viewport/FaceViewport.h>

#include <QtTest>

#include <limits>
#include <map>
#include <memory>
#include <set>

using namespace lacrima;
using namespace lacrima::scenetest;

namespace {

// Every vertex of the triangles around `vertex`, by position (uv-seam copies are one point).
std::set<int> oneRing(const HeadMesh& head, const std::vector<int>& weld, int vertex) {
  std::set<int> ring{weld[vertex]};
  for (const HeadSubmesh& sub : head.submeshes)
    for (const Eigen::Vector3i& t : sub.triangles)
      if (weld[t[0]] == weld[vertex] || weld[t[1]] == weld[vertex] || weld[t[2]] == weld[vertex])
        for (int k = 0; k < 3; ++k) ring.insert(weld[t[k]]);
  return ring;
}

// Vertices on an edge of only one triangle (the eye and mouth holes, the neck cut): their
// triangles do not go all round them, so a ray through them may pass into the hole.
std::set<int> boundaryVertices(const HeadMesh& head, const std::vector<int>& weld) {
  std::map<std::pair<int, int>, int> edges;
  for (const HeadSubmesh& sub : head.submeshes)
    for (const Eigen::Vector3i& t : sub.triangles)
      for (int k = 0; k < 3; ++k) {
        const int a = weld[t[k]], b = weld[t[(k + 1) % 3]];
        ++edges[{std::min(a, b), std::max(a, b)}];
      }
  std::set<int> boundary;
  for (const auto& [edge, count] : edges)
    if (count == 1) boundary.insert({edge.first, edge.second});
  return boundary;
}

// Whether every triangle round `vertex` faces `eye`: a fan that folds over (a crease seen edge
// on, the silhouette) need not cover the vertex's own pixel, so a ray through it may pass by.
bool fanFaces(const HeadMesh& head, const Eigen::Matrix3Xf& shown, const std::vector<int>& weld,
              int vertex, const Eigen::Vector3d& eye) {
  const Eigen::Vector3d towardsEye = (eye - shown.col(vertex).cast<double>()).normalized();
  bool any = false;
  for (const HeadSubmesh& sub : head.submeshes)
    for (const Eigen::Vector3i& t : sub.triangles)
      if (weld[t[0]] == weld[vertex] || weld[t[1]] == weld[vertex] || weld[t[2]] == weld[vertex]) {
        const Eigen::Vector3d a = shown.col(t[0]).cast<double>(),
                              b = shown.col(t[1]).cast<double>(),
                              c = shown.col(t[2]).cast<double>();
        if ((b - a).cross(c - a).normalized().dot(towardsEye) < 0.2) return false;
        any = true;
      }
  return any;
}

const Eigen::Vector3i& globalTriangle(const HeadMesh& head, int global) {
  for (const HeadSubmesh& sub : head.submeshes) {
    if (global < int(sub.triangles.size())) return sub.triangles[global];
    global -= int(sub.triangles.size());
  }
  qFatal("triangle index out of range");
}

}  // namespace

class ViewportPickingTest : public QObject {
  Q_OBJECT

  std::unique_ptr<HeadMesh> head_;
  std::unique_ptr<viewport::FaceViewport> viewport_;

  static void settle() {
    for (int i = 0; i < 4; ++i) {
      QCoreApplication::processEvents();
      QTest::qWait(30);
    }
  }
  void drag(int dx, int dy) {
    auto send = [&](QEvent::Type type, QPoint at, Qt::MouseButton button,
                    Qt::MouseButtons buttons) {
      QMouseEvent event(type, QPointF(at), QPointF(viewport_->mapToGlobal(at)), button, buttons,
                        Qt::NoModifier);
      QCoreApplication::sendEvent(viewport_.get(), &event);
    };
    const QPoint from(200, 150);
    send(QEvent::MouseButtonPress, from, Qt::LeftButton, Qt::LeftButton);
    send(QEvent::MouseMove, from + QPoint(dx, dy), Qt::NoButton, Qt::LeftButton);
    send(QEvent::MouseButtonRelease, from + QPoint(dx, dy), Qt::LeftButton, Qt::NoButton);
  }
  Eigen::Vector3d eyeOfView() const {
    // The camera sits where the rays come from: the ray through the middle starts on the near
    // plane just in front of the eye, and all rays start near one another.
    return viewport_->rayAt(QPointF(200, 150))->origin;
  }

  // project() then pick() for skin vertices whose triangles all face the camera: the hit is on a
  // triangle of the vertex's one-ring, else (the vertex hidden behind a nearer part) nearer to the
  // camera than the vertex. Only the skin is pickable here (the eyebrow and eyelash cards float
  // just in front of it, as they do for the workspace, which leaves them out the same way). Returns
  // how many hit the ring, -1 on any wrong hit or when fewer than 60% do (the rest are hidden
  // behind the nose, the lips, the brow ridge from some angle).
  int pickProjectedVertices(const Eigen::Matrix3Xf& shown) {
    const HeadMesh& head = *head_;
    std::vector<bool> onlySkin(head.submeshes.size(), false);
    onlySkin[head.findSubmesh("skin") - head.submeshes.data()] = true;
    viewport_->setPickableSubmeshes(onlySkin);
    const auto restore = qScopeGuard([&] { viewport_->setPickableSubmeshes({}); });
    const std::vector<int> weld = weldCoincidentVertices(head.positions);
    const std::set<int> boundary = boundaryVertices(head, weld);
    const HeadSubmesh& skin = *head.findSubmesh("skin");
    const Eigen::Vector3d eye = eyeOfView();
    int onRing = 0, tried = 0;
    for (int v = skin.firstVertex; v < skin.firstVertex + skin.vertexCount; v += 23) {
      if (boundary.count(weld[v])) continue;
      const Eigen::Vector3d p = shown.col(v).cast<double>();
      if (!fanFaces(head, shown, weld, v, eye)) continue;
      const auto pixel = viewport_->project(p);
      if (!pixel || !QRectF(viewport_->rect()).contains(*pixel)) continue;
      ++tried;
      const auto hit = viewport_->pick(*pixel);
      if (!hit) {
        // Only a vertex on the silhouette's very edge can slip past every triangle.
        qWarning("vertex %d at (%.1f, %.1f) picked nothing", v, pixel->x(), pixel->y());
        continue;
      }
      // The hit shows where the pixel is: it projects back onto it.
      const QPointF back = *viewport_->project(hit->position);
      if (QLineF(back, *pixel).length() > 0.01) {
        qWarning("hit projects to (%f, %f), pixel (%f, %f)", back.x(), back.y(), pixel->x(),
                 pixel->y());
        return -1;
      }
      const Eigen::Vector3i& tri = globalTriangle(head, hit->triangle);
      // The same triangle by its sub-mesh's own numbering; the nearest corner is one of it.
      const Eigen::Vector3i& local = head.submeshes[hit->submesh].triangles[hit->submeshTriangle];
      if (local != tri ||
          hit->triangle != viewport::firstTriangleOf(head, hit->submesh) + hit->submeshTriangle)
        return -1;
      int corner = 0;
      hit->barycentric.maxCoeff(&corner);
      if (hit->vertex != tri[corner]) return -1;
      const std::set<int> ring = oneRing(head, weld, v);
      if (ring.count(weld[tri[0]]) || ring.count(weld[tri[1]]) || ring.count(weld[tri[2]])) {
        ++onRing;
        continue;
      }
      if ((hit->position - eye).norm() >= (p - eye).norm() - 1e-4) {
        qWarning(
            "vertex %d: hit triangle %d (sub-mesh %d) is neither beside it nor in front "
            "(%f vs %f)",
            v, hit->triangle, hit->submesh, (hit->position - eye).norm(), (p - eye).norm());
        return -1;
      }
    }
    qInfo("%d of %d facing vertices picked on their own triangles", onRing, tried);
    return tried > 20 && onRing >= 0.6 * tried ? onRing : -1;
  }

  // Pixels that differ from the bare backdrop (an empty head shows only the backdrop).
  QRect headPixels(const QImage& picture, const QImage& backdrop) {
    QRect box;
    for (const QPoint& p : differingPixels(picture, backdrop, 12)) box |= QRect(p, QSize(1, 1));
    return box;
  }

 private slots:
  void initTestCase() {
    if (!rigging::defaultHeadAvailable()) LACRIMA_SKIP_WITHOUT_DEFAULT_HEAD();
    if (QGuiApplication::platformName() != QLatin1String("xcb"))
      QSKIP("needs the xcb platform (run under xvfb-run)");
    head_ = std::make_unique<HeadMesh>(rigging::loadDefaultHead());
    viewport_ = std::make_unique<viewport::FaceViewport>();
    viewport_->resize(400, 300);
    viewport_->setHead(*head_);
    viewport_->show();
    QVERIFY(QTest::qWaitForWindowExposed(viewport_.get()));
    QTRY_VERIFY(viewport_->renderCount() >= 1);
  }

  void projectThenPickFindsTheVertex_data() {
    QTest::addColumn<int>("yawPixels");
    QTest::addColumn<int>("pitchPixels");
    QTest::newRow("framing") << 0 << 0;
    QTest::newRow("from the right") << 150 << 0;
    QTest::newRow("from the left, above") << -120 << 60;
    QTest::newRow("from below") << 0 << -90;
  }
  void projectThenPickFindsTheVertex() {
    QFETCH(int, yawPixels);
    QFETCH(int, pitchPixels);
    viewport_->resetView();
    drag(yawPixels, pitchPixels);
    settle();
    QVERIFY(pickProjectedVertices(head_->positions) > 0);
  }

  void aPixelOffTheHeadPicksNothing() {
    viewport_->resetView();
    settle();
    QVERIFY(viewport_->rayAt(QPointF(3, 3)));
    QVERIFY(!viewport_->pick(QPointF(3, 3)));
    QVERIFY(!viewport_->pick(QPointF(397, 297)));
    QVERIFY(!viewport_->pick(QPointF(qQNaN(), 10)));
  }

  void picksTheFrameShownAndAlongADrag() {
    viewport_->resetView();
    // A frame with the whole head moved up by a tenth of its height: the pick follows it.
    Eigen::Matrix3Xf moved = head_->positions;
    const float lift = 0.1f * (head_->boundsMax() - head_->boundsMin()).y();
    moved.row(1).array() += lift;
    playback::FrameView view;
    view.neutral = head_.get();
    view.positions = &moved;
    view.normals = &head_->normals;
    view.revision = 100;
    viewport_->showFrame(view);
    settle();
    QVERIFY(pickProjectedVertices(moved) > 0);
    // Back to the neutral frame: picking the neutral positions again.
    view.positions = nullptr;
    view.normals = nullptr;
    view.revision = 101;
    viewport_->showFrame(view);
    settle();
    QVERIFY(pickProjectedVertices(head_->positions) > 0);
    // A drag picks at every mouse move: 200 picks across the face, after one that builds the
    // hierarchy again (the pickable set was just reset). What a pick costs is a figure of
    // `lacrima-bench pick`.
    viewport_->pick(QPointF(200, 150));
    int hits = 0;
    for (int i = 0; i < 200; ++i) hits += bool(viewport_->pick(QPointF(150 + i / 2.0, 150)));
    QVERIFY(hits > 150);
  }

  void unpickableSubmeshesAreSeenThrough() {
    viewport_->resetView();
    settle();
    const int skin = int(head_->findSubmesh("skin") - head_->submeshes.data());
    const Eigen::Vector3d eye = eyeOfView();
    // A pixel of the left eye where the pick stops on the eye (eyeball or cornea), not the lids.
    const HeadSubmesh& eyeball = *head_->findSubmesh("eye_l");
    QPointF pixel;
    std::optional<viewport::SurfaceHit> all;
    for (int v = eyeball.firstVertex; v < eyeball.firstVertex + eyeball.vertexCount && !all; ++v) {
      pixel = *viewport_->project(head_->positions.col(v).cast<double>());
      all = viewport_->pick(pixel);
      if (all && (head_->submeshes[all->submesh].name.find("eye") == std::string::npos &&
                  head_->submeshes[all->submesh].name.find("cornea") == std::string::npos))
        all.reset();
    }
    QVERIFY(all);
    // Only the skin pickable: the ray goes through the eye to the skin behind it, or nothing.
    std::vector<bool> onlySkin(head_->submeshes.size(), false);
    onlySkin[skin] = true;
    viewport_->setPickableSubmeshes(onlySkin);
    const auto restore = qScopeGuard([&] { viewport_->setPickableSubmeshes({}); });
    const auto through = viewport_->pick(pixel);
    QVERIFY(!through || (through->submesh == skin &&
                         (through->position - eye).norm() > (all->position - eye).norm()));
    viewport_->setPickableSubmeshes({});
    QCOMPARE(viewport_->pick(pixel)->triangle, all->triangle);
  }

  void markersShowInTheirColourAndLeaveNoTrace() {
    viewport_->resetView();
    settle();
    const QImage before = viewport_->grabFrame();
    const HeadSubmesh& skin = *head_->findSubmesh("skin");
    // The nose tip (the skin's most forward vertex) and a point at the back of the head.
    int nose = skin.firstVertex, back = skin.firstVertex;
    for (int v = skin.firstVertex; v < skin.firstVertex + skin.vertexCount; ++v) {
      if (head_->positions(2, v) > head_->positions(2, nose)) nose = v;
      if (head_->positions(2, v) < head_->positions(2, back)) back = v;
    }
    const Eigen::Vector3d nosePoint = head_->positions.col(nose).cast<double>();
    const Eigen::Vector3d backPoint = head_->positions.col(back).cast<double>();
    const QColor green(20, 230, 60), blue(40, 90, 250);
    std::vector<viewport::Marker> markers;
    markers.push_back({nosePoint, green, 14, false, true});
    markers.push_back({backPoint, blue, 14, false, true});  // behind the head, shown on top
    // Hundreds more in a grid on the forehead, as a workspace with every point placed shows.
    for (int i = 0; i < 300; ++i)
      markers.push_back(
          {nosePoint + Eigen::Vector3d(0.01 * (i % 20 - 10), 0.3 + 0.01 * (i / 20), -0.2),
           QColor(200, 40, 40), 5, false, false});
    const auto start = SteadyClock::now();
    viewport_->setMarkers(markers);
    qInfo("setMarkers with %zu markers: %.3f ms", markers.size(), millisecondsSince(start));
    const QImage marked = viewport_->grabFrame();
    const auto colourAt = [&](const QImage& image, const Eigen::Vector3d& p) {
      return meanColour(image, *viewport_->project(p), 1);
    };
    auto near = [](const MeanColour& m, const QColor& c) {
      return std::abs(m.r - c.red()) < 6 && std::abs(m.g - c.green()) < 6 &&
             std::abs(m.b - c.blue()) < 6;
    };
    QVERIFY(near(colourAt(marked, nosePoint), green));
    QVERIFY(near(colourAt(marked, backPoint), blue));
    // Hidden behind the head when not on top: the picture there is as before.
    markers[1].onTop = false;
    viewport_->setMarkers(markers);
    const QImage hidden = viewport_->grabFrame();
    QVERIFY(!near(colourAt(hidden, backPoint), blue));
    QVERIFY(std::abs(colourAt(hidden, backPoint).luminance() -
                     colourAt(before, backPoint).luminance()) < 3);
    // Highlighted: brighter, with a white ring just outside the dark outline.
    markers[0].highlighted = true;
    viewport_->setMarkers(markers);
    const QImage highlighted = viewport_->grabFrame();
    const QPointF tip = *viewport_->project(nosePoint);
    QVERIFY(colourAt(highlighted, nosePoint).luminance() > colourAt(marked, nosePoint).luminance());
    const MeanColour ring = meanColour(highlighted, tip + QPointF(7 + 1.5 + 1.2, 0), 0);
    QVERIFY2(ring.r > 230 && ring.g > 230 && ring.b > 230, "no white ring round the highlight");
    // Markers nobody can draw (not finite, behind the eye, no size, absurdly large) are left
    // out or clamped; the others still show.
    const double nan = std::numeric_limits<double>::quiet_NaN();
    markers.push_back({Eigen::Vector3d(nan, 0, 0), blue, 9, false, true});
    markers.push_back({eyeOfView() + 10 * (eyeOfView() - nosePoint), blue, 9, false, true});
    markers.push_back({backPoint, blue, 0, false, true});
    markers.push_back({backPoint, blue, -4, false, true});
    markers.push_back({nosePoint + Eigen::Vector3d(0, 0.3, 0), blue, 1e9, false, false});
    viewport_->setMarkers(markers);
    QVERIFY(near(colourAt(viewport_->grabFrame(), nosePoint), green.lighter(130)));
    // Cleared: exactly the picture before.
    viewport_->setMarkers({});
    QCOMPARE(differingPixels(before, viewport_->grabFrame(), 0).size(), std::size_t{0});
  }

  void aZUpHeadInMillimetresIsFramedWhole() {
    LACRIMA_REQUIRE_SHARED(rigtest::kIctMesh);
    HeadMesh ict = rigging::importHeadMesh(rigtest::kIctMesh.toStdString());
    // Centimetres to millimetres, +y up to +z up (a quarter turn about x: y -> z, z -> -y).
    const Eigen::Matrix3f toZUp =
        Eigen::AngleAxisf(float(M_PI / 2), Eigen::Vector3f::UnitX()).toRotationMatrix();
    ict.positions = 10.0f * toZUp * ict.positions;
    ict.computeNormals();
    HeadMesh empty;
    viewport_->setHead(empty);
    const QImage backdrop = viewport_->grabFrame();
    viewport_->setHead(ict);
    const QImage picture = viewport_->grabFrame();
    const QRect box = headPixels(picture, backdrop);
    qInfo("head pixels %d,%d %dx%d in 400x300", box.x(), box.y(), box.width(), box.height());
    // Whole: a margin all round; and large: most of the height or width.
    QVERIFY(box.left() > 8 && box.top() > 6 && box.right() < 392 && box.bottom() < 294);
    QVERIFY(box.height() > 180 || box.width() > 240);  // 60% of the picture

    // The workspace knows the face frame: face left +x, up +z, forward -y.
    Eigen::Matrix3d faceToHead;
    faceToHead.col(0) = Eigen::Vector3d::UnitX();
    faceToHead.col(1) = Eigen::Vector3d::UnitZ();
    faceToHead.col(2) = -Eigen::Vector3d::UnitY();
    viewport_->setViewFrame(faceToHead);
    QVERIFY(viewport_->viewFrame().isApprox(faceToHead));
    const QImage framed = viewport_->grabFrame();
    const QRect faceBox = headPixels(framed, backdrop);
    qInfo("in its view frame: head pixels %d,%d %dx%d", faceBox.x(), faceBox.y(), faceBox.width(),
          faceBox.height());
    QVERIFY(faceBox.left() > 8 && faceBox.top() > 6 && faceBox.right() < 392 &&
            faceBox.bottom() < 294);
    QVERIFY(faceBox.height() > 180 || faceBox.width() > 240);
    // Up on screen is the face's up; the face looks at the camera: the nose (most forward, -y)
    // is picked at its own pixel and sits between the top of the head and the chin.
    int top = 0, nose = 0, bottom = 0;
    for (int v = 0; v < ict.vertexCount(); ++v) {
      if (ict.positions(2, v) > ict.positions(2, top)) top = v;
      if (ict.positions(2, v) < ict.positions(2, bottom)) bottom = v;
      if (ict.positions(1, v) < ict.positions(1, nose)) nose = v;
    }
    const QPointF topPixel = *viewport_->project(ict.positions.col(top).cast<double>());
    const QPointF nosePixel = *viewport_->project(ict.positions.col(nose).cast<double>());
    const QPointF bottomPixel = *viewport_->project(ict.positions.col(bottom).cast<double>());
    QVERIFY(topPixel.y() < nosePixel.y() && nosePixel.y() < bottomPixel.y());
    const auto hit = viewport_->pick(nosePixel);
    QVERIFY(hit);
    QVERIFY((hit->position - ict.positions.col(nose).cast<double>()).norm() < 2.0);  // mm
    // Pick speed on the 28k-vertex head, the first pick building the hierarchy.
    auto start = SteadyClock::now();
    viewport_->setPickableSubmeshes({});
    viewport_->pick(nosePixel);
    const double first = millisecondsSince(start);
    start = SteadyClock::now();
    for (int i = 0; i < 200; ++i) viewport_->pick(nosePixel + QPointF(i % 20, i / 20));
    qInfo("ICT pick: first (builds the hierarchy) %.2f ms, then %.4f ms each", first,
          millisecondsSince(start) / 200);
    viewport_->setHead(*head_);
  }

  void aToolCanTakeADragOver() {
    viewport_->resetView();
    settle();
    auto send = [&](QEvent::Type type, QPoint at, Qt::MouseButton button,
                    Qt::MouseButtons buttons) {
      QMouseEvent event(type, QPointF(at), QPointF(viewport_->mapToGlobal(at)), button, buttons,
                        Qt::NoModifier);
      QCoreApplication::sendEvent(viewport_.get(), &event);
    };
    // The tool claims presses on the head (a feature point to drag), not those beside it.
    QSignalSpy pressed(viewport_.get(), &viewport::FaceViewport::pointerPressed);
    QSignalSpy dragged(viewport_.get(), &viewport::FaceViewport::pointerDragged);
    QSignalSpy released(viewport_.get(), &viewport::FaceViewport::pointerReleased);
    QSignalSpy clicked(viewport_.get(), &viewport::FaceViewport::clicked);
    QSignalSpy hovered(viewport_.get(), &viewport::FaceViewport::hovered);
    const auto connection = connect(viewport_.get(), &viewport::FaceViewport::pointerPressed, this,
                                    [&](QPointF pixel, Qt::MouseButton button) {
                                      if (button == Qt::LeftButton && viewport_->pick(pixel))
                                        viewport_->claimDrag();
                                    });
    const QImage before = viewport_->grabFrame();
    const QPoint onHead = viewport_->project(head_->positions.col(0).cast<double>())->toPoint();
    QVERIFY(viewport_->pick(onHead));
    send(QEvent::MouseButtonPress, onHead, Qt::LeftButton, Qt::LeftButton);
    send(QEvent::MouseMove, onHead + QPoint(30, 10), Qt::NoButton, Qt::LeftButton);
    send(QEvent::MouseMove, onHead + QPoint(50, 20), Qt::NoButton, Qt::LeftButton);
    send(QEvent::MouseButtonRelease, onHead + QPoint(50, 20), Qt::LeftButton, Qt::NoButton);
    settle();
    QCOMPARE(pressed.count(), 1);
    QCOMPARE(dragged.count(), 2);
    QCOMPARE(dragged.last().at(0).toPointF(), QPointF(onHead + QPoint(50, 20)));
    QCOMPARE(released.count(), 1);
    QCOMPARE(clicked.count(), 0);
    // The camera did not move.
    QCOMPARE(differingPixels(before, viewport_->grabFrame(), 0).size(), std::size_t{0});
    // Beside the head the same drag orbits as always.
    send(QEvent::MouseButtonPress, QPoint(3, 3), Qt::LeftButton, Qt::LeftButton);
    send(QEvent::MouseMove, QPoint(60, 13), Qt::NoButton, Qt::LeftButton);
    send(QEvent::MouseButtonRelease, QPoint(60, 13), Qt::LeftButton, Qt::NoButton);
    settle();
    QCOMPARE(dragged.count(), 2);
    QVERIFY(differingPixels(before, viewport_->grabFrame(), 10).size() > 1000);
    // A press and release in place is a click; a move with no button a hover.
    send(QEvent::MouseButtonPress, QPoint(5, 5), Qt::LeftButton, Qt::LeftButton);
    send(QEvent::MouseButtonRelease, QPoint(6, 5), Qt::LeftButton, Qt::NoButton);
    QCOMPARE(clicked.count(), 1);
    QCOMPARE(clicked.last().at(0).toPointF(), QPointF(6, 5));
    send(QEvent::MouseMove, QPoint(40, 40), Qt::NoButton, Qt::NoButton);
    QCOMPARE(hovered.count(), 1);
    disconnect(connection);
    viewport_->resetView();
    settle();
  }

  void theOffscreenRendererInvertsItsProjectionToo() {
    scene::FaceRenderer renderer(*head_, QSize(320, 240));
    renderer.orbit(25, -10);
    for (int v = 0; v < head_->vertexCount(); v += 997) {
      const Eigen::Vector3d p = head_->positions.col(v).cast<double>();
      const auto ray = renderer.rayAt(renderer.project(p));
      QVERIFY(ray);
      QVERIFY(std::abs(ray->direction.norm() - 1) < 1e-12);
      // The ray passes through the point (float camera matrices: a few millionths of the view).
      QVERIFY((p - ray->origin).cross(ray->direction).norm() <
              1e-5 * renderer.scene().view().distance);
      QVERIFY((p - ray->origin).dot(ray->direction) > 0);
    }
    QVERIFY(!renderer.rayAt(QPointF(qQNaN(), 0)));
  }

  void withoutAHeadNothingIsProjectedOrPicked() {
    viewport::FaceViewport bare;
    QVERIFY(!bare.project(Eigen::Vector3d::Zero()));
    QVERIFY(!bare.pick(QPointF(10, 10)));
    bare.setMarkers({viewport::Marker{}});  // stored for later, no scene yet: no crash
  }

  void cleanupTestCase() { viewport_.reset(); }
};

QTEST_MAIN(ViewportPickingTest)
#include "ViewportPickingTest.moc"
