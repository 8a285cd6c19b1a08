// The off-screen renderer on the real default head (skipped when it is not fetched): tears show
// below the eyes and nowhere else, texture blending changes the eye region and only it, the
// camera and projection behave. Runs under xvfb-run (OGRE renders through GLX).
#include "../support/MissingData.h"
#include "ImageCompare.h"
#include "SyntheticTears.h"

#include <lacrima/rigging/DefaultHead.h>
#include <lacrima/scene/CameraPreset.h>
#include <lacrima/scene/FaceRenderer.h>
#include <lacrima/scene/FaceScene.h>
#include <lacrima/scene/OgreRuntime.h>
#include <lacrima/scene/OverlayMasks.h>

#include <QtTest>

#include <memory>
#include <optional>

using namespace lacrima;
using namespace lacrima::scenetest;

class FaceRendererTest : public QObject {
  Q_OBJECT

  std::unique_ptr<HeadMesh> head_;
  std::unique_ptr<SyntheticTears> tears_;
  std::unique_ptr<scene::FaceRenderer> renderer_;
  std::array<scene::EyeSphere, 2> eyes_;
  long long revision_ = 0;

  playback::FrameView neutral() {
    playback::FrameView v;
    v.neutral = head_.get();
    v.revision = ++revision_;
    return v;
  }
  QImage render(playback::FrameView view) {
    view.revision = ++revision_;
    renderer_->show(view);
    return renderer_->render();
  }
  // The skin vertex nearest to `point` (a point on the visible surface to sample the image at).
  Eigen::Vector3d skinPoint(const Eigen::Vector3d& point) const {
    const HeadSubmesh* skin = head_->findSubmesh("skin");
    double best = 1e30;
    Eigen::Vector3d found = point;
    for (int v = skin->firstVertex; v < skin->firstVertex + skin->vertexCount; ++v) {
      const double d = (head_->positions.col(v).cast<double>() - point).squaredNorm();
      if (d < best) {
        best = d;
        found = head_->positions.col(v).cast<double>();
      }
    }
    return found;
  }
  Eigen::Vector3d eyeCentre(int e) const {
    return eyes_[static_cast<std::size_t>(e)].centre.cast<double>();
  }
  double eyeRadius(int e) const { return eyes_[static_cast<std::size_t>(e)].radius; }

 private slots:
  void initTestCase() {
    if (!rigging::defaultHeadAvailable()) LACRIMA_SKIP_WITHOUT_DEFAULT_HEAD();
    head_ = std::make_unique<HeadMesh>(rigging::loadDefaultHead());
    for (int e = 0; e < 2; ++e) {
      const auto sphere = scene::eyeSphere(*head_, e == 0 ? "eye_l" : "eye_r");
      QVERIFY(sphere);
      eyes_[static_cast<std::size_t>(e)] = *sphere;
    }
    tears_ = std::make_unique<SyntheticTears>(*head_);
    QVERIFY(!tears_->surface().empty());
    QVERIFY(!tears_->trails().empty());
    renderer_ = std::make_unique<scene::FaceRenderer>(*head_, QSize(640, 480));
    QVERIFY(scene::OgreRuntime::running());
  }

  void rendersTheFaceUpright() {
    const QImage image = render(neutral());
    QCOMPARE(image.size(), QSize(640, 480));
    QCOMPARE(image.format(), QImage::Format_RGBA8888);
    // Both eyes in the upper half, the face's left eye (+x) on the image's right, the chin below.
    const QPointF left = renderer_->project(eyeCentre(0)), right = renderer_->project(eyeCentre(1));
    QVERIFY(left.x() > right.x());
    QVERIFY(left.y() > 0 && left.y() < 240 && right.y() > 0 && right.y() < 240);
    const QPointF chin =
        renderer_->project(skinPoint(Eigen::Vector3d(0, head_->boundsMin().y() + 0.6, 1.2)));
    QVERIFY(chin.y() > left.y() + 100);
    // The face is drawn where project() says: the skin between the eyes is much brighter than the
    // backdrop in the corner, and the backdrop is a dark neutral grey, lighter at the top.
    const MeanColour face = meanColour(image, 0.5 * (left + right) + QPointF(0, 20), 3);
    const MeanColour corner = meanColour(image, QPointF(5, 5), 3),
                     bottom = meanColour(image, QPointF(5, 474), 3);
    QVERIFY2(face.luminance() > corner.luminance() + 60, "no skin where the face should be");
    QVERIFY(corner.luminance() < 80 && corner.luminance() > bottom.luminance());
    QVERIFY(std::abs(corner.r - corner.b) < 12);
  }

