// The collider's triangle grid (TriangleGrid.h), checked against ODE on the cheek sheet with a
// collapsed row and scattered zero-area triangles, for nearest() at the radii the simulation
// uses and for resolve() with particles crossing the sheet fast (the ray path):
//  * with SkinQueryMethod::Grid (the default) the grid answers every query: the same nearest
//    triangle, point and distance as ODE bit for bit, and the same crossings of fast paths
//    (ODE computes a crossing in single precision, so the crossing point agrees to rounding);
//  * resolve() shared over 1, 2 and 3 threads gives the same bits;
//  * with SkinQueryMethod::Ode, ODE is skipped for the queries the grid proves empty, and
//    skipping never changes an answer: a collider whose grid is built (warm: it has seen more
//    than a thousand queries on this pose) answers bit for bit as one that asks ODE every time
//    (cold: reset to the same pose before the threshold).
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

bool sameBits(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::memcmp(a.data(), b.data(), sizeof(double) * 3) == 0;
}

std::unique_ptr<SkinCollider> colliderFor(const Scene& s, SkinQueryMethod method) {
  Eigen::AlignedBox3d envelope = s.box;
  envelope.min().array() -= 1.0;
  envelope.max().array() += 1.0;
  return std::make_unique<SkinCollider>(s.vertices, s.triangles, envelope, kRadius, kBand, kProbe,
                                        method);
}

// A query point: half near the sheet's vertices (contacts), half anywhere around it.
Eigen::Vector3d queryPoint(const Scene& scene, std::mt19937_64& rng, int q) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const Eigen::Vector3d lo = scene.box.min().array() - 0.1, size = scene.box.sizes().array() + 0.2;
  Eigen::Vector3d x = lo + Eigen::Vector3d(unit(rng), unit(rng), unit(rng)).cwiseProduct(size);
  if (q % 2 == 0) {
    const Eigen::Vector3d v = scene.vertices.col(
        static_cast<Eigen::Index>(unit(rng) * static_cast<double>(scene.vertices.cols() - 1)));
    x = v + 0.04 * Eigen::Vector3d(unit(rng) - 0.5, unit(rng) - 0.5, unit(rng) - 0.5);
  }
  return x;
}

// Particles above the sheet moved in one step through it, past it, or hardly at all, with
// their starting points in `previous`.
ParticleSet fastParticles(const Scene& scene, std::mt19937_64& rng, int n,
                          std::vector<Eigen::Vector3d>& previous) {
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const Eigen::Vector3d normalish(0, 0.34, 0.94);  // the sheet faces +z, tilted up
  ParticleSet a;
  previous.clear();
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector3d v = scene.vertices.col(static_cast<Eigen::Index>(
        (unit(rng) + 1) * 0.5 * static_cast<double>(scene.vertices.cols() - 1)));
    const Eigen::Vector3d start = v + normalish * (0.05 + 0.1 * (unit(rng) + 1)) +
                                  0.05 * Eigen::Vector3d(unit(rng), unit(rng), 0);
    a.add(start, 1.0, static_cast<std::uint64_t>(i), Eye::Left);
    previous.push_back(start);
    const double depth = i % 3 == 0 ? -0.4 : (i % 3 == 1 ? 0.2 * unit(rng) : 0.001);
    a.position.back() = v + normalish * depth + 0.2 * Eigen::Vector3d(unit(rng), unit(rng), 0);
    a.velocity.back() = (a.position.back() - start) * 22.0;
  }
  return a;
}

bool sameParticle(const ParticleSet& a, const ParticleSet& b, std::size_t s) {
  return sameBits(a.position[s], b.position[s]) && sameBits(a.velocity[s], b.velocity[s]) &&
         a.contact[s].triangle == b.contact[s].triangle &&
         sameBits(a.contact[s].barycentric, b.contact[s].barycentric) &&
         std::memcmp(&a.clearance[s], &b.clearance[s], sizeof(double)) == 0;
}

