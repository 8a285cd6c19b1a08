// A pressure solver registered by this test build alone (DummySolver) must appear everywhere a
// user meets the tear methods, with no other change: the registry's lists, projects (read with
// the apps' keys), the quality mapping and the simulation, the Effects panel, lacrima-bench's
// options and the accuracy sweep's solvers. And a key no registry holds is an error naming the
// known ones everywhere, never a silent default.
#include "../bench/BenchCommandLine.h"
#include "../bench/SweepSolvers.h"
#include "../bench/TearMethodOptions.h"
#include "PressureSolver.h"  // internal to lacrima_tears: the registry a method is added to

#include <lacrima/common/ProjectDocument.h>
#include <lacrima/playback/TearQualityOptions.h>
#include <lacrima/tears/SyntheticSkin.h>
#include <lacrima/tears/TearMethods.h>
#include <lacrima/tears/TearSimulation.h>
#include <lacrima/viewport/EffectsPanel.h>

#include <QComboBox>
#include <QtTest>

#include <algorithm>
#include <atomic>
#include <stdexcept>
#include <string>
#include <vector>

using namespace lacrima;

namespace {

// No pressure at all: what matters is that it is made and called.
class DummySolver final : public tears::PressureSolver {
 public:
  explicit DummySolver(double strength) : strength_(strength) {}
  static inline std::atomic<int> made{0}, calls{0};
  static inline double lastStrength = 0;

  double soundSpeed() const override { return 0; }
  void computePressures(tears::ParticleSet& particles, const tears::ActivePairs&, double,
                        tears::TearCounters&) override {
    ++calls;
    std::fill(particles.pressure.begin(), particles.pressure.end(), 0.0);
  }
  double accelerationBound(double largest) const override { return largest; }
  void correctVelocities(tears::ParticleSet&, const tears::ActivePairs&, double,
                         const tears::SkinView&, tears::TearCounters&) override {}
  double strength() const { return strength_; }