  void tearPixelsOnlyBelowTheEyes() {
    playback::FrameView crying = tears_->view();
    const QImage with = render(crying);
    crying.surface = nullptr;
    crying.trails = nullptr;
    const QImage without = render(crying);
    const std::vector<QPoint> tears = differingPixels(with, without, 10);
    qInfo("%zu tear pixels", tears.size());
    QVERIFY2(tears.size() > 150, "the tears barely show");

    const QPointF left = renderer_->project(eyeCentre(0)), right = renderer_->project(eyeCentre(1));
    const double eyeY = std::min(left.y(), right.y());
    const double middle = 0.5 * (left.x() + right.x()), spacing = left.x() - right.x();
    const double eyeRadiusPixels =
        (renderer_->project(eyeCentre(0) + Eigen::Vector3d(0, eyeRadius(0), 0)) - left)
            .manhattanLength();
    int leftSide = 0, rightSide = 0, lowDown = 0;
    for (const QPoint& p : tears) {
      QVERIFY2(p.y() > eyeY,
               qPrintable(QString("tear pixel (%1, %2) above the eyes").arg(p.x()).arg(p.y())));
      QVERIFY2(std::abs(p.x() - middle) < 1.2 * spacing,
               qPrintable(QString("tear pixel (%1, %2) far from the face").arg(p.x()).arg(p.y())));
      (p.x() > middle ? leftSide : rightSide)++;
      if (p.y() > eyeY + 3 * eyeRadiusPixels) ++lowDown;
    }
    QVERIFY2(leftSide > 50 && rightSide > 50, "tears missing under one eye");
    QVERIFY2(lowDown > 30, "no tear pixels down the cheeks (the running drops and trails)");
  }

  // Drops following one another down one path leave trails over each other; the water there is
  // drawn once (TrailStencil), so three strips look like the newest one alone, not like a tint
  // stacked three times with its glints added up.
  void overlappingTrailsAreDrawnOnce() {
    SyntheticTears::Options one, three;
    three.streamDrops = 3;
    const SyntheticTears single(*head_, one), stream(*head_, three);
    QCOMPARE(stream.trails().triangleCount(), 3 * single.trails().triangleCount());
    playback::FrameView a = single.view(), b = stream.view();
    a.surface = b.surface = nullptr;
    const QImage once = render(a), thrice = render(b);
    const QImage dry = render(neutral());
    const std::size_t trail = differingPixels(once, dry, 10).size();
    const std::vector<QPoint> stacked = differingPixels(once, thrice, 6);
    qInfo("%zu trail pixels, %zu differ with three strips over each other", trail, stacked.size());
    QVERIFY2(trail > 100, "the trail barely shows");
    QVERIFY(stacked.size() < trail / 20);
  }

  void withoutTearsNothingChanges() {
    const QImage a = render(neutral());
    playback::FrameView empty = neutral();
    empty.surface = nullptr;
    empty.trails = nullptr;
    empty.particles = nullptr;
    const QImage b = render(empty);
    QCOMPARE(differingPixels(a, b, 0).size(), std::size_t{0});
    // Switching tears off after showing them leaves no trace.
    render(tears_->view());
    QCOMPARE(differingPixels(a, render(empty), 0).size(), std::size_t{0});
  }

  void particleSpheresShowWhereTheParticlesAre() {
    playback::FrameView view = neutral();
    const QImage without = render(view);
    view.particles = &tears_->particles();
    view.particleRadius = tears_->particleRadius();
    const QImage with = render(view);
    const std::vector<QPoint> changed = differingPixels(with, without, 10);
    QVERIFY2(changed.size() > 30, "particle spheres do not show");
    const double eyeY =
        std::min(renderer_->project(eyeCentre(0)).y(), renderer_->project(eyeCentre(1)).y());
    for (const QPoint& p : changed) QVERIFY(p.y() > eyeY);
  }

