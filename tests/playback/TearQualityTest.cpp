// The tear quality levels (TearQualityOptions.h): each level gives the simulation options it
// claims, explicit choices replace the level's, a short run at every level (and with every
// advanced choice) stays finite on the default head, shorter sub-steps take more of them, and
// a quality change restarts the tears where an effect toggle does not.
#include "../support/MissingData.h"
#include "PlaybackTestSupport.h"

#include <lacrima/playback/FrameProducer.h>
#include <lacrima/playback/TearQualityOptions.h>
#include <lacrima/rigging/DefaultHead.h>

#include <QtTest>

#include <stdexcept>
#include <string>
#include <vector>

using namespace lacrima;
using namespace lacrima::playback;
using namespace lacrima::playback::test;

namespace {

constexpr TearQuality kLevels[] = {TearQuality::Preview, TearQuality::Balanced,
                                   TearQuality::Reference};

struct RunResult {
  long long substeps = 0;
  int particles = 0;
  bool finite = true;
};

// 22 frames (one second) of 20 tears per eye with the jaw moving, at `quality`.
RunResult run(const HeadRig& rig, const TearQualitySettings& quality) {
  SceneSettings scene;
  scene.quality = quality;
  scene.particles = true;  // the view then shows every particle
  FrameProducer producer(rig, scene);
  const FapAnimation animation = cryingAnimation(22, 20);
  RunResult result;
  for (const FapValues& values : animation.frames) {
    const FrameView& view = producer.produce(values, 1.0 / kFps, 0);
    result.substeps += producer.lastTimes().substeps;
    if (!view.particles) continue;
    for (std::size_t i = 0; i < view.particles->position.size(); ++i)
      if (!view.particles->position[i].allFinite() || !view.particles->velocity[i].allFinite())
        result.finite = false;
  }
  result.particles = producer.particleCount();
  return result;
}

}  // namespace

class TearQualityTest : public QObject {
  Q_OBJECT

  std::unique_ptr<HeadRig> rig_;

 private slots:
  // Balanced is the simulation's defaults; Preview and Reference scale the sub-step factors
  // the sweep measured (x1.5, x0.5) and keep WCSPH, Müller tension and the grid.
  void levelsGiveTheOptionsTheyClaim() {
    const tears::SimulationOptions defaults;
    for (TearQuality level : kLevels) {
      const TearQualityLevel& info = tearQualityLevel(level);
      QVERIFY(info.level == level);
      QVERIFY(!info.label.empty() && !info.summary.empty());
      const tears::SimulationOptions o = simulationOptions({level, {}, {}, {}});
      QCOMPARE(o.lambdaCfl, defaults.lambdaCfl * info.substepFactor);
      QCOMPARE(o.lambdaAcceleration, defaults.lambdaAcceleration * info.substepFactor);
      QCOMPARE(o.lambdaViscosity,
               std::min(defaults.lambdaViscosity, defaults.lambdaViscosity * info.substepFactor));
      QVERIFY(o.pressureSolver.key == info.solver && info.solver == "wcsph");
      QVERIFY(o.surfaceTension.key == info.tension && info.tension == "mueller");
      QVERIFY(o.neighbours.key == info.neighbours && info.neighbours == "grid");
      QVERIFY(o.pressureSolver == defaults.pressureSolver);
      QVERIFY(o.surfaceTension == defaults.surfaceTension);
      QVERIFY(o.neighbours == defaults.neighbours);
      // Nothing else moves.
      QCOMPARE(o.neighbourSkin, defaults.neighbourSkin);
      QCOMPARE(o.maxSubsteps, defaults.maxSubsteps);
      QCOMPARE(o.maxSubstepSeconds, defaults.maxSubstepSeconds);
    }
    QCOMPARE(tearQualityLevel(TearQuality::Balanced).substepFactor, 1.0);
    QCOMPARE(tearQualityLevel(TearQuality::Preview).substepFactor, 1.5);
    QCOMPARE(tearQualityLevel(TearQuality::Reference).substepFactor, 0.5);
    const tears::SimulationOptions balanced = simulationOptions({});
    QCOMPARE(balanced.lambdaCfl, defaults.lambdaCfl);
    QCOMPARE(balanced.lambdaAcceleration, defaults.lambdaAcceleration);
    QCOMPARE(balanced.lambdaViscosity, defaults.lambdaViscosity);
  }

  void advancedChoicesReplaceTheLevels() {
    TearQualitySettings quality{TearQuality::Preview, "dfsph", "akinci", "octree"};
    tears::SimulationOptions o = simulationOptions(quality);
    QCOMPARE(o.pressureSolver.key, std::string("dfsph"));
    QCOMPARE(o.surfaceTension.key, std::string("akinci"));
    QCOMPARE(o.neighbours.key, std::string("octree"));
    QCOMPARE(o.lambdaCfl, simulationOptions({TearQuality::Preview, {}, {}, {}}).lambdaCfl);
    quality = {TearQuality::Reference, "wcsph", "mueller", "grid"};
    o = simulationOptions(quality);
    QCOMPARE(o.pressureSolver.key, std::string("wcsph"));
    QCOMPARE(o.surfaceTension.key, std::string("mueller"));
    QCOMPARE(o.neighbours.key, std::string("grid"));
    // Position-based fluids replace the level's solver only.
    o = simulationOptions({TearQuality::Balanced, "pbf", {}, {}});
    QCOMPARE(o.pressureSolver.key, std::string("pbf"));
    QCOMPARE(o.lambdaCfl, simulationOptions({}).lambdaCfl);
    QCOMPARE(o.surfaceTension.key, std::string("mueller"));
  }

