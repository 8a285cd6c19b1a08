// Ray against triangles (RayMesh.h): the single-triangle test on exact cases and the hard ones
// (parallel rays, zero-area triangles, shared edges, rays starting on or past the face), and the
// hierarchy against brute force on a closed bumpy sphere, before and after refit().
#include <lacrima/common/RayMesh.h>

#include <QtTest>

#include <cmath>
#include <limits>
#include <random>

using namespace lacrima;

namespace {

// A closed sphere of radius about 1 with bumps (so rays meet front and back faces at every
// angle), `rings` x `segments` quads split into triangles; poles are shared vertices.
struct Sphere {
  Eigen::Matrix3Xf vertices;
  std::vector<Eigen::Vector3i> triangles;
};

Sphere bumpySphere(int rings, int segments) {
  Sphere s;
  s.vertices.resize(3, 2 + (rings - 1) * segments);
  s.vertices.col(0) = Eigen::Vector3f(0, 1, 0);
  s.vertices.col(1) = Eigen::Vector3f(0, -1, 0);
  for (int r = 1; r < rings; ++r)
    for (int k = 0; k < segments; ++k) {
      const double theta = M_PI * r / rings, phi = 2 * M_PI * k / segments;
      const double radius = 1 + 0.15 * std::sin(5 * phi) * std::sin(3 * theta);
      s.vertices.col(2 + (r - 1) * segments + k) =
          (radius * Eigen::Vector3d(std::sin(theta) * std::cos(phi), std::cos(theta),
                                    std::sin(theta) * std::sin(phi)))
              .cast<float>();
    }
  auto at = [&](int r, int k) { return 2 + (r - 1) * segments + (k % segments); };
  for (int k = 0; k < segments; ++k) {
    s.triangles.emplace_back(0, at(1, k + 1), at(1, k));
    s.triangles.emplace_back(1, at(rings - 1, k), at(rings - 1, k + 1));
    for (int r = 1; r + 1 < rings; ++r) {
      s.triangles.emplace_back(at(r, k), at(r, k + 1), at(r + 1, k));
      s.triangles.emplace_back(at(r + 1, k), at(r, k + 1), at(r + 1, k + 1));
    }
  }
  return s;
}

std::optional<RayHit> bruteForce(const Sphere& s, const Ray& ray) {
  std::optional<RayHit> best;
  for (std::size_t t = 0; t < s.triangles.size(); ++t) {
    const Eigen::Vector3i& tri = s.triangles[t];
    auto hit = intersectRayTriangle(ray, s.vertices.col(tri[0]).cast<double>(),
                                    s.vertices.col(tri[1]).cast<double>(),
                                    s.vertices.col(tri[2]).cast<double>());
    if (hit && (!best || hit->distance < best->distance)) {
      best = hit;
      best->triangle = static_cast<int>(t);
    }
  }
  return best;
}

}  // namespace

class RayMeshTest : public QObject {
  Q_OBJECT

 private slots:
  void hitsATriangleWhereTheRayCrossesIt() {
    const Eigen::Vector3d a(0, 0, 0), b(2, 0, 0), c(0, 2, 0);
    const auto hit = intersectRayTriangle({{0.5, 0.25, 3}, {0, 0, -1}}, a, b, c);
    QVERIFY(hit);
    QCOMPARE(hit->distance, 3.0);
    QVERIFY((hit->point - Eigen::Vector3d(0.5, 0.25, 0)).norm() < 1e-12);
    // barycentric weights reproduce the point: 0.5 = 2 u, 0.25 = 2 v
    QVERIFY((hit->barycentric - Eigen::Vector3d(0.625, 0.25, 0.125)).norm() < 1e-12);
    // From behind the face too (two-sided), and an oblique ray.
    QVERIFY(intersectRayTriangle({{0.5, 0.25, -3}, {0, 0, 1}}, a, b, c));
    const Eigen::Vector3d from(-1, -1, 1);
    const auto oblique =
        intersectRayTriangle({from, (Eigen::Vector3d(0.4, 0.4, 0) - from).normalized()}, a, b, c);
    QVERIFY(oblique);
    QVERIFY((oblique->point - Eigen::Vector3d(0.4, 0.4, 0)).norm() < 1e-12);
  }

