// Wet trails: a drop sliding down the cheek sheet leaves a trail on the sheet that rides along
// when the sheet moves; a trail is at least as wide as its drop's footprint; a drop that splits
// branches its trail; merging drops continue one trail; trails dry and disappear; the section cap
// bounds memory; a real simulation's tears leave trails; nothing is done when nothing is wet.
#include "SheetDrops.h"
#include "TearTestSupport.h"

#include <lacrima/tears/DropFootprint.h>
#include <lacrima/tears/TrailBuilder.h>

#include <QtTest>

#include <malloc.h>

#include <cmath>
#include <numbers>

using namespace lacrima::tears;
using namespace lacrima::tears::testing;

namespace {

void checkOnSheet(const TrailMesh& mesh, const Motion* motion = nullptr) {
  QVERIFY(mesh.positions().allFinite() && mesh.normals().allFinite() && mesh.alpha().allFinite());
  const auto p = mesh.positions();
  for (int v = 0; v < p.cols(); ++v) {
    const Eigen::Vector3d x = motion ? motion->undo(p.col(v)) : Eigen::Vector3d(p.col(v));
    QVERIFY2(distanceToSheet(x) <= kH, QByteArray::number(distanceToSheet(x) / kH));
    QVERIFY(std::abs(mesh.normals().col(v).norm() - 1) < 1e-9);
    QVERIFY(mesh.alpha()[v] >= 0 && mesh.alpha()[v] <= 1);
  }
  // Wound counter-clockwise seen from outside the skin.
  const auto t = mesh.triangles();
  for (int i = 0; i < t.cols(); ++i) {
    const Eigen::Vector3d a = p.col(t(0, i));
    const Eigen::Vector3d n = (p.col(t(1, i)) - a).cross(p.col(t(2, i)) - a);
    QVERIFY(n.dot(mesh.normals().col(t(0, i))) >= -1e-12);
  }
}

}  // namespace

class TearTrailsTest : public QObject {
  Q_OBJECT

 private slots:
  void nothingWetNoWork() {
    Scene scene;
    TrailBuilder trails(scene.sheet.triangles);
    QVERIFY(scene.step(trails, {}).empty());
    QCOMPARE(trails.lastMilliseconds(), 0.0);
    QCOMPARE(trails.trackedDrops(), 0);
  }

