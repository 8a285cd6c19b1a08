// The tear surface: the generated marching-cubes table, closed and consistently oriented meshes
// of one particle, a ball and a long drop spanning many grid cells, vertices on the iso surface,
// outward normals, convergence as the cubes shrink, effects on demand (no particles, no run),
// degenerate inputs and the cube cap, the block-wise mesher against a brute-force marching cubes of
// the colour field, and the accuracy-against-time table.
#include "TearTestSupport.h"

// Internals of lacrima_tears (player/tears/src is on this test's include path).
#include "MarchingCubesTable.h"
#include "SurfaceMesherField.h"

#include <lacrima/tears/SurfaceMesher.h>

#include <QtTest>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <map>
#include <numbers>
#include <random>
#include <set>

using namespace lacrima::tears;
using namespace lacrima::tears::testing;

namespace {

// A particle set with its grid, meshed at kernel radius h.
struct Drop {
  std::vector<Eigen::Vector3d> x;
  std::vector<double> m;
  UniformGrid grid;

  const TearSurface& mesh(SurfaceMesher& mesher, double h, double s, double iso = 0.5,
                          std::size_t maxCubes = SurfaceMesherSettings{}.maxCubes) {
    m.assign(x.size(), 1.0);
    grid.build(x, h);
    return mesher.build(x, m, grid, {h, s, iso, maxCubes});
  }
};

// Particles of a cubic lattice of spacing h/2 inside a ball, slightly jittered (deterministic),
// like a drop at rest.
Drop latticeBall(int count, double h, const Eigen::Vector3d& centre = Eigen::Vector3d::Zero(),
                 double jitter = 0.05) {
  const double spacing = 0.5 * h;
  std::vector<Eigen::Vector3d> lattice;
  const int n = static_cast<int>(std::ceil(std::cbrt(count))) + 2;
  for (int i = -n; i <= n; ++i)
    for (int j = -n; j <= n; ++j)
      for (int k = -n; k <= n; ++k) lattice.emplace_back(i * spacing, j * spacing, k * spacing);
  std::stable_sort(lattice.begin(), lattice.end(),
                   [](const auto& a, const auto& b) { return a.squaredNorm() < b.squaredNorm(); });
  Drop d;
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> u(-jitter * spacing, jitter * spacing);
  for (int p = 0; p < count; ++p)
    d.x.push_back(centre + lattice[static_cast<std::size_t>(p)] +
                  Eigen::Vector3d(u(random), u(random), u(random)));
  return d;
}

// Every directed edge appears once and its reverse once: each edge has exactly two triangles
// and they are wound consistently. Returns an explanation on failure, empty on success.
QByteArray closedAndOriented(const TearSurface& s) {
  std::map<std::pair<int, int>, int> directed;
  const auto t = s.triangles();
  for (int i = 0; i < t.cols(); ++i) {
    if (t(0, i) == t(1, i) || t(1, i) == t(2, i) || t(0, i) == t(2, i))
      return "triangle with a repeated vertex";
    for (int k = 0; k < 3; ++k) ++directed[{t(k, i), t((k + 1) % 3, i)}];
  }
  for (const auto& [edge, count] : directed) {
    if (count != 1)
      return "directed edge used " + QByteArray::number(count) + " times (non-manifold or flipped)";
    if (!directed.count({edge.second, edge.first})) return "open edge (a hole)";
  }
  return {};
}

double enclosedVolume(const TearSurface& s) {
  const auto p = s.positions();
  const auto t = s.triangles();
  double v = 0;
  for (int i = 0; i < t.cols(); ++i)
    v += p.col(t(0, i)).dot(p.col(t(1, i)).cross(p.col(t(2, i)))) / 6.0;
  return v;
}

double area(const TearSurface& s) {
  const auto p = s.positions();
  const auto t = s.triangles();
  double a = 0;
  for (int i = 0; i < t.cols(); ++i)
    a += 0.5 * (p.col(t(1, i)) - p.col(t(0, i))).cross(p.col(t(2, i)) - p.col(t(0, i))).norm();
  return a;
}

// Distance from x to the iso surface of the field: Newton steps along the gradient.
double distanceToIso(const SurfaceMesherField& field, const Eigen::Vector3d& x, double iso) {
  Eigen::Vector3d y = x;
  for (int k = 0; k < 20; ++k) {
    const Eigen::Vector3d g = field.gradient(y);
    const double r = field.value(y) - iso;
    if (g.squaredNorm() == 0) break;
    y -= r * g / g.squaredNorm();
    if (std::abs(r) < 1e-13) break;
  }
  return (y - x).norm();
}

struct VertexError {
  double mean = 0, max = 0, worstIso = 0;
};
VertexError vertexError(const SurfaceMesher& mesher, double iso) {
  VertexError e;
  const auto p = mesher.surface().positions();
  for (int v = 0; v < p.cols(); ++v) {
    const double d = distanceToIso(mesher.field(), p.col(v), iso);
    e.mean += d;
    e.max = std::max(e.max, d);
    e.worstIso = std::max(e.worstIso, std::abs(mesher.field().value(p.col(v)) - iso));
  }
  if (p.cols() > 0) e.mean /= static_cast<double>(p.cols());
  return e;
}

}  // namespace

