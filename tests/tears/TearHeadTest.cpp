// The tear simulation on the real default head (MakeHuman hm08 skin, rigging/DefaultHead.h),
// not the generated sheet: tears emitted at the lower eyelids must run down the cheeks, stay on
// the skin and survive a jaw-opening deformation arriving in a single frame. Skipped when the
// head has not been fetched (packaging/fetch-default-head.sh).
#include <lacrima/rig/DefaultHead.h>
#include <lacrima/tears/TearSimulation.h>

#include <QtTest>

#include <algorithm>
#include <cmath>
#include <memory>

using namespace lacrima;
using namespace lacrima::tears;

namespace {

constexpr double kFrameDt = 1.0 / 22.0;
constexpr int kPerEye = 60;
constexpr int kFrames = 66;  // 3 s at 22 fps

Eigen::AlignedBox3d boundsOf(const HeadMesh& head, const HeadSubmesh& sub) {
  Eigen::AlignedBox3d box;
  for (const auto& t : sub.triangles)
    for (int a = 0; a < 3; ++a) box.extend(head.positions.col(t[a]).cast<double>());
  return box;
}

Eigen::AlignedBox3d eyeBounds(const HeadMesh& head, const char* name) {
  const HeadSubmesh* eye = head.findSubmesh(name);
  Eigen::AlignedBox3d box;
  for (int v = eye->firstVertex; v < eye->firstVertex + eye->vertexCount; ++v)
    box.extend(head.positions.col(v).cast<double>());
  return box;
}

}  // namespace

class TearHeadTest : public QObject {
  Q_OBJECT

private:
  std::unique_ptr<HeadMesh> head_;
  Eigen::AlignedBox3d skinBox_, allowed_;
  double eyeLevel_ = 0;  // lower edge of the lower eyeball (head units)

  // Every particle finite, inside a box around the head and the commanded count per eye.
  void checkFrame(const TearSimulation& sim, int frame) {
    const ParticleSet& p = sim.particles();
    const QByteArray where = QByteArray("frame ") + QByteArray::number(frame);
    QVERIFY2(sim.count(Eye::Left) == kPerEye && sim.count(Eye::Right) == kPerEye, where + ": wrong particle count");
    for (int i = 0; i < p.size(); ++i) {
      const auto s = static_cast<std::size_t>(i);
      QVERIFY2(p.position[s].allFinite() && p.velocity[s].allFinite() && std::isfinite(p.mass[s]),
               where + ": non-finite particle state");
      QVERIFY2(allowed_.contains(p.position[s]), where + ": a particle left the box around the head");
    }
  }

private slots:
  void initTestCase() {
    if (!defaultHeadAvailable()) QSKIP("default head not fetched (packaging/fetch-default-head.sh)");
    head_ = std::make_unique<HeadMesh>(loadDefaultHead());
    const HeadSubmesh* skin = head_->findSubmesh("skin");
    QVERIFY(skin && head_->findSubmesh("eye_l") && head_->findSubmesh("eye_r"));
    skinBox_ = boundsOf(*head_, *skin);
    // 3 cm (0.3 dm) around the skin: the simulation recycles particles at its own box (skin
    // bounds + 3 cm), so anything beyond this escaped without being caught.
    allowed_ = skinBox_;
    allowed_.min().array() -= 0.35;
    allowed_.max().array() += 0.35;
    eyeLevel_ = std::min(eyeBounds(*head_, "eye_l").min().y(), eyeBounds(*head_, "eye_r").min().y());
  }

  void tearsRunDownTheCheeks() {
    auto sim = TearSimulation::forHead(*head_);
    for (int f = 0; f < kFrames; ++f) {
      sim->step(head_->positions, kPerEye, kPerEye, kFrameDt);
      checkFrame(*sim, f);
      if (QTest::currentTestFailed()) return;
    }
    // Most tears have run below the eyes and are on the skin (tracked contact): they flow down
    // the face instead of falling off or sticking at the source.
    const ParticleSet& p = sim->particles();
    int belowOnSkin = 0;
    for (int i = 0; i < p.size(); ++i) {
      const auto s = static_cast<std::size_t>(i);
      if (p.position[s].y() < eyeLevel_ && p.contact[s].triangle >= 0) ++belowOnSkin;
    }
    qInfo("%d of %d particles below the eyes on the skin, %lld sub-steps, %lld recycled", belowOnSkin, p.size(),
          sim->counters().substeps, sim->counters().recycled);
    QVERIFY2(belowOnSkin > p.size() / 2, QByteArray::number(belowOnSkin) + " of " + QByteArray::number(p.size()) +
                                             " particles below the eyes on the skin");
  }

  void jawOpeningDoesNotTunnel() {
    auto sim = TearSimulation::forHead(*head_);
    for (int f = 0; f < kFrames / 2; ++f) {
      sim->step(head_->positions, kPerEye, kPerEye, kFrameDt);
      checkFrame(*sim, f);
      if (QTest::currentTestFailed()) return;
    }
    // Jaw-opening-like pose, applied in one frame: skin vertices below the eyes move down,
    // ramping from 0 at eye level to 5 mm (0.05 dm) a decimetre lower, so the cheeks the tears
    // run on are stretched and dragged under them, then the pose holds.
    const HeadSubmesh* skin = head_->findSubmesh("skin");
    Eigen::Matrix3Xf open = head_->positions;
    for (const auto& t : skin->triangles)
      for (int a = 0; a < 3; ++a) {
        const int v = t[a];
        const double depth = eyeLevel_ - head_->positions(1, v);
        const double ramp = std::clamp(depth / 1.0, 0.0, 1.0);
        open(1, v) = static_cast<float>(head_->positions(1, v) - 0.05 * ramp);
      }
    for (int f = kFrames / 2; f < kFrames; ++f) {
      sim->step(open, kPerEye, kPerEye, kFrameDt);
      checkFrame(*sim, f);
      if (QTest::currentTestFailed()) return;
    }
    // Nothing was pushed through: no particle sits more than a particle radius behind the
    // nearest skin vertex's normal plane.
    const ParticleSet& p = sim->particles();
    const HeadSubmesh* sk = head_->findSubmesh("skin");
    int behind = 0;
    for (int i = 0; i < p.size(); ++i) {
      const auto s = static_cast<std::size_t>(i);
      double best = 1e30;
      int nearest = -1;
      for (int v = sk->firstVertex; v < sk->firstVertex + sk->vertexCount; ++v) {
        const double d2 = (open.col(v).cast<double>() - p.position[s]).squaredNorm();
        if (d2 < best) {
          best = d2;
          nearest = v;
        }
      }
      const Eigen::Vector3d n = head_->normals.col(nearest).cast<double>();
      if ((p.position[s] - open.col(nearest).cast<double>()).dot(n) < -2 * sim->particleRadius()) ++behind;
    }
    qInfo("%d of %d particles behind the skin, %lld swept out by the moving skin", behind, p.size(),
          sim->counters().sweptParticles);
    QVERIFY2(behind <= p.size() / 20, QByteArray::number(behind) + " particles behind the skin");
  }
};

QTEST_GUILESS_MAIN(TearHeadTest)
#include "TearHeadTest.moc"