  void rednessReddensAroundTheEyesOnly() {
    playback::FrameView calm = neutral(), red = neutral();
    red.overlays.redness = 1;
    const QImage a = render(calm), b = render(red);
    for (int e = 0; e < 2; ++e) {
      const double r = eyeRadius(e);
      const double outwards = e == 0 ? 1 : -1;
      for (const Eigen::Vector3d& offset :
           {Eigen::Vector3d(0, -1.3 * r, r),
            Eigen::Vector3d(outwards * 1.3 * r, -0.3 * r, 0.6 * r)}) {
        const QPointF at = renderer_->project(skinPoint(eyeCentre(e) + offset));
        const MeanColour before = meanColour(a, at, 2), after = meanColour(b, at, 2);
        qInfo("eye %d at (%.0f, %.0f): redness %.3f -> %.3f, luminance %.1f -> %.1f", e, at.x(),
              at.y(), before.redness(), after.redness(), before.luminance(), after.luminance());
        QVERIFY2(after.redness() > before.redness() * 1.08,
                 "the skin around the eye did not redden");
        QVERIFY2(after.luminance() < before.luminance() - 3,
                 "the skin around the eye did not darken");
      }
    }
    // Far from the eyes nothing moves: the forehead and the chin stay exactly as they were.
    const Eigen::Vector3d mid = 0.5 * (eyeCentre(0) + eyeCentre(1));
    for (const Eigen::Vector3d& far :
         {Eigen::Vector3d(mid.x(), mid.y() + 6 * eyeRadius(0), mid.z() + eyeRadius(0)),
          Eigen::Vector3d(mid.x() + 2.5 * eyeRadius(0), mid.y() - 8 * eyeRadius(0), mid.z())}) {
      const QPointF at = renderer_->project(skinPoint(far));
      const MeanColour before = meanColour(a, at, 2), after = meanColour(b, at, 2);
      QCOMPARE(after.r, before.r);
      QCOMPARE(after.g, before.g);
    }
  }

  void wetEyesChangeTheEyes() {
    playback::FrameView dry = neutral(), wet = neutral();
    wet.overlays.wetEyes = {1.0, 0.0};
    const QImage a = render(dry), b = render(wet);
    const QPointF left = renderer_->project(eyeCentre(0) + Eigen::Vector3d(0, 0, eyeRadius(0)));
    const QPointF right = renderer_->project(eyeCentre(1) + Eigen::Vector3d(0, 0, eyeRadius(1)));
    double changedLeft = 0, changedRight = 0;
    for (int dy = -4; dy <= 4; ++dy)
      for (int dx = -12; dx <= 12; ++dx) {
        changedLeft += channelDifference(a, b, int(left.x()) + dx, int(left.y()) + dy);
        changedRight += channelDifference(a, b, int(right.x()) + dx, int(right.y()) + dy);
      }
    qInfo("wet left eye: mean channel change %.2f (right eye %.2f)", changedLeft / 225,
          changedRight / 225);
    QVERIFY2(changedLeft / 225 > 3, "the wet overlay did not change the left eye");
    QCOMPARE(changedRight, 0.0);  // only the eye that is wet
  }

  // Full redness, close up: the iris (the eyeball's front pole) keeps every pixel, the sclera on
  // its nose side (32 degrees off the front, in view from this camera for both eyes) turns pinker.
  void rednessReddensTheScleraNotTheIris() {
    const auto resetView = qScopeGuard([this] { renderer_->resetView(); });
    renderer_->zoom(0.4);
    playback::FrameView calm = neutral(), red = neutral();
    red.overlays.redness = 1;
    const QImage a = render(calm), b = render(red);
    for (int e = 0; e < 2; ++e) {
      const double r = eyeRadius(e), nasal = e == 0 ? -1 : 1;
      const QPointF iris = renderer_->project(eyeCentre(e) + Eigen::Vector3d(0, 0, r));
      for (int dy = -2; dy <= 2; ++dy)
        for (int dx = -2; dx <= 2; ++dx)
          QCOMPARE(channelDifference(a, b, int(iris.x()) + dx, int(iris.y()) + dy), 0);
      const QPointF at =
          renderer_->project(eyeCentre(e) + r * Eigen::Vector3d(nasal * 0.53, 0, 0.848));
      const MeanColour before = meanColour(a, at, 1), after = meanColour(b, at, 1);
      qInfo("eye %d sclera at (%.0f, %.0f): redness %.3f -> %.3f", e, at.x(), at.y(),
            before.redness(), after.redness());
      QVERIFY2(before.redness() < 1.25, "not the sclera: too red already");
      QVERIFY2(after.redness() > before.redness() * 1.1, "the sclera did not redden");
    }
  }