bool sameHit(bool foundA, const SkinHit& a, bool foundB, const SkinHit& b) {
  if (foundA != foundB) return false;
  if (!foundA) return true;
  return a.triangle == b.triangle && sameBits(a.point, b.point) &&
         sameBits(a.barycentric, b.barycentric) && a.interior == b.interior &&
         std::memcmp(&a.distance, &b.distance, sizeof(double)) == 0;
}

// Asks `a` and `b` the same nearest() queries at the simulation's three radii (`before(q)` runs
// ahead of query q); the answers found, and the first query whose answers differ (-1: none).
struct NearestComparison {
  int found = 0, firstDifference = -1;
};
template <class Before>
NearestComparison compareNearest(const Scene& scene, std::uint64_t seed, int queries,
                                 SkinCollider& a, CollisionCounters& aCounters, SkinCollider& b,
                                 CollisionCounters& bCounters, Before&& before) {
  std::mt19937_64 rng(seed);
  const double radii[] = {kRadius + kBand, kRadius + kProbe, 3 * kRadius + 0.02};
  NearestComparison result;
  for (int q = 0; q < queries; ++q) {
    before(q);
    const Eigen::Vector3d x = queryPoint(scene, rng, q);
    const double r = radii[q % 3];
    SkinHit hitA, hitB;
    const bool foundA = a.nearest(x, r, hitA, aCounters);
    const bool foundB = b.nearest(x, r, hitB, bCounters);
    if (!sameHit(foundA, hitA, foundB, hitB)) {
      result.firstDifference = q;
      return result;
    }
    result.found += foundA ? 1 : 0;
  }
  return result;
}

}  // namespace

class SkinColliderGridTest : public QObject {
  Q_OBJECT

 private slots:
  void gridNearestIsOdes() {
    const Scene scene = stressSheet();
    auto grid = colliderFor(scene, SkinQueryMethod::Grid);
    auto ode = colliderFor(scene, SkinQueryMethod::Ode);
    CollisionCounters gridCounters, odeCounters;
    const int queries = 20000;
    const NearestComparison c =
        compareNearest(scene, 17, queries, *grid, gridCounters, *ode, odeCounters, [](int) {});
    QVERIFY2(c.firstDifference < 0, qPrintable(QString("query %1 differs").arg(c.firstDifference)));
    QVERIFY(c.found > queries / 10 && c.found < queries * 9 / 10);
    QCOMPARE(gridCounters.gridQueries, static_cast<long long>(queries));
    QCOMPARE(gridCounters.odeQueries, 0LL);
    QCOMPARE(gridCounters.trimeshUpdates, 0LL);
  }

  void gridCrossingsAreOdes() {
    const Scene scene = stressSheet();
    const double rounding = 1e-6 * scene.box.sizes().maxCoeff();
    auto grid = colliderFor(scene, SkinQueryMethod::Grid);
    auto ode = colliderFor(scene, SkinQueryMethod::Ode);
    CollisionCounters gridCounters, odeCounters;
    ParallelChunks oneThread(1);
    std::mt19937_64 rng(23);
    int contacts = 0, crossings = 0;
    for (int batch = 0; batch < 20; ++batch) {
      std::vector<Eigen::Vector3d> previous;
      ParticleSet a = fastParticles(scene, rng, 300, previous);
      ParticleSet b = a;
      grid->resolve(a, previous, gridCounters, oneThread);
      ode->resolve(b, previous, odeCounters, oneThread);
      for (std::size_t s = 0; s < a.position.size(); ++s) {
        const QString where = QString("batch %1 particle %2").arg(batch).arg(s);
        QVERIFY2(a.contact[s].triangle == b.contact[s].triangle, qPrintable(where));
        QVERIFY2((a.position[s] - b.position[s]).norm() <= rounding, qPrintable(where));
        QVERIFY2((a.velocity[s] - b.velocity[s]).norm() <= 1e-6 * (1 + b.velocity[s].norm()),
                 qPrintable(where));
        contacts += a.contact[s].triangle >= 0 ? 1 : 0;
        crossings += s % 3 == 0 && a.contact[s].triangle >= 0 ? 1 : 0;
      }
    }
    QVERIFY(contacts > 1000);  // caught by the sheet: rays and spheres both answered
    QVERIFY(crossings > 500);  // through the sheet in one step: the ray path
    QCOMPARE(gridCounters.odeQueries, 0LL);
  }

