// The face frame (FaceFrame.h): measured from the feature points, snapped to the
// nearest of the 24 axis-aligned rotations, applied before the rig is built. The default head's
// frame is the identity (nothing changes); the ICT head exported Z-up, facing +y or -z and in
// millimetres rigs to the same rig.json feature points up to rounding and scale.
#include "../support/MissingData.h"
#include "TestHeadFiles.h"

#include <lacrima/rigging/DefaultHead.h>
#include <lacrima/rigging/FaceFrame.h>
#include <lacrima/rigging/FeaturePointFile.h>
#include <lacrima/rigging/MeshImport.h>
#include <lacrima/rigging/RigBuilder.h>
#include <lacrima/rigging/RigDescription.h>

#include <Eigen/Geometry>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QtTest>

#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <vector>

using namespace lacrima;
using namespace lacrima::rigtest;

namespace {

// The 24 rotations that permute and negate the axes, built independently of the library.
std::vector<Eigen::Matrix3d> axisRotations() {
  std::vector<Eigen::Matrix3d> out;
  std::array<int, 3> p{0, 1, 2};
  do {
    for (int signs = 0; signs < 8; ++signs) {
      Eigen::Matrix3d r = Eigen::Matrix3d::Zero();
      for (int i = 0; i < 3; ++i)
        r(i, p[static_cast<std::size_t>(i)]) = (signs >> i) & 1 ? -1.0 : 1.0;
      if (r.determinant() > 0) out.push_back(r);
    }
  } while (std::next_permutation(p.begin(), p.end()));
  return out;
}

// How a head is exported: mesh coordinates = scale x turn x face-frame coordinates.
struct Export {
  const char* name;
  Eigen::Matrix3d turn;
  double scale;
};

Eigen::Matrix3d rows(std::initializer_list<std::initializer_list<double>> values) {
  Eigen::Matrix3d m;
  int i = 0;
  for (const auto& row : values) {
    int j = 0;
    for (double v : row) m(i, j++) = v;
    ++i;
  }
  return m;
}

// Z-up facing -y (Blender's front view), Z-up facing +y, Y-up facing -z; centimetres to mm.
const std::vector<Export>& exports() {
  static const std::vector<Export> list{
      {"Z-up, facing -y, mm", rows({{1, 0, 0}, {0, 0, -1}, {0, 1, 0}}), 10.0},
      {"Z-up, facing +y, mm", rows({{-1, 0, 0}, {0, 0, 1}, {0, 1, 0}}), 10.0},
      {"Y-up, facing -z, mm", rows({{-1, 0, 0}, {0, 1, 0}, {0, 0, -1}}), 10.0},
  };
  return list;
}

HeadMesh exported(const HeadMesh& mesh, const Export& e) {
  HeadMesh out = mesh;
  out.positions = (e.scale * e.turn * mesh.positions.cast<double>()).cast<float>();
  out.normals = (e.turn * mesh.normals.cast<double>()).cast<float>();
  return out;
}

// The file as it reads for the exported mesh: every coordinate and length it gives.
rigging::FeaturePointFile exported(rigging::FeaturePointFile fdp, const Export& e) {
  auto map = [&](std::optional<Eigen::Vector3d>& x) {
    if (x) x = e.scale * e.turn * *x;
  };
  map(fdp.eyeLeft.centre);
  map(fdp.eyeRight.centre);
  map(fdp.neckPivot);
  for (auto& [id, spec] : fdp.points) {
    map(spec.at.position);
    if (spec.radius) *spec.radius *= e.scale;
  }
  for (std::optional<rigging::SurfacePoint>* tear : {&fdp.tearLeft, &fdp.tearRight})
    if (*tear) map((*tear)->position);
  return fdp;
}

// The path every head takes to its rig (rigHead, lacrima-rig): validate, face frame, build,
// rig.json.
struct Rigged {
  std::unique_ptr<HeadMesh> mesh;  // the rig points at it
  rigging::FaceFrame frame;
  rigging::BuiltRig rig;
  QJsonObject json;
  Warnings warnings;
};

Rigged rig(const HeadMesh& mesh, const rigging::FeaturePointFile& file) {
  Rigged r;
  r.mesh = std::make_unique<HeadMesh>(mesh);
  rigging::FeaturePointFile fdp = rigging::validateFeaturePoints(file, *r.mesh, &r.warnings);
  r.frame = rigging::bringToFaceFrame(*r.mesh, fdp, &r.warnings);
  r.rig = rigging::buildRig(*r.mesh, fdp);
  r.json = QJsonDocument::fromJson(
               QByteArray::fromStdString(rigging::rigDescriptionJson(*r.mesh, r.rig, {}, r.frame)))
               .object();
  return r;
}

// The value at `keys` below `v` (objects only).
QJsonValue at(QJsonValue v, std::initializer_list<QString> keys) {
  for (const QString& key : keys) v = v.toObject().value(key);
  return v;
}

Eigen::Vector3d vec(const QJsonValue& v) {
  const QJsonArray a = v.toArray();
  return {a.at(0).toDouble(), a.at(1).toDouble(), a.at(2).toDouble()};
}

std::string joined(const Warnings& warnings) {
  std::string text;
  for (const Diagnostic& d : warnings) text += d.toString() + "\n";
  return text;
}

}  // namespace

