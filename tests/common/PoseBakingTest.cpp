#include "SyntheticHead.h"

#include <lacrima/common/FapTable.h>
#include <lacrima/common/PoseBaking.h>
#include <lacrima/common/PoseSet.h>

#include <QtTest>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>
#include <vector>

using namespace lacrima;
using synthetic::buildHead;

namespace {

const VertexPose& poseOf(const PoseSet& set, int fap) {
  return set.poses[static_cast<size_t>(channelIndex(fap))];
}

std::vector<int> translationalFaps() {
  std::vector<int> faps;
  for (int fap = 3; fap <= kFapCount; ++fap)
    if (fapInfo(fap).motion == FapMotion::Translation) faps.push_back(fap);
  return faps;
}

// Whether some warning mentions every part.
bool warned(const PoseBakeReport& report, std::initializer_list<std::string> parts) {
  return std::any_of(report.warnings.begin(), report.warnings.end(), [&](const std::string& w) {
    return std::all_of(parts.begin(), parts.end(),
                       [&](const std::string& p) { return w.find(p) != std::string::npos; });
  });
}

std::string allWarnings(const PoseBakeReport& report) {
  std::string all;
  for (const std::string& w : report.warnings) all += w + "\n";
  return all;
}

// The offset a pose gives vertex v, or zero when v is not in it.
Eigen::Vector3f offsetOf(const VertexPose& pose, int v) {
  const auto it = std::lower_bound(pose.vertices.begin(), pose.vertices.end(), v);
  if (it == pose.vertices.end() || *it != v) return Eigen::Vector3f::Zero();
  return pose.offsets.col(it - pose.vertices.begin());
}

// Distance from the axis through the eye's centre and its pupil point.
double axisDistance(const Eigen::Vector3f& p, const Eigen::Vector3f& centre,
                    const Eigen::Vector3f& pupil) {
  const Eigen::Vector3d a = (pupil - centre).cast<double>().normalized();
  const Eigen::Vector3d d = (p - centre).cast<double>();
  return (d - d.dot(a) * a).norm();
}

}  // namespace

class PoseBakingTest : public QObject {
  Q_OBJECT

 private slots:
  void completeRigBakesEveryLowLevelFapWithoutWarnings() {
    const synthetic::Head head = buildHead();
    PoseBakeReport report;
    const PoseSet set = bakePoses(head.rig(), &report);
    QVERIFY2(report.warnings.empty(), allWarnings(report).c_str());
    std::vector<int> expected(kFapCount - 2);
    std::iota(expected.begin(), expected.end(), 3);
    QCOMPARE(report.bakedFaps, expected);
    QCOMPARE(set.vertexCount, head.mesh.vertexCount());
    ChannelMask mask;
    for (int fap : expected) mask.set(size_t(channelIndex(fap)));
    QCOMPARE(set.drivenChannels(), mask);
    for (int fap : {1, 2, 23, 24, 25, 26, 48, 49, 50, 69, 70}) QVERIFY(poseOf(set, fap).empty());
  }