  void missesOutsideBehindAndParallel() {
    const Eigen::Vector3d a(0, 0, 0), b(2, 0, 0), c(0, 2, 0);
    QVERIFY(!intersectRayTriangle({{1.5, 1.5, 3}, {0, 0, -1}}, a, b, c));  // beyond the edge bc
    QVERIFY(!intersectRayTriangle({{0.5, 0.5, 3}, {0, 0, 1}}, a, b, c));   // pointing away
    QVERIFY(!intersectRayTriangle({{0.5, 0.5, 0}, {0, 0, -1}}, a, b, c));  // starts on the face
    // Parallel to the face: in its plane and just above it.
    QVERIFY(!intersectRayTriangle({{-1, 0.5, 0}, {1, 0, 0}}, a, b, c));
    QVERIFY(!intersectRayTriangle({{-1, 0.5, 1e-3}, {1, 0, 0}}, a, b, c));
  }

  void degenerateTrianglesAreSkippedWithoutNaNs() {
    const Eigen::Vector3d a(0, 0, 0), b(1, 1, 0), c(2, 2, 0);  // collinear
    QVERIFY(!intersectRayTriangle({{1, 1, 3}, {0, 0, -1}}, a, b, c));
    QVERIFY(!intersectRayTriangle({{1, 1, 3}, {0, 0, -1}}, a, a, a));  // a point
    const double nan = std::numeric_limits<double>::quiet_NaN();
    QVERIFY(!intersectRayTriangle({{1, 1, 3}, {0, 0, -1}}, a, Eigen::Vector3d(nan, 0, 0), c));
    // In a mesh: the zero-area triangle is never the answer, its neighbour is.
    Eigen::Matrix3Xf v(3, 4);
    v << 0, 2, 0, 1, 0, 0, 2, 1, 0, 0, 0, 0;        // columns (0,0,0) (2,0,0) (0,2,0) (1,1,0)
    const RayMesh mesh(v, {{1, 3, 2}, {0, 1, 2}});  // the first one is degenerate: 3 is on 1-2
    const auto hit = mesh.closestHit({{1, 1, 5}, {0, 0, -1}});
    QVERIFY(hit);
    QCOMPARE(hit->triangle, 1);
    QVERIFY(hit->barycentric.allFinite());
  }

  void aRayThroughASharedEdgeOrCornerHitsOneSide() {
    // Two triangles sharing the diagonal of the unit square; rays exactly on the diagonal and
    // on the shared corners must not slip through.
    Eigen::Matrix3Xf v(3, 4);
    v << 0, 1, 1, 0, 0, 0, 1, 1, 0, 0, 0, 0;
    const RayMesh mesh(v, {{0, 1, 2}, {0, 2, 3}});
    for (double s : {0.0, 0.1, 0.37, 0.5, 0.9, 1.0}) {
      const auto hit = mesh.closestHit({{s, s, 1}, {0, 0, -1}});
      QVERIFY2(hit, qPrintable(QString("diagonal at %1").arg(s)));
      QVERIFY(std::abs(hit->distance - 1) < 1e-12);
    }
  }

  void theHierarchyFindsWhatBruteForceFinds() {
    const Sphere s = bumpySphere(40, 64);
    RayMesh mesh(s.vertices, s.triangles);
    QCOMPARE(mesh.triangleCount(), int(s.triangles.size()));
    std::mt19937 random(7);
    std::uniform_real_distribution<double> unit(-1, 1);
    int hits = 0;
    for (int i = 0; i < 400; ++i) {
      // From outside towards a point near the middle (hits), or random directions (some miss),
      // and from inside (every ray hits the closed surface).
      const Eigen::Vector3d origin =
          i % 3 == 2 ? 0.3 * Eigen::Vector3d(unit(random), unit(random), unit(random))
                     : 3 * Eigen::Vector3d(unit(random), unit(random), unit(random)).normalized();
      Eigen::Vector3d direction =
          i % 3 == 0
              ? Eigen::Vector3d(0.5 * Eigen::Vector3d(unit(random), unit(random), 0) - origin)
              : Eigen::Vector3d(unit(random), unit(random), unit(random));
      const Ray ray{origin, direction.normalized()};
      const auto expected = bruteForce(s, ray);
      const auto got = mesh.closestHit(ray);
      QCOMPARE(bool(got), bool(expected));
      if (i % 3 == 2) QVERIFY(got);
      if (!got) continue;
      ++hits;
      QVERIFY(std::abs(got->distance - expected->distance) < 1e-9);
      QVERIFY((got->point - expected->point).norm() < 1e-9);
      // The barycentric weights reproduce the point on the triangle named.
      const Eigen::Vector3i& tri = s.triangles[got->triangle];
      const Eigen::Vector3d p = got->barycentric[0] * s.vertices.col(tri[0]).cast<double>() +
                                got->barycentric[1] * s.vertices.col(tri[1]).cast<double>() +
                                got->barycentric[2] * s.vertices.col(tri[2]).cast<double>();
      QVERIFY((p - got->point).norm() < 1e-9);
    }
    QVERIFY(hits > 200);
  }

