// The named cameras fit any head (player::presetView, scene::presetView with FaceLandmarks):
// on the ICT-FaceKit head in its centimetres, scaled to millimetres and exported Z-up, close-left
// shows the left tear's source near the middle of the picture with the left eye above it, at
// the default head's relative size, and front shows both eyes and the chin; on the default head
// every view is the mesh-only one to the bit (the reference renders depend on them). Engine-free
// projections (no display); skips without the default head or ../shared.
#include <lacrima/player/HeadViews.h>
#include <lacrima/rigging/DefaultHead.h>
#include <lacrima/rigging/FeaturePointFile.h>
#include <lacrima/rigging/MeshImport.h>

#include "../rigging/TestHeadFiles.h"
#include "../support/MissingData.h"

#include <QFileInfo>
#include <QtTest>

#include <cmath>
#include <limits>
#include <numbers>

using namespace lacrima;
using scene::CameraPreset;

namespace {

constexpr double kAspect = 16.0 / 9.0;  // --render's default 1280x720

// Where `point` shows in a 16:9 picture of `view`: x right, y up, -1..1 edge to edge.
Eigen::Vector2d project(const scene::OrbitView& view, const Eigen::Vector3d& point) {
  const Eigen::Vector3d c =
      view.orientation().toRotationMatrix().transpose() * (point - view.eye());
  const double t = std::tan(0.5 * view.fovYDegrees * std::numbers::pi / 180.0);
  return {c.x() / (-c.z() * t * kAspect), c.y() / (-c.z() * t)};
}

bool inPicture(const Eigen::Vector2d& p, double margin) {
  return std::abs(p.x()) <= margin && std::abs(p.y()) <= margin;
}

// The view's height at its target in ES0: how large the face shows.
double viewHeightInEs0(const scene::OrbitView& view, double es0) {
  return 2 * view.distance * std::tan(0.5 * view.fovYDegrees * std::numbers::pi / 180.0) / es0;
}

// The ICT head as exported: mesh = scale x turn x face frame, the feature-point file to match.
std::unique_ptr<playback::HeadRig> ictRig(double scale, const Eigen::Matrix3d& turn) {
  HeadMesh mesh = rigging::importHeadMesh(rigtest::kIctMesh.toStdString());
  mesh.positions = (scale * turn * mesh.positions.cast<double>()).cast<float>();
  mesh.normals = (turn * mesh.normals.cast<double>()).cast<float>();
  rigging::FeaturePointFile fdp = rigging::readFeaturePointFile(rigtest::kIctFdp.toStdString());
  auto map = [&](std::optional<Eigen::Vector3d>& x) {
    if (x) x = scale * turn * *x;
  };
  map(fdp.eyeLeft.centre);
  map(fdp.eyeRight.centre);
  map(fdp.neckPivot);
  for (auto& [id, spec] : fdp.points) {
    map(spec.at.position);
    if (spec.radius) *spec.radius *= scale;
  }
  for (std::optional<rigging::SurfacePoint>* tear : {&fdp.tearLeft, &fdp.tearRight})
    if (*tear) map((*tear)->position);
  return playback::rigHead(std::move(mesh), fdp);
}

}  // namespace

class HeadViewsTest : public QObject {
  Q_OBJECT

  std::unique_ptr<playback::HeadRig> default_;
  double defaultCloseHeight_ = 0;             // the default head's close-left view height in ES0
  Eigen::Vector2d defaultTear_, defaultEye_;  // where its close-left shows the tear and eye

 private slots:
  void initTestCase() {
    if (!QFileInfo::exists(QString::fromStdString(rigging::defaultHeadPackageDir())))
      LACRIMA_SKIP_WITHOUT_DEFAULT_HEAD();
    default_ = playback::loadDefaultHeadRig();
    const scene::OrbitView close = player::presetView(*default_, CameraPreset::CloseLeft);
    defaultCloseHeight_ = viewHeightInEs0(close, default_->rig.fapu.es0);
    defaultTear_ = project(close, default_->rig.tearLeft.position);
    defaultEye_ = project(close, *default_->rig.eyeCentreLeft);
    qInfo(
        "default head close-left: tear at (%.2f, %.2f), left eye at (%.2f, %.2f), view %.2f "
        "ES0 high",
        defaultTear_.x(), defaultTear_.y(), defaultEye_.x(), defaultEye_.y(), defaultCloseHeight_);
  }

  void defaultHeadKeepsItsViews() {
    // Bit for bit: the landmarks path gives the mesh-only views on the default head.
    QVERIFY(player::faceLandmarks(*default_));
    for (const CameraPreset preset :
         {CameraPreset::Framing, CameraPreset::Front, CameraPreset::ThreeQuarter,
          CameraPreset::Profile, CameraPreset::CloseLeft, CameraPreset::CloseRight}) {
      const scene::OrbitView meshOnly = scene::presetView(default_->head, preset);
      const scene::OrbitView fromRig = player::presetView(*default_, preset);
      QVERIFY2(fromRig == meshOnly, std::string(toString(preset)).c_str());
    }
    QVERIFY(scene::presetView(default_->head, CameraPreset::Framing) ==
            scene::OrbitView::framing(default_->head));
  }

