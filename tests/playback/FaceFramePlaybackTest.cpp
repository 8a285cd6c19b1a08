// A head exported Z-up plays upright: rigHead brings it into the face frame, so its
// tears run down its face towards the chin, exactly as the Y-up original's do.
// Skipped when the default head has not been fetched.
#include "../support/MissingData.h"
#include "PlaybackTestSupport.h"

#include <lacrima/common/MediaFiles.h>
#include <lacrima/playback/FrameProducer.h>
#include <lacrima/playback/HeadRig.h>
#include <lacrima/rigging/DefaultHead.h>
#include <lacrima/rigging/FaceFrame.h>
#include <lacrima/rigging/FeaturePointFile.h>
#include <lacrima/tears/ParticleSet.h>

#include <QtTest>

#include <memory>

using namespace lacrima;
using namespace lacrima::playback;
using namespace lacrima::playback::test;

namespace {

// Z-up, facing -y (Blender's convention): mesh = turn x face frame.
Eigen::Matrix3d zUpTurn() {
  Eigen::Matrix3d m;
  m << 1, 0, 0, 0, 0, -1, 0, 1, 0;
  return m;
}

// Where the tears are after `frames` frames of both eyes crying: the mean particle position
// minus the mean of the two sources, in the rig's frame; `particles` receives the final set.
Eigen::Vector3d tearDrift(const HeadRig& rig, int frames, tears::ParticleSet& particles) {
  SceneSettings scene;
  scene.particles = true;
  FrameProducer producer(rig, scene);
  FapValues values{};
  channel(values, "tears_l_eye") = 40;
  channel(values, "tears_r_eye") = 40;
  for (int f = 0; f < frames; ++f) producer.produce(values, 1.0 / kFps, 0.0);
  particles = *producer.view().particles;
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& p : particles.position) mean += p;
  mean /= std::max(1, particles.size());
  return mean - 0.5 * (rig.rig.tearLeft.position + rig.rig.tearRight.position);
}

}  // namespace

class FaceFramePlaybackTest : public QObject {
  Q_OBJECT

 private slots:
  void initTestCase() {
    if (!rigging::defaultHeadAvailable()) LACRIMA_SKIP_WITHOUT_DEFAULT_HEAD();
  }

  // The default head turned Z-up (and its feature-point file with it) cries for 1.5 s: the
  // tears' mean drift, turned back into the Z-up head's own coordinates, points down its face
  // (from between the eyes towards the mouth), and the tears are those of the upright head.
  void zUpHeadCriesTowardsItsChin() {
    const HeadMesh upright = rigging::loadDefaultHead();
    const rigging::FeaturePointFile fdp = rigging::validateFeaturePoints(
        rigging::readFeaturePointFile(findMediaFile("default-head.fdp.json")), upright, nullptr);
    const Eigen::Matrix3d turn = zUpTurn();
    HeadMesh zUp = upright;
    rigging::applyAxisRotation(turn, zUp.positions);
    rigging::applyAxisRotation(turn, zUp.normals);
    rigging::FeaturePointFile zUpFdp = fdp;
    zUpFdp.path = "z-up.fdp.json";
    if (zUpFdp.neckPivot) zUpFdp.neckPivot = turn * *zUpFdp.neckPivot;
    for (auto& [id, point] : zUpFdp.points)  // the stored positions are in mesh coordinates too
      if (point.at.position) point.at.position = turn * *point.at.position;

    // Down the face in the Z-up head's own coordinates, from its points alone.
    auto at = [&](const char* id) {
      return rigging::surfacePosition(zUpFdp.points.at(id).at, zUp);
    };
    const Eigen::Vector3d down =
        (0.5 * (at("8.3") + at("8.4")) - 0.5 * (at("3.5") + at("3.6"))).normalized();
    QVERIFY(down.z() < -0.9);  // the turn did what it says: the chin is at -z

    const std::unique_ptr<HeadRig> rig = rigHead(zUp, zUpFdp);
    QCOMPARE(rig->frame.rotation, turn.transpose());
    QVERIFY(rig->head.positions == upright.positions);  // turned back exactly

    constexpr int kFrames = 33;  // 1.5 s at 22 fps
    tears::ParticleSet particles;
    const Eigen::Vector3d drift = tearDrift(*rig, kFrames, particles);
    QVERIFY2(particles.size() > 20, qPrintable(QString::number(particles.size())));
    const Eigen::Vector3d driftInMesh = rig->frame.rotation.transpose() * drift;
    const double along = driftInMesh.normalized().dot(down);
    qInfo("Z-up head: %d particles drifted %.3f head units, cosine with down the face %.3f",
          particles.size(), drift.norm(), along);
    QVERIFY2(along > 0.8, qPrintable(QString::number(along)));
    QVERIFY(drift.norm() > 0.05 * rig->rig.fapu.es0);

    // The upright head's tears, bit for bit: same mesh, same rig, same simulation.
    const std::unique_ptr<HeadRig> reference = rigHead(upright, fdp);
    QCOMPARE(reference->frame.rotation, Eigen::Matrix3d::Identity());
    tears::ParticleSet expected;
    tearDrift(*reference, kFrames, expected);
    QVERIFY(sameParticles(particles, expected));
  }
};

QTEST_GUILESS_MAIN(FaceFramePlaybackTest)
#include "FaceFramePlaybackTest.moc"