  void axisParallelRaysAndRaysAlongBoxFaces() {
    // Direction components of exactly zero give infinite inverse directions in the slab test;
    // a ray lying in a box's face plane must still be tested, not dropped on a NaN.
    const Sphere s = bumpySphere(12, 16);
    const RayMesh mesh(s.vertices, s.triangles);
    for (const Eigen::Vector3d& d :
         {Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, -1, 0), Eigen::Vector3d(0, 0, 1)}) {
      const Ray ray{-3 * d, d};
      const auto expected = bruteForce(s, ray), got = mesh.closestHit(ray);
      QVERIFY(got && expected);
      QVERIFY(std::abs(got->distance - expected->distance) < 1e-9);
    }
    // The north pole vertex is at y = 1 exactly: a ray along x in the plane y = 1 grazes it.
    const Ray grazing{{-3, 1, 0}, {1, 0, 0}};
    QCOMPARE(bool(mesh.closestHit(grazing)), bool(bruteForce(s, grazing)));
  }

  void refitFollowsMovedVertices() {
    Sphere s = bumpySphere(20, 32);
    RayMesh mesh(s.vertices, s.triangles);
    const Ray ray{{0, 0, 5}, {0, 0, -1}};
    const double before = mesh.closestHit(ray)->distance;
    s.vertices.array() *= 2;          // scaled about the origin: the front surface comes closer
    s.vertices.row(0).array() += 10;  // and moved away from the ray entirely
    mesh.refit(s.vertices);
    QVERIFY(!mesh.closestHit(ray));
    s.vertices.row(0).array() -= 10;
    mesh.refit(s.vertices);
    const auto after = mesh.closestHit(ray);
    QVERIFY(after);
    QVERIFY(std::abs((5 - after->distance) - 2 * (5 - before)) < 1e-5);
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, mesh.refit(Eigen::Matrix3Xf(3, 2)));
  }

  void badInputIsRefusedOrHarmless() {
    Eigen::Matrix3Xf v(3, 3);
    v << 0, 1, 0, 0, 0, 1, 0, 0, 0;
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, RayMesh(v, {{0, 1, 3}}));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, RayMesh(v, {{-1, 1, 2}}));
    const RayMesh empty(v, {});
    QVERIFY(!empty.closestHit({{0.2, 0.2, 1}, {0, 0, -1}}));
    const RayMesh mesh(v, {{0, 1, 2}});
    QVERIFY(mesh.closestHit({{0.2, 0.2, 1}, {0, 0, -7}}));  // direction normalised
    QCOMPARE(mesh.closestHit({{0.2, 0.2, 1}, {0, 0, -7}})->distance, 1.0);
    QVERIFY(!mesh.closestHit({{0.2, 0.2, 1}, {0, 0, 0}}));
    const double nan = std::numeric_limits<double>::quiet_NaN();
    QVERIFY(!mesh.closestHit({{0.2, 0.2, 1}, {0, nan, -1}}));
    QVERIFY(!mesh.closestHit({{nan, 0.2, 1}, {0, 0, -1}}));
    v(0, 1) = std::numeric_limits<float>::infinity();  // a non-finite vertex: no hit, no crash
    const RayMesh broken(v, {{0, 1, 2}});
    QVERIFY(!broken.closestHit({{0.2, 0.2, 1}, {0, 0, -1}}));
  }
};

QTEST_GUILESS_MAIN(RayMeshTest)
#include "RayMeshTest.moc"
