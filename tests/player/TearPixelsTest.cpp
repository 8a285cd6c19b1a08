// The demo rendered through FaceRenderer (the viewport's scene), under xvfb-run: at a frame
// with tears, tear pixels lie below the eyes and none far from the face; with the tears
// switched off the frame has none; close up, a running tear is a band of water with highlights,
// not a line; texture blending visibly reddens the eye region.
//
// A tear pixel is one that differs from the same face with no tears at all: the demo with its
// tear channels cleared, so nothing is simulated. Texture blending is off in both renders, so
// only the tears' own geometry (surface, trails, particles) can make a difference.
#include "../support/MissingData.h"

#include <lacrima/playback/Playback.h>
#include <lacrima/rigging/DefaultHead.h>
#include <lacrima/scene/CameraPreset.h>
#include <lacrima/scene/FaceRenderer.h>
#include <lacrima/scene/FaceScene.h>
#include <lacrima/tears/TrailBuilder.h>

#include <QtTest>

#include <algorithm>
#include <cmath>
#include <vector>

using namespace lacrima;
using namespace lacrima::playback;

namespace {

const std::string kDemo = LACRIMA_SOURCE_DIR "/media/demo/crying.fap";
constexpr double kTearTime = 6.0;  // tears flowing on both cheeks, before the sob
const QSize kSize(800, 600);

// Close up, 1280x720, on the left cheek while the left tear runs down it.
const QSize kCloseSize(1280, 720);
constexpr double kRunningTearTime = 6.8;
// Water pixels differ from the dry face by more than this in some channel: clearly visible.
constexpr int kWaterContrast = 20;
// A tear track is 1-3 mm wide; close up (about 7 px per mm) a real one is 7 to 20 px, more
// with the bead. Measured: the hairline tears this test was written against had a median of
// 11 px (their dark rims and beads included), the rivulets 20 px.
constexpr int kMinimumTearWidth = 16;
// Pixels of glints along the water, brighter than any skin nearby (measured: about 460).
constexpr int kMinimumHighlights = 100;

int luminance(QRgb c) { return (2 * qRed(c) + 5 * qGreen(c) + qBlue(c)) / 8; }

bool differs(QRgb a, QRgb b, int tolerance) {
  return std::abs(qRed(a) - qRed(b)) > tolerance || std::abs(qGreen(a) - qGreen(b)) > tolerance ||
         std::abs(qBlue(a) - qBlue(b)) > tolerance;
}

struct Region {
  QRectF belowEyes;  // from the eyes' centres down to the mouth corners, cheek to cheek
  QRectF face;       // everything a tear may touch: brows to below the chin, ear to ear
};

}  // namespace

class TearPixelsTest : public QObject {
  Q_OBJECT

  std::unique_ptr<HeadRig> rig_;
  std::unique_ptr<scene::FaceRenderer> renderer_;
  FapAnimation dry_;
  Region region_;

  QImage render(const FrameView& view) {
    renderer_->show(view);
    return renderer_->render().convertToFormat(QImage::Format_RGB32);
  }

  QImage renderDemo(const FapAnimation& animation, SceneSettings scene, double t) {
    Playback playback(*rig_);
    playback.setAnimation(animation, scene);
    return render(playback.seek(t));
  }

  // The demo file itself (tears and all) at t, and which tear layers its frame had.
  struct WetFrame {
    QImage image;
    bool surface = false, trails = false;
  };
  WetFrame renderWet(const SceneSettings& scene, double t) {
    Playback playback(*rig_);
    playback.open(kDemo);
    playback.setScene(scene);
    const FrameView& view = playback.seek(t);
    return {render(view), view.surface != nullptr, view.trails != nullptr};
  }

