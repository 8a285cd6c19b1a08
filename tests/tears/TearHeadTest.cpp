// The tear simulation on the real default head (MakeHuman hm08 skin, rigging/DefaultHead.h),
// not the generated sheet: tears emitted at the lower eyelids must run down the cheeks, stay on
// the skin and survive a jaw-opening deformation arriving in a single frame. Skipped when the
// head has not been fetched (packaging/fetch-default-head.sh).
#include "../support/MissingData.h"

#include <lacrima/rigging/DefaultHead.h>
#include <lacrima/rigging/FeaturePointFile.h>
#include <lacrima/rigging/RigBuilder.h>
#include <lacrima/tears/TearSimulation.h>

#include <QtTest>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <random>

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

// Closest point of triangle abc to p (brute-force reference, by projection and edge clamping).
Eigen::Vector3d closestPoint(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                             const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  const Eigen::Vector3d n = (b - a).cross(c - a).normalized();
  const Eigen::Vector3d q = p - (p - a).dot(n) * n;  // in the plane
  const auto inside = [&](const Eigen::Vector3d& u, const Eigen::Vector3d& w) {
    return (w - u).cross(q - u).dot(n) >= 0;
  };
  if (inside(a, b) && inside(b, c) && inside(c, a)) return q;
  const auto onSegment = [&](const Eigen::Vector3d& u, const Eigen::Vector3d& w) {
    const double s = std::clamp((p - u).dot(w - u) / (w - u).squaredNorm(), 0.0, 1.0);
    return Eigen::Vector3d(u + s * (w - u));
  };
  Eigen::Vector3d best = onSegment(a, b);
  for (const Eigen::Vector3d& candidate : {onSegment(b, c), onSegment(c, a)})
    if ((candidate - p).squaredNorm() < (best - p).squaredNorm()) best = candidate;
  return best;
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
    QVERIFY2(sim.count(Eye::Left) == kPerEye && sim.count(Eye::Right) == kPerEye,
             where + ": wrong particle count");
    for (int i = 0; i < p.size(); ++i) {
      const auto s = static_cast<std::size_t>(i);
      QVERIFY2(p.position[s].allFinite() && p.velocity[s].allFinite() && std::isfinite(p.mass[s]),
               where + ": non-finite particle state");
      QVERIFY2(allowed_.contains(p.position[s]),
               where + ": a particle left the box around the head");
    }
  }

 private slots:
  void initTestCase() {
    if (!rigging::defaultHeadAvailable()) LACRIMA_SKIP_WITHOUT_DEFAULT_HEAD();
    head_ = std::make_unique<HeadMesh>(rigging::loadDefaultHead());
    const HeadSubmesh* skin = head_->findSubmesh("skin");
    QVERIFY(skin && head_->findSubmesh("eye_l") && head_->findSubmesh("eye_r"));
    skinBox_ = boundsOf(*head_, *skin);
    // 3 cm (0.3 dm) around the skin: the simulation recycles particles at its own box (skin
    // bounds + 3 cm), so anything beyond this escaped without being caught.
    allowed_ = skinBox_;
    allowed_.min().array() -= 0.35;
    allowed_.max().array() += 0.35;
    eyeLevel_ =
        std::min(eyeBounds(*head_, "eye_l").min().y(), eyeBounds(*head_, "eye_r").min().y());
  }

  void defaultSourcesSitWhereTheRigPutsThem() {
    // forHead's own rule (no feature points) against the rig's (lower-lid mid-point minus
    // IRISD0 / 4, nearest skin vertex): the same place to within 2 mm (0.02 dm), on the skin,
    // facing forward; and sources the caller gives are used as they are.
    Warnings warnings;
    const rigging::FeaturePointFile fdp =
        rigging::readFeaturePointFile(LACRIMA_SOURCE_DIR "/media/default-head.fdp.json", &warnings);
    rigging::validateFeaturePoints(fdp, *head_, &warnings);
    const rigging::BuiltRig rig = rigging::buildRig(*head_, fdp);
    for (auto [eye, rigSource] :
         {std::pair{Eye::Left, rig.tearLeft}, std::pair{Eye::Right, rig.tearRight}}) {
      const Eigen::Vector3d own = TearSimulation::defaultTearSource(*head_, eye);
      const double gap = (own - rigSource.position).norm();
      qInfo("%s eye: default source %.4f %.4f %.4f, the rig's %.4f %.4f %.4f (%.2f mm apart)",
            eye == Eye::Left ? "left" : "right", own.x(), own.y(), own.z(), rigSource.position.x(),
            rigSource.position.y(), rigSource.position.z(), 100 * gap);
      QVERIFY2(gap < 0.02, QByteArray::number(gap));
      QVERIFY(rigSource.normal.z() > 0.7);
      QVERIFY((eye == Eye::Left) == (own.x() > 0));  // +x is the face's own left
    }
    HeadTearOptions given;
    given.leftSource = rig.tearLeft.position;
    given.rightSource = rig.tearRight.position + Eigen::Vector3d(0, -0.1, 0);
    auto sim = TearSimulation::forHead(*head_, {}, {}, given);
    QCOMPARE(sim->source(Eye::Left), rig.tearLeft.position);
    QCOMPARE(sim->source(Eye::Right), *given.rightSource);
  }

  void nearestSkinPointMatchesBruteForce() {
    // The collider's nearest-point query (ODE sphere against the trimesh, then exact closest
    // points) against a scan of every triangle of the collision surface (skin and eyes), for
    // points scattered in front of the face at distances up to the emitter's search radius.
    // ODE lists at most a buffer's worth of triangles, in its tree's order: with a large sphere
    // it used to miss the nearest (an emission 0.4 mm off the source on this head).
    auto sim = TearSimulation::forHead(*head_);
    const HeadSubmesh* skin = head_->findSubmesh("skin");
    std::vector<Eigen::Vector3i> surface = skin->triangles;  // what forHead collides with
    for (const char* name : {"eye_l", "eye_r", "cornea_l", "cornea_r"}) {
      const HeadSubmesh* eye = head_->findSubmesh(name);
      QVERIFY(eye);
      surface.insert(surface.end(), eye->triangles.begin(), eye->triangles.end());
    }
    const auto v = [&](int i) { return Eigen::Vector3d(head_->positions.col(i).cast<double>()); };
    const double radius = 8 * sim->kernelRadius();
    std::mt19937_64 random(17);
    std::uniform_real_distribution<double> unit(0, 1);
    int checked = 0, found = 0;
    for (int q = 0; q < 400; ++q) {
      // A random skin triangle on the front of the face, then a point off it.
      const Eigen::Vector3i& t =
          skin->triangles[static_cast<std::size_t>(unit(random) * skin->triangles.size())];
      const Eigen::Vector3d n = (v(t[1]) - v(t[0])).cross(v(t[2]) - v(t[0])).normalized();
      if (!n.allFinite() || n.z() < 0.3 ||
          v(t[0]).y() < skinBox_.min().y() + 0.3 * skinBox_.sizes().y())
        continue;
      const Eigen::Vector3d x =
          (v(t[0]) + v(t[1]) + v(t[2])) / 3 + unit(random) * radius * n +
          0.5 * radius *
              Eigen::Vector3d(unit(random) - 0.5, unit(random) - 0.5, unit(random) - 0.5);
      double best = std::numeric_limits<double>::infinity();
      for (const auto& u : surface) {
        const Eigen::Vector3d a = v(u[0]), b = v(u[1]), c = v(u[2]);
        const Eigen::Vector3d un = (b - a).cross(c - a);
        if (!(un.squaredNorm() > 0)) continue;
        const Eigen::Vector3d p = closestPoint(x, a, b, c);
        if ((x - p).dot(un) < 0) continue;  // behind that triangle: not a point the tears see
        best = std::min(best, (x - p).norm());
      }
      const SkinPoint hit = sim->nearestSkinPoint(x, radius);
      ++checked;
      if (best >= radius) {
        QVERIFY2(!hit.found() || hit.distance >= radius * (1 - 1e-9),
                 "found a point beyond the radius");
        continue;
      }
      ++found;
      QVERIFY2(hit.found(), QByteArray("query ") + QByteArray::number(q) +
                                ": nothing found, brute force " + QByteArray::number(best));
      QVERIFY2(std::abs(hit.distance - best) < 1e-9,
               QByteArray("query ") + QByteArray::number(q) + ": distance " +
                   QByteArray::number(hit.distance) + ", brute force " + QByteArray::number(best));
    }
    qInfo("%d queries, %d with skin in reach, %lld grid queries", checked, found,
          sim->counters().gridQueries);
    QVERIFY(found > 100);
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
    qInfo("%d of %d particles below the eyes on the skin, %lld sub-steps, %lld recycled",
          belowOnSkin, p.size(), sim->counters().substeps, sim->counters().recycled);
    QVERIFY2(belowOnSkin > p.size() / 2, QByteArray::number(belowOnSkin) + " of " +
                                             QByteArray::number(p.size()) +
                                             " particles below the eyes on the skin");
  }

  void dropsFallFromTheChin() {
    // Steady crying, three more particles per eye every frame up to 300 (the demo peaks at 100
    // in 8 s): the tears run down the cheeks, gather under the chin and fall from it as drops
    // within 10 s, instead of clinging there until the count removes them, or crawling down
    // the neck. A drop falling from the chin: particles that touched the skin within 5 mm of the
    // chin's lowest point at most half a second ago, now free of the skin, below the chin,
    // moving down (some of a burst at the source fall past the chin too: those never touched).
    const HeadSubmesh* skin = head_->findSubmesh("skin");
    double chin = 1e30;  // the chin's lowest point: the lowest skin in front of the neck
    for (const auto& t : skin->triangles)
      for (int a = 0; a < 3; ++a) {
        const Eigen::Vector3f x = head_->positions.col(t[a]);
        if (x.z() > 1.0 && std::abs(x.x()) < 0.5) chin = std::min(chin, double(x.y()));
      }
    auto sim = TearSimulation::forHead(*head_);
    const double U = sim->parameters().headUnitsPerMetre;
    const auto microlitres = [&](double mass) {
      return mass / sim->parameters().restDensity / (U * U * U) * 1e9;
    };
    std::map<std::uint64_t, int> atChin;  // particle id -> last frame on the skin at the chin
    int firstFall = -1, falling = 0, onNeck = 0;
    double fallingMass = 0, fallingVy = 0, hangingMass = 0;
    for (int f = 0; f < 220 && firstFall < 0; ++f) {
      const int perEye = std::min(300, 3 * (f + 1));
      sim->step(head_->positions, perEye, perEye, kFrameDt);
      const ParticleSet& p = sim->particles();
      QCOMPARE(p.size(), 2 * perEye);
      falling = 0;
      fallingMass = fallingVy = 0;
      double chinMass = 0;
      for (int i = 0; i < p.size(); ++i) {
        const auto s = static_cast<std::size_t>(i);
        const Eigen::Vector3d& x = p.position[s];
        QVERIFY2(x.allFinite() && p.velocity[s].allFinite(), "non-finite particle state");
        if (p.contact[s].triangle >= 0 && x.y() < chin + 0.05) {
          atChin[p.id[s]] = f;
          chinMass += p.mass[s];
        }
        if (p.contact[s].triangle >= 0 && x.z() < 1.0 && x.y() < chin) ++onNeck;
        const auto seen = atChin.find(p.id[s]);
        if (p.contact[s].triangle < 0 && x.y() < chin - 2 * sim->particleRadius() &&
            p.velocity[s].y() < -0.2 * U && seen != atChin.end() && f - seen->second <= 11) {
          ++falling;
          fallingMass += p.mass[s];
          fallingVy += p.velocity[s].y() / U;
        }
      }
      if (falling >= 10)
        firstFall = f;
      else
        hangingMass = chinMass;
    }
    QVERIFY2(firstFall >= 0, "no drop fell from the chin in 10 s");
    qInfo(
        "the first drop fell from the chin at %.2f s: %d particles, %.1f uL, at %.2f m/s "
        "(%.1f uL hung there the frame before); %lld recycled, %d contacts on the neck",
        firstFall * kFrameDt, falling, microlitres(fallingMass), fallingVy / falling,
        microlitres(hangingMass), sim->counters().recycled, onNeck);
    // A drop of water's size (pendant drops on skin hold 20-30 uL), falling faster than it
    // could slide, with nothing removed and nothing on the neck.
    QVERIFY2(microlitres(fallingMass) > 10, QByteArray::number(microlitres(fallingMass)));
    QVERIFY(fallingVy / falling < -0.3);
    QCOMPARE(sim->counters().removed, 0LL);
    QCOMPARE(onNeck, 0);
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
      if ((p.position[s] - open.col(nearest).cast<double>()).dot(n) < -2 * sim->particleRadius())
        ++behind;
    }
    qInfo("%d of %d particles behind the skin, %lld swept out by the moving skin", behind, p.size(),
          sim->counters().sweptParticles);
    QVERIFY2(behind <= p.size() / 20, QByteArray::number(behind) + " particles behind the skin");
  }
};

QTEST_GUILESS_MAIN(TearHeadTest)
#include "TearHeadTest.moc"