  // A key no registry holds is refused, naming the known ones, never replaced by a default.
  void unknownChoicesAreErrorsNamingTheKnownKeys() {
    const auto message = [](const TearQualitySettings& quality) {
      try {
        simulationOptions(quality);
      } catch (const std::invalid_argument& e) {
        return std::string(e.what());
      }
      return std::string("no error");
    };
    QCOMPARE(message({TearQuality::Balanced, "pcisph", {}, {}}),
             std::string("unknown pressure solver \"pcisph\"; expected \"wcsph\", \"dfsph\" or "
                         "\"pbf\""));
    QCOMPARE(message({TearQuality::Balanced, {}, "becker", {}}),
             std::string("unknown surface tension \"becker\"; expected \"mueller\" or "
                         "\"akinci\""));
    QCOMPARE(message({TearQuality::Balanced, {}, {}, "kd-tree"}),
             std::string("unknown neighbour structure \"kd-tree\"; expected \"grid\" or "
                         "\"octree\""));
    const TearMethodKeys keys = tearMethodKeys();
    QCOMPARE(keys.solvers, (std::vector<std::string>{"wcsph", "dfsph", "pbf"}));
    QCOMPARE(keys.tensions, (std::vector<std::string>{"mueller", "akinci"}));
    QCOMPARE(keys.neighbours, (std::vector<std::string>{"grid", "octree"}));
  }

  void producerRunsEveryLevelFinite_data() {
    QTest::addColumn<int>("level");
    // 0: the level's own; 1: DFSPH, Akinci and the octree; 2: PBF
    QTest::addColumn<int>("advanced");
    for (TearQuality level : kLevels) {
      const std::string name(toString(level));
      QTest::newRow(name.c_str()) << static_cast<int>(level) << 0;
      QTest::newRow((name + ", dfsph akinci octree").c_str()) << static_cast<int>(level) << 1;
      if (level == TearQuality::Balanced)
        QTest::newRow((name + ", pbf").c_str()) << static_cast<int>(level) << 2;
    }
  }

  void producerRunsEveryLevelFinite() {
    QFETCH(int, level);
    QFETCH(int, advanced);
    if (!loadRig()) LACRIMA_SKIP_WITHOUT_DEFAULT_HEAD();
    TearQualitySettings quality{static_cast<TearQuality>(level), {}, {}, {}};
    if (advanced == 2) quality.solver = "pbf";
    if (advanced == 1) {
      quality.solver = "dfsph";
      quality.tension = "akinci";
      quality.neighbours = "octree";
    }
    SceneSettings scene;
    scene.quality = quality;
    const FrameProducer producer(*rig_, scene);
    const tears::SimulationOptions expected = simulationOptions(quality);
    QCOMPARE(producer.simulationOptions().lambdaCfl, expected.lambdaCfl);
    QVERIFY(producer.simulationOptions().pressureSolver == expected.pressureSolver);
    QVERIFY(producer.simulationOptions().surfaceTension == expected.surfaceTension);
    QVERIFY(producer.simulationOptions().neighbours == expected.neighbours);
    const RunResult result = run(*rig_, quality);
    QVERIFY(result.finite);
    QVERIFY(result.particles > 0);
    QVERIFY(result.substeps > 0);
  }

  // The levels differ where they claim to: the same second of tears takes more sub-steps the
  // shorter the level's sub-steps are.
  void shorterSubstepsTakeMore() {
    if (!loadRig()) LACRIMA_SKIP_WITHOUT_DEFAULT_HEAD();
    const long long preview = run(*rig_, {TearQuality::Preview, {}, {}, {}}).substeps;
    const long long balanced = run(*rig_, {}).substeps;
    const long long reference = run(*rig_, {TearQuality::Reference, {}, {}, {}}).substeps;
    QVERIFY2(preview < balanced && balanced < reference,
             qPrintable(QStringLiteral("%1 %2 %3").arg(preview).arg(balanced).arg(reference)));
  }

  void qualityChangeRestartsTheTears() {
    if (!loadRig()) LACRIMA_SKIP_WITHOUT_DEFAULT_HEAD();
    FrameProducer producer(*rig_);
    const FapAnimation animation = cryingAnimation(11, 20);
    for (const FapValues& values : animation.frames) producer.produce(values, 1.0 / kFps, 0);
    QVERIFY(producer.particleCount() > 0);
    QVERIFY(producer.lastTimes().substeps > 0);

    SceneSettings scene = producer.scene();
    scene.particles = !scene.particles;  // an effect: the tears go on
    QVERIFY(!restartsTears(producer.scene(), scene));
    producer.setScene(scene);
    QVERIFY(producer.particleCount() > 0);

    scene.quality.level = TearQuality::Reference;
    QVERIFY(restartsTears(producer.scene(), scene));
    producer.setScene(scene);
    QCOMPARE(producer.particleCount(), 0);
    QCOMPARE(producer.simulationOptions().lambdaCfl, simulationOptions(scene.quality).lambdaCfl);

    producer.produce(animation.frames.back(), 1.0 / kFps, 0);
    QVERIFY(producer.particleCount() > 0);
    scene.quality.neighbours = "octree";  // an advanced choice restarts them too
    producer.setScene(scene);
    QCOMPARE(producer.particleCount(), 0);
    QCOMPARE(producer.simulationOptions().neighbours.key, std::string("octree"));
  }

 private:
  bool loadRig() {
    if (!rig_ && rigging::defaultHeadAvailable()) rig_ = loadDefaultHeadRig();
    return rig_ != nullptr;
  }
};

QTEST_GUILESS_MAIN(TearQualityTest)
#include "TearQualityTest.moc"
