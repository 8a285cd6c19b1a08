// Small drops on the skin as spherical caps (DropCaps.h): a drop at rest becomes one cap of its
// volume sitting on the sheet, its particles flagged for the mesher; of a stream of drops only
// the leading one gets a cap, the ones behind it are left to the trails; large drops and drops
// in the air stay with the mesher; the number of caps is bounded. Also the cap formula itself
// (DropFootprint.h) and the mesher's skip flags.
#include "SheetDrops.h"

#include <lacrima/tears/DropCaps.h>
#include <lacrima/tears/DropFootprint.h>
#include <lacrima/tears/SurfaceMesher.h>

#include <QtTest>

#include <cmath>
#include <numbers>

using namespace lacrima::tears;
using namespace lacrima::tears::testing;

namespace {

constexpr double kPi = std::numbers::pi;

// Volume enclosed by a cap mesh closed by its rim's fan (divergence theorem: the sum over
// triangles of a . (b x c) / 6, plus the flat base seen from below).
double capVolume(const TearSurface& mesh, const Eigen::Vector3d& baseCentre) {
  const auto p = mesh.positions();
  const auto t = mesh.triangles();
  double volume = 0;
  for (int i = 0; i < t.cols(); ++i) {
    const Eigen::Vector3d a = p.col(t(0, i)) - baseCentre, b = p.col(t(1, i)) - baseCentre,
                          c = p.col(t(2, i)) - baseCentre;
    volume += a.dot(b.cross(c)) / 6;
  }
  return volume;  // the base's triangles through baseCentre add nothing (coplanar with it)
}

// Sets every particle of the drops [first, first + count) (in order of addition) moving at v.
void setVelocity(ParticleSet& particles, int first, int count, const Eigen::Vector3d& v) {
  for (int i = first; i < first + count; ++i) particles.velocity[static_cast<std::size_t>(i)] = v;
}

int flagged(std::span<const std::uint8_t> flags) {
  int n = 0;
  for (std::uint8_t f : flags) n += f ? 1 : 0;
  return n;
}

}  // namespace

class DropCapsTest : public QObject {
  Q_OBJECT

 private slots:
  // V = (pi R^3 / 3)(2 - 3 cos + cos^3), a = R sin, H = R (1 - cos): the cap of a volume holds
  // that volume, and a hemisphere is the half ball.
  void sphericalCapHoldsItsVolume() {
    for (double degrees : {20.0, 35.0, 70.0, 90.0, 150.0}) {
      const double theta = degrees * kPi / 180, volume = 2.5;
      const CapShape cap = sphericalCap(volume, theta);
      const double R = cap.contactRadius / std::sin(theta);
      const double back = kPi * cap.height * cap.height * (3 * R - cap.height) / 3;
      QVERIFY2(std::abs(back - volume) < 1e-12 * volume, QByteArray::number(degrees));
      QVERIFY(std::abs(cap.height - R * (1 - std::cos(theta))) < 1e-12);
    }
    const CapShape half = sphericalCap(2 * kPi / 3, kPi / 2);  // half a unit ball
    QVERIFY(std::abs(half.contactRadius - 1) < 1e-12 && std::abs(half.height - 1) < 1e-12);
    QCOMPARE(sphericalCap(0, 1).contactRadius, 0.0);
    QCOMPARE(sphericalCap(1, 0).contactRadius, 0.0);
    QCOMPARE(sphericalCap(std::nan(""), 1).contactRadius, 0.0);
  }