  // The FAP definition itself: 1024 steps move the feature point (weight 1) by X0 along its
  // direction; every other vertex of the influence by w * X0; nothing else moves at all.
  void valueOf1024MovesTheFeaturePointByOneX0() {
    const synthetic::Head head = buildHead();
    const RigInput rig = head.rig();
    const PoseBlender blender(head.mesh, bakePoses(rig));
    Eigen::Matrix3Xf positions, normals;
    for (int fap : translationalFaps()) {
      const FapInfo& info = fapInfo(fap);
      const std::string id(info.featurePoint);
      const double x0 = 1024.0 * head.fapu.unitValue(info.unit);
      FapValues values{};
      values[size_t(channelIndex(fap))] = 1024.0f;
      blender.blend(values, positions, normals);

      const int fp = head.featureVertex.at(id);
      const Eigen::Vector3d moved =
          (positions.col(fp) - head.mesh.positions.col(fp)).cast<double>();
      const Eigen::Vector3d expected = x0 * info.positiveMotion.cast<double>();
      QVERIFY2((moved - expected).norm() < 1e-4 * x0,
               qPrintable(QString("FAP %1 moved %2 by %3, expected %4 along its direction")
                              .arg(fap)
                              .arg(id.c_str())
                              .arg(moved.norm())
                              .arg(x0)));

      const FeaturePointInfluence& influence = head.influences.at(id);
      std::vector<float> weight(size_t(head.mesh.vertexCount()), 0.0f);
      for (size_t k = 0; k < influence.vertices.size(); ++k)
        weight[size_t(influence.vertices[k])] = influence.weights[k];
      for (int v = 0; v < head.mesh.vertexCount(); ++v) {
        const Eigen::Vector3d d = (positions.col(v) - head.mesh.positions.col(v)).cast<double>();
        if (weight[size_t(v)] == 0.0f) {
          QVERIFY2(
              positions.col(v) == head.mesh.positions.col(v),
              qPrintable(QString("FAP %1 moved vertex %2 outside the influence").arg(fap).arg(v)));
        } else {
          QVERIFY((d - weight[size_t(v)] * expected).norm() < 1e-4 * x0);
        }
      }
    }
  }

  void posesAreStoredSparsely() {
    const synthetic::Head head = buildHead();
    const PoseSet set = bakePoses(head.rig());
    for (int fap : translationalFaps()) {
      const VertexPose& pose = poseOf(set, fap);
      const size_t influenceSize =
          head.influences.at(std::string(fapInfo(fap).featurePoint)).vertices.size();
      QCOMPARE(pose.vertices.size(), influenceSize);
      QCOMPARE(size_t(pose.offsets.cols()), influenceSize);
      QVERIFY(influenceSize < size_t(head.mesh.vertexCount()) / 4);  // a local pose, not dense
      QVERIFY(std::is_sorted(pose.vertices.begin(), pose.vertices.end()));
      QVERIFY(std::adjacent_find(pose.vertices.begin(), pose.vertices.end()) ==
              pose.vertices.end());
    }
  }

  // On a face that is its own mirror image, FAP m = mirroredFap(n) must be the mirror image of
  // n: its pose at mirror(v) is M d_n(v) (negated where the table says so), M = diag(-1, 1, 1).
  void leftRightPairsGiveMirroredPoses() {
    const synthetic::Head head = buildHead();
    const PoseSet set = bakePoses(head.rig());
    int pairs = 0;
    for (int fap = 3; fap <= kFapCount; ++fap) {
      const VertexPose& pose = poseOf(set, fap);
      if (pose.empty()) continue;  // rotations: see the blending suite
      const VertexPose& image = poseOf(set, mirroredFap(fap));
      QCOMPARE(image.vertices.size(), pose.vertices.size());
      const float sign = mirrorNegates(fap) ? -1.0f : 1.0f;
      for (size_t k = 0; k < pose.vertices.size(); ++k) {
        const int v = pose.vertices[k];
        Eigen::Vector3f expected = sign * pose.offsets.col(Eigen::Index(k));
        expected.x() = -expected.x();
        const Eigen::Vector3f got = offsetOf(image, head.mirror[size_t(v)]);
        QVERIFY2((got - expected).norm() <= 1e-6f * std::max(1e-6f, expected.norm()),
                 qPrintable(
                     QString("FAP %1 vertex %2 vs FAP %3").arg(fap).arg(v).arg(mirroredFap(fap))));
      }
      if (mirroredFap(fap) != fap) ++pairs;
    }
    QCOMPARE(pairs, 2 * 21);  // every left/right pair of FAPs 3-68 with a linear pose
  }

