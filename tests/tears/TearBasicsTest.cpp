// Building blocks of the tear simulation: kernel normalisation, neighbour search against brute
// force, parameter JSON validation and unit scaling, emission (count up and down, oldest first,
// recycling), effects on demand (zero channels do zero work) and determinism.
#include "TearTestSupport.h"

// Internals of lacrima_tears (player/tears/src is on this test's include path).
#include "ActivePairs.h"
#include "CellIndex.h"
#include "DensitySolver.h"
#include "Emitter.h"
#include "Kernels.h"
#include "Octree.h"
#include "VerletPairs.h"

#include <lacrima/tears/TrailBuilder.h>
#include <lacrima/tears/UniformGrid.h>

#include <QtTest>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numbers>
#include <random>
#include <set>
#include <thread>

using namespace lacrima::tears;
using namespace lacrima::tears::testing;

namespace {

// Integral over the ball of radius h of f(r), by the midpoint rule in r (4 pi r^2 dr).
template <typename F>
double radialIntegral(double h, F f, int steps = 200000) {
  double sum = 0;
  const double dr = h / steps;
  for (int i = 0; i < steps; ++i) {
    const double r = (i + 0.5) * dr;
    sum += f(r) * 4 * std::numbers::pi * r * r * dr;
  }
  return sum;
}

std::vector<Eigen::Vector3d> scatter(int n, double extent, unsigned seed, bool clustered) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> u(-extent, extent);
  std::vector<Eigen::Vector3d> x;
  for (int i = 0; i < n; ++i) {
    Eigen::Vector3d p(u(random), u(random), u(random));
    if (clustered && i % 3 == 0) p *= 0.05;                     // a dense lump
    if (clustered && i % 7 == 0) p = x.empty() ? p : x.back();  // exact duplicates
    x.push_back(p);
  }
  return x;
}

std::vector<std::set<int>> bruteForce(const std::vector<Eigen::Vector3d>& x, double h) {
  std::vector<std::set<int>> sets(x.size());
  for (std::size_t i = 0; i < x.size(); ++i)
    for (std::size_t j = 0; j < x.size(); ++j)
      if (i != j && (x[i] - x[j]).squaredNorm() < h * h) sets[i].insert(static_cast<int>(j));
  return sets;
}

std::vector<std::set<int>> asSets(const NeighbourList& list) {
  std::vector<std::set<int>> sets(static_cast<std::size_t>(list.particleCount()));
  for (int i = 0; i < list.particleCount(); ++i) {
    const auto of = list.of(i);
    sets[static_cast<std::size_t>(i)] = std::set<int>(of.begin(), of.end());
    if (static_cast<int>(sets[static_cast<std::size_t>(i)].size()) != static_cast<int>(of.size()))
      sets[static_cast<std::size_t>(i)].insert(-1);  // a duplicate: never equal to brute force
  }
  return sets;
}

}  // namespace

class TearBasicsTest : public QObject {
  Q_OBJECT

 private slots:
  void poly6IntegratesToOne() {
    for (double h : {0.0016, 0.016, 0.5, 3.0}) {
      const Poly6Kernel w(h);
      const double integral = radialIntegral(h, [&](double r) { return w.value(r * r); });
      QVERIFY2(std::abs(integral - 1.0) < 1e-6, QByteArray::number(integral, 'g', 12));
    }
  }

  void spikyAndViscosityKernelsIntegrateToOne() {
    const double h = 0.016;
    const SpikyKernel spiky(h);
    const ViscosityKernel viscosity(h);
    QVERIFY(std::abs(radialIntegral(h, [&](double r) { return spiky.value(r); }) - 1.0) < 1e-6);
    // The viscosity kernel diverges like 1/r at 0; the midpoint rule still converges.
    QVERIFY(std::abs(radialIntegral(h, [&](double r) { return viscosity.value(r); }) - 1.0) < 1e-4);
  }

  void kernelDerivativesMatchFiniteDifferences() {
    const double h = 0.02, e = 1e-7;
    const Poly6Kernel w(h);
    const SpikyKernel spiky(h);
    const ViscosityKernel visc(h);
    for (double r : {0.003, 0.01, 0.017}) {
      const Eigen::Vector3d x(r, 0, 0);
      const double numeric = (w.value((r + e) * (r + e)) - w.value((r - e) * (r - e))) / (2 * e);
      QVERIFY(std::abs(w.gradient(x, r * r).x() - numeric) < 1e-6 * std::abs(numeric));
      const double spikyNumeric = (spiky.value(r + e) - spiky.value(r - e)) / (2 * e);
      QVERIFY(std::abs(spiky.gradientFactor(r) * r - spikyNumeric) < 1e-6 * std::abs(spikyNumeric));
      // Laplacian of a radial function: f'' + 2 f' / r.
      auto lap = [&](auto f) {
        return (f(r + e) - 2 * f(r) + f(r - e)) / (e * e) + (f(r + e) - f(r - e)) / (e * r);
      };
      const double poly6Lap = lap([&](double s) { return w.value(s * s); });
      QVERIFY(std::abs(w.laplacian(r * r) - poly6Lap) < 1e-3 * std::abs(poly6Lap));
      const double viscLap = lap([&](double s) { return visc.value(s); });
      QVERIFY(std::abs(visc.laplacian(r) - viscLap) < 1e-3 * std::abs(viscLap));
    }
  }

