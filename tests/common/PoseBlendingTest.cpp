#include "SyntheticHead.h"

#include <lacrima/common/FapTable.h>
#include <lacrima/common/PoseBaking.h>
#include <lacrima/common/PoseSet.h>

#include <QtTest>

#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <stdexcept>

using namespace lacrima;
using synthetic::buildHead;

namespace {

// The FAP value that turns by `degrees` (AU = 1e-5 rad).
float turnValue(double degrees) { return float(degrees * std::numbers::pi / 180.0 / 1e-5); }

float& channel(FapValues& values, int fap) { return values[size_t(channelIndex(fap))]; }

// A head plus two probe vertices (on no triangle) 1 unit in front of and above the neck pivot.
struct ProbedHead {
  synthetic::Head head = buildHead();
  int front = 0, top = 0;

  ProbedHead() {
    const int n = head.mesh.vertexCount();
    head.mesh.positions.conservativeResize(3, n + 2);
    head.mesh.positions.col(n) = synthetic::neckPivot() + Eigen::Vector3f::UnitZ();
    head.mesh.positions.col(n + 1) = synthetic::neckPivot() + Eigen::Vector3f::UnitY();
    head.mesh.submeshes.push_back({"probes", -1, n, 2, {}});
    head.mesh.computeNormals();
    front = n;
    top = n + 1;
  }
};

// Every channel at a deterministic value within half its slider range; tears at 0.
FapValues mixedFrame(unsigned seed) {
  std::mt19937 random(seed);
  FapValues values{};
  for (int fap = 3; fap <= kFapCount; ++fap) {
    const FapInfo& info = fapInfo(fap);
    const double t = double(random() % 10001) / 10000.0;
    channel(values, fap) =
        float(std::round(0.5 * (info.sliderMin + t * (info.sliderMax - info.sliderMin))));
  }
  return values;
}

bool allUnitLength(const Eigen::Matrix3Xf& normals) {
  return ((normals.colwise().norm().array() - 1.0f).abs() < 1e-5f).all();
}

}  // namespace

class PoseBlendingTest : public QObject {
  Q_OBJECT

 private slots:
  void zeroValuesReproduceTheNeutralHeadExactly() {
    const synthetic::Head head = buildHead();
    const PoseBlender blender(head.mesh, bakePoses(head.rig()));
    Eigen::Matrix3Xf positions, normals;
    blender.blend(FapValues{}, positions, normals);
    QVERIFY(positions == head.mesh.positions);
    QVERIFY(normals == head.mesh.normals);
  }

  void linearChannelsSuperpose() {
    const synthetic::Head head = buildHead();
    const PoseSet set = bakePoses(head.rig());
    const PoseBlender blender(head.mesh, set);
    FapValues values{};
    channel(values, 3) = 700.0f;    // jaw and
    channel(values, 52) = -300.0f;  // lower lip overlap around the chin
    Eigen::Matrix3Xf positions, normals;
    blender.blend(values, positions, normals);
    Eigen::Matrix3Xf expected = head.mesh.positions;
    for (int fap : {3, 52}) {
      const VertexPose& pose = set.poses[size_t(channelIndex(fap))];
      for (size_t k = 0; k < pose.vertices.size(); ++k)
        expected.col(pose.vertices[k]) += channel(values, fap) * pose.offsets.col(Eigen::Index(k));
    }
    QVERIFY((positions - expected).cwiseAbs().maxCoeff() < 1e-6f);
  }