  void rotationsBecomeTheRigsGroups() {
    const synthetic::Head head = buildHead();
    const PoseSet set = bakePoses(head.rig());
    std::vector<int> eyeLeft = head.eyeLeft.vertices;
    std::sort(eyeLeft.begin(), eyeLeft.end());
    QCOMPARE(set.eyeLeft.vertices, eyeLeft);
    QCOMPARE(set.eyeLeft.centre, head.eyeLeft.centre);
    QCOMPARE(set.eyeRight.centre, head.eyeRight.centre);
    QCOMPARE(set.eyeRight.vertices.size(), eyeLeft.size());
    QCOMPARE(set.head.centre, synthetic::neckPivot());
    QCOMPARE(int(set.head.vertices.size()), head.mesh.vertexCount());  // all when none given

    RigInput rig = head.rig();
    rig.headVertices = {5, 3, 3, 9};  // unsorted with a duplicate
    QCOMPARE(bakePoses(rig).head.vertices, (std::vector<int>{3, 5, 9}));
  }

  void missingInfluencesWarnInsteadOfFailing() {
    const synthetic::Head head = buildHead();
    RigInput rig = head.rig();
    rig.influences.erase("2.1");
    rig.influences["8.3"] = {};  // present but empty
    PoseBakeReport report;
    const PoseSet set = bakePoses(rig, &report);
    for (int fap : {3, 14, 15}) {
      QVERIFY(poseOf(set, fap).empty());
      QVERIFY2(warned(report, {"FAP " + std::to_string(fap) + " (", "2.1"}),
               allWarnings(report).c_str());
      QVERIFY(std::find(report.bakedFaps.begin(), report.bakedFaps.end(), fap) ==
              report.bakedFaps.end());
    }
    for (int fap : {53, 59}) {
      QVERIFY(poseOf(set, fap).empty());
      QVERIFY(warned(report, {"FAP " + std::to_string(fap) + " (", "8.3"}));
    }
    QVERIFY(!poseOf(set, 4).empty());

    // Nothing at all but the mesh: every FAP is reported, nothing throws, blending still works.
    RigInput bare;
    bare.mesh = &head.mesh;
    PoseBakeReport bareReport;
    const PoseSet empty = bakePoses(bare, &bareReport);
    QVERIFY(warned(bareReport, {"FAPU MNS", "3, 4, 5"}));
    QVERIFY(warned(bareReport, {"FAPs 23 and 25", "left"}));
    QCOMPARE(bareReport.bakedFaps, (std::vector<int>{47, 48, 49, 50}));  // tongue sub-mesh, head
    const PoseBlender blender(head.mesh, empty);
    FapValues values{};
    values.fill(500.0f);
    Eigen::Matrix3Xf positions, normals;
    blender.blend(values, positions, normals);
    QVERIFY(positions.allFinite() && normals.allFinite());
  }

  void badInfluenceEntriesAreSkippedWithAWarning() {
    const synthetic::Head head = buildHead();
    RigInput rig = head.rig();
    FeaturePointInfluence& jaw = rig.influences.at("2.1");
    const size_t valid = jaw.vertices.size();
    const int n = head.mesh.vertexCount();
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const int outside = head.featureVertex.at("10.1");  // far from the chin, so not yet listed
    const int chin = head.featureVertex.at("2.1");
    // A duplicate keeps the larger weight, whatever the order.
    jaw.vertices.insert(jaw.vertices.end(), {-1, n, outside, outside, outside, chin});
    jaw.weights.insert(jaw.weights.end(), {1.0f, 1.0f, nan, 0.0f, 2.5f, 0.25f});
    jaw.vertices.push_back(outside + 1);  // a vertex without a weight
    PoseBakeReport report;
    const PoseSet set = bakePoses(rig, &report);
    QVERIFY2(warned(report, {"2.1", "4 influence entries skipped"}), allWarnings(report).c_str());
    QVERIFY(warned(report, {"2.1", "1 weights above 1 clamped"}));
    QVERIFY(warned(report, {"2.1", "unmatched"}));
    const VertexPose& pose = poseOf(set, 3);
    QCOMPARE(pose.vertices.size(), valid + 1);
    const float unit = float(head.fapu.unitValue(FapUnit::MNS));
    QVERIFY((offsetOf(pose, outside) - Eigen::Vector3f(0, -unit, 0)).norm() < 1e-9f);
    QVERIFY((offsetOf(pose, chin) - Eigen::Vector3f(0, -unit, 0)).norm() < 1e-9f);
    QVERIFY(pose.offsets.allFinite());
  }