  void badLandmarksFallBackToTheMesh() {
    scene::FaceLandmarks face = *player::faceLandmarks(*default_);
    const scene::OrbitView meshOnly = scene::presetView(default_->head, CameraPreset::CloseLeft);
    for (int bad = 0; bad < 5; ++bad) {
      scene::FaceLandmarks broken = face;
      if (bad == 0) broken.eyeSeparation = 0;
      if (bad == 1) broken.eyeLeft.x() = std::nan("");
      if (bad == 2) std::swap(broken.eyeLeft, broken.eyeRight);  // left at -x
      if (bad == 3) broken.chin.y() = std::numeric_limits<double>::infinity();
      if (bad == 4) broken.chin.y() = 1e6;  // the neck cut above the whole head: nothing left
      const scene::OrbitView view =
          scene::presetView(default_->head, CameraPreset::CloseLeft, broken);
      QVERIFY(view == meshOnly);
      QVERIFY(view.target.allFinite() && std::isfinite(view.distance));
    }
  }

  void ictViews_data() {
    QTest::addColumn<double>("scale");
    QTest::addColumn<bool>("zUp");
    QTest::newRow("centimetres, Y-up") << 1.0 << false;
    QTest::newRow("millimetres, Y-up") << 10.0 << false;
    QTest::newRow("millimetres, Z-up facing -y") << 10.0 << true;
  }

  void ictViews() {
    LACRIMA_REQUIRE_SHARED(rigtest::kIctMesh);
    QFETCH(double, scale);
    QFETCH(bool, zUp);
    Eigen::Matrix3d turn = Eigen::Matrix3d::Identity();
    if (zUp) turn << 1, 0, 0, 0, 0, -1, 0, 1, 0;
    const auto rig = ictRig(scale, turn);
    const rigging::BuiltRig& r = rig->rig;
    QVERIFY(r.eyeCentreLeft && r.eyeCentreRight);
    const double es0 = r.fapu.es0;

    // close-left: the tear's source near the middle (the view aims a little below it, at the
    // cheek the tear runs down), the left eye above it in the upper part; both where the
    // default head's close-left shows them.
    const scene::OrbitView close = player::presetView(*rig, CameraPreset::CloseLeft);
    const Eigen::Vector2d tear = project(close, r.tearLeft.position);
    const Eigen::Vector2d eye = project(close, *r.eyeCentreLeft);
    qInfo("close-left: tear at (%.2f, %.2f), left eye at (%.2f, %.2f), view %.2f ES0 high",
          tear.x(), tear.y(), eye.x(), eye.y(), viewHeightInEs0(close, es0));
    QVERIFY2(std::abs(tear.x()) < 0.25 && std::abs(tear.y()) < 0.6,
             "the tear source is not near the middle");
    QVERIFY2(eye.y() > 0.2 && inPicture(eye, 0.9), "the left eye is not in the upper part");
    QVERIFY(eye.y() > tear.y());
    QVERIFY((tear - defaultTear_).norm() < 0.15 && (eye - defaultEye_).norm() < 0.15);
    // A close-up, not the neck or the whole face: the chin is out of the picture, the other eye
    // at its far edge.
    QVERIFY(!inPicture(project(close, r.featurePoints.at("2.1")), 1.0));
    QVERIFY(project(close, *r.eyeCentreRight).x() < -0.6);
    // The same relative size as on the default head (within a fifth).
    const double ratio = viewHeightInEs0(close, es0) / defaultCloseHeight_;
    QVERIFY2(ratio > 0.8 && ratio < 1.25, qPrintable(QString::number(ratio)));

    // close-right mirrors it.
    const scene::OrbitView closeRight = player::presetView(*rig, CameraPreset::CloseRight);
    const Eigen::Vector2d tearRight = project(closeRight, r.tearRight.position);
    QVERIFY(std::abs(tearRight.x() + tear.x()) < 0.02 && std::abs(tearRight.y() - tear.y()) < 0.02);

    // front: both eyes and the chin in view, the eyes level and either side of the middle.
    const scene::OrbitView front = player::presetView(*rig, CameraPreset::Front);
    const Eigen::Vector2d left = project(front, *r.eyeCentreLeft);
    const Eigen::Vector2d right = project(front, *r.eyeCentreRight);
    const Eigen::Vector2d chin = project(front, r.featurePoints.at("2.1"));
    qInfo("front: eyes at (%.2f, %.2f) (%.2f, %.2f), chin at (%.2f, %.2f)", left.x(), left.y(),
          right.x(), right.y(), chin.x(), chin.y());
    QVERIFY(inPicture(left, 0.9) && inPicture(right, 0.9) && inPicture(chin, 0.9));
    QVERIFY(left.x() > 0 && right.x() < 0);  // seen from the front, the face's left is on the right
    QVERIFY(std::abs(left.y() - right.y()) < 0.02);
    QVERIFY(chin.y() < left.y() - 0.5);
    // Face-sized: eye to chin spans a third of the picture or more, not a far-away whole body.
    QVERIFY(left.y() - chin.y() > 0.6);
  }
};

QTEST_GUILESS_MAIN(HeadViewsTest)
#include "HeadViewsTest.moc"