  void dropAtRestIsOneCapOfItsVolume() {
    Scene scene;
    DropCaps caps(scene.sheet.triangles);
    scene.particles.clear();
    addDrop(scene.particles, scene.probe, {0.2, 0.5, 6, 1});
    scene.grid.build(scene.particles.position, kH);
    const TearSurface& mesh =
        caps.update(scene.particles, scene.grid, kH, kRadius, scene.sheet.positions);
    QCOMPARE(caps.capCount(), 1);
    QCOMPARE(flagged(caps.skipped()), 6);
    const DropCapSettings& s = caps.settings();
    QCOMPARE(mesh.vertexCount(), 1 + s.rings * s.segments);
    QCOMPARE(mesh.triangleCount(), s.segments * (2 * s.rings - 1));

    const double theta = s.contactAngleDegrees * kPi / 180;
    const CapShape cap = sphericalCap(6 * parcelVolume(kRadius), theta);
    const auto p = mesh.positions();
    const auto n = mesh.normals();
    QVERIFY(p.allFinite() && n.allFinite());
    // The top is H above the sheet (plus the rim lift), the rim on it, a apart from the top's
    // foot; every normal is unit and points away from the skin.
    const double lift = s.rimLift * cap.contactRadius;
    QVERIFY2(std::abs(distanceToSheet(p.col(0)) - (cap.height + lift)) < 0.05 * cap.height,
             QByteArray::number(distanceToSheet(p.col(0)) / cap.height));
    const Eigen::Vector3d up = sheetNormal(0.2);
    for (int v = 1 + (s.rings - 1) * s.segments; v < p.cols(); ++v) {
      QVERIFY(distanceToSheet(p.col(v)) < lift + 0.05 * cap.contactRadius);
      const Eigen::Vector3d radial = p.col(v) - p.col(0);
      const double across = (radial - radial.dot(up) * up).norm();
      QVERIFY2(std::abs(across - cap.contactRadius) < 0.05 * cap.contactRadius,
               QByteArray::number(across / cap.contactRadius));
    }
    for (int v = 0; v < n.cols(); ++v) {
      QVERIFY(std::abs(n.col(v).norm() - 1) < 1e-12);
      QVERIFY(n.col(v).dot(up) > 0.2);
    }
    // Wound counter-clockwise seen from outside, and holding the drop's water, less what the
    // inscribed mesh of 3 rings and 14 segments cuts off (91%).
    const auto t = mesh.triangles();
    for (int i = 0; i < t.cols(); ++i) {
      const Eigen::Vector3d a = p.col(t(0, i));
      QVERIFY((p.col(t(1, i)) - a).cross(p.col(t(2, i)) - a).dot(n.col(t(0, i))) > 0);
    }
    const Eigen::Vector3d foot = p.col(0) - (cap.height + lift) * up;
    const double volume = capVolume(mesh, foot + lift * up);
    const double held = volume / (6 * parcelVolume(kRadius));
    QVERIFY2(held > 0.88 && held <= 1, QByteArray::number(held));
  }

  // Three drops sliding down the sheet in one stream, and one beside it: the lowest of the
  // stream and the one beside it lead and get caps; the two behind are the trail's.
  void onlyTheLeadingDropOfAStreamGetsACap() {
    Scene scene;
    DropCaps caps(scene.sheet.triangles);
    scene.particles.clear();
    const Eigen::Vector3d down = -(kLean * Eigen::Vector3d::UnitY()) * 10 * kH;  // 10 h/s
    int first = 0;
    for (const DropSpec& d : {DropSpec{0.0, 0.50, 4, 1}, DropSpec{0.0, 0.55, 4, 100},
                              DropSpec{0.0, 0.60, 4, 200}, DropSpec{0.15, 0.55, 4, 300}}) {
      addDrop(scene.particles, scene.probe, d);
      setVelocity(scene.particles, first, d.count, down);
      first += d.count;
    }
    scene.grid.build(scene.particles.position, kH);
    const TearSurface& mesh =
        caps.update(scene.particles, scene.grid, kH, kRadius, scene.sheet.positions);
    QCOMPARE(caps.capCount(), 2);
    QCOMPARE(flagged(caps.skipped()), 16);  // all four are off the mesher's hands
    // The caps' tops: one at the stream's lowest drop, one beside it.
    const int perCap = 1 + caps.settings().rings * caps.settings().segments;
    const Eigen::Vector3d top0 = mesh.positions().col(0), top1 = mesh.positions().col(perCap);
    auto near = [](const Eigen::Vector3d& x, double u, double v) {
      return (x - sheetPoint(u, v)).norm() < 2 * kH;
    };
    QVERIFY((near(top0, 0.0, 0.50) && near(top1, 0.15, 0.55)) ||
            (near(top1, 0.0, 0.50) && near(top0, 0.15, 0.55)));

    // At rest, every small drop sits on its own and gets a cap.
    for (auto& v : scene.particles.velocity) v.setZero();
    caps.update(scene.particles, scene.grid, kH, kRadius, scene.sheet.positions);
    QCOMPARE(caps.capCount(), 4);
  }