  // A FAP's own influence replaces its point's in that FAP's pose only: 31 (raise) gets a
  // different footprint, 37 (squeeze, same point 4.1) keeps the point's; bad entries of the
  // FAP's own influence are skipped and named after the FAP.
  void fapInfluenceReplacesThePointsForThatFapOnly() {
    const synthetic::Head head = buildHead();
    RigInput rig = head.rig();
    const PoseSet plain = bakePoses(rig);
    const int point = head.featureVertex.at("4.1");
    const int far = head.featureVertex.at("10.1");  // outside 4.1's influence
    QVERIFY(offsetOf(poseOf(plain, 31), far).isZero());
    rig.fapInfluences[31] = {{point, far, -1}, {1.0f, 0.5f, 1.0f}};
    PoseBakeReport report;
    const PoseSet set = bakePoses(rig, &report);
    const float unit = float(head.fapu.unitValue(FapUnit::ENS));
    QCOMPARE(poseOf(set, 31).vertices.size(), size_t(2));
    QVERIFY((offsetOf(poseOf(set, 31), point) - Eigen::Vector3f(0, unit, 0)).norm() < 1e-9f);
    QVERIFY((offsetOf(poseOf(set, 31), far) - Eigen::Vector3f(0, 0.5f * unit, 0)).norm() < 1e-9f);
    QCOMPARE(poseOf(set, 37).vertices, poseOf(plain, 37).vertices);
    QVERIFY(poseOf(set, 37).offsets == poseOf(plain, 37).offsets);
    QVERIFY2(warned(report, {"FAP 31 (raise_l_i_eyebrow)'s own influence", "1 influence entries"}),
             allWarnings(report).c_str());
  }

  void unusableFapuLeavesItsFapsWithoutPoses() {
    const synthetic::Head head = buildHead();
    RigInput rig = head.rig();
    rig.fapu.mns0 = 0;
    rig.fapu.es0 = std::numeric_limits<double>::infinity();
    PoseBakeReport report;
    const PoseSet set = bakePoses(rig, &report);
    QVERIFY2(warned(report, {"FAPU MNS = 0", "3, 4, 5"}), allWarnings(report).c_str());
    QVERIFY(warned(report, {"FAPU ES = inf", "27, 28"}));
    for (int fap = 3; fap <= kFapCount; ++fap) {
      const FapUnit unit = fapInfo(fap).unit;
      if (unit == FapUnit::MNS || unit == FapUnit::ES) QVERIFY(poseOf(set, fap).empty());
      QVERIFY(poseOf(set, fap).offsets.allFinite());
    }
    QVERIFY(!poseOf(set, 6).empty());  // MW still fine
  }