  void gridAndOctreeMatchBruteForce() {
    for (bool clustered : {false, true}) {
      const auto x = scatter(1500, 0.1, clustered ? 7 : 3, clustered);
      for (double h : {0.004, 0.016}) {
        const auto expected = bruteForce(x, h);
        NeighbourList list;
        UniformGrid grid;
        grid.find(x, h, list);
        QVERIFY(asSets(list) == expected);
        Octree octree(h);
        octree.find(x, h, list);
        QVERIFY(asSets(list) == expected);
        Octree fineOctree(0.3 * h);  // leaves smaller than h: particles listed in many leaves
        fineOctree.find(x, h, list);
        QVERIFY(asSets(list) == expected);
      }
    }
  }

  // The pairs the density pass keeps from a Verlet list. `faulty` is set unless each pair is
  // kept once with i < j and what the pass computed matches double precision over all pairs:
  // every kept pair's offset (from the stored positions) and r^2, and every density (the particle
  // itself included), so the SIMD candidate loop is held to the plain sums with and without strays.
  // Shared on three threads, the pass must give the same bits, and each particle's reach must be
  // its largest candidate partner (the density windows are sized by it).
  static std::vector<std::set<int>> keptPairs(const ParticleSet& p, const VerletPairs& verlet,
                                              double h, bool& faulty) {
    ParticleSet copy = p;
    ActivePairs active;
    DensitySolver(h).compute(copy, verlet, active);
    std::vector<std::set<int>> sets(p.position.size());
    faulty = false;
    {
      ParticleSet sharedCopy = p;
      ActivePairs shared;
      ParallelChunks three(3);
      three.setParticleCount(p.size());
      DensitySolver(h).compute(sharedCopy, verlet, shared, &three);
      faulty = faulty || sharedCopy.density != copy.density || shared.first != active.first ||
               shared.last != active.last || shared.pairCount() != active.pairCount();
      for (int i = 0; i < verlet.particleCount(); ++i) {
        std::uint32_t largest = static_cast<std::uint32_t>(i);
        for (std::uint32_t k = verlet.begin(i); k < verlet.end(i); ++k)
          largest = std::max(largest, verlet.partners()[k]);
        faulty = faulty || verlet.reach(i) != largest;
        const auto si = static_cast<std::size_t>(i);
        for (std::uint32_t k = active.begin(si); k < active.end(si); ++k)
          faulty = faulty || shared.partner[k] != active.partner[k] || shared.r2[k] != active.r2[k];
      }
    }
    double worstOffset = 0;
    for (int i = 0; i < active.particleCount(); ++i)
      for (std::uint32_t k = active.begin(static_cast<std::size_t>(i));
           k < active.end(static_cast<std::size_t>(i)); ++k) {
        const int j = static_cast<int>(active.partner[k]);
        faulty = faulty || j <= i || !sets[static_cast<std::size_t>(i)].insert(j).second;
        sets[static_cast<std::size_t>(j)].insert(i);
        const Eigen::Vector3d d =
            p.position[static_cast<std::size_t>(i)] - p.position[static_cast<std::size_t>(j)];
        // The offset a later pass recomputes from the stored float positions.
        const float* xi = &active.position[4 * static_cast<std::size_t>(i)];
        const float* xj = &active.position[4 * static_cast<std::size_t>(j)];
        const float dx = xi[0] - xj[0], dy = xi[1] - xj[1], dz = xi[2] - xj[2];
        const Eigen::Vector3d stored(dx, dy, dz);
        worstOffset = std::max({worstOffset, (stored - d).norm() / h,
                                std::abs(active.r2[k] - d.squaredNorm()) / (h * h)});
        // r^2 must be that offset's own (the passes take both), and lane 3 must be 0.
        if (active.r2[k] != dx * dx + dy * dy + dz * dz || xi[3] != 0.0f || xj[3] != 0.0f)
          faulty = true;
      }
    std::size_t kept = 0;
    for (const auto& partners : sets) kept += partners.size();
    faulty = faulty || 2 * active.pairCount() != kept;  // each pair is in two sets
    Poly6Kernel w(h);
    double worstDensity = 0;
    for (std::size_t i = 0; i < p.position.size(); ++i) {
      double rho = 0;
      for (std::size_t j = 0; j < p.position.size(); ++j)
        rho += p.mass[j] * w.value((p.position[i] - p.position[j]).squaredNorm());
      worstDensity = std::max(worstDensity, std::abs(copy.density[i] - rho) / rho);
    }
    if (worstOffset > 1e-4 || worstDensity > 1e-4) {
      qWarning("density pass: offset error %g h, density error %g", worstOffset, worstDensity);
      faulty = true;
    }
    return sets;
  }

