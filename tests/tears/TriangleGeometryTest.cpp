// The per-pose skin faces (SkinFace, edges formed once per frame) must give exactly what the
// closest-point test gave when it formed the edges from the corners on every call: the
// collider's contacts, and so every particle, depend on these bits. Checked against a
// straightforward corner-based reference (the Ericson test as the collider used it before the
// faces existed) on random triangles at several scales and on degenerate ones (zero area,
// collinear, coincident corners, needles), and for sane triangles against a brute-force
// distance in long double.
#include "TriangleGeometry.h"  // internal to lacrima_tears, header-only (player/tears/src is on this test's include path)

#include <QtTest>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <random>

using namespace lacrima::tears;

namespace {

bool sameBits(const Eigen::Vector3d& x, const Eigen::Vector3d& y) {
  return std::memcmp(x.data(), y.data(), 3 * sizeof(double)) == 0;
}

bool sameBits(const TrianglePoint& x, const TrianglePoint& y) {
  return sameBits(x.point, y.point) && sameBits(x.barycentric, y.barycentric) &&
         x.interior == y.interior;
}

using Vec = Eigen::Matrix<long double, 3, 1>;

Vec wide(const Eigen::Vector3d& v) { return v.cast<long double>(); }

long double segmentDistance(const Vec& p, const Vec& a, const Vec& b) {
  const Vec d = b - a;
  const long double len2 = d.squaredNorm();
  const long double t = len2 > 0 ? std::clamp((p - a).dot(d) / len2, 0.0L, 1.0L) : 0.0L;
  return (p - (a + t * d)).norm();
}

// Distance from p to the triangle: to the plane where p projects inside, else to the nearest edge.
long double bruteDistance(const Eigen::Vector3d& pd, const Eigen::Vector3d& ad,
                          const Eigen::Vector3d& bd, const Eigen::Vector3d& cd) {
  const Vec p = wide(pd), a = wide(ad), b = wide(bd), c = wide(cd);
  const Vec n = (b - a).cross(c - a);
  const Vec q = p - n * ((p - a).dot(n) / n.squaredNorm());
  const bool inside = (b - a).cross(q - a).dot(n) >= 0 && (c - b).cross(q - b).dot(n) >= 0 &&
                      (a - c).cross(q - c).dot(n) >= 0;
  if (inside) return (p - q).norm();
  return std::min({segmentDistance(p, a, b), segmentDistance(p, b, c), segmentDistance(p, c, a)});
}

SkinFace faceOf(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  const Eigen::Vector3d cross = (b - a).cross(c - a);
  const double area2 = cross.squaredNorm();
  const bool degenerate = !(area2 > 0);
  return makeSkinFace(
      a, b, c, degenerate ? Eigen::Vector3d::Zero() : Eigen::Vector3d(cross / std::sqrt(area2)),
      degenerate);
}

}  // namespace

class TriangleGeometryTest : public QObject {
  Q_OBJECT