class TearSurfaceTest : public QObject {
  Q_OBJECT

 private slots:
  // Every case cuts exactly the edges whose corners differ in sign, each triangle has three
  // distinct edges, and complementary cases cut the same edges.
  void tableCutsExactlyTheSignChangingEdges() {
    const MarchingCubesTable& table = MarchingCubesTable::instance();
    for (int c = 0; c < 256; ++c) {
      std::array<bool, 12> used{};
      for (int t = 0; t < table[c].triangleCount; ++t) {
        const auto* e = &table[c].edges[static_cast<std::size_t>(3 * t)];
        QVERIFY(e[0] != e[1] && e[1] != e[2] && e[0] != e[2]);
        for (int k = 0; k < 3; ++k) used[static_cast<std::size_t>(e[k])] = true;
      }
      for (int e = 0; e < 12; ++e) {
        const bool a = (c >> MarchingCubesTable::edgeLowerCorner(e)) & 1;
        const bool b = (c >> MarchingCubesTable::edgeUpperCorner(e)) & 1;
        QCOMPARE(used[static_cast<std::size_t>(e)], a != b);
      }
    }
    QCOMPARE(table[0].triangleCount, 0);
    QCOMPARE(table[255].triangleCount, 0);
  }

  // One particle: c = (1 - r^2/h^2)^3, a sphere of radius R = h sqrt(1 - iso^(1/3)).
  void singleParticleIsAClosedSphere() {
    const double h = 1.0, iso = 0.5, R = h * std::sqrt(1 - std::cbrt(iso));
    Drop d;
    d.x = {Eigen::Vector3d(0.123, -0.377, 0.051)};
    SurfaceMesher mesher;
    const TearSurface& s = d.mesh(mesher, h, h / 8, iso);
    QVERIFY(s.triangleCount() > 50);
    const QByteArray why = closedAndOriented(s);
    QVERIFY2(why.isEmpty(), why);
    const auto p = s.positions();
    const auto n = s.normals();
    for (int v = 0; v < p.cols(); ++v) {
      const Eigen::Vector3d radial = p.col(v) - d.x[0];
      QVERIFY(std::abs(radial.norm() - R) < 0.02 * h);
      // The corners' analytic gradients, interpolated: radial to within 2.6 degrees.
      QVERIFY(n.col(v).dot(radial.normalized()) > 0.999);
      QVERIFY(std::abs(n.col(v).norm() - 1) < 1e-12);
    }
    const double exact = 4.0 / 3.0 * std::numbers::pi * R * R * R;
    QVERIFY(std::abs(enclosedVolume(s) - exact) < 0.05 * exact);  // positive: wound outward
  }

  void ballIsClosedWithOutwardNormalsOnTheIsoSurface() {
    const double h = 0.016;  // the default kernel in decimetres
    Drop d = latticeBall(500, h, Eigen::Vector3d(0.3, 1.1, -0.2));
    SurfaceMesher mesher;
    const TearSurface& s = d.mesh(mesher, h, h / 2);
    QVERIFY(s.triangleCount() > 100);
    const QByteArray why = closedAndOriented(s);
    QVERIFY2(why.isEmpty(), why);
    QVERIFY(enclosedVolume(s) > 0);
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    for (const auto& x : d.x) centre += x / static_cast<double>(d.x.size());
    const auto p = s.positions();
    const auto n = s.normals();
    double worst = 0, mean = 0;
    for (int v = 0; v < p.cols(); ++v) {
      QVERIFY(n.col(v).dot((p.col(v) - centre).normalized()) > 0.3);
      // Interpolated corner gradients against the field's gradient at the vertex itself.
      const double cosine =
          std::clamp(n.col(v).dot(-mesher.field().gradient(p.col(v)).normalized()), -1.0, 1.0);
      const double degrees = std::acos(cosine) * 180 / std::numbers::pi;
      worst = std::max(worst, degrees);
      mean += degrees / static_cast<double>(p.cols());
    }
    qInfo(
        "normals %.2f degrees (mean), %.2f (worst) from the exact colour-field gradient at cube "
        "h/2",
        mean, worst);
    QVERIFY2(mean < 3 && worst < 10, QByteArray::number(mean) + " " + QByteArray::number(worst));
    const VertexError e = vertexError(mesher, 0.5);
    // Linear interpolation of a smooth field: the error is second order in s.
    QVERIFY2(e.max < 0.1 * h, QByteArray::number(e.max / h));
    QVERIFY2(e.worstIso < 0.1, QByteArray::number(e.worstIso));
  }