  void verletPairsWithinHMatchBruteForce() {
    // The solver's half lists: candidates within h + skin, reused while the two largest
    // displacements (less the drift) sum to less than the skin, then filtered to h by the
    // density pass; beyond that, particles far from the median displacement become strays whose
    // pairs are searched afresh. The pairs kept must be exactly the brute-force set at the
    // MOVED positions in every case: all moved by 0.45 skin; one by 0.75 skin and
    // the rest by 0.24 skin; all carried 5 skins along one direction, each also 0.3 skin its own
    // way (a sliding film); a few teleported across the cloud (re-emitted drops) and two pushed
    // past the skin (strays).
    for (bool clustered : {false, true}) {
      for (double h : {0.004, 0.016}) {
        for (bool oneFast : {false, true}) {
          const double skin = 0.3 * h;
          auto x = scatter(2600, 0.1, clustered ? 5 : 9, clustered);
          CellIndex index;
          index.build(x, h + skin);
          std::vector<Eigen::Vector3d> sorted;
          for (int i : index.order()) sorted.push_back(x[static_cast<std::size_t>(i)]);
          index.build(sorted, h + skin);  // already in cell order: the order is the identity
          for (std::size_t s = 0; s < sorted.size(); ++s)
            QCOMPARE(index.order()[s], static_cast<int>(s));
          VerletPairs verlet;
          verlet.build(index, h, skin);
          {
            // Shared on three threads (2,600 particles, three chunks): the same list.
            VerletPairs shared;
            ParallelChunks three(3);
            three.setParticleCount(static_cast<int>(sorted.size()));
            QVERIFY(three.shared());
            shared.build(index, h, skin, three);
            QCOMPARE(shared.pairCount(), verlet.pairCount());
            QVERIFY(std::equal(verlet.partners(), verlet.partners() + verlet.pairCount(),
                               shared.partners()));
            for (int i = 0; i < verlet.particleCount(); ++i)
              QVERIFY(shared.begin(i) == verlet.begin(i) && shared.end(i) == verlet.end(i));
          }
          QVERIFY(verlet.refresh(index, sorted));
          QVERIFY(!verlet.hasStrays());

          std::mt19937_64 random(clustered ? 21 : 22);
          std::normal_distribution<double> gauss;
          ParticleSet p;
          const std::size_t fast = 3 * sorted.size() / 4;
          for (std::size_t i = 0; i < sorted.size(); ++i) {
            Eigen::Vector3d dir(gauss(random), gauss(random), gauss(random));
            dir.normalize();
            const double step = !oneFast ? 0.45 : (i == fast ? 0.75 : 0.24);
            p.add(sorted[i] + step * skin * dir, 1.0, i + 1, Eye::Left);
          }
          bool faulty = false;
          QVERIFY(verlet.refresh(index, p.position));
          QVERIFY(!verlet.hasStrays());
          QVERIFY(keptPairs(p, verlet, h, faulty) == bruteForce(p.position, h));
          QVERIFY(!faulty);

          // The whole cloud carried along: no strays, no rebuild.
          ParticleSet carried = p;
          for (std::size_t i = 0; i < carried.position.size(); ++i)
            carried.position[i] = sorted[i] + Eigen::Vector3d(3 * skin, -4 * skin, 0) +
                                  0.3 * skin * (p.position[i] - sorted[i]).normalized();
          QVERIFY(verlet.refresh(index, carried.position));
          QVERIFY(!verlet.hasStrays());
          QVERIFY(keptPairs(carried, verlet, h, faulty) == bruteForce(carried.position, h));
          QVERIFY(!faulty);

          // Two displacements summing past the skin, and five particles teleported into the
          // cloud (the rest moved by 0.2 skin): strays, and still exactly the brute-force pairs.
          for (std::size_t i = 0; i < p.position.size(); ++i)
            p.position[i] = sorted[i] + 0.2 * skin * (p.position[i] - sorted[i]).normalized();
          p.position[7] = sorted[7] + Eigen::Vector3d(0.77 * skin, 0, 0);
          p.position[9] = sorted[9] + Eigen::Vector3d(0, 0.51 * skin, 0);
          for (std::size_t t = 0; t < 5; ++t)
            p.position[100 + 211 * t] = sorted[1400 - 97 * t] + Eigen::Vector3d(0.1 * h, 0, 0);
          QVERIFY(verlet.refresh(index, p.position));
          QVERIFY(verlet.hasStrays());
          QVERIFY(verlet.strayCount() >= 7);
          QVERIFY(keptPairs(p, verlet, h, faulty) == bruteForce(p.position, h));
          QVERIFY(!faulty);

          // Too many strays: a rebuild is cheaper, and the list says so.
          for (std::size_t i = 0; i < p.position.size(); i += 8)
            p.position[i] = sorted[i] + Eigen::Vector3d(0, 0, 2 * skin);
          QVERIFY(!verlet.refresh(index, p.position));
          // And a non-finite position never passes.
          p.position = sorted;
          p.position[3].x() = std::numeric_limits<double>::quiet_NaN();
          QVERIFY(!verlet.refresh(index, p.position));
        }
      }
    }
  }