  void slidingDropLeavesATrailThatFollowsTheSheet() {
    Scene scene;
    TrailBuilder trails(scene.sheet.triangles);
    const int frames = 40;
    for (int f = 0; f < frames; ++f) scene.step(trails, {{0.3, 0.8 - 0.005 * f, 30, 1}});
    const TrailMesh& mesh = trails.mesh();
    // 0.2 dm slid, a section every d_min = h / 2 = 0.008 dm (the drop moves 0.005 per frame).
    QVERIFY2(trails.sections().size() >= 15, QByteArray::number(int(trails.sections().size())));
    QCOMPARE(mesh.triangleCount(), 4 * static_cast<int>(trails.segments().size()));
    QCOMPARE(mesh.vertexCount(), 3 * static_cast<int>(trails.sections().size()));
    checkOnSheet(mesh);
    // The trail is as wide as the drop and runs down the sheet.
    const auto p = mesh.positions();
    const double width = (p.col(0) - p.col(2)).norm();
    QVERIFY(width > 2 * kRadius && width < 10 * kH);
    QVERIFY(p.col(0).y() > p.col(p.cols() - 1).y() + 0.1);
    QVERIFY(trails.wetArea(Eye::Left) > 0);
    QCOMPARE(trails.wetArea(Eye::Right), 0.0);
    QVERIFY(trails.lastMilliseconds() > 0);

    // The face moves (and the drop with it): the trail rides along, no new section appears.
    Motion motion{scene.sheet.centre, Eigen::Vector3d(0.1, -0.05, 0.02),
                  Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitY()).toRotationMatrix()};
    const Eigen::Matrix3Xd before = p;
    const std::size_t sectionsBefore = trails.sections().size();
    const Eigen::Matrix3Xf moved = movedSheet(scene.sheet, motion.translation,
                                              Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitY()));
    const TrailMesh& after =
        scene.step(trails, {{0.3, 0.8 - 0.005 * (frames - 1), 30, 1}}, 0.0, &moved, &motion);
    QCOMPARE(trails.sections().size(), sectionsBefore);
    for (int v = 0; v < before.cols(); ++v)
      QVERIFY((after.positions().col(v) - motion.apply(before.col(v))).norm() < 1e-5);
    checkOnSheet(after, &motion);
  }

  // A drop of one particle is a parcel of water 2r wide, but on the skin it spreads to the
  // footprint of its volume (DropFootprint.h): the trail a lone particle leaves is that wide,
  // not a 2r hairline.
  void trailIsAsWideAsTheDropsFootprint() {
    Scene scene;
    TrailBuilder trails(scene.sheet.triangles);
    for (int f = 0; f < 20; ++f) scene.step(trails, {{0.1, 0.8 - 0.005 * f, 1, 1}});
    QVERIFY(trails.sections().size() >= 5);
    const double footprint =
        sphericalCap(parcelVolume(kRadius),
                     TrailSettings{}.contactAngleDegrees * std::numbers::pi / 180)
            .contactRadius;
    QVERIFY(footprint > 1.5 * kRadius);  // so the test tells the two widths apart
    const auto p = trails.mesh().positions();
    for (int section = 0; section < p.cols() / 3; ++section) {
      const double width = (p.col(3 * section) - p.col(3 * section + 2)).norm();
      QVERIFY2(std::abs(width - 2 * footprint) < 0.02 * footprint,
               QByteArray::number(width / (2 * footprint)));
    }
  }

  void sharpTurnDoesNotFoldTheTrail() {
    // A drop slides straight down, then turns sideways (a turn of 60 or 90 degrees within one
    // section): the inner edge of the strip would run backwards across the last cross-section,
    // folding triangles over (wound clockwise seen from outside). Every triangle must stay wound
    // outward, and the trail must still cover the turn.
    for (double degrees : {60.0, 90.0}) {
      Scene scene;
      TrailBuilder trails(scene.sheet.triangles);
      const double step = 0.01;  // a section per frame (d_min = h / 2 = 0.008)
      const double turn = degrees * std::numbers::pi / 180;
      double u = 0.0, v = 0.8;
      for (int f = 0; f < 24; ++f) {
        if (f < 12) {
          v -= step;
        } else {
          u += step * std::sin(turn);
          v -= step * std::cos(turn);
        }
        scene.step(trails, {{u, v, 40, 1}});
      }
      QVERIFY(trails.segments().size() >= 18);
      checkOnSheet(trails.mesh());
      // Neither edge of the strip runs backwards: each boundary point is level with or ahead of
      // the last one along the centre's motion (a pivot stays put).
      const auto x = trails.mesh().positions();
      for (const TrailSegment& segment : trails.segments()) {
        const Eigen::Vector3d forward = x.col(3 * segment.to + 1) - x.col(3 * segment.from + 1);
        for (int side : {0, 2})
          QVERIFY((x.col(3 * segment.to + side) - x.col(3 * segment.from + side)).dot(forward) >=
                  -1e-12);
      }
      // Only pivot triangles (no area) are left out: the strip covers the turn.
      const int expected = 4 * static_cast<int>(trails.segments().size());
      qInfo("%g degrees: %d of %d triangles drawn", degrees, trails.mesh().triangleCount(),
            expected);
      QVERIFY(trails.mesh().triangleCount() >= expected - 4);
      if (QTest::currentTestFailed()) qWarning("turn of %g degrees", degrees);
      QVERIFY(!QTest::currentTestFailed());
    }
  }

  void splittingDropBranches() {
    Scene scene;
    TrailBuilder trails(scene.sheet.triangles);
    for (int f = 0; f < 8; ++f) scene.step(trails, {{0.0, 0.8 - 0.006 * f, 40, 1}});
    QCOMPARE(trails.trackedDrops(), 1);
    const double v0 = 0.8 - 0.006 * 7;
    // The drop parts: two halves, keeping their particle ids, drifting apart as they slide on
    // (about 25 degrees either side of straight down).
    for (int f = 1; f <= 24; ++f)
      scene.step(trails,
                 {{-0.003 * f, v0 - 0.006 * f, 20, 1}, {0.003 * f, v0 - 0.006 * f, 20, 21}});
    QCOMPARE(trails.trackedDrops(), 2);
    QVERIFY(trails.branches() >= 1);
    // Some section starts two segments: the branch point shared by both parts.
    std::map<int, int> outgoing;
    for (const TrailSegment& s : trails.segments()) ++outgoing[s.from];
    int forks = 0;
    for (const auto& [section, count] : outgoing) forks += count >= 2;
    QCOMPARE(forks, 1);
    checkOnSheet(trails.mesh());
  }

  void mergingDropsContinueOneTrail() {
    Scene scene;
    TrailBuilder trails(scene.sheet.triangles);
    // Two drops converge while sliding (about 25 degrees either side of straight down) ...
    for (int f = 0; f < 10; ++f)
      scene.step(trails, {{-0.07 + 0.004 * f, 0.8 - 0.008 * f, 20, 1},
                          {0.07 - 0.004 * f, 0.8 - 0.008 * f, 20, 101}});
    QCOMPARE(trails.trackedDrops(), 2);
    const std::size_t segmentsBefore = trails.segments().size();
    // ... and run on as one drop made of both sets of particles.
    for (int f = 0; f < 10; ++f) {
      ParticleSet& p = scene.particles;
      p.clear();
      addDrop(p, scene.probe, {-0.008, 0.72 - 0.008 * f, 20, 1});
      addDrop(p, scene.probe, {0.008, 0.72 - 0.008 * f, 20, 101});
      scene.grid.build(p.position, kH);
      trails.update(p, scene.grid, kH, kRadius, scene.sheet.positions, kFrameDt);
    }
    QCOMPARE(trails.trackedDrops(), 1);
    QVERIFY(trails.segments().size() > segmentsBefore);
    // One trail goes on: no section starts two segments, and the merged drop's newest segments
    // form one chain.
    std::map<int, int> outgoing;
    for (const TrailSegment& s : trails.segments()) ++outgoing[s.from];
    for (const auto& [section, count] : outgoing) QCOMPARE(count, 1);
    checkOnSheet(trails.mesh());
  }

  void aFallingDropLeavesNoTrailInTheAir() {
    // A drop slides, falls off (three updates in the air, touching nothing), lands 3 cm lower
    // and slides on: two trails, and no strip bridging the fall.
    Scene scene;
    TrailBuilder trails(scene.sheet.triangles);
    for (int f = 0; f < 8; ++f) scene.step(trails, {{0.0, 0.8 - 0.006 * f, 30, 1}});
    const std::size_t sectionsBefore = trails.sections().size();
    QVERIFY(sectionsBefore >= 2);
    for (int f = 0; f < 3; ++f) {
      scene.step(trails, {{0.0, 0.7 - 0.1 * f, 30, 1, Eye::Left, 0.1}});
      QCOMPARE(trails.sections().size(), sectionsBefore);  // nothing wet in the air
    }
    for (int f = 0; f < 8; ++f) scene.step(trails, {{0.0, 0.4 - 0.006 * f, 30, 1}});
    QVERIFY(trails.sections().size() > sectionsBefore + 2);
    // Every segment joins two sections a few steps apart: none spans the 3 cm fall.
    const auto middle = [&](int section) {
      return scene.probe.point(trails.sections()[static_cast<std::size_t>(section)].point[1]);
    };
    for (const TrailSegment& s : trails.segments())
      QVERIFY2((middle(s.from) - middle(s.to)).norm() < 0.05,
               QByteArray::number((middle(s.from) - middle(s.to)).norm()));
    checkOnSheet(trails.mesh());
  }

  void trailsDryAndAreRemoved() {
    Scene scene;
    TrailSettings settings;
    settings.drySeconds = 4;
    TrailBuilder trails(scene.sheet.triangles, settings);
    for (int f = 0; f < 20; ++f) scene.step(trails, {{0.3, 0.8 - 0.006 * f, 30, 1}});
    QVERIFY(!trails.mesh().empty());
    const double wet = trails.wetArea(Eye::Left);
    scene.step(trails, {}, 2.0);  // the drop is gone; the trail dries on
    QVERIFY(!trails.mesh().empty());
    QVERIFY(trails.mesh().alpha().maxCoeff() <= 0.5 + 1e-9);
    QVERIFY(trails.wetArea(Eye::Left) < 0.6 * wet);
    scene.step(trails, {}, 2.5);
    QVERIFY(trails.mesh().empty());
    QCOMPARE(trails.sections().size(), std::size_t{0});
    QCOMPARE(trails.wetArea(Eye::Left), 0.0);
    scene.step(trails, {}, 1.0);
    QCOMPARE(trails.lastMilliseconds(), 0.0);  // dry skin, no drops: no work
  }

  void sectionCapBoundsMemory() {
    Scene scene;
    TrailSettings settings;
    settings.maxSections = 20;
    TrailBuilder trails(scene.sheet.triangles, settings);
    for (int f = 0; f < 120; ++f) {
      scene.step(trails,
                 {{0.3, 1.0 - 0.012 * f, 25, 1}, {-0.3, 1.0 - 0.012 * f, 25, 101, Eye::Right}});
      QVERIFY(trails.sections().size() <= 20);
      QVERIFY(trails.segments().size() <= 20);
    }
    QVERIFY(trails.segments().size() >= 10);
    QVERIFY(trails.wetArea(Eye::Right) > 0);
    checkOnSheet(trails.mesh());
  }

  // A copy (the player keeps one with every checkpoint) shares the skin's tables instead of
  // copying them: half a megabyte on the default head, most of a checkpoint of the demo.
  void copiesShareTheSkinTables() {
    Scene scene;
    TrailBuilder trails(scene.sheet.triangles);
    for (int f = 0; f < 10; ++f) scene.step(trails, {{0.3, 0.8 - 0.005 * f, 30, 1}});
    const std::size_t tables = scene.sheet.triangles.size() * (sizeof(Eigen::Vector3i) + 3 * 4);
    QVERIFY(trails.bytes() < tables);
    const double before = static_cast<double>(mallinfo2().uordblks);
    std::vector<TrailBuilder> kept(4, trails);
    const double each = (static_cast<double>(mallinfo2().uordblks) - before) / 4;
    if (!(each > 0)) QSKIP("mallinfo2 does not see this build's allocator (a sanitizer's)");
    QVERIFY2(each < 0.25 * static_cast<double>(tables),
             qPrintable(QStringLiteral("a copy took %1 bytes; the tables are %2")
                            .arg(each, 0, 'f', 0)
                            .arg(tables)));
    QVERIFY(each <= 1.5 * static_cast<double>(trails.bytes()));
  }

  // The simulation's own tears: trails appear on the sheet behind them.
  void simulatedTearsLeaveTrails() {
    const SyntheticSkin sheet = makeCheekSheet();
    auto sim = makeSheetSimulation(sheet);
    TrailBuilder trails(sheet.triangles);
    for (int f = 0; f < 66; ++f) {
      sim->step(sheet.positions, 60, 0, kFrameDt);
      trails.update(*sim, sheet.positions, kFrameDt);
    }
    QVERIFY2(trails.segments().size() >= 3, QByteArray::number(int(trails.segments().size())));
    checkOnSheet(trails.mesh());
    QVERIFY(trails.wetArea(Eye::Left) > 0);
  }
};

QTEST_GUILESS_MAIN(TearTrailsTest)
#include "TearTrailsTest.moc"