  // Past maxCaps the remaining small drops are left to the mesher (not skipped), so thousands
  // of scattered particles cannot make an unbounded cap mesh.
  void capsAreBounded() {
    Scene scene;
    DropCapSettings settings;
    settings.maxCaps = 3;
    DropCaps caps(scene.sheet.triangles, settings);
    scene.particles.clear();
    for (int d = 0; d < 6; ++d)
      addDrop(scene.particles, scene.probe,
              {-0.25 + 0.1 * d, 0.5, 3, 1 + 100 * static_cast<std::uint64_t>(d)});
    scene.grid.build(scene.particles.position, kH);
    caps.update(scene.particles, scene.grid, kH, kRadius, scene.sheet.positions);
    QCOMPARE(caps.capCount(), 3);
    QCOMPARE(flagged(caps.skipped()), 9);
    QCOMPARE(caps.mesh().vertexCount(), 3 * (1 + settings.rings * settings.segments));
  }

  void largeDropsAndDropsInTheAirAreTheMeshers() {
    Scene scene;
    DropCaps caps(scene.sheet.triangles);
    scene.particles.clear();
    addDrop(scene.particles, scene.probe, {0.0, 0.5, caps.settings().maxParticles, 1});
    const int inAir =
        scene.particles.add(sheetPoint(0.2, 0.3) + 5 * kH * sheetNormal(0.2), 1.0, 500, Eye::Left);
    scene.grid.build(scene.particles.position, kH);
    caps.update(scene.particles, scene.grid, kH, kRadius, scene.sheet.positions);
    QCOMPARE(caps.capCount(), 0);
    QVERIFY(caps.mesh().empty());
    QCOMPARE(flagged(caps.skipped()), 0);
    QCOMPARE(int(caps.skipped().size()), scene.particles.size());
    QVERIFY(inAir >= 0);
  }

  void badSettingsAreRefused() {
    const SyntheticSkin sheet = makeCheekSheet();
    for (auto change : std::initializer_list<void (*)(DropCapSettings&)>{
             [](DropCapSettings& s) { s.maxParticles = 0; },
             [](DropCapSettings& s) { s.segments = 2; },
             [](DropCapSettings& s) { s.contactAngleDegrees = 0; },
             [](DropCapSettings& s) { s.contactAngleDegrees = std::nan(""); },
             [](DropCapSettings& s) { s.minimumSpeed = -1; },
             [](DropCapSettings& s) { s.rimLift = 1; },
             [](DropCapSettings& s) { s.maxCaps = -1; }}) {
      DropCapSettings s;
      change(s);
      QVERIFY_THROWS_EXCEPTION(std::invalid_argument, DropCaps(sheet.triangles, s));
    }
  }

  // Through the simulation: the caps' particles are left out of the marching-cubes surface, and
  // a skip list of the wrong size is an error, not a read past the end.
  void mesherSkipsTheCapsParticles() {
    const SyntheticSkin sheet = makeCheekSheet();
    const auto simulation = makeSheetSimulation(sheet);
    TearSimulation& sim = *simulation;
    for (int f = 0; f < 10; ++f) sim.step(sheet.positions, 6, 0, kFrameDt);
    QCOMPARE(sim.particles().size(), 6);
    SurfaceMesher mesher;
    QVERIFY(!mesher.update(sim).empty());
    const std::vector<std::uint8_t> all(6, 1);
    QVERIFY(mesher.update(sim, SurfaceMesherSettings{}.maxCubes, all).empty());
    const std::vector<std::uint8_t> wrong(5, 0);
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                             mesher.update(sim, SurfaceMesherSettings{}.maxCubes, wrong));
    DropCaps caps(sheet.triangles);
    caps.update(sim, sheet.positions);
    QCOMPARE(caps.capCount(), 1);  // six particles on the sheet: one small drop
    QVERIFY(mesher.update(sim, SurfaceMesherSettings{}.maxCubes, caps.skipped()).empty());
  }
};

QTEST_GUILESS_MAIN(DropCapsTest)
#include "DropCapsTest.moc"