 private:
  double strength_;
};

void registerDummy() {
  tears::MethodInfo info{"dummy",
                         "Dummy",
                         "A solver of the registry test",
                         {{"strength", "How strong it is not", 1, 0, 10, false}}};
  tears::pressureSolverRegistry().add(
      {std::move(info),
       [](const tears::MethodValues& values, const tears::ScaledParameters&,
          const tears::TearSettings&) -> std::unique_ptr<tears::PressureSolver> {
         ++DummySolver::made;
         DummySolver::lastStrength = values.number("strength");
         return std::make_unique<DummySolver>(values.number("strength"));
       }});
}

// The bench's method options over `arguments` (argv[0] is the sub-command): the exit status
// parse() asks for, nullopt to run.
std::optional<int> parseBench(std::vector<std::string> arguments,
                              tears::SimulationOptions& options) {
  bench::BenchCommandLine line("tears", "test");
  bench::addTearMethodOptions(line, options);
  std::vector<char*> argv;
  for (std::string& a : arguments) argv.push_back(a.data());
  return line.parse(static_cast<int>(argv.size()), argv.data());
}

std::string errorOf(const std::function<void()>& run) {
  try {
    run();
  } catch (const std::exception& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace

class TearMethodRegistryTest : public QObject {
  Q_OBJECT

 private slots:
  void initTestCase() { registerDummy(); }

  void theRegistryListsIt() {
    const std::vector<std::string> keys =
        tears::registeredKeys(tears::MethodFamily::PressureSolver);
    QCOMPARE(keys, (std::vector<std::string>{"wcsph", "dfsph", "pbf", "dummy"}));
    QCOMPARE(tears::knownKeys(tears::MethodFamily::PressureSolver),
             std::string(R"("wcsph", "dfsph", "pbf" or "dummy")"));
    // A key is registered once.
    QVERIFY(errorOf(registerDummy).find("registered already") != std::string::npos);
    // The defaults name registered methods, and so do the quality levels.
    const tears::SimulationOptions defaults;
    QVERIFY(tears::findMethod(tears::MethodFamily::PressureSolver, defaults.pressureSolver.key));
    QVERIFY(tears::findMethod(tears::MethodFamily::SurfaceTension, defaults.surfaceTension.key));
    QVERIFY(tears::findMethod(tears::MethodFamily::NeighbourStructure, defaults.neighbours.key));
    for (TearQuality level :
         {TearQuality::Preview, TearQuality::Balanced, TearQuality::Reference}) {
      const playback::TearQualityLevel& info = playback::tearQualityLevel(level);
      QVERIFY(tears::findMethod(tears::MethodFamily::PressureSolver, info.solver));
      QVERIFY(tears::findMethod(tears::MethodFamily::SurfaceTension, info.tension));
      QVERIFY(tears::findMethod(tears::MethodFamily::NeighbourStructure, info.neighbours));
    }
  }

  void aProjectMayChooseIt() {
    const TearMethodKeys keys = playback::tearMethodKeys();
    const std::string project =
        R"({"format": "lacrima-project", "version": 2, "keys": [], "scene": {"solver": "dummy"}})";
    const ProjectDocument read =
        ProjectDocument::fromJson(project, "p.lacrima", ProjectDocument::Use::Edit, &keys);
    QCOMPARE(*read.scene.quality.solver, std::string("dummy"));
    const std::string unknown =
        R"({"format": "lacrima-project", "version": 2, "keys": [], "scene": {"solver": "x"}})";
    QCOMPARE(errorOf([&] {
               ProjectDocument::fromJson(unknown, "p.lacrima", ProjectDocument::Use::Edit, &keys);
             }),
             std::string(R"(p.lacrima:1:67: scene.solver: expected "wcsph", "dfsph", "pbf" or )"
                         R"("dummy", got "x")"));
  }

  void theSimulationRunsIt() {
    const tears::SimulationOptions options =
        playback::simulationOptions({TearQuality::Preview, "dummy", {}, {}});
    QCOMPARE(options.pressureSolver.key, std::string("dummy"));
    const tears::SyntheticSkin sheet = tears::makeCheekSheet();
    tears::SimulationOptions withStrength = options;
    withStrength.headHeight = 2.7;
    withStrength.pressureSolver.parameters["strength"] = 4;
    const int madeBefore = DummySolver::made;
    tears::TearSimulation sim(sheet.positions, sheet.triangles, {}, withStrength);
    QCOMPARE(DummySolver::made.load(), madeBefore + 1);
    QCOMPARE(DummySolver::lastStrength, 4.0);
    sim.setSource(tears::Eye::Left, sheet.leftSource);
    const int callsBefore = DummySolver::calls;
    for (int f = 0; f < 3; ++f) sim.step(sheet.positions, 10, 0, 1.0 / 22);
    QVERIFY(DummySolver::calls > callsBefore);
    QCOMPARE(sim.particles().size(), 10);

    // Its parameters are checked as it is made, and an unknown key is refused.
    withStrength.pressureSolver.parameters["strength"] = 11;
    QCOMPARE(
        errorOf([&] { tears::TearSimulation(sheet.positions, sheet.triangles, {}, withStrength); }),
        std::string("dummy strength: expected a number in [0, 10], got 11"));
    withStrength.pressureSolver = "sph";
    QCOMPARE(
        errorOf([&] { tears::TearSimulation(sheet.positions, sheet.triangles, {}, withStrength); }),
        std::string(R"(unknown pressure solver "sph"; expected "wcsph", "dfsph", "pbf" or )"
                    R"("dummy")"));
  }

  void theEffectsPanelOffersIt() {
    viewport::EffectsPanel panel;
    QComboBox* solver = panel.solver();
    const int index = solver->findData(QStringLiteral("dummy"));
    QVERIFY(index > 0);
    QCOMPARE(solver->itemText(index), QStringLiteral("Dummy"));
    QCOMPARE(solver->itemData(index, Qt::ToolTipRole).toString(),
             QStringLiteral("A solver of the registry test"));
    solver->setCurrentIndex(index);
    SceneSettings scene;
    panel.applyTo(scene);
    QCOMPARE(*scene.quality.solver, std::string("dummy"));
    // A project's choice shows as it was written.
    SceneSettings chosen;
    chosen.quality.solver = "dummy";
    viewport::EffectsPanel shown;
    shown.display(chosen);
    QCOMPARE(shown.solver()->currentData().toString(), QStringLiteral("dummy"));
  }

  void theBenchTakesItAndItsParameters() {
    tears::SimulationOptions options;
    QCOMPARE(parseBench({"tears", "--solver", "dummy", "--dummy-strength", "3"}, options),
             std::nullopt);
    QCOMPARE(options.pressureSolver.key, std::string("dummy"));
    QCOMPARE(options.pressureSolver.parameters.at("strength"), 3.0);
    QCOMPARE(bench::describeMethod(tears::MethodFamily::PressureSolver, options.pressureSolver),
             std::string("Dummy (strength 3)"));
    // The built-ins' parameters come from the registry too.
    tears::SimulationOptions pbf;
    QCOMPARE(parseBench({"tears", "--solver", "pbf", "--pbf-iterations", "8"}, pbf), std::nullopt);
    QCOMPARE(pbf.pressureSolver.parameters.at("iterations"), 8.0);
    // Usage errors (exit status 2): an unknown key, a parameter of a method not chosen, a value
    // out of its range.
    for (const std::vector<std::string>& wrong :
         {std::vector<std::string>{"tears", "--solver", "sph"},
          std::vector<std::string>{"tears", "--dummy-strength", "3"},
          std::vector<std::string>{"tears", "--solver", "dummy", "--dummy-strength", "30"},
          std::vector<std::string>{"tears", "--tension", "becker"},
          std::vector<std::string>{"tears", "--neighbours", "kd-tree"}}) {
      tears::SimulationOptions untouched;
      QCOMPARE(parseBench(wrong, untouched), std::optional<int>(2));
    }
  }

  void theSweepComparesIt() {
    const std::vector<bench::SolverEntry> solvers = bench::sweepSolvers();
    QCOMPARE(solvers.size(), std::size_t(4));
    QCOMPARE(solvers.front().key, tears::SimulationOptions{}.pressureSolver.key);  // the reference
    QCOMPARE(solvers.back().key, std::string("dummy"));
    QCOMPARE(solvers.back().name, std::string("Dummy"));
  }
};

QTEST_MAIN(TearMethodRegistryTest)
#include "TearMethodRegistryTest.moc"