  void headYawKeepsEveryDistanceToThePivot() {
    const synthetic::Head head = buildHead();
    const PoseBlender blender(head.mesh, bakePoses(head.rig()));
    FapValues values{};
    channel(values, 49) = turnValue(60);
    Eigen::Matrix3Xf positions, normals;
    blender.blend(values, positions, normals);
    const Eigen::Vector3f pivot = synthetic::neckPivot();
    const Eigen::VectorXf before = (head.mesh.positions.colwise() - pivot).colwise().norm();
    const Eigen::VectorXf after = (positions.colwise() - pivot).colwise().norm();
    QVERIFY((before - after).cwiseAbs().maxCoeff() < 1e-5f);
    // and it did turn: the nose tip swings 60 degrees about the vertical through the pivot
    const int nose = head.featureVertex.at("9.3");
    const Eigen::Vector3f from = head.mesh.positions.col(nose) - pivot,
                          to = positions.col(nose) - pivot;
    const float cosine = Eigen::Vector2f(from.x(), from.z())
                             .normalized()
                             .dot(Eigen::Vector2f(to.x(), to.z()).normalized());
    QVERIFY(std::abs(cosine - 0.5f) < 1e-5f);
    QVERIFY(to.x() > from.x());  // positive yaw faces toward the face's left
  }

  // 90-degree values are exact rotations, not linearised offsets, and follow the table's axes:
  // yaw +y (front -> face's left), pitch +x (front -> down), roll +z (top -> face's right).
  void ninetyDegreeHeadTurnsAreExact() {
    const ProbedHead probed;
    const PoseBlender blender(probed.head.mesh, bakePoses(probed.head.rig()));
    const Eigen::Vector3f pivot = synthetic::neckPivot();
    auto turned = [&](FapValues values, int probe) {
      Eigen::Matrix3Xf positions, normals;
      blender.blend(values, positions, normals);
      return Eigen::Vector3f(positions.col(probe) - pivot);
    };
    auto near = [](const Eigen::Vector3f& a, const Eigen::Vector3f& b) {
      return (a - b).norm() < 1e-5f;
    };
    FapValues yaw{}, pitch{}, roll{}, yawPitch{};
    channel(yaw, 49) = turnValue(90);
    channel(pitch, 48) = turnValue(90);
    channel(roll, 50) = turnValue(90);
    QVERIFY(near(turned(yaw, probed.front), {1, 0, 0}));
    QVERIFY(near(turned(pitch, probed.front), {0, -1, 0}));
    QVERIFY(near(turned(roll, probed.top), {-1, 0, 0}));
    QVERIFY(near(turned(roll, probed.front), {0, 0, 1}));

    // The documented order R_yaw * R_pitch * R_roll: nod first (front -> down, top -> front),
    // then yaw about the neck's vertical (down stays down, front -> face's left).
    channel(yawPitch, 49) = turnValue(90);
    channel(yawPitch, 48) = turnValue(90);
    QVERIFY(near(turned(yawPitch, probed.front), {0, -1, 0}));
    QVERIFY(near(turned(yawPitch, probed.top), {1, 0, 0}));
  }

  void eyeballTurnsOnlyItsOwnVerticesAboutItsCentre() {
    const synthetic::Head head = buildHead();
    const PoseBlender blender(head.mesh, bakePoses(head.rig()));
    const int pole = head.featureVertex.at("3.5");
    const Eigen::Vector3f centre = head.eyeLeft.centre;
    std::vector<char> inLeftEye(size_t(head.mesh.vertexCount()), 0);
    for (int v : head.eyeLeft.vertices) inLeftEye[size_t(v)] = 1;

    for (int fap : {23, 25}) {
      FapValues values{};
      channel(values, fap) = turnValue(20);
      Eigen::Matrix3Xf positions, normals;
      blender.blend(values, positions, normals);
      for (int v = 0; v < head.mesh.vertexCount(); ++v) {
        if (!inLeftEye[size_t(v)]) {
          QVERIFY(positions.col(v) == head.mesh.positions.col(v));
          continue;
        }
        const float before = (head.mesh.positions.col(v) - centre).norm();
        QVERIFY(std::abs((positions.col(v) - centre).norm() - before) < 1e-6f);
      }
      const Eigen::Vector3f gaze = (positions.col(pole) - centre) / synthetic::kEyeRadius;
      const float s = std::sin(float(20 * std::numbers::pi / 180));
      if (fap == 23)
        QVERIFY((gaze - Eigen::Vector3f(s, 0, std::sqrt(1 - s * s))).norm() < 1e-5f);
      else
        QVERIFY((gaze - Eigen::Vector3f(0, -s, std::sqrt(1 - s * s))).norm() < 1e-5f);
    }

    // The right eye's yaw also looks toward the face's left.
    FapValues values{};
    channel(values, 24) = turnValue(20);
    Eigen::Matrix3Xf positions, normals;
    blender.blend(values, positions, normals);
    const int rightPole = head.featureVertex.at("3.6");
    QVERIFY(positions(0, rightPole) > head.mesh.positions(0, rightPole) + 0.05f);
    QVERIFY(positions.col(pole) == head.mesh.positions.col(pole));
  }