  // A uv seam duplicates a vertex bit for bit; weights that list only one copy must still move
  // both, or the seam would open.
  void seamCopiesMoveWithTheirVertex() {
    synthetic::Head head = buildHead();
    const FeaturePointInfluence& jaw = head.influences.at("2.1");
    const int skinVertex = jaw.vertices[jaw.vertices.size() / 2];
    const float skinWeight = jaw.weights[jaw.vertices.size() / 2];
    const int eyeVertex = head.eyeLeft.vertices[3];
    const int n = head.mesh.vertexCount();
    head.mesh.positions.conservativeResize(3, n + 2);
    head.mesh.positions.col(n) = head.mesh.positions.col(skinVertex);
    head.mesh.positions.col(n + 1) = head.mesh.positions.col(eyeVertex);
    head.mesh.submeshes.push_back({"seam", -1, n, 2, {}});
    head.mesh.computeNormals();

    const PoseSet set = bakePoses(head.rig());
    QCOMPARE(offsetOf(poseOf(set, 3), n), offsetOf(poseOf(set, 3), skinVertex));
    QCOMPARE(offsetOf(poseOf(set, 3), n).y(),
             -skinWeight * float(head.fapu.unitValue(FapUnit::MNS)));
    QVERIFY(std::binary_search(set.eyeLeft.vertices.begin(), set.eyeLeft.vertices.end(), n + 1));
    QCOMPARE(poseOf(set, 3).vertices.size(), jaw.vertices.size() + 1);
  }

  // FAP 29 widens the pupil: inside the pupil (r <= r_p = IRISD0/6) the disc scales so that its
  // diameter grows by one IRISD step per unit; the iris ring tapers to the fixed rim
  // (r = IRISD0/2); the back of the eye, the cornea and the other eye stay put.
  void pupilDilationGrowsThePupilDisc() {
    const synthetic::Head head = buildHead();
    const PoseSet set = bakePoses(head.rig());
    const PoseBlender blender(head.mesh, set);
    const double step = head.fapu.unitValue(FapUnit::IRISD);
    const double irisRadius = head.fapu.irisd0 / 2, pupilRadius = irisRadius / 3;
    const float value = 150.0f;
    FapValues values{};
    values[size_t(channelIndex(29))] = value;
    Eigen::Matrix3Xf positions, normals;
    blender.blend(values, positions, normals);

    const Eigen::Vector3f centre = head.eyeLeft.centre, pupil = head.featurePoints.at("3.5");
    const HeadSubmesh& eye = *head.mesh.findSubmesh("eye_l");
    int insidePupil = 0, inIris = 0;
    for (int v = 0; v < head.mesh.vertexCount(); ++v) {
      const Eigen::Vector3f before = head.mesh.positions.col(v), after = positions.col(v);
      const bool onEye = v >= eye.firstVertex && v < eye.firstVertex + eye.vertexCount;
      const double r = axisDistance(before, centre, pupil);
      const bool front = (before - centre).dot(pupil - centre) > 0;
      if (!onEye || !front || r >= irisRadius || r == 0) {
        QVERIFY2(after == before, qPrintable(QString("vertex %1 moved").arg(v)));
        continue;
      }
      const double grown = axisDistance(after, centre, pupil);
      // Radial only: the height along the axis is kept.
      QVERIFY(std::abs((after - before).dot((pupil - centre).normalized())) < 1e-6f);
      if (r <= pupilRadius) {
        ++insidePupil;
        QVERIFY(std::abs(grown / r - (1 + value * step / (2 * pupilRadius))) < 1e-4);
      } else {
        ++inIris;
        const double expected =
            r + value * 0.5 * step * (irisRadius - r) / (irisRadius - pupilRadius);
        QVERIFY(std::abs(grown - expected) < 1e-5);
        QVERIFY(grown > r);
      }
    }
    QVERIFY(insidePupil >= 8 && inIris >= 16);  // rings of the synthetic eye in each zone

    // The right pupil's pose mirrors the left one.
    QCOMPARE(poseOf(set, 30).vertices.size(), poseOf(set, 29).vertices.size());
  }

