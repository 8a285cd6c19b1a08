// Drops that fall: where the skin faces down, water hangs from its contact until its weight
// reaches what the contact line holds (Tate's law, DropDetachment_Tate1864.h), then falls.
// The law itself on a flat ceiling, against its formula; water fed onto a chin-sized sphere
// runs down the front, gathers under it into a drop that hangs and grows, and the drop falls
// freely once it is heavy enough; runs with falling drops repeat bit for bit and restore from
// checkpoints.
#include "DropDetachment_Tate1864.h"
#include "TearTestSupport.h"

#include <QtTest>

#include <cmath>
#include <numbers>

using namespace lacrima::tears;
using namespace lacrima::tears::testing;

namespace {

// Microlitres in a volume of head units cubed (decimetres: 1 dm^3 = 10^6 uL).
double microlitres(double volume, const ScaledParameters& p) {
  return volume / std::pow(p.headUnitsPerMetre, 3) * 1e9;
}

// Every pair closer than h, each once (i < j), as the density pass lists them.
ActivePairs pairsWithin(const ParticleSet& p, double h) {
  ActivePairs pairs;
  for (int i = 0; i < p.size(); ++i) {
    pairs.first.push_back(static_cast<std::uint32_t>(pairs.partner.size()));
    for (int j = i + 1; j < p.size(); ++j)
      if ((p.position[static_cast<std::size_t>(i)] - p.position[static_cast<std::size_t>(j)])
              .squaredNorm() < h * h)
        pairs.partner.push_back(static_cast<std::uint32_t>(j));
    pairs.last.push_back(static_cast<std::uint32_t>(pairs.partner.size()));
  }
  pairs.kept = pairs.partner.size();
  return pairs;
}

// What one frame of the sphere run shows.
struct SphereFrame {
  double hanging = 0;       // mass in contact under the sphere (y < -0.85 R), head units^3
  double hangingSpeed = 0;  // of their centre of mass, m/s
  int falling = 0;          // free particles below the sphere's lowest point
  double fallingMass = 0;
  double fallingVy = 0;         // their mean vertical velocity, m/s
  double fallingLowest = 0;     // their lowest height, in sphere radii
  double fallingClearance = 0;  // their least distance from the sphere, in particle radii
};

SphereFrame look(const TearSimulation& sim, double radius) {
  SphereFrame f;
  const ParticleSet& p = sim.particles();
  const double U = sim.parameters().headUnitsPerMetre, r = sim.particleRadius();
  f.fallingClearance = 1e9;
  Eigen::Vector3d momentum = Eigen::Vector3d::Zero();
  for (int i = 0; i < p.size(); ++i) {
    const auto s = static_cast<std::size_t>(i);
    const Eigen::Vector3d& x = p.position[s];
    if (p.contact[s].triangle >= 0 && x.y() < -0.85 * radius) {
      f.hanging += p.mass[s];
      momentum += p.mass[s] * p.velocity[s];
    }
    if (p.contact[s].triangle < 0 && x.y() < -radius - 2 * r) {
      ++f.falling;
      f.fallingMass += p.mass[s];
      f.fallingVy += p.velocity[s].y() / U;
      f.fallingLowest = std::min(f.fallingLowest, x.y() / radius);
      f.fallingClearance = std::min(f.fallingClearance, (x.norm() - radius) / r);
    }
  }
  if (f.falling > 0) f.fallingVy /= f.falling;
  if (f.hanging > 0) f.hangingSpeed = momentum.norm() / f.hanging / U;
  return f;
}

}  // namespace

class TearDropsTest : public QObject {
  Q_OBJECT