  // Yaw then pitch about the turned horizontal axis: at 90 degrees of yaw a positive pitch
  // still looks down (with the other order it would do nothing to the gaze).
  void eyePitchIsAboutTheTurnedAxis() {
    const synthetic::Head head = buildHead();
    const PoseBlender blender(head.mesh, bakePoses(head.rig()));
    FapValues values{};
    channel(values, 23) = turnValue(90);
    channel(values, 25) = turnValue(90);
    Eigen::Matrix3Xf positions, normals;
    blender.blend(values, positions, normals);
    const Eigen::Vector3f gaze = positions.col(head.featureVertex.at("3.5")) - head.eyeLeft.centre;
    QVERIFY((gaze - Eigen::Vector3f(0, -synthetic::kEyeRadius, 0)).norm() < 1e-5f);
  }

  // A thrust eyeball turns about its displaced centre, not about the empty socket.
  void thrustEyeballTurnsInPlace() {
    const synthetic::Head head = buildHead();
    const PoseBlender blender(head.mesh, bakePoses(head.rig()));
    FapValues values{};
    channel(values, 27) = 400.0f;
    channel(values, 23) = turnValue(30);
    channel(values, 25) = turnValue(-15);
    Eigen::Matrix3Xf positions, normals;
    blender.blend(values, positions, normals);
    const Eigen::Vector3f centre =
        head.eyeLeft.centre + Eigen::Vector3f(0, 0, float(400 * head.fapu.unitValue(FapUnit::ES)));
    for (int v : head.eyeLeft.vertices) {
      const float before = (head.mesh.positions.col(v) - head.eyeLeft.centre).norm();
      QVERIFY(std::abs((positions.col(v) - centre).norm() - before) < 1e-5f);
    }
  }

  void normalsAreUnitAndEqualToFreshNormals() {
    const synthetic::Head head = buildHead();
    const PoseBlender blender(head.mesh, bakePoses(head.rig()));
    Eigen::Matrix3Xf positions, normals;
    blender.blend(mixedFrame(7), positions, normals);
    QVERIFY(allUnitLength(normals));
    HeadMesh fresh = head.mesh;
    fresh.positions = positions;
    fresh.computeNormals();
    QVERIFY((normals - fresh.normals).cwiseAbs().maxCoeff() < 1e-6f);
    QVERIFY((normals - head.mesh.normals).cwiseAbs().maxCoeff() > 0.05f);  // they did change
  }

  // With every channel in use, the mirrored frame (mirroredFap, negated where mirrorNegates)
  // gives the mirror image of the head: rotations, pupils and tongue included.
  void mirroredValuesGiveTheMirroredHead() {
    const synthetic::Head head = buildHead();
    const PoseBlender blender(head.mesh, bakePoses(head.rig()));
    const FapValues values = mixedFrame(11);
    FapValues mirrored{};
    for (int fap = 3; fap <= kFapCount; ++fap)
      channel(mirrored, mirroredFap(fap)) =
          (mirrorNegates(fap) ? -1.0f : 1.0f) * values[size_t(channelIndex(fap))];
    Eigen::Matrix3Xf positions, normals, image, imageNormals;
    blender.blend(values, positions, normals);
    blender.blend(mirrored, image, imageNormals);
    float worst = 0;
    for (int v = 0; v < head.mesh.vertexCount(); ++v) {
      Eigen::Vector3f expected = positions.col(v);
      expected.x() = -expected.x();
      worst = std::max(worst, (image.col(head.mirror[size_t(v)]) - expected).norm());
    }
    QVERIFY2(worst < 1e-5f, qPrintable(QString("worst mirror error %1").arg(worst)));
  }