class FaceFrameTest : public QObject {
  Q_OBJECT

 private slots:
  // Each of the 24 rotations is found from its own axes, and from axes turned 30 degrees off
  // them; the search's answer is always one of the 24.
  void nearestAxisRotationCoversEveryConvention() {
    const std::vector<Eigen::Matrix3d> all = axisRotations();
    QCOMPARE(all.size(), std::size_t{24});
    const Eigen::Matrix3d off =
        Eigen::AngleAxisd(30.0 * EIGEN_PI / 180.0, Eigen::Vector3d(1, 2, 3).normalized())
            .toRotationMatrix();
    for (const Eigen::Matrix3d& r : all) {
      QCOMPARE(rigging::nearestAxisRotation(r.transpose()), r);
      const Eigen::Matrix3d turned = r.transpose() * off;  // the face turned 30 degrees
      QCOMPARE(rigging::nearestAxisRotation(turned), r);
      QVERIFY(std::abs(rigging::rotationDegrees(r * turned) - 30.0) < 1e-9);
    }
  }

  // A = [left up forward] from two eyes and a mouth; degenerate input gives none, never NaN.
  void faceAxesFromEyesAndMouth() {
    const auto axes = rigging::faceAxes({1, 0, 0}, {-1, 0, 0}, {0, -2, 0.5});
    QVERIFY(axes);
    QVERIFY((axes->col(0) - Eigen::Vector3d(1, 0, 0)).norm() < 1e-15);
    QVERIFY((axes->col(1) - Eigen::Vector3d(0, 2, -0.5).normalized()).norm() < 1e-15);
    QVERIFY(std::abs(axes->determinant() - 1.0) < 1e-12);
    QCOMPARE(rigging::nearestAxisRotation(*axes), Eigen::Matrix3d::Identity());
    // Z-up, facing -y: left is still +x, up +z, forward -y.
    const auto zUp = rigging::faceAxes({1, 0, 0}, {-1, 0, 0}, {0, 0, -2});
    QVERIFY(zUp);
    QCOMPARE(rigging::nearestAxisRotation(*zUp), exports()[0].turn.transpose());
    const double nan = std::numeric_limits<double>::quiet_NaN();
    QVERIFY(!rigging::faceAxes({1, 0, 0}, {1, 0, 0}, {0, -2, 0}));  // one eye
    QVERIFY(!rigging::faceAxes({1, 0, 0}, {-1, 0, 0}, {3, 0, 0}));  // mouth on the eye line
    QVERIFY(!rigging::faceAxes({1, 0, 0}, {-1, 0, 0}, {0, 0, 0}));  // mouth between the eyes
    QVERIFY(!rigging::faceAxes({nan, 0, 0}, {-1, 0, 0}, {0, -2, 0}));
    QVERIFY(!rigging::faceAxes({1e300, 0, 0}, {-1e300, 0, 0}, {0, -1e300, 0}));  // overflow
  }

