// The orbit camera's view frame (OrbitView.h), engine-free: faceFrameRotation makes any usable
// frame a rotation and refuses unusable ones; framing sees a head without eyes whole from the
// reset direction whatever its units, and a head turned by R framed with the frame R is the same
// view turned by R; eyes that do not fit the frame fall back to the box.
#include <lacrima/scene/OrbitView.h>

#include <QtTest>

#include <cmath>
#include <limits>
#include <numbers>

using namespace lacrima;
using namespace lacrima::scene;

namespace {

// A box head `size` (x, y, z), centred at `centre`, with optional eye boxes at the front top.
HeadMesh boxHead(const Eigen::Vector3f& size, const Eigen::Vector3f& centre, bool eyes) {
  HeadMesh head;
  std::vector<Eigen::Vector3f> points;
  auto addBox = [&](const std::string& name, const Eigen::Vector3f& mid,
                    const Eigen::Vector3f& half) {
    HeadSubmesh sub;
    sub.name = name;
    sub.firstVertex = static_cast<int>(points.size());
    sub.vertexCount = 8;
    for (int k = 0; k < 8; ++k)
      points.push_back(mid + Eigen::Vector3f((k & 1) ? half.x() : -half.x(),
                                             (k & 2) ? half.y() : -half.y(),
                                             (k & 4) ? half.z() : -half.z()));
    const int f = sub.firstVertex;
    for (const auto& [a, b, c] : {std::array{0, 1, 3},
                                  {0, 3, 2},
                                  {4, 6, 7},
                                  {4, 7, 5},
                                  {0, 4, 5},
                                  {0, 5, 1},
                                  {2, 3, 7},
                                  {2, 7, 6},
                                  {0, 2, 6},
                                  {0, 6, 4},
                                  {1, 5, 7},
                                  {1, 7, 3}})
      sub.triangles.emplace_back(f + a, f + b, f + c);
    head.submeshes.push_back(sub);
  };
  addBox("skin", centre, 0.5f * size);
  if (eyes) {
    const Eigen::Vector3f eyeHalf = 0.05f * size;
    for (float side : {+1.0f, -1.0f})
      addBox(side > 0 ? "eye_l" : "eye_r",
             centre + Eigen::Vector3f(side * 0.2f * size.x(), 0.15f * size.y(), 0.4f * size.z()),
             eyeHalf);
  }
  head.positions.resize(3, static_cast<Eigen::Index>(points.size()));
  for (std::size_t i = 0; i < points.size(); ++i) head.positions.col(Eigen::Index(i)) = points[i];
  head.computeNormals();
  return head;
}

HeadMesh transformed(HeadMesh head, const Eigen::Matrix3f& rotation, float scale) {
  head.positions = scale * rotation * head.positions;
  head.computeNormals();
  return head;
}

// The largest angle, over all vertices, between the view axis and the direction to a vertex,
// as a fraction of half the vertical field of view (both axes: a landscape view is wider).
double fillOfView(const OrbitView& view, const HeadMesh& head) {
  const Eigen::Matrix3d axes = view.orientation().toRotationMatrix();
  const double tangent = std::tan(0.5 * view.fovYDegrees * std::numbers::pi / 180);
  double fill = 0;
  for (int v = 0; v < head.vertexCount(); ++v) {
    const Eigen::Vector3d c =
        axes.transpose() * (head.positions.col(v).cast<double>() - view.eye());
    if (!(c.z() < 0)) return std::numeric_limits<double>::infinity();  // behind the camera
    fill = std::max(fill, std::max(std::abs(c.x()), std::abs(c.y())) / (-c.z() * tangent));
  }
  return fill;
}

}  // namespace

class OrbitFrameTest : public QObject {
  Q_OBJECT