  void pairBuffersKeepTheirPlaceAsTheyGrow() {
    // The candidate list and the density pass's pairs are megabytes at 10,000 particles: a
    // rebuild with as many or a few more pairs must reuse them, not move them to freshly mapped
    // pages (which once cost 10,000 page faults in 44 frames of the sheet).
    const double h = 0.004, skin = 0.3 * h;
    auto x = scatter(2600, 0.1, 5, true);
    CellIndex index;
    index.build(x, h + skin);
    std::vector<Eigen::Vector3d> sorted;
    for (int i : index.order()) sorted.push_back(x[static_cast<std::size_t>(i)]);
    index.build(sorted, h + skin);
    ParticleSet p;
    for (std::size_t i = 0; i < sorted.size(); ++i) p.add(sorted[i], 1.0, i + 1, Eye::Left);
    VerletPairs verlet;
    ActivePairs active;
    verlet.build(index, h, skin);
    DensitySolver(h).compute(p, verlet, active);
    const std::uint32_t* candidates = verlet.partners();
    const std::uint32_t* kept = active.partner.data();
    const std::size_t pairs = verlet.pairCount();
    for (int rebuild = 0; rebuild < 3; ++rebuild) {
      verlet.build(index, h, skin);
      DensitySolver(h).compute(p, verlet, active);
      QCOMPARE(verlet.pairCount(), pairs);
      QCOMPARE(verlet.partners(), candidates);
      QCOMPARE(active.partner.data(), kept);
    }
    // Slightly wider candidates (about 3 % more pairs): still in place.
    verlet.build(index, h, 1.01 * skin);
    QVERIFY(verlet.pairCount() > pairs && verlet.pairCount() < pairs + pairs / 10);
    QCOMPARE(verlet.partners(), candidates);
    DensitySolver(h).compute(p, verlet, active);
    QCOMPARE(active.partner.data(), kept);
  }

  void gridExposesOccupiedCells() {
    const auto x = scatter(300, 0.05, 11, false);
    UniformGrid grid;
    grid.build(x, 0.01);
    const auto cells = grid.occupiedCells();
    std::set<std::tuple<int, int, int>> expected;
    for (const auto& p : x) {
      const Eigen::Vector3i c = grid.cellOf(p);
      expected.insert({c.x(), c.y(), c.z()});
    }
    QCOMPARE(cells.size(), expected.size());
    QVERIFY(std::is_sorted(cells.begin(), cells.end(), [](const auto& a, const auto& b) {
      return std::tie(a.x(), a.y(), a.z()) < std::tie(b.x(), b.y(), b.z());
    }));
    std::size_t total = 0;
    for (const auto& c : cells) {
      const auto members = grid.particlesInCell(c);
      for (int i : members) QCOMPARE(grid.cellOf(x[static_cast<std::size_t>(i)]), c);
      total += members.size();
    }
    QCOMPARE(total, x.size());
  }

  void cellRowsAreTheirOccupiedCells() {
    // rowCells (the drop finder's neighbour runs) and row (the searches' particle runs) against
    // a cell-by-cell lookup, around every occupied cell and beyond the box's edges.
    const auto x = scatter(400, 0.05, 12, true);
    CellIndex index;
    index.build(x, 0.01);
    for (std::size_t c = 0; c < index.cellCount(); ++c) {
      const Eigen::Vector3i cell = index.cellCoordinates(c);
      for (int dx = -2; dx <= 2; ++dx)
        for (int dy = -2; dy <= 2; ++dy) {
          std::vector<std::uint32_t> expected;
          for (int dz = -1; dz <= 1; ++dz) {
            const std::int64_t n = index.findCell(cell + Eigen::Vector3i(dx, dy, dz));
            if (n >= 0) expected.push_back(static_cast<std::uint32_t>(n));
          }
          const CellIndex::Range run = index.rowCells(cell.x() + dx, cell.y() + dy, cell.z());
          std::vector<std::uint32_t> listed;
          for (std::uint32_t n = run.begin; n < run.end; ++n) listed.push_back(n);
          QCOMPARE(listed, expected);
          const CellIndex::Range particles = index.row(cell.x() + dx, cell.y() + dy, cell.z());
          if (expected.empty()) {
            QCOMPARE(particles.end - particles.begin, 0u);
          } else {
            QCOMPARE(particles.begin, index.cellStart(expected.front()));
            QCOMPARE(particles.end, index.cellStart(expected.back() + 1));
          }
        }
    }
  }