  void sharedResolveIsBitIdentical() {
    const Scene scene = stressSheet();
    std::mt19937_64 rng(31);
    std::vector<Eigen::Vector3d> previous;
    const ParticleSet start = fastParticles(scene, rng, 3 * kParallelParticles, previous);
    ParticleSet reference;
    for (int threads : {1, 2, 3}) {
      auto grid = colliderFor(scene, SkinQueryMethod::Grid);
      ParallelChunks parallel(threads);
      parallel.setParticleCount(static_cast<int>(start.position.size()));
      QCOMPARE(parallel.shared(), threads > 1);
      ParticleSet p = start;
      CollisionCounters counters;
      grid->resolve(p, previous, counters, parallel);
      // Then the skin moves a particle radius and more (carrying, anchors and swept rays).
      Eigen::Matrix3Xd moved = scene.vertices;
      moved.row(2).array() += 3 * kRadius;
      grid->moveSurface(moved, p, counters, parallel);
      if (threads == 1) {
        reference = p;
        continue;
      }
      for (std::size_t s = 0; s < p.position.size(); ++s)
        QVERIFY2(sameParticle(p, reference, s),
                 qPrintable(QString("%1 threads, particle %2").arg(threads).arg(s)));
    }
  }

  void odeNearestIsUnchangedBySkipping() {
    const Scene scene = stressSheet();
    auto warm = colliderFor(scene, SkinQueryMethod::Ode),
         cold = colliderFor(scene, SkinQueryMethod::Ode);
    CollisionCounters warmCounters, coldCounters;
    const int queries = 40 * kBatch;
    const NearestComparison c =
        compareNearest(scene, 99, queries, *warm, warmCounters, *cold, coldCounters, [&](int q) {
          // cold: reset before the grid's threshold, so it always asks ODE
          if (q % kBatch == 0) cold->resetSurface(scene.vertices, coldCounters);
        });
    QVERIFY2(c.firstDifference < 0, qPrintable(QString("query %1 differs").arg(c.firstDifference)));
    // Both kinds of answer occurred, and the warm collider skipped ODE for empty ones.
    QVERIFY(c.found > queries / 10 && c.found < queries * 9 / 10);
    QCOMPARE(coldCounters.odeQueries, static_cast<long long>(queries));
    QVERIFY(warmCounters.odeQueries < coldCounters.odeQueries - queries / 5);
  }

  void odeResolveIsUnchangedBySkipping() {
    const Scene scene = stressSheet();
    auto warm = colliderFor(scene, SkinQueryMethod::Ode),
         cold = colliderFor(scene, SkinQueryMethod::Ode);
    ParallelChunks oneThread(1);
    CollisionCounters warmCounters, coldCounters;
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    // Warm the grid up on this pose.
    for (int q = 0; q < 2 * kBatch; ++q) {
      SkinHit hit;
      warm->nearest(scene.box.center() + Eigen::Vector3d(unit(rng), unit(rng), unit(rng)),
                    kRadius + kProbe, hit, warmCounters);
    }
    long long swept = 0;
    for (int batch = 0; batch < 20; ++batch) {
      cold->resetSurface(scene.vertices, coldCounters);
      std::vector<Eigen::Vector3d> previous;
      const int n = kBatch / 3;  // at most a ray and a sphere query each
      ParticleSet a = fastParticles(scene, rng, n, previous);
      ParticleSet b = a;
      warm->resolve(a, previous, warmCounters, oneThread);
      cold->resolve(b, previous, coldCounters, oneThread);
      for (int i = 0; i < n; ++i) {
        const auto s = static_cast<std::size_t>(i);
        QVERIFY2(sameParticle(a, b, s),
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