 private slots:
  void faceFrameRotationMakesRotations() {
    QVERIFY(faceFrameRotation(Eigen::Matrix3d::Identity()).isIdentity());
    // Z-up, facing -y, given with sloppy lengths and a skewed forward axis.
    Eigen::Matrix3d sloppy;
    sloppy.col(0) = Eigen::Vector3d(3, 0, 0);
    sloppy.col(1) = Eigen::Vector3d(0, 0, 2);
    sloppy.col(2) = Eigen::Vector3d(0, -5, 0.4);
    const Eigen::Matrix3d r = faceFrameRotation(sloppy);
    QVERIFY((r.transpose() * r).isIdentity(1e-12));
    QVERIFY(std::abs(r.determinant() - 1) < 1e-12);
    QVERIFY(r.col(1).isApprox(Eigen::Vector3d::UnitZ()));   // up kept
    QVERIFY(r.col(2).isApprox(-Eigen::Vector3d::UnitY()));  // forward made perpendicular
    QVERIFY(r.col(0).isApprox(Eigen::Vector3d::UnitX()));   // side completes it
    // Unusable: identity, never NaN.
    Eigen::Matrix3d parallel = Eigen::Matrix3d::Identity();
    parallel.col(2) = parallel.col(1);
    QVERIFY(faceFrameRotation(parallel).isIdentity());
    QVERIFY(faceFrameRotation(Eigen::Matrix3d::Zero()).isIdentity());
    Eigen::Matrix3d broken = Eigen::Matrix3d::Identity();
    broken(0, 1) = std::numeric_limits<double>::quiet_NaN();
    QVERIFY(faceFrameRotation(broken).isIdentity());
  }

  void aHeadWithoutEyesIsSeenWholeInAnyUnitAndAxes() {
    const HeadMesh cm = boxHead({16, 24, 20}, {0, 160, 2}, false);
    const Eigen::Matrix3f zUp =
        Eigen::AngleAxisf(float(std::numbers::pi / 2), Eigen::Vector3f::UnitX()).matrix();
    for (const HeadMesh& head : {cm, transformed(cm, zUp, 10), transformed(cm, zUp, 0.01f)}) {
      const OrbitView view = OrbitView::framing(head);
      const double fill = fillOfView(view, head);
      QVERIFY2(std::abs(fill - 0.85) < 1e-9, qPrintable(QString::number(fill)));
      QVERIFY(view.minDistance < view.distance && view.distance < view.maxDistance);
    }
  }

  void aTurnedHeadInItsFrameIsTheSameViewTurned() {
    const HeadMesh upright = boxHead({2, 2.6, 2.2}, {0.3f, 1, -0.2f}, true);
    const OrbitView reference = OrbitView::framing(upright);
    // Z up, facing -y, in millimetres: R takes the face frame to the head's axes.
    Eigen::Matrix3d r;
    r.col(0) = Eigen::Vector3d::UnitX();
    r.col(1) = Eigen::Vector3d::UnitZ();
    r.col(2) = -Eigen::Vector3d::UnitY();
    const HeadMesh turned = transformed(upright, r.cast<float>(), 100);
    const OrbitView view = OrbitView::framing(turned, r);
    QVERIFY(view.frame.isApprox(r));
    QVERIFY(view.target.isApprox(100 * r * reference.target, 1e-6));
    QVERIFY(std::abs(view.distance - 100 * reference.distance) < 1e-6 * view.distance);
    QVERIFY((view.eye() - view.target)
                .normalized()
                .isApprox(r * (reference.eye() - reference.target).normalized(), 1e-9));
    // The camera's up is the face's up, turned: the orbit turns about it.
    const Eigen::Matrix3d axes = view.orientation().toRotationMatrix();
    QVERIFY(axes.col(1).isApprox(r * reference.orientation().toRotationMatrix().col(1), 1e-9));
    OrbitView turnedAround = view;
    turnedAround.orbit(90, 0);
    QVERIFY(std::abs((turnedAround.eye() - view.target).dot(r.col(1)) -
                     (view.eye() - view.target).dot(r.col(1))) < 1e-9 * view.distance);
  }

  void eyesThatDoNotFitTheFrameFallBackToTheBox() {
    const HeadMesh upright = boxHead({2, 2.6, 2.2}, {0, 0, 0}, true);
    const Eigen::Matrix3f zUp =
        Eigen::AngleAxisf(float(std::numbers::pi / 2), Eigen::Vector3f::UnitX()).matrix();
    const HeadMesh turned = transformed(upright, zUp, 1);
    // Seen through the identity the eyes sit at the front of the box, not above its middle:
    // the eyes' framing would cut the head; the box's sees it whole.
    const OrbitView view = OrbitView::framing(turned);
    QVERIFY(fillOfView(view, turned) <= 0.85 + 1e-9);
    QVERIFY(view.target.isZero(1e-9));  // the box's centre
    // Upright, the eyes frame it: aimed 0.03 head heights below the eyes (at y = 0.15 of 2.6).
    const OrbitView byEyes = OrbitView::framing(upright);
    QVERIFY(std::abs(byEyes.target.y() - (0.15 * 2.6 - 0.03 * 2.6)) < 1e-6);
  }
};

QTEST_GUILESS_MAIN(OrbitFrameTest)
#include "OrbitFrameTest.moc"