  // A thin drop 30 cells long and cubes that do not divide the cell (s = h / 2.7): no holes at
  // cell or cube borders, whatever the alignment.
  void longDropAcrossManyCellsHasNoHoles() {
    const double h = 0.016;
    Drop d;
    for (int i = 0; i < 120; ++i)
      for (int j = 0; j < 3; ++j)
        d.x.emplace_back(0.001 + i * 0.25 * h + 0.1 * h * std::sin(i * 0.7),
                         j * 0.45 * h + 0.02 * h * std::cos(i * 1.3),
                         0.15 * h * std::sin(i * 0.31));
    SurfaceMesher mesher;
    for (double s : {h / 2.7, h / 2, h / 3.3}) {
      const TearSurface& surface = d.mesh(mesher, h, s);
      QVERIFY(mesher.stats().activeCells > 25);
      QVERIFY(mesher.stats().blocks > 8);  // the drop crosses many block borders
      const QByteArray why = closedAndOriented(surface);
      QVERIFY2(why.isEmpty(), why + " at s = h / " + QByteArray::number(h / s));
      QVERIFY(enclosedVolume(surface) > 0);
    }
  }

  // Area and volume approach the analytic sphere of one particle as the cubes shrink, at second
  // order (linear interpolation of a smooth field): each halving of s cuts the error ~4x.
  void areaAndVolumeConverge() {
    const double h = 1.0, R = h * std::sqrt(1 - std::cbrt(0.5));
    const double exactVolume = 4.0 / 3.0 * std::numbers::pi * R * R * R,
                 exactArea = 4 * std::numbers::pi * R * R;
    Drop d;
    d.x = {Eigen::Vector3d(0.31, 0.17, -0.06)};
    SurfaceMesher mesher;
    double previousVolume = 0, previousArea = 0;
    for (double s : {h / 4, h / 8, h / 16}) {
      const TearSurface& surface = d.mesh(mesher, h, s);
      QVERIFY(!mesher.stats().capped);
      const double volumeError = std::abs(enclosedVolume(surface) - exactVolume) / exactVolume;
      const double areaError = std::abs(area(surface) - exactArea) / exactArea;
      if (previousVolume > 0) {
        QVERIFY2(volumeError < previousVolume / 3,
                 QByteArray::number(volumeError / previousVolume));
        QVERIFY2(areaError < previousArea / 3, QByteArray::number(areaError / previousArea));
      }
      previousVolume = volumeError;
      previousArea = areaError;
    }
    QVERIFY(previousVolume < 0.015);
    QVERIFY(previousArea < 0.008);
  }

  // Effects on demand: without particles nothing runs and nothing is counted; with them the
  // simulation counts one run per update.
  void noParticlesNoWork() {
    const SyntheticSkin sheet = makeCheekSheet();
    auto sim = makeSheetSimulation(sheet);
    SurfaceMesher mesher;
    sim->step(sheet.positions, 0, 0, kFrameDt);
    QVERIFY(mesher.update(*sim).empty());
    QCOMPARE(sim->counters().surfaceRuns, 0LL);
    QCOMPARE(mesher.stats().cubes, std::size_t{0});
    for (int f = 0; f < 3; ++f) {
      sim->step(sheet.positions, 40, 30, kFrameDt);
      const TearSurface& s = mesher.update(*sim);
      QVERIFY(s.triangleCount() > 0);
      QVERIFY(s.positions().allFinite() && s.normals().allFinite());
      QVERIFY(mesher.stats().milliseconds > 0);
    }
    QCOMPARE(sim->counters().surfaceRuns, 3LL);
    sim->step(sheet.positions, 0, 0, kFrameDt);  // all removed
    QVERIFY(mesher.update(*sim).empty());
    QCOMPARE(sim->counters().surfaceRuns, 3LL);
  }