 private slots:
  void tateThresholdOnACeiling() {
    // Square patches of particles touching a horizontal ceiling: a patch lets go exactly when
    // its weight reaches 2 pi r gamma, r the radius of a disc of its contacts' footprints;
    // water hanging under the contacts adds weight but no contact; a patch far from another
    // is weighed alone; a wall is not weighed at all.
    const ScaledParameters params = ScaledParameters::from({}, UnitScale::fromHeadHeight(2.7));
    const double m = params.particleMass, s = params.spacing, g = params.gravity;
    const double gamma = params.holdingTension;
    DropDetachment_Tate1864 detachment(gamma, params.restDensity);
    const Eigen::Vector3d gravity(0, -g, 0);
    // Two faces, as the collider keeps them: a ceiling (normal down) and a wall (normal +x).
    // The detachment reads only the normals.
    std::vector<SkinFace> faces(2);
    faces[0].normal = Eigen::Vector3d(0, -1, 0);
    faces[1].normal = Eigen::Vector3d(1, 0, 0);
    for (SkinFace& face : faces) face.degenerate = false;
    const SkinView ceiling{faces};
    const auto patch = [&](ParticleSet& p, int side, double x0, int layers, int triangle) {
      for (int layer = 0; layer < layers; ++layer)
        for (int a = 0; a < side; ++a)
          for (int b = 0; b < side; ++b) {
            const int i =
                p.add(Eigen::Vector3d(x0 + a * s, -params.particleRadius - layer * s, b * s), m,
                      static_cast<std::uint64_t>(p.size() + 1), Eye::Left);
            if (layer == 0) p.contact[static_cast<std::size_t>(i)].triangle = triangle;
          }
    };
    const double footprint = std::cbrt(m / params.restDensity) * std::cbrt(m / params.restDensity);
    const auto usage = [&](int contacts, int all) {
      const double capacity =
          2 * std::numbers::pi * std::sqrt(contacts * footprint / std::numbers::pi) * gamma;
      return all * m * g / capacity;
    };

    int firstFalling = 0;
    for (int side = 1; side <= 14; ++side) {
      ParticleSet p;
      patch(p, side, 0, 1, 0);
      patch(p, 3, 1.0, 1, 0);  // a small patch 1 dm away: holds whatever the first one does
      QVERIFY(detachment.update(p, pairsWithin(p, params.h), ceiling, gravity));
      const double expected = std::max(0.0, 1 - usage(side * side, side * side));
      const auto spare = detachment.spare();
      QCOMPARE(static_cast<int>(spare.size()), p.size());
      for (int i = 0; i < side * side; ++i)
        QVERIFY2(std::abs(spare[static_cast<std::size_t>(i)] - expected) < 1e-12,
                 QByteArray::number(side) + ": " +
                     QByteArray::number(spare[static_cast<std::size_t>(i)]) + " vs " +
                     QByteArray::number(expected));
      QVERIFY(std::abs(spare[static_cast<std::size_t>(side * side)] - (1 - usage(9, 9))) < 1e-12);
      QCOMPARE(detachment.releasedCount(), expected == 0 ? side * side : 0);
      if (expected == 0 && firstFalling == 0) firstFalling = side;
    }
    // The first patch to fall: Tate's mass for its contact, and, at the default adhesion, the
    // 20 uL a drop of fresh water on a ceiling holds (docs/tears.md).
    QVERIFY(firstFalling > 1);
    const double heldMass = (firstFalling - 1) * (firstFalling - 1) * m;
    const double fellMass = firstFalling * firstFalling * m;
    qInfo("a %dx%d patch holds (%.1f uL), a %dx%d one falls (%.1f uL)", firstFalling - 1,
          firstFalling - 1, microlitres(heldMass / params.restDensity, params), firstFalling,
          firstFalling, microlitres(fellMass / params.restDensity, params));
    QVERIFY(microlitres(heldMass / params.restDensity, params) < 20);
    QVERIFY(microlitres(fellMass / params.restDensity, params) > 20);

    // Two more layers hanging under a 4x4 patch triple its weight and leave its contact.
    {
      ParticleSet p;
      patch(p, 4, 0, 3, 0);
      detachment.update(p, pairsWithin(p, params.h), ceiling, gravity);
      QVERIFY(std::abs(detachment.spare()[0] - std::max(0.0, 1 - usage(16, 48))) < 1e-12);
      QCOMPARE(detachment.spare()[16], 1.0);  // hanging particles touch nothing
    }
    // On a wall nothing hangs: nothing is weighed.
    {
      ParticleSet p;
      patch(p, 14, 0, 1, 1);
      QVERIFY(!detachment.update(p, pairsWithin(p, params.h), ceiling, gravity));
      QVERIFY(detachment.spare().empty());
    }
    // The holding tension follows the adhesion parameter: none holds nothing.
    TearSettings sticky, dry;
    sticky.set("adhesion", 1000);
    dry.set("adhesion", 0);
    const UnitScale scale = UnitScale::fromHeadHeight(2.7);
    QCOMPARE(ScaledParameters::from(sticky, scale).holdingTension, 50 * gamma);
    QCOMPARE(ScaledParameters::from(dry, scale).holdingTension, 0.0);
  }