  void hugeAndNonFiniteValuesStayFinite() {
    const synthetic::Head head = buildHead();
    const PoseBlender blender(head.mesh, bakePoses(head.rig()));
    Eigen::Matrix3Xf positions, normals;
    for (float huge : {1e6f, -1e7f, 1e7f, 1e30f, std::numeric_limits<float>::max()}) {
      FapValues values{};
      values.fill(huge);
      blender.blend(values, positions, normals);
      QVERIFY2(positions.allFinite() && normals.allFinite(), qPrintable(QString::number(huge)));
      QVERIFY(allUnitLength(normals));
    }

    // Not-a-number and infinities count as 0: the other channels still act normally.
    FapValues values = mixedFrame(3);
    Eigen::Matrix3Xf reference, referenceNormals;
    blender.blend(values, reference, referenceNormals);
    channel(values, 1) = std::numeric_limits<float>::quiet_NaN();
    for (int fap : {3, 24, 29, 47, 48}) {
      FapValues poisoned = values;
      channel(poisoned, fap) = fap % 2 ? std::numeric_limits<float>::quiet_NaN()
                                       : -std::numeric_limits<float>::infinity();
      FapValues zeroed = values;
      channel(zeroed, fap) = 0;
      blender.blend(poisoned, positions, normals);
      blender.blend(zeroed, reference, referenceNormals);
      QVERIFY(positions == reference && normals == referenceNormals);
    }
  }

  void outputBuffersAreReusedAcrossFrames() {
    const synthetic::Head head = buildHead();
    const PoseBlender blender(head.mesh, bakePoses(head.rig()));
    Eigen::Matrix3Xf positions(3, 5), normals;  // wrong size: resized once
    blender.blend(mixedFrame(1), positions, normals);
    QCOMPARE(positions.cols(), Eigen::Index(head.mesh.vertexCount()));
    QCOMPARE(normals.cols(), Eigen::Index(head.mesh.vertexCount()));
    const float* positionData = positions.data();
    const float* normalData = normals.data();
    for (unsigned frame = 2; frame < 6; ++frame) {
      blender.blend(mixedFrame(frame), positions, normals);
      QCOMPARE(positions.data(), positionData);
      QCOMPARE(normals.data(), normalData);
    }
  }

  void posesThatDoNotFitTheHeadAreRejected() {
    const synthetic::Head head = buildHead();
    const PoseSet good = bakePoses(head.rig());

    PoseSet wrongCount = good;
    wrongCount.vertexCount += 1;
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, PoseBlender(head.mesh, wrongCount));

    PoseSet outOfRange = good;
    outOfRange.poses[size_t(channelIndex(3))].vertices.back() = head.mesh.vertexCount();
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, PoseBlender(head.mesh, outOfRange));

    PoseSet shortOffsets = good;
    shortOffsets.poses[size_t(channelIndex(4))].offsets.resize(3, 1);
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, PoseBlender(head.mesh, shortOffsets));

    PoseSet badCentre = good;
    badCentre.eyeLeft.centre.x() = std::numeric_limits<float>::quiet_NaN();
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, PoseBlender(head.mesh, badCentre));

    // An empty set fits any head and blends to the neutral one.
    const PoseBlender empty(head.mesh, PoseSet{});
    Eigen::Matrix3Xf positions, normals;
    empty.blend(mixedFrame(5), positions, normals);
    QVERIFY(positions == head.mesh.positions);
  }
};

QTEST_GUILESS_MAIN(PoseBlendingTest)
#include "PoseBlendingTest.moc"