 private slots:
  void initTestCase() {
    if (!rigging::defaultHeadAvailable()) LACRIMA_SKIP_WITHOUT_DEFAULT_HEAD();
    rig_ = loadDefaultHeadRig();
    renderer_ = std::make_unique<scene::FaceRenderer>(rig_->head, kSize);
    Playback probe(*rig_);
    probe.open(kDemo);
    dry_ = probe.animation();
    for (FapValues& v : dry_.frames)
      v[channelIndex(kTearLeftFap)] = v[channelIndex(kTearRightFap)] = 0;

    const rigging::BuiltRig& r = rig_->rig;
    QVERIFY(r.eyeCentreLeft && r.eyeCentreRight);
    const QPointF eyeL = renderer_->project(*r.eyeCentreLeft),
                  eyeR = renderer_->project(*r.eyeCentreRight);
    const QPointF mouthL = renderer_->project(r.featurePoints.at("8.3")),
                  mouthR = renderer_->project(r.featurePoints.at("8.4"));
    const QPointF chin = renderer_->project(r.featurePoints.at("2.1"));
    const double eyeGap = std::abs(eyeL.x() - eyeR.x());
    QVERIFY2(eyeGap > 40, "the eyes are too close together in the image to tell regions apart");
    const double left = std::min(eyeL.x(), eyeR.x()), right = std::max(eyeL.x(), eyeR.x());
    const double eyeY = 0.5 * (eyeL.y() + eyeR.y());
    region_.belowEyes = QRectF(QPointF(left - 0.5 * eyeGap, eyeY),
                               QPointF(right + 0.5 * eyeGap, std::max(mouthL.y(), mouthR.y())));
    region_.face = QRectF(QPointF(left - eyeGap, eyeY - 0.8 * eyeGap),
                          QPointF(right + eyeGap, chin.y() + 0.8 * eyeGap));
    qInfo("eyes at (%.0f, %.0f) and (%.0f, %.0f); tear sources at (%.0f, %.0f) and (%.0f, %.0f)",
          eyeL.x(), eyeL.y(), eyeR.x(), eyeR.y(), renderer_->project(r.tearLeft.position).x(),
          renderer_->project(r.tearLeft.position).y(), renderer_->project(r.tearRight.position).x(),
          renderer_->project(r.tearRight.position).y());
  }

  void tearsBelowTheEyesOnly() {
    SceneSettings scene;
    scene.textureBlending = false;
    const QImage reference = renderDemo(dry_, scene, kTearTime);
    const WetFrame frame = renderWet(scene, kTearTime);
    QVERIFY(frame.surface && frame.trails);
    const QImage& wet = frame.image;

    int below = 0, far = 0, total = 0;
    std::array<int, 2> perSide{0, 0};
    const double middle = region_.belowEyes.center().x();
    for (int y = 0; y < wet.height(); ++y)
      for (int x = 0; x < wet.width(); ++x) {
        if (!differs(wet.pixel(x, y), reference.pixel(x, y), 6)) continue;
        ++total;
        const QPointF p(x + 0.5, y + 0.5);
        if (region_.belowEyes.contains(p)) {
          ++below;
          ++perSide[x < middle ? 0 : 1];
        }
        if (!region_.face.contains(p)) ++far;
      }
    qInfo("%d tear pixels: %d below the eyes (%d and %d either side), %d far from the face", total,
          below, perSide[0], perSide[1], far);
    QVERIFY2(below >= 200, QByteArray::number(below) + " tear pixels below the eyes");
    QVERIFY2(perSide[0] >= 50 && perSide[1] >= 50, "tears should run down both cheeks");
    QCOMPARE(far, 0);
  }

  void tearsSwitchedOffLeaveNone() {
    SceneSettings scene;
    scene.textureBlending = false;
    const QImage reference = renderDemo(dry_, scene, kTearTime);
    scene.surface = scene.trails = scene.particles = false;
    Playback playback(*rig_);
    playback.open(kDemo);
    playback.setScene(scene);
    const FrameView& view = playback.seek(kTearTime);
    QVERIFY(playback.producer().particleCount() > 0);  // the tears are there, only not drawn
    const QImage off = render(view);
    int count = 0;
    for (int y = 0; y < off.height(); ++y)
      for (int x = 0; x < off.width(); ++x)
        count += differs(off.pixel(x, y), reference.pixel(x, y), 6) ? 1 : 0;
    QCOMPARE(count, 0);
  }