  void dropsHangGrowAndFallUnderAChin() {
    // Water fed at 22 particles a second (about 11 uL/s) onto the front of a 3 cm sphere runs
    // down and gathers under it. There it hangs, in contact and at rest, and grows; then it
    // falls as a drop: free of the skin, below the sphere, accelerating at g, with the mass a
    // pendant drop of water holds. A residue stays behind and hangs again.
    const SyntheticSkin chin = makeChinSphere();
    SimulationOptions options;
    options.headHeight = 2.7;
    options.boxMarginMetres = 0.1;  // room to watch the drop fall for a few frames
    auto sim =
        std::make_unique<TearSimulation>(chin.positions, chin.triangles, TearSettings{}, options);
    sim->setSource(Eye::Left, chin.leftSource);
    sim->setSource(Eye::Right, chin.rightSource);
    const ScaledParameters& params = sim->parameters();
    const double R = chin.radius;
    InvariantChecker checker(chin, 0.35);
    std::vector<SphereFrame> frames;
    int detached = -1;
    for (int f = 0; f < 300 && detached < 0; ++f) {
      const int count = f + 1;
      sim->step(chin.positions, count, 0, kFrameDt);
      const FrameReport r = checker.check(*sim, count, 0);
      QVERIFY2(r.finite && r.countOk, QByteArray("frame ") + QByteArray::number(f));
      frames.push_back(look(*sim, R));
      if (frames.back().falling >= 10) detached = f;
    }
    QVERIFY2(detached > 0, "no drop fell in 300 frames");
    const SphereFrame before = frames[static_cast<std::size_t>(detached - 1)];
    qInfo("a drop of %.1f uL fell after %.2f s, %.1f uL were hanging just before",
          microlitres(frames.back().fallingMass / params.restDensity, params), detached * kFrameDt,
          microlitres(before.hanging / params.restDensity, params));

    // Before it fell, a drop hung under the sphere for seconds, growing from under 10 uL to over
    // 15 uL as water arrived: in contact, nothing falling, its centre of mass slower than 3 cm/s
    // (the speed water arrives at) and, over the last second, slower than 1 cm/s.
    int firstHanging = -1;
    for (int f = 0; f < detached && firstHanging < 0; ++f)
      if (microlitres(frames[static_cast<std::size_t>(f)].hanging / params.restDensity, params) >
          1.0)
        firstHanging = f;
    QVERIFY(firstHanging >= 0);
    QVERIFY2(detached - firstHanging >= 44, QByteArray::number(detached - firstHanging));
    const double startUl = microlitres(
        frames[static_cast<std::size_t>(firstHanging)].hanging / params.restDensity, params);
    const double endUl = microlitres(before.hanging / params.restDensity, params);
    qInfo("it hung for %.2f s, from %.1f to %.1f uL", (detached - firstHanging) * kFrameDt, startUl,
          endUl);
    QVERIFY2(startUl < 10 && endUl > 15,
             QByteArray::number(startUl) + " then " + QByteArray::number(endUl));
    for (int f = firstHanging; f < detached; ++f) {
      const SphereFrame& h = frames[static_cast<std::size_t>(f)];
      const QByteArray where = QByteArray("frame ") + QByteArray::number(f) + ": " +
                               QByteArray::number(h.hangingSpeed) + " m/s";
      QVERIFY2(h.falling == 0 && h.hanging > 0, where);
      QVERIFY2(h.hangingSpeed < (f < detached - 22 ? 0.03 : 0.01), where);
    }

    // The drop: 15 to 45 uL (pendant water drops on skin hold roughly 20-30 uL), most of what
    // hung, below the sphere and clear of it.
    const SphereFrame& fell = frames.back();
    const double fellUl = microlitres(fell.fallingMass / params.restDensity, params);
    QVERIFY2(fellUl > 15 && fellUl < 45, QByteArray::number(fellUl));
    QVERIFY2(fell.fallingMass > 0.6 * before.hanging, QByteArray::number(fellUl));
    QVERIFY(fell.fallingLowest < -1);
    QVERIFY2(fell.fallingClearance > 1, QByteArray::number(fell.fallingClearance));

    // It falls freely: over the next frames its mean vertical velocity grows by g per second
    // (within 15%; the only other forces are the drop's own, which cancel in the mean).
    const int count = detached + 2;
    std::vector<double> vy{fell.fallingVy};
    for (int f = detached + 1; f < detached + 3; ++f) {
      sim->step(chin.positions, count, 0, kFrameDt);
      const SphereFrame next = look(*sim, R);
      QVERIFY2(next.falling >= fell.falling / 2, QByteArray::number(next.falling));
      vy.push_back(next.fallingVy);
    }
    const double acceleration = (vy.front() - vy.back()) / ((vy.size() - 1) * kFrameDt);
    qInfo("falling at %.2f, %.2f, %.2f m/s: %.2f m/s^2", vy[0], vy[1], vy[2], acceleration);
    QVERIFY2(std::abs(acceleration - 9.81) < 0.15 * 9.81, QByteArray::number(acceleration));
    // What stayed on the skin hangs on: the contact line's residue.
    QVERIFY(look(*sim, R).hanging > 0);
  }