  // Rotating by a member of G24 and back is exact, for positions and vectors alike.
  void axisRotationIsExact() {
    const Eigen::Matrix3Xf points = Eigen::Matrix3Xf::Random(3, 200) * 1234.5f;
    for (const Eigen::Matrix3d& r : axisRotations()) {
      Eigen::Matrix3Xf turned = points;
      rigging::applyAxisRotation(r, turned);
      QVERIFY(turned.isApprox((r.cast<float>() * points), 0.0f));
      rigging::applyAxisRotation(r.transpose(), turned);
      QVERIFY(turned == points);
      const Eigen::Vector3d x(0.1, -7.3, 1e-9);
      QVERIFY(rigging::applyAxisRotation(r.transpose(), rigging::applyAxisRotation(r, x)) == x);
    }
  }

  // The default head is modelled in the face frame: rotation I, small tilt, nothing touched.
  void defaultHeadFrameIsTheIdentity() {
    if (!rigging::defaultHeadAvailable()) LACRIMA_SKIP_WITHOUT_DEFAULT_HEAD();
    const HeadMesh head = rigging::loadDefaultHead();
    rigging::FeaturePointFile fdp = rigging::validateFeaturePoints(
        rigging::readFeaturePointFile(kDefaultFdp.toStdString()), head, nullptr);
    HeadMesh copy = head;
    Warnings warnings;
    const rigging::FaceFrame frame = rigging::bringToFaceFrame(copy, fdp, &warnings);
    qInfo("default head: face tilted %.2f degrees from the axes", frame.tiltDegrees);
    QVERIFY(frame.wasMeasured);
    QCOMPARE(frame.rotation, Eigen::Matrix3d::Identity());
    QVERIFY(frame.tiltDegrees < 10.0);
    QVERIFY2(warnings.empty(), joined(warnings).c_str());
    QVERIFY(copy.positions == head.positions);  // bit for bit
    QVERIFY(copy.normals == head.normals);
  }

  // The ICT head as exported in three other conventions, in millimetres: the frame found is
  // the inverse of the export's turn, and rig.json lists the same feature points, eye centres,
  // neck pivot, tear sources and FAPU, up to rounding and the scale.
  void ictHeadInAnyConventionRigsTheSame() {
    LACRIMA_REQUIRE_SHARED(kIctMesh);
    const HeadMesh ict = rigging::importHeadMesh(kIctMesh.toStdString());
    rigging::FeaturePointFile fdp = rigging::validateFeaturePoints(
        rigging::readFeaturePointFile(kIctFdp.toStdString()), ict, nullptr);
    rigging::recordPositions(fdp, ict);
    const Rigged original = rig(ict, fdp);
    qInfo("ICT head: face tilted %.2f degrees from the axes", original.frame.tiltDegrees);
    QCOMPARE(original.frame.rotation, Eigen::Matrix3d::Identity());
    const double es0 = original.rig.fapu.es0;

    for (const Export& e : exports()) {
      const Rigged turned = rig(exported(ict, e), exported(fdp, e));
      QVERIFY2(turned.warnings.size() == original.warnings.size(),
               (e.name + std::string(": ") + joined(turned.warnings)).c_str());
      QCOMPARE(turned.frame.rotation, e.turn.transpose());
      // acos is steep near 0: float rounding of the scaled mesh shows as ~1e-5 degrees.
      QVERIFY(std::abs(turned.frame.tiltDegrees - original.frame.tiltDegrees) < 1e-3);
      const double tolerance = 1e-5 * e.scale * es0;  // float rounding of the scaled mesh
      double worst = 0;
      auto same = [&](const Eigen::Vector3d& a, const Eigen::Vector3d& b, const QString& what) {
        worst = std::max(worst, (a - e.scale * b).norm());
        QVERIFY2((a - e.scale * b).norm() <= tolerance,
                 qPrintable(QString("%1: %2").arg(e.name, what)));
      };
      const QJsonObject points = at(turned.json, {"feature_points"}).toObject();
      const QJsonObject reference = at(original.json, {"feature_points"}).toObject();
      QCOMPARE(points.keys(), reference.keys());
      QVERIFY(points.size() >= 40);  // every point of the ICT file
      for (const QString& id : reference.keys())
        same(vec(points[id].toObject()["position"]), vec(reference[id].toObject()["position"]), id);
      for (const char* side : {"left", "right"}) {
        same(vec(at(turned.json, {"eyes", side, "centre"})),
             vec(at(original.json, {"eyes", side, "centre"})), QString("eye ") + side);
        same(vec(at(turned.json, {"tear_sources", side, "position"})),
             vec(at(original.json, {"tear_sources", side, "position"})), QString("tears ") + side);
      }
      same(vec(at(turned.json, {"neck_pivot"})), vec(at(original.json, {"neck_pivot"})),
           "neck pivot");
      for (const char* unit : {"IRISD0", "ES0", "ENS0", "MNS0", "MW0"}) {
        const double a = at(turned.json, {"fapu", unit}).toDouble();
        const double b = at(original.json, {"fapu", unit}).toDouble();
        QVERIFY2(std::abs(a - e.scale * b) <= 1e-5 * e.scale * b, unit);
      }
      // rig.json says which rotation brought the head into the frame.
      const QJsonArray rotation = at(turned.json, {"face_frame", "rotation"}).toArray();
      for (int i = 0; i < 3; ++i)
        QCOMPARE(vec(rotation.at(i)), Eigen::Vector3d(e.turn.transpose().row(i)));
      qInfo("%s: rotation found, largest difference %.3g (ES0 %.3g)", e.name, worst,
            turned.rig.fapu.es0);
    }
  }

