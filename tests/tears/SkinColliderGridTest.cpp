// The collider skips ODE for sphere and ray queries its triangle grid proves empty
// (TriangleGrid.h). Skipping must never change an answer: a collider whose grid is built
// (warm: it has seen more than a thousand queries on this pose) must answer every query
// bit for bit as one that asks ODE every time (cold: reset to the same pose before the
// threshold). Checked on the cheek sheet with a collapsed row and scattered zero-area
// triangles, for nearest() at the radii the simulation uses and for resolve() with particles
// crossing the sheet fast (the ray path), and that the grid did skip queries.
#include "SkinCollider.h"  // internal to lacrima_tears (player/tears/src is on this test's include path)

#include <lacrima/tears/SyntheticSkin.h>

#include <QtTest>

#include <cstring>
#include <random>

using namespace lacrima::tears;

namespace {

constexpr double kRadius = 0.01, kBand = 0.005, kProbe = 0.03;
constexpr int kBatch = 500;  // queries per cold collider reset: below the grid's threshold

struct Scene {
  Eigen::Matrix3Xd vertices;
  std::vector<Eigen::Vector3i> triangles;
  Eigen::AlignedBox3d box;
};

Scene stressSheet() {
  CheekSheetOptions options;
  options.collapsedRow = true;
  options.extraDegenerateTriangles = 40;
  const SyntheticSkin sheet = makeCheekSheet(options);
  Scene s{sheet.positions.cast<double>(), sheet.triangles, {}};
  for (Eigen::Index i = 0; i < s.vertices.cols(); ++i) s.box.extend(s.vertices.col(i));
  return s;
}

std::unique_ptr<SkinCollider> colliderFor(const Scene& s) {
  Eigen::AlignedBox3d envelope = s.box;
  envelope.min().array() -= 1.0;
  envelope.max().array() += 1.0;
  return std::make_unique<SkinCollider>(s.vertices, s.triangles, envelope, kRadius, kBand, kProbe);
}

bool sameBits(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::memcmp(a.data(), b.data(), sizeof(double) * 3) == 0;
}

bool sameHit(bool foundA, const SkinHit& a, bool foundB, const SkinHit& b) {
  if (foundA != foundB) return false;
  if (!foundA) return true;
  return a.triangle == b.triangle && sameBits(a.point, b.point) &&
         sameBits(a.barycentric, b.barycentric) && a.interior == b.interior &&
         std::memcmp(&a.distance, &b.distance, sizeof(double)) == 0;
}

}  // namespace

class SkinColliderGridTest : public QObject {
  Q_OBJECT

 private slots:
  void nearestIsUnchangedBySkipping() {
    const Scene scene = stressSheet();
    auto warm = colliderFor(scene), cold = colliderFor(scene);
    CollisionCounters warmCounters, coldCounters;
    std::mt19937_64 rng(99);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const Eigen::Vector3d lo = scene.box.min().array() - 0.1,
                          size = scene.box.sizes().array() + 0.2;
    const double radii[] = {kRadius + kBand, kRadius + kProbe, 3 * kRadius + 0.02};
    int found = 0;
    const int queries = 40 * kBatch;
    for (int q = 0; q < queries; ++q) {
      if (q % kBatch == 0) cold->resetSurface(scene.vertices, coldCounters);  // cold: never a grid
      // Half the points near the sheet (contacts), half anywhere in the box.
      Eigen::Vector3d x = lo + Eigen::Vector3d(unit(rng), unit(rng), unit(rng)).cwiseProduct(size);
      if (q % 2 == 0) {
        const Eigen::Vector3d v = scene.vertices.col(
            static_cast<Eigen::Index>(unit(rng) * static_cast<double>(scene.vertices.cols() - 1)));
        x = v + 0.04 * Eigen::Vector3d(unit(rng) - 0.5, unit(rng) - 0.5, unit(rng) - 0.5);
      }
      const double r = radii[q % 3];
      SkinHit a, b;
      const bool fa = warm->nearest(x, r, a, warmCounters);
      const bool fb = cold->nearest(x, r, b, coldCounters);
      QVERIFY2(sameHit(fa, a, fb, b), qPrintable(QString("query %1 differs").arg(q)));
      found += fa ? 1 : 0;
    }
    // Both kinds of answer occurred, and the warm collider skipped ODE for empty ones.
    QVERIFY(found > queries / 10 && found < queries * 9 / 10);
    QCOMPARE(coldCounters.odeQueries, static_cast<long long>(queries));
    QVERIFY(warmCounters.odeQueries < coldCounters.odeQueries - queries / 5);
  }

  void resolveIsUnchangedBySkipping() {
    const Scene scene = stressSheet();
    auto warm = colliderFor(scene), cold = colliderFor(scene);
    CollisionCounters warmCounters, coldCounters;
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    // Warm the grid up on this pose.
    for (int q = 0; q < 2 * kBatch; ++q) {
      SkinHit hit;
      warm->nearest(scene.box.center() + Eigen::Vector3d(unit(rng), unit(rng), unit(rng)),
                    kRadius + kProbe, hit, warmCounters);
    }
    const Eigen::Vector3d normalish(0, 0.34, 0.94);  // the sheet faces +z, tilted up
    long long swept = 0;
    for (int batch = 0; batch < 20; ++batch) {
      cold->resetSurface(scene.vertices, coldCounters);
      ParticleSet a;
      std::vector<Eigen::Vector3d> previous;
      const int n = kBatch / 3;  // at most a ray and a sphere query each
      for (int i = 0; i < n; ++i) {
        const Eigen::Vector3d v = scene.vertices.col(static_cast<Eigen::Index>(
            (unit(rng) + 1) * 0.5 * static_cast<double>(scene.vertices.cols() - 1)));
        const Eigen::Vector3d start = v + normalish * (0.05 + 0.1 * (unit(rng) + 1)) +
                                      0.05 * Eigen::Vector3d(unit(rng), unit(rng), 0);
        a.add(start, 1.0, static_cast<std::uint64_t>(i), Eye::Left);
        previous.push_back(start);
        // Fast particles: through the sheet, or past it, or hardly moving.
        const double depth = i % 3 == 0 ? -0.4 : (i % 3 == 1 ? 0.2 * unit(rng) : 0.001);
        a.position.back() = v + normalish * depth + 0.2 * Eigen::Vector3d(unit(rng), unit(rng), 0);
        a.velocity.back() = (a.position.back() - start) * 22.0;
      }
      ParticleSet b = a;
      warm->resolve(a, previous, warmCounters);
      cold->resolve(b, previous, coldCounters);
      for (int i = 0; i < n; ++i) {
        const auto s = static_cast<std::size_t>(i);
        QVERIFY2(sameBits(a.position[s], b.position[s]) && sameBits(a.velocity[s], b.velocity[s]) &&
                     a.contact[s].triangle == b.contact[s].triangle &&
                     sameBits(a.contact[s].barycentric, b.contact[s].barycentric) &&
                     std::memcmp(&a.clearance[s], &b.clearance[s], sizeof(double)) == 0,
                 qPrintable(QString("batch %1 particle %2 differs").arg(batch).arg(i)));
        swept += a.contact[s].triangle >= 0 ? 1 : 0;
      }
    }
    QVERIFY(swept > 100);  // particles were caught by the sheet (rays and spheres both answered)
    QVERIFY(warmCounters.odeQueries - 2 * kBatch < coldCounters.odeQueries);
  }
};

QTEST_APPLESS_MAIN(SkinColliderGridTest)
#include "SkinColliderGridTest.moc"