  void pupilDilationWithoutGeometryWarns() {
    const synthetic::Head head = buildHead();
    RigInput rig = head.rig();
    rig.eyeLeft = {};
    rig.featurePoints.erase("3.6");
    PoseBakeReport report;
    const PoseSet set = bakePoses(rig, &report);
    QVERIFY(poseOf(set, 29).empty() && poseOf(set, 30).empty());
    QVERIFY2(warned(report, {"FAP 29 (dilate_l_pupil)", "no left eyeball vertices"}),
             allWarnings(report).c_str());
    QVERIFY(warned(report, {"FAP 30 (dilate_r_pupil)", "3.6"}));

    // A pupil point at the eye's centre gives no axis.
    rig = head.rig();
    rig.featurePoints["3.5"] = head.eyeLeft.centre;
    PoseBakeReport centred;
    QVERIFY(poseOf(bakePoses(rig, &centred), 29).empty());
    QVERIFY(warned(centred, {"FAP 29", "no axis"}));
  }

  // FAP 47: each tongue vertex rises by |x - midline| * 1e-5 per unit (weights 1 here), so
  // mirrored vertices rise alike and the midline stays.
  void tongueRollRaisesTheSidesSymmetrically() {
    const synthetic::Head head = buildHead();
    checkTongueRoll(head, bakePoses(head.rig()));
  }

  void tongueRollFallsBackToTheTongueSubmesh() {
    const synthetic::Head head = buildHead();
    RigInput rig = head.rig();
    rig.influences.erase("6.3");
    rig.influences.erase("6.4");
    rig.featurePoints.erase("6.3");  // midline from 6.2 instead
    PoseBakeReport report;
    const PoseSet set = bakePoses(rig, &report);
    QVERIFY2(warned(report, {"FAP 47", "'tongue' sub-mesh"}), allWarnings(report).c_str());
    checkTongueRoll(head, set);
  }

  // A corrupt feature point must not reach the poses: the pupil gets no axis, and the tongue
  // takes its midline from the next candidate (6.2).
  void nonFiniteFeaturePointsKeepPosesFinite() {
    const synthetic::Head head = buildHead();
    RigInput rig = head.rig();
    const float nan = std::numeric_limits<float>::quiet_NaN();
    rig.featurePoints["3.5"].y() = nan;
    rig.featurePoints["6.3"].x() = nan;
    PoseBakeReport report;
    const PoseSet set = bakePoses(rig, &report);
    QVERIFY(poseOf(set, 29).empty());
    QVERIFY2(warned(report, {"FAP 29", "no axis"}), allWarnings(report).c_str());
    for (const VertexPose& pose : set.poses) QVERIFY(pose.offsets.allFinite());
    checkTongueRoll(head, set);
  }

  void nullMeshThrows() { QVERIFY_THROWS_EXCEPTION(std::invalid_argument, bakePoses(RigInput{})); }

 private:
  static void checkTongueRoll(const synthetic::Head& head, const PoseSet& set) {
    const PoseBlender blender(head.mesh, set);
    const float value = 20000.0f;  // 0.2 rad
    FapValues values{};
    values[size_t(channelIndex(47))] = value;
    Eigen::Matrix3Xf positions, normals;
    blender.blend(values, positions, normals);
    const HeadSubmesh& tongue = *head.mesh.findSubmesh("tongue");
    int risen = 0;
    for (int v = 0; v < head.mesh.vertexCount(); ++v) {
      const Eigen::Vector3f before = head.mesh.positions.col(v), lift = positions.col(v) - before;
      if (v < tongue.firstVertex || v >= tongue.firstVertex + tongue.vertexCount) {
        QVERIFY(lift.isZero(0));
        continue;
      }
      const float expected = std::abs(before.x()) * 1e-5f * value;
      QVERIFY(std::abs(lift.y() - expected) < 1e-6f);
      QVERIFY(lift.x() == 0 && lift.z() == 0);
      QCOMPARE(lift, Eigen::Vector3f(positions.col(head.mirror[size_t(v)]) -
                                     head.mesh.positions.col(head.mirror[size_t(v)])));
      if (before.x() != 0) {
        QVERIFY(lift.y() > 0);
        ++risen;
      }
    }
    QVERIFY(risen > 0);
  }
};

QTEST_GUILESS_MAIN(PoseBakingTest)
#include "PoseBakingTest.moc"