  void fallingDropsRepeatBitwiseAndRestore() {
    // Drops falling off the sphere, weighed every sub-step, change nothing of determinism: two
    // runs agree bit for bit, and a run restored from a checkpoint taken while a drop hung
    // (after other input in between) ends where the straight run ends, trails included.
    const SyntheticSkin chin = makeChinSphere();
    const auto make = [&] { return makeSheetSimulation(chin); };
    const auto stepA = [&](TearSimulation& sim, TrailBuilder& trails, int f) {
      sim.step(chin.positions, std::min(400, 2 * (f + 1)), f / 4, kFrameDt);
      trails.update(sim, chin.positions, kFrameDt);
    };
    auto a = make();
    TrailBuilder trailsA(chin.triangles);
    long long releasedAt100 = 0;
    for (int f = 0; f < 160; ++f) {
      stepA(*a, trailsA, f);
      if (f == 99) releasedAt100 = a->counters().releasedContacts;
    }
    QVERIFY2(a->counters().releasedContacts > releasedAt100,
             "no drop fell after the checkpoint: the test would prove nothing");
    const FrameState expected = stateOf(*a, trailsA);

    auto b = make();
    TrailBuilder trailsB(chin.triangles);
    for (int f = 0; f < 100; ++f) stepA(*b, trailsB, f);
    const TearCheckpoint saved = b->checkpoint();
    const TrailBuilder savedTrails = trailsB;
    for (int f = 0; f < 20; ++f) {
      b->step(chin.positions, 300, 30, kFrameDt);
      trailsB.update(*b, chin.positions, kFrameDt);
    }
    b->restore(saved);
    trailsB = savedTrails;
    for (int f = 100; f < 160; ++f) stepA(*b, trailsB, f);
    QVERIFY2(sameBits(stateOf(*b, trailsB), expected), "the restored run diverged");

    auto c = make();
    TrailBuilder trailsC(chin.triangles);
    for (int f = 0; f < 160; ++f) stepA(*c, trailsC, f);
    QVERIFY2(sameBits(stateOf(*c, trailsC), expected), "two runs differ");
  }
};

QTEST_GUILESS_MAIN(TearDropsTest)
#include "TearDropsTest.moc"