 private slots:
  void facesMatchCornersOnRandomTriangles() {
    std::mt19937_64 rng(20240611);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    const std::array<double, 4> scales{1e-4, 1e-2, 1.0, 3e2};
    int interior = 0, rim = 0, checkedDistance = 0;
    for (double scale : scales) {
      const Eigen::Vector3d offset(unit(rng) * 10 * scale, unit(rng) * 10 * scale,
                                   unit(rng) * 10 * scale);
      for (int n = 0; n < 4000; ++n) {
        auto point = [&] {
          return Eigen::Vector3d(offset + scale * Eigen::Vector3d(unit(rng), unit(rng), unit(rng)));
        };
        const Eigen::Vector3d a = point(), b = point(), c = point();
        const SkinFace face = faceOf(a, b, c);
        for (int k = 0; k < 8; ++k) {
          // Points near the plane (contacts) and well off it, inside and outside the face.
          const Eigen::Vector3d p =
              (k < 4 ? a + 0.3 * (b - a) * unit(rng) + 0.7 * (c - a) * std::abs(unit(rng))
                     : point()) +
              (k % 2 ? 0.05 : 1.0) * scale * Eigen::Vector3d(unit(rng), unit(rng), unit(rng));
          const TrianglePoint fast = closestPointOnFace(p, face);
          // The corner-based entry forms the edges itself: a face must give the same bits.
          const TrianglePoint ref = closestPointOnTriangle(p, a, b, c);
          QVERIFY2(sameBits(fast, ref), "a face gives other bits than its corners");
          (fast.interior ? interior : rim)++;
          // Exact, not only repeatable: the distance matches brute force on triangles with a
          // usable shape (needles are covered below, for bits only).
          const double longest = std::max({(b - a).norm(), (c - b).norm(), (a - c).norm()});
          const double area = 0.5 * (b - a).cross(c - a).norm();
          if (area > 1e-3 * longest * longest) {
            const long double brute = bruteDistance(p, a, b, c);
            QVERIFY(std::abs(static_cast<long double>((p - fast.point).norm()) - brute) <=
                    1e-9L * scale);
            ++checkedDistance;
          }
          QVERIFY(std::abs(fast.barycentric.sum() - 1.0) < 1e-9);
        }
      }
    }
    // Both the face case (tracked contacts) and the rim cases were exercised.
    QVERIFY(interior > 10000);
    QVERIFY(rim > 10000);
    QVERIFY(checkedDistance > 50000);
  }

  void facesMatchCornersOnDegenerateTriangles() {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    int cases = 0;
    for (int n = 0; n < 3000; ++n) {
      const Eigen::Vector3d a(unit(rng), unit(rng), unit(rng));
      const Eigen::Vector3d d(unit(rng), unit(rng), unit(rng));
      const Eigen::Vector3d e(unit(rng), unit(rng), unit(rng));
      const std::array<std::array<Eigen::Vector3d, 3>, 6> shapes{{
          {a, a, a},                            // one point
          {a, a, a + d},                        // two corners coincide
          {a, a + d, a + 0.37 * d},             // collinear: zero area
          {a, a + d, a + 2.0 * d},              // collinear, c beyond b
          {a, a + d, a + 1e-9 * e},             // needle: one edge almost nothing
          {a, a + d, a + 0.5 * d + 1e-12 * e},  // sliver: almost collinear
      }};
      for (const auto& s : shapes) {
        const SkinFace face = faceOf(s[0], s[1], s[2]);
        for (int k = 0; k < 4; ++k) {
          const Eigen::Vector3d p =
              s[0] + (k == 0 ? Eigen::Vector3d(0.5 * d)
                             : Eigen::Vector3d(unit(rng), unit(rng), unit(rng)));
          const TrianglePoint fast = closestPointOnFace(p, face);
          const TrianglePoint ref = closestPointOnTriangle(p, s[0], s[1], s[2]);
          // NaN included: a degenerate face must not turn one NaN pattern into another.
          QVERIFY2(sameBits(fast, ref), "a degenerate face gives other bits than its corners");
          ++cases;
        }
      }
    }
    QCOMPARE(cases, 3000 * 6 * 4);
  }

  void faceRecordHoldsThePose() {
    const Eigen::Vector3d a(0.1, 0.2, 0.3), b(1.1, 0.25, 0.3), c(0.2, 1.3, 0.35);
    const SkinFace face = faceOf(a, b, c);
    QVERIFY(sameBits(face.a, a) && sameBits(face.b, b) && sameBits(face.c, c));
    QVERIFY(sameBits(face.ab, Eigen::Vector3d(b - a)) && sameBits(face.ac, Eigen::Vector3d(c - a)));
    QVERIFY(!face.degenerate);
    QVERIFY(std::abs(face.normal.norm() - 1.0) < 1e-15);
    QVERIFY(std::abs(face.normal.dot(b - a)) < 1e-15 &&
            face.normal.z() > 0);  // counter-clockwise faces +z
    QVERIFY(faceOf(a, b, a + 0.5 * (b - a)).degenerate);
  }
};

QTEST_APPLESS_MAIN(TriangleGeometryTest)
#include "TriangleGeometryTest.moc"