  // A face modelled turned (35 degrees about the vertical) stays as modelled: no axis rotation,
  // a warning with the angle. Degenerate points leave the head alone with a warning.
  void turnedOrUnmeasurableFacesAreWarnedAbout() {
    if (!rigging::defaultHeadAvailable()) LACRIMA_SKIP_WITHOUT_DEFAULT_HEAD();
    const HeadMesh head = rigging::loadDefaultHead();
    const rigging::FeaturePointFile fdp = rigging::validateFeaturePoints(
        rigging::readFeaturePointFile(kDefaultFdp.toStdString()), head, nullptr);
    HeadMesh turned = head;
    const Eigen::Matrix3f yaw =
        Eigen::AngleAxisf(35.0f * static_cast<float>(EIGEN_PI) / 180.0f, Eigen::Vector3f::UnitY())
            .toRotationMatrix();
    turned.positions = yaw * head.positions;
    turned.normals = yaw * head.normals;
    rigging::FeaturePointFile copy = fdp;
    Warnings warnings;
    const rigging::FaceFrame frame = rigging::bringToFaceFrame(turned, copy, &warnings);
    QCOMPARE(frame.rotation, Eigen::Matrix3d::Identity());
    QVERIFY(std::abs(frame.tiltDegrees - 35.0) < 5.0);
    QCOMPARE(warnings.size(), std::size_t{1});
    QVERIFY2(warnings[0].message.find("the face is turned 3") != std::string::npos,
             warnings[0].message.c_str());

    // Mouth corners missing and the chin on the eye line: nothing to measure from.
    rigging::FeaturePointFile partial;
    partial.path = "partial.fdp.json";
    partial.points["3.5"] = fdp.points.at("3.5");
    partial.points["3.6"] = fdp.points.at("3.6");
    HeadMesh same = head;
    warnings.clear();
    const rigging::FaceFrame none = rigging::bringToFaceFrame(same, partial, &warnings);
    QVERIFY(!none.wasMeasured);
    QCOMPARE(none.rotation, Eigen::Matrix3d::Identity());
    QVERIFY(same.positions == head.positions);
    QCOMPARE(warnings.size(), std::size_t{1});
    QVERIFY(warnings[0].toString().starts_with("partial.fdp.json: cannot tell which way"));
  }
};

QTEST_GUILESS_MAIN(FaceFrameTest)
#include "FaceFrameTest.moc"