  // Buffers keep their capacity: meshing the same drop again does not move them.
  void steadyDropDoesNotReallocate() {
    Drop d = latticeBall(200, 0.016);
    SurfaceMesher mesher;
    const TearSurface& s = d.mesh(mesher, 0.016, 0.008);
    const double* positions = s.positions().data();
    const int* triangles = s.triangles().data();
    for (int k = 0; k < 3; ++k) d.mesh(mesher, 0.016, 0.008);
    QCOMPARE(s.positions().data(), positions);
    QCOMPARE(s.triangles().data(), triangles);
  }

  // The block-wise mesher (single-precision splat into blocks of 4^3 cubes) against the plain
  // algorithm: c and grad c gathered in double at every lattice corner of the box, a vertex on
  // every sign-changing edge, the table's triangles in every cube. The drop straddles the origin
  // (negative block coordinates) and several blocks per axis, with cubes that do not divide h:
  // same vertices (to float rounding), same triangles, same normals, watertight, and two
  // meshers give bitwise the same mesh.
  void blockMesherMatchesBruteForceMarchingCubes() {
    const double h = 0.016, s = h / 2.7, iso = 0.5;
    Drop d = latticeBall(400, h, Eigen::Vector3d(-0.002, 0.0013, -0.0007), 0.3);
    SurfaceMesher mesher;
    const TearSurface& surface = d.mesh(mesher, h, s, iso);
    QVERIFY(!mesher.stats().capped);
    QVERIFY(mesher.stats().blocks >= 8);
    const QByteArray why = closedAndOriented(surface);
    QVERIFY2(why.isEmpty(), why);

    const SurfaceMesherField& field = mesher.field();
    Eigen::Vector3d low = d.x.front(), high = low;
    for (const auto& x : d.x) {
      low = low.cwiseMin(x);
      high = high.cwiseMax(x);
    }
    const Eigen::Vector3i first = ((low.array() - h) / s).floor().cast<int>() - 1;
    const Eigen::Vector3i last = ((high.array() + h) / s).ceil().cast<int>() + 1;
    const Eigen::Vector3i n = last - first + Eigen::Vector3i::Ones();
    const auto at = [&](int i, int j, int k) {
      return (static_cast<std::size_t>(i) * n.y() + j) * n.z() + k;
    };
    std::vector<double> value(static_cast<std::size_t>(n.prod()));
    std::vector<Eigen::Vector3d> gradient(value.size());
    for (int i = 0; i < n.x(); ++i)
      for (int j = 0; j < n.y(); ++j)
        for (int k = 0; k < n.z(); ++k) {
          const Eigen::Vector3d p = (first + Eigen::Vector3i(i, j, k)).cast<double>() * s;
          value[at(i, j, k)] = field.value(p);
          gradient[at(i, j, k)] = field.gradient(p);
        }
    // Reference vertices, one per sign-changing edge (keyed by lower corner and axis).
    std::map<std::array<int, 4>, int> edgeVertex;
    std::vector<Eigen::Vector3d> position, normal;
    const auto vertexOn = [&](const Eigen::Vector3i& lower, int axis) {
      const std::array<int, 4> key{lower.x(), lower.y(), lower.z(), axis};
      if (const auto found = edgeVertex.find(key); found != edgeVertex.end()) return found->second;
      Eigen::Vector3i upper = lower;
      ++upper[axis];
      const double a = value[at(lower.x(), lower.y(), lower.z())],
                   b = value[at(upper.x(), upper.y(), upper.z())];
      const double mu = (iso - a) / (b - a);
      Eigen::Vector3d p = (first + lower).cast<double>() * s;
      p[axis] += mu * s;
      const Eigen::Vector3d& ga = gradient[at(lower.x(), lower.y(), lower.z())];
      const Eigen::Vector3d g = ga + mu * (gradient[at(upper.x(), upper.y(), upper.z())] - ga);
      position.push_back(p);
      normal.push_back(-g.normalized());
      return edgeVertex[key] = static_cast<int>(position.size()) - 1;
    };
    const MarchingCubesTable& table = MarchingCubesTable::instance();
    std::set<std::array<int, 3>> reference;
    const auto canonical = [](std::array<int, 3> t) {
      std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());  // keeps the winding
      return t;
    };
    for (int i = 0; i + 1 < n.x(); ++i)
      for (int j = 0; j + 1 < n.y(); ++j)
        for (int k = 0; k + 1 < n.z(); ++k) {
          int configuration = 0;
          for (int c = 0; c < 8; ++c)
            if (value[at(i + (c & 1), j + ((c >> 1) & 1), k + (c >> 2))] >= iso)
              configuration |= 1 << c;
          const MarchingCubesCase& cube = table[configuration];
          for (int t = 0; t < cube.triangleCount; ++t) {
            std::array<int, 3> triangle{};
            for (int v = 0; v < 3; ++v) {
              const int edge = cube.edges[static_cast<std::size_t>(3 * t + v)];
              const int c = MarchingCubesTable::edgeLowerCorner(edge);
              triangle[static_cast<std::size_t>(v)] =
                  vertexOn(Eigen::Vector3i(i + (c & 1), j + ((c >> 1) & 1), k + (c >> 2)),
                           MarchingCubesTable::edgeAxis(edge));
            }
            reference.insert(canonical(triangle));
          }
        }
    QCOMPARE(surface.vertexCount(), static_cast<int>(position.size()));
    QCOMPARE(surface.triangleCount(), static_cast<int>(reference.size()));
    // Each mesher vertex is the reference vertex on its edge, to float rounding (a vertex lies on
    // one edge, the nearest other vertex is a large fraction of s away).
    const auto p = surface.positions();
    const auto nrm = surface.normals();
    std::vector<int> match(static_cast<std::size_t>(p.cols()), -1);
    std::vector<char> used(position.size(), 0);
    for (int v = 0; v < p.cols(); ++v) {
      double best = 1e300;
      for (std::size_t r = 0; r < position.size(); ++r) {
        const double dist = (p.col(v) - position[r]).norm();
        if (dist < best) {
          best = dist;
          match[static_cast<std::size_t>(v)] = static_cast<int>(r);
        }
      }
      const auto r = static_cast<std::size_t>(match[static_cast<std::size_t>(v)]);
      QVERIFY2(best < 1e-3 * s, QByteArray::number(best / s));
      QVERIFY(!used[r]);
      used[r] = 1;
      QVERIFY2(nrm.col(v).dot(normal[r]) > 1 - 1e-6,
               QByteArray::number(nrm.col(v).dot(normal[r]), 'g', 12));
      QVERIFY(std::abs(field.value(p.col(v)) - iso) < 0.1);
    }
    std::set<std::array<int, 3>> meshed;
    const auto tri = surface.triangles();
    for (int t = 0; t < tri.cols(); ++t)
      meshed.insert(canonical({match[static_cast<std::size_t>(tri(0, t))],
                               match[static_cast<std::size_t>(tri(1, t))],
                               match[static_cast<std::size_t>(tri(2, t))]}));
    QVERIFY(meshed == reference);