  // The look of a running tear, from pixels, so it cannot silently regress to hairlines: close
  // up, the rows the tear crosses hold a run of water pixels (differing from the dry face by
  // kWaterContrast) whose median width is at least kMinimumTearWidth, and the water holds
  // highlights brighter than the brightest dry skin within 40 px on its row.
  void closeUpTearIsAWaterBodyWithHighlights() {
    renderer_->resize(kCloseSize);
    renderer_->scene().setView(scene::presetView(rig_->head, scene::CameraPreset::CloseLeft));
    SceneSettings scene;
    scene.textureBlending = false;
    const QImage dry = renderDemo(dry_, scene, kRunningTearTime);
    const QImage wet = renderWet(scene, kRunningTearTime).image;
    renderer_->resize(kSize);
    renderer_->resetView();

    std::vector<int> widths;
    int highlights = 0;
    for (int y = 0; y < wet.height(); ++y) {
      int widest = 0, run = 0, gap = 0;
      for (int x = 0; x < wet.width(); ++x) {
        const bool water = differs(wet.pixel(x, y), dry.pixel(x, y), kWaterContrast);
        if (water) {
          run += 1 + gap;  // a one-pixel gap inside the water does not split it
          gap = 0;
          int brightestSkin = 0;
          for (int k = std::max(0, x - 40); k <= std::min(wet.width() - 1, x + 40); ++k)
            brightestSkin = std::max(brightestSkin, luminance(dry.pixel(k, y)));
          if (luminance(wet.pixel(x, y)) > brightestSkin + 8) ++highlights;
        } else if (run > 0 && gap == 0) {
          gap = 1;
        } else {
          widest = std::max(widest, run);
          run = gap = 0;
        }
      }
      widest = std::max(widest, run);
      if (widest > 0) widths.push_back(widest);
    }
    QVERIFY2(widths.size() > 100, "the tear should cross much of the close-up");
    std::nth_element(widths.begin(), widths.begin() + widths.size() / 2, widths.end());
    const int median = widths[widths.size() / 2];
    qInfo(
        "close-up tear: %d rows, median width %d px (at least %d), %d highlight pixels (at "
        "least %d)",
        int(widths.size()), median, kMinimumTearWidth, highlights, kMinimumHighlights);
    QVERIFY(median >= kMinimumTearWidth);
    QVERIFY(highlights >= kMinimumHighlights);
  }

  // Late in the demo the eye redness is high: the skin around the eyes turns redder.
  void textureBlendingReddensTheEyes() {
    SceneSettings scene;
    scene.surface = scene.trails = false;
    Playback playback(*rig_);
    playback.open(kDemo);
    playback.setScene(scene);
    const FrameView& view = playback.seek(0.9 * playback.duration());
    QVERIFY(view.overlays.redness > 0.8);
    const QImage blended = render(view);
    scene.textureBlending = false;
    playback.setScene(scene);
    const QImage plain = render(playback.view());
    auto redness = [&](const QImage& image) {
      double red = 0, green = 0;
      const QRect box = QRectF(region_.belowEyes.left(),
                               region_.belowEyes.top() - 0.25 * region_.belowEyes.height(),
                               region_.belowEyes.width(), 0.5 * region_.belowEyes.height())
                            .toRect();
      for (int y = box.top(); y <= box.bottom(); ++y)
        for (int x = box.left(); x <= box.right(); ++x) {
          red += qRed(image.pixel(x, y));
          green += qGreen(image.pixel(x, y));
        }
      return red / std::max(1.0, green);
    };
    qInfo("red/green around the eyes: %.3f blended, %.3f plain", redness(blended), redness(plain));
    QVERIFY(redness(blended) > redness(plain) * 1.03);
  }
};

QTEST_MAIN(TearPixelsTest)
#include "TearPixelsTest.moc"