  void parameterJsonLoadsAndValidates() {
    const TearSettings s = TearSettings::fromJson(R"({"pressure": 0.008, "kernel": 0.25})");
    QCOMPARE(s.pressure, 0.008);
    QCOMPARE(s.kernel, 0.25);
    QCOMPARE(s.adhesion, 20.0);  // untouched names keep the table's default
    const auto fails = [](const char* json, const char* mentions) {
      try {
        TearSettings::fromJson(json);
      } catch (const std::invalid_argument& e) {
        if (!std::strstr(e.what(), mentions))
          qWarning("message '%s' lacks '%s'", e.what(), mentions);
        return std::strstr(e.what(), mentions) != nullptr;
      }
      return false;
    };
    QVERIFY(fails(R"({"adhesion": 20000})", "adhesion"));        // above its range
    QVERIFY(fails(R"({"kernel": 0})", "kernel"));                // below its range
    QVERIFY(fails(R"({"viscocity": 1})", "unknown parameter"));  // misspelt
    QVERIFY(fails(R"({"tension": "high"})", "expected a number"));
    QVERIFY(fails(R"({"tension": 0.2)", "invalid JSON"));
    QVERIFY(fails(R"([0.2])", "JSON object"));
    TearSettings t;
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, t.set("iso", 0.0));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, t.set("gravity", std::nan("")));
  }

  void unitScalingMakesTearSizedDrops() {
    const UnitScale dm = UnitScale::fromHeadHeight(2.7);
    QCOMPARE(dm.headUnitsPerMetre, 10.0);
    const ScaledParameters p = ScaledParameters::from(TearSettings{}, dm);
    QVERIFY(std::abs(p.h - 0.016) < 1e-12);  // kernel 0.5 -> 1.6 mm
    // 100 particles at rest density: a sphere of a few millimetres.
    const double volume = 100 * p.particleMass / p.restDensity;
    const double diameterMm = 2 * std::cbrt(3 * volume / (4 * std::numbers::pi)) * 100;  // dm -> mm
    QVERIFY2(diameterMm > 3 && diameterMm < 6, QByteArray::number(diameterMm));
    QCOMPARE(p.gravity, 98.1);
    // The same head in metres gets the same physics in its own units.
    const ScaledParameters m =
        ScaledParameters::from(TearSettings{}, UnitScale::fromHeadHeight(0.27));
    QVERIFY(std::abs(m.h * 10 - p.h) < 1e-12);
    QVERIFY(std::abs(m.gravity * 10 - p.gravity) < 1e-9);
    QVERIFY(std::abs(m.soundSpeed * 10 - p.soundSpeed) < 1e-9);
  }

  void zeroChannelsDoNoWork() {
    const SyntheticSkin sheet = makeCheekSheet();
    auto sim = makeSheetSimulation(sheet);
    for (int f = 0; f < 30; ++f) sim->step(sheet.positions, 0, 0, kFrameDt);
    const TearCounters& c = sim->counters();
    QCOMPARE(c.frames, 30LL);
    QCOMPARE(c.sphSteps, 0LL);
    QCOMPARE(c.substeps, 0LL);
    QCOMPARE(c.neighbourSearches, 0LL);
    QCOMPARE(c.trimeshUpdates, 0LL);
    QCOMPARE(c.odeQueries, 0LL);
    QCOMPARE(c.gridQueries, 0LL);
    // Crying, then back to zero: once the particles are gone the work stops again.
    for (int f = 0; f < 5; ++f) sim->step(sheet.positions, 10, 10, kFrameDt);
    QVERIFY(sim->counters().substeps > 0);
    sim->step(sheet.positions, 0, 0, kFrameDt);
    const TearCounters after = sim->counters();
    for (int f = 0; f < 10; ++f)
      sim->step(movedSheet(sheet, Eigen::Vector3d(0.01 * f, 0, 0)), 0, 0, kFrameDt);
    QCOMPARE(sim->counters().substeps, after.substeps);
    QCOMPARE(sim->counters().trimeshUpdates, after.trimeshUpdates);
    QCOMPARE(sim->counters().odeQueries, after.odeQueries);
    QCOMPARE(sim->counters().gridQueries, after.gridQueries);
    QCOMPARE(sim->counters().neighbourSearches, after.neighbourSearches);
    QCOMPARE(sim->particles().size(), 0);
  }

  void countUpAndDownRemovesOldestFirst() {
    const SyntheticSkin sheet = makeCheekSheet();
    auto sim = makeSheetSimulation(sheet);
    sim->step(sheet.positions, 10, 4, kFrameDt);
    sim->step(sheet.positions, 25, 4, kFrameDt);
    QCOMPARE(sim->count(Eye::Left), 25);
    QCOMPARE(sim->count(Eye::Right), 4);
    std::vector<std::uint64_t> left;
    for (int i = 0; i < sim->particles().size(); ++i)
      if (sim->particles().eye[static_cast<std::size_t>(i)] == Eye::Left)
        left.push_back(sim->particles().id[static_cast<std::size_t>(i)]);
    std::sort(left.begin(), left.end());
    sim->step(sheet.positions, 12, 4, kFrameDt);
    QCOMPARE(sim->count(Eye::Left), 12);
    QCOMPARE(sim->count(Eye::Right), 4);  // the other eye is untouched
    std::vector<std::uint64_t> kept;
    for (int i = 0; i < sim->particles().size(); ++i)
      if (sim->particles().eye[static_cast<std::size_t>(i)] == Eye::Left)
        kept.push_back(sim->particles().id[static_cast<std::size_t>(i)]);
    std::sort(kept.begin(), kept.end());
    // The 12 youngest survive.
    QVERIFY(std::equal(kept.begin(), kept.end(), left.end() - 12));
    QCOMPARE(sim->counters().removed, 13LL);
    QVERIFY(sim->wetness(Eye::Left).trailVolume > 0);  // dried tears wet the skin
    QVERIFY(sim->wetness(Eye::Left).skin > 0 && sim->wetness(Eye::Left).skin < 1);
    QCOMPARE(sim->wetness(Eye::Left).eye, 0.12);
    // FAP channels drive the same path.
    lacrima::FapValues channels{};
    channels[lacrima::channelIndex(lacrima::kTearLeftFap)] = 3.7f;
    channels[lacrima::channelIndex(lacrima::kTearRightFap)] = -2.0f;
    sim->step(sheet.positions, channels, kFrameDt);
    QCOMPARE(sim->count(Eye::Left), 3);
    QCOMPARE(sim->count(Eye::Right), 0);
  }

  void recyclingKeepsTheCount() {
    // No adhesion and a steep sheet: drops fall off the bottom and are re-emitted.
    CheekSheetOptions options;
    options.tiltDegrees = -15;  // leaning forward: an overhang
    options.height = 0.8;
    const SyntheticSkin sheet = makeCheekSheet(options);
    TearSettings settings;
    settings.set("adhesion", 0);
    auto sim = makeSheetSimulation(sheet, settings);
    runAndCheck(*sim, sheet, 20, 20, 66);
    QVERIFY2(sim->counters().recycled > 0, "nothing fell off");
  }

  // Escaped particles are re-emitted in their own slots: the rest keep index and state, the
  // re-emitted ones are new (larger ids, at rest, no contact, full mass) at the site, in front
  // of the skin, and not on top of the particles already there.
  void respawnReusesTheirSlots() {
    const double spacing = 0.01;
    Emitter emitter(spacing, 2.0);
    ParticleSet p;
    const EmissionSite site{Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(0, 0, 1)};
    emitter.spawn(p, Eye::Left, 30, site);
    emitter.spawn(p, Eye::Right, 10,
                  EmissionSite{Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 0, 1)});
    QCOMPARE(p.size(), 40);
    const std::uint64_t newestBefore = *std::max_element(p.id.begin(), p.id.end());
    const std::vector<int> fallen{3, 17, 35};  // two left, one right particle fell off
    for (int s : fallen) {
      p.position[static_cast<std::size_t>(s)] = Eigen::Vector3d(0, -5, 0);
      p.velocity[static_cast<std::size_t>(s)] = Eigen::Vector3d(0, -1, 0);
      p.mass[static_cast<std::size_t>(s)] = 0.5;
      p.contact[static_cast<std::size_t>(s)].triangle = 4;
    }
    const ParticleSet before = p;
    emitter.respawn(p, Eye::Left, fallen, site);
    QCOMPARE(p.size(), 40);
    for (int i = 0; i < p.size(); ++i) {
      const auto s = static_cast<std::size_t>(i);
      if (std::find(fallen.begin(), fallen.end(), i) == fallen.end()) {
        QCOMPARE(p.id[s], before.id[s]);
        QVERIFY(p.position[s] == before.position[s]);
        continue;
      }
      QVERIFY(p.id[s] > newestBefore);
      QVERIFY(p.eye[s] == Eye::Left);
      QVERIFY(p.velocity[s].isZero());
      QCOMPARE(p.mass[s], 2.0);
      QCOMPARE(p.contact[s].triangle, -1);
      QVERIFY(p.position[s].z() > -1e-9 * spacing);  // in front of the skin
      QVERIFY(p.position[s].norm() < 10 * spacing);  // at the site
      for (int j = 0; j < p.size(); ++j)
        if (j != i)
          QVERIFY((p.position[s] - p.position[static_cast<std::size_t>(j)]).norm() > 0.5 * spacing);
    }
  }

  void sameInputGivesBitwiseIdenticalState() {
    const SyntheticSkin sheet = makeCheekSheet();
    auto run = [&] {
      auto sim = makeSheetSimulation(sheet);
      for (int f = 0; f < 30; ++f) {
        const Eigen::Matrix3Xf x =
            movedSheet(sheet, Eigen::Vector3d(0.003 * std::sin(0.4 * f), 0, 0));
        sim->step(x, 20 + f, 40 - f, kFrameDt);
      }
      return std::make_pair(sim->particles().position, sim->particles().velocity);
    };
    const auto a = run();
    const auto b = run();
    QCOMPARE(a.first.size(), b.first.size());
    QVERIFY(std::memcmp(a.first.data(), b.first.data(), a.first.size() * sizeof(Eigen::Vector3d)) ==
            0);
    QVERIFY(std::memcmp(a.second.data(), b.second.data(),
                        a.second.size() * sizeof(Eigen::Vector3d)) == 0);
  }

  void checkpointRestoreRepeatsTheFutureBitwise_data() {
    QTest::addColumn<QString>("method");
    QTest::addColumn<QString>("solver");
    QTest::newRow("grid") << "grid"
                          << "wcsph";
    QTest::newRow("octree") << "octree"
                            << "wcsph";
    QTest::newRow("grid, DFSPH") << "grid"
                                 << "dfsph";
    QTest::newRow("grid, PBF") << "grid"
                               << "pbf";
  }

  void checkpointRestoreRepeatsTheFutureBitwise() {
    // Run A: 120 frames. Run B: 60 frames, checkpoint (and copy the trail builder), 30 frames
    // of other input (counts, skin motion), restore, then A's frames 60..119: B must end where
    // A ends, bit for bit. The input exercises what a checkpoint must carry: spawning and
    // removal (emitter ids), a swaying sheet (carried contacts, refitted ODE mesh), drops
    // sliding off (recycling), and trails.
    QFETCH(QString, method);
    QFETCH(QString, solver);
    CheekSheetOptions sheetOptions;
    sheetOptions.height = 1.2;  // short: some drops run off the bottom and are recycled
    const SyntheticSkin sheet = makeCheekSheet(sheetOptions);
    SimulationOptions options;
    options.neighbours = method.toStdString();
    options.pressureSolver = solver.toStdString();
    const auto skinAt = [&](int f, double amplitude) {
      return movedSheet(
          sheet, Eigen::Vector3d(amplitude * std::sin(0.3 * f), 0, 0),
          Eigen::AngleAxisd(0.5 * amplitude * std::sin(0.2 * f), Eigen::Vector3d::UnitY()));
    };
    const auto countsAt = [](int f) { return std::pair{std::min(60, 10 + f), f < 80 ? 30 : 12}; };
    const auto stepA = [&](TearSimulation& sim, TrailBuilder& trails, int f) {
      const Eigen::Matrix3Xf x = skinAt(f, 0.02);
      const auto [left, right] = countsAt(f);
      sim.step(x, left, right, kFrameDt);
      trails.update(sim, x, kFrameDt);
    };

    auto a = makeSheetSimulation(sheet, {}, options);
    TrailBuilder trailsA(sheet.triangles);
    for (int f = 0; f < 120; ++f) stepA(*a, trailsA, f);
    const FrameState expected = stateOf(*a, trailsA);
    if (solver == "wcsph") QVERIFY(a->counters().recycled > 0);  // DFSPH drops slide slower
    QVERIFY(a->counters().removed > 0);
    // Recycled drops re-emitted in place are strays until the next rebuild: the checkpoint
    // must carry the cells their pairs are searched in.
    if (method == "grid") QVERIFY(a->counters().straySubsteps > 0);
    QVERIFY(!trailsA.mesh().empty());

    auto b = makeSheetSimulation(sheet, {}, options);
    TrailBuilder trailsB(sheet.triangles);
    for (int f = 0; f < 60; ++f) stepA(*b, trailsB, f);
    const TearCheckpoint saved = b->checkpoint();
    const TearCheckpoint copy = saved;  // a checkpoint is a value
    const TrailBuilder savedTrails = trailsB;
    QCOMPARE(copy.particleCount(), b->particles().size());
    QVERIFY(copy.bytes() >
            static_cast<std::size_t>(b->particles().size()) * sizeof(Eigen::Vector3d));
    const FrameState atSave = stateOf(*b, trailsB);
    for (int f = 0; f < 30; ++f) {
      const Eigen::Matrix3Xf x = skinAt(f, 0.05);
      b->step(x, 5 + 2 * f, 40 - f, kFrameDt);
      trailsB.update(*b, x, kFrameDt);
    }
    QVERIFY(!sameBits(stateOf(*b, trailsB), atSave));
    b->restore(copy);
    trailsB = savedTrails;
    // Restored: the state is the saved one (trail mesh too), before any step.
    QVERIFY(sameBits(stateOf(*b, trailsB), atSave));
    for (int f = 60; f < 120; ++f) stepA(*b, trailsB, f);
    QVERIFY2(sameBits(stateOf(*b, trailsB), expected),
             "the restored run diverged from the original");

    // Restoring twice from the same checkpoint repeats again; a foreign or empty one is refused.
    b->restore(saved);
    trailsB = savedTrails;
    for (int f = 60; f < 120; ++f) stepA(*b, trailsB, f);
    QVERIFY(sameBits(stateOf(*b, trailsB), expected));
    // A copy of the trails continues as the original would, though it starts without the
    // original's working buffers (Scratch.h); the restore above kept the simulation's own.
    b->restore(saved);
    TrailBuilder copiedTrails = savedTrails;
    for (int f = 60; f < 120; ++f) stepA(*b, copiedTrails, f);
    QVERIFY(sameBits(stateOf(*b, copiedTrails), expected));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, a->restore(saved));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, a->restore(TearCheckpoint{}));
  }

  void octreeAndGridSimulateAlike() {
    // Same neighbour sets, possibly in another order: one sub-step agrees to rounding (over
    // many steps the rounding differences grow, as in any particle system).
    const SyntheticSkin sheet = makeCheekSheet();
    SimulationOptions octreeOptions;
    octreeOptions.neighbours = "octree";
    auto grid = makeSheetSimulation(sheet);
    auto octree = makeSheetSimulation(sheet, {}, octreeOptions);
    grid->step(sheet.positions, 30, 0, 1e-4);
    octree->step(sheet.positions, 30, 0, 1e-4);
    QCOMPARE(grid->counters().substeps, 1LL);
    QCOMPARE(octree->counters().substeps, 1LL);
    double worst = 0;
    for (int i = 0; i < 30; ++i)
      worst = std::max(worst, (grid->particles().position[static_cast<std::size_t>(i)] -
                               octree->particles().position[static_cast<std::size_t>(i)])
                                  .norm());
    QVERIFY2(worst < 1e-9 * grid->kernelRadius(), QByteArray::number(worst));
  }

  void tearsSlideDownAndStayOnTheSheet() {
    const SyntheticSkin sheet = makeCheekSheet();
    auto sim = makeSheetSimulation(sheet);
    runAndCheck(*sim, sheet, 50, 0, 44);
    const ParticleSet& p = sim->particles();
    int touching = 0;
    double meanY = 0;
    for (int i = 0; i < p.size(); ++i) {
      touching += p.contact[static_cast<std::size_t>(i)].triangle >= 0;
      meanY += p.position[static_cast<std::size_t>(i)].y() / p.size();
    }
    QVERIFY2(touching >= 40, QByteArray::number(touching));  // the drop clings to the skin
    // It runs down, at tear speed: between 0.5 and 5 cm/s on average over these 2 s.
    const double speedCmPerS = (sheet.leftSource.y() - meanY) * 10 / (44 * kFrameDt);
    QVERIFY2(speedCmPerS > 0.5 && speedCmPerS < 5, QByteArray::number(speedCmPerS));
  }

  // Two simulations stepping at once on two threads (the editor's preview does this while it
  // switches heads) give what each gives alone, bit for bit. Debian's ODE keeps its trimesh
  // caches process-wide, so without lockOde() the runs corrupted each other.
  void simulationsOnTwoThreadsMatchTheirRunsAlone() {
    CheekSheetOptions sheetOptions;
    sheetOptions.height = 1.2;
    const SyntheticSkin sheet = makeCheekSheet(sheetOptions);
    const auto run = [&](double amplitude) {
      auto sim = makeSheetSimulation(sheet);
      TrailBuilder trails(sheet.triangles);
      for (int f = 0; f < 90; ++f) {
        const Eigen::Matrix3Xf x =
            movedSheet(sheet, Eigen::Vector3d(amplitude * std::sin(0.3 * f), 0, 0),
                       Eigen::AngleAxisd(amplitude * std::sin(0.2 * f), Eigen::Vector3d::UnitY()));
        sim->step(x, std::min(80, 10 + f), 40, kFrameDt);
        trails.update(*sim, x, kFrameDt);
      }
      return stateOf(*sim, trails);
    };
    const FrameState aloneA = run(0.02);
    const FrameState aloneB = run(0.05);
    FrameState togetherA, togetherB;
    std::thread other([&] { togetherB = run(0.05); });
    togetherA = run(0.02);
    other.join();
    QVERIFY(sameBits(togetherA, aloneA));
    QVERIFY(sameBits(togetherB, aloneB));
  }
};

QTEST_GUILESS_MAIN(TearBasicsTest)
#include "TearBasicsTest.moc"