  // Three-quarter view of the face's left side: walking across the jaw line from the cheek to
  // the neck, the jaw's underside (facing down, away from the key light) is a soft shade, not a
  // grey crease: no pixel much darker than the neck below it, none much less red than it. The
  // points are on the default head's left jaw (x = 0.45, y from 6.65 down to 6.25).
  void jawLineHasNoCrease() {
    const auto resetView = qScopeGuard([this] { renderer_->resetView(); });
    renderer_->scene().setView(scene::presetView(*head_, scene::CameraPreset::ThreeQuarter));
    const QImage image = render(neutral());
    const QPointF cheek = renderer_->project(skinPoint(Eigen::Vector3d(0.46, 6.65, 1.25)));
    const QPointF neck = renderer_->project(skinPoint(Eigen::Vector3d(0.45, 6.25, 0.4)));
    const MeanColour below = meanColour(image, neck, 1);
    double darkest = 1e9, leastRed = 1e9;
    QString profile;
    for (int i = 0; i <= 40; ++i) {
      const MeanColour c = meanColour(image, cheek + (neck - cheek) * (i / 40.0), 1);
      darkest = std::min(darkest, c.luminance());
      leastRed = std::min(leastRed, c.redness());
      profile += QString(" %1/%2").arg(c.luminance(), 0, 'f', 0).arg(c.redness(), 0, 'f', 2);
    }
    qInfo("cheek (%.0f, %.0f) to neck (%.0f, %.0f), luminance/redness:%s", cheek.x(), cheek.y(),
          neck.x(), neck.y(), qPrintable(profile));
    // Without the bounce from below it was 0.54 of the neck's luminance, and grey (0.88 of its
    // redness); with it about 0.8 and warmer than the neck.
    QVERIFY2(darkest > 0.7 * below.luminance(), "a dark line along the jaw");
    QVERIFY2(leastRed > 0.92 * below.redness(), "a grey line along the jaw");
  }

  void textureBlendingOffEqualsNoOverlay() {
    playback::FrameView plain = neutral(), off = neutral();
    off.overlays.redness = 1;
    off.overlays.wetEyes = {1, 1};
    off.overlays.blush = 1;
    off.textureBlending = false;
    const QImage a = render(plain), b = render(off);
    QCOMPARE(differingPixels(a, b, 0).size(), std::size_t{0});
    off.textureBlending = true;
    QVERIFY(differingPixels(a, render(off), 10).size() > 100);
  }

  void cameraOrbitsZoomsAndResets() {
    const QImage first = render(neutral());
    const QPointF eye = renderer_->project(eyeCentre(0));
    renderer_->orbit(30, 0);
    QVERIFY(differingPixels(first, render(neutral()), 10).size() > 1000);
    // Orbiting to the face's left (+x) brings the left eye towards the image's middle.
    QVERIFY(std::abs(renderer_->project(eyeCentre(0)).x() - 320) < std::abs(eye.x() - 320));
    renderer_->resetView();
    renderer_->zoom(0.5);
    const QPointF closer = renderer_->project(eyeCentre(0));
    QVERIFY(std::abs(closer.x() - 320) > std::abs(eye.x() - 320));
    renderer_->resetView();
    QCOMPARE(differingPixels(first, render(neutral()), 0).size(), std::size_t{0});
  }

  void resizeKeepsTheFraming() {
    renderer_->resize(QSize(320, 240));
    const QImage small = render(neutral());
    QCOMPARE(small.size(), QSize(320, 240));
    const QPointF eye = renderer_->project(eyeCentre(0));
    renderer_->resize(QSize(640, 480));
    const QPointF big = renderer_->project(eyeCentre(0));
    QVERIFY(std::abs(2 * eye.x() - big.x()) < 1.0 && std::abs(2 * eye.y() - big.y()) < 1.0);
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, renderer_->resize(QSize(0, 10)));
  }

  void rejectsFramesOfTheWrongSize() {
    playback::FrameView view = neutral();
    const Eigen::Matrix3Xf wrong = Eigen::Matrix3Xf::Zero(3, 10);
    view.positions = &wrong;
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, renderer_->show(view));
    // The renderer still works afterwards.
    QCOMPARE(render(neutral()).size(), QSize(640, 480));
  }

  void reportsTimes() {
    render(tears_->view());
    const auto& t = renderer_->lastTimes();
    QVERIFY(t.upload >= 0 && t.render > 0 && t.readback > 0);
  }

  void cleanupTestCase() {
    renderer_.reset();
    QVERIFY(!scene::OgreRuntime::running());  // the last holder shut OGRE down
  }
};

QTEST_MAIN(FaceRendererTest)
#include "FaceRendererTest.moc"