    // Deterministic: a second mesher (and a rebuild) produce bitwise the same arrays.
    SurfaceMesher other;
    Drop again = d;
    const TearSurface& second = again.mesh(other, h, s, iso);
    QCOMPARE(second.vertexCount(), surface.vertexCount());
    QCOMPARE(second.triangleCount(), surface.triangleCount());
    QVERIFY(std::memcmp(second.positions().data(), surface.positions().data(),
                        sizeof(double) * 3 * surface.vertexCount()) == 0);
    QVERIFY(std::memcmp(second.normals().data(), surface.normals().data(),
                        sizeof(double) * 3 * surface.vertexCount()) == 0);
    QVERIFY(std::memcmp(second.triangles().data(), surface.triangles().data(),
                        sizeof(int) * 3 * surface.triangleCount()) == 0);
  }

  void degenerateInputsStayFiniteAndBounded() {
    const double h = 0.016;
    SurfaceMesher mesher;
    // Particles exactly on cell corners (and so on lattice corners, s = h / 2).
    {
      Drop d;
      for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
          for (int k = 0; k < 2; ++k) d.x.emplace_back(i * h, j * h, k * h);
      const TearSurface& s = d.mesh(mesher, h, h / 2);
      QVERIFY(s.positions().allFinite() && s.normals().allFinite());
      const QByteArray why = closedAndOriented(s);
      QVERIFY2(why.isEmpty(), why);
    }
    // All particles at one point: the volumes split a single particle's, c = (1 - r^2/h^2)^3.
    {
      Drop d;
      d.x.assign(100, Eigen::Vector3d(0.5 * h, 0.5 * h, 0.5 * h));
      const TearSurface& s = d.mesh(mesher, h, h / 8);
      QVERIFY(s.triangleCount() > 0);
      const QByteArray why = closedAndOriented(s);
      QVERIFY2(why.isEmpty(), why);
      const double R = h * std::sqrt(1 - std::cbrt(0.5));
      const auto p = s.positions();
      for (int v = 0; v < p.cols(); ++v)
        QVERIFY(std::abs((p.col(v) - d.x[0]).norm() - R) < 0.05 * h);
    }
    // Cube size at both ends of the parameter range relative to the kernel: cube_size 50 with
    // kernel 0.5 (s = 100 h), and cube_size 0.005 with kernel 50 (s = h / 10^4).
    {
      Drop d = latticeBall(300, h);
      const TearSurface& coarse = d.mesh(mesher, h, 100 * h);
      QVERIFY(coarse.positions().allFinite());
      QVERIFY(mesher.stats().cubes <= SurfaceMesherSettings{}.maxCubes);
      const QByteArray coarseWhy = closedAndOriented(coarse);
      QVERIFY2(coarseWhy.isEmpty(), coarseWhy);

      const long long cappedBefore = mesher.cappedBuilds();
      const TearSurface& fine = d.mesh(mesher, h, h * 1e-4, 0.5, 200000);
      QVERIFY(mesher.stats().capped);
      QCOMPARE(mesher.cappedBuilds(), cappedBefore + 1);
      QVERIFY(mesher.stats().cubes <= 200000);
      QVERIFY(mesher.stats().cubeSize > h * 1e-4);
      QVERIFY(fine.triangleCount() > 0);
      QVERIFY(fine.positions().allFinite() && fine.normals().allFinite());
      const QByteArray fineWhy = closedAndOriented(fine);
      QVERIFY2(fineWhy.isEmpty(), fineWhy);
    }
    // Bad settings are refused, not meshed.
    {
      Drop d = latticeBall(10, h);
      QVERIFY_THROWS_EXCEPTION(std::invalid_argument, d.mesh(mesher, h, 0.0));
      QVERIFY_THROWS_EXCEPTION(std::invalid_argument, d.mesh(mesher, h, h / 2, std::nan("")));
    }
  }

  // "Show what accuracy costs in time": vertex distance to the true iso surface and volume
  // against a very fine reference, per cube size, for 100- and 1000-particle drops at the default
  // kernel (h = 1.6 mm). Printed as a table; the error must fall as the cubes shrink.
  void accuracyAgainstTime() {
    const double L = 0.032, h = 0.5 * L;  // decimetres per 2009 unit; kernel 0.5
    for (int count : {100, 1000}) {
      Drop d = latticeBall(count, h);
      SurfaceMesher reference;
      const double referenceVolume =
          enclosedVolume(d.mesh(reference, h, 0.04 * L, 0.5, std::size_t{1} << 21));
      QVERIFY(!reference.stats().capped);
      qInfo("%d particles (reference: cube_size 0.04, %zu cubes, volume %.4g dm^3)", count,
            reference.stats().cubes, referenceVolume);
      qInfo(
          "  cube_size   ms (median of 9)   cubes   triangles   mean |d|/h   max |d|/h   volume "
          "error");
      double previousMean = 1e9;
      for (double cube : {1.0, 0.5, 0.25, 0.125, 0.0625}) {
        SurfaceMesher mesher;
        std::vector<double> ms;
        for (int r = 0; r < 9; ++r) {
          d.mesh(mesher, h, cube * L);
          ms.push_back(mesher.stats().milliseconds);
        }
        std::sort(ms.begin(), ms.end());
        const VertexError e = vertexError(mesher, 0.5);
        const double volumeError =
            std::abs(enclosedVolume(mesher.surface()) - referenceVolume) / referenceVolume;
        qInfo("  %9.4g   %16.3f   %5zu   %9d   %10.4f   %9.4f   %11.2f%%", cube, ms[4],
              mesher.stats().cubes, mesher.surface().triangleCount(), e.mean / h, e.max / h,
              100 * volumeError);
        QVERIFY(closedAndOriented(mesher.surface()).isEmpty());
        if (cube <= 0.5)
          QVERIFY2(e.mean < previousMean, "vertex error does not fall with the cube size");
        previousMean = e.mean;
      }
    }
  }
};

QTEST_GUILESS_MAIN(TearSurfaceTest)
#include "TearSurfaceTest.moc"
