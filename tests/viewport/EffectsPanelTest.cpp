// The Scene panel's quality choice driving a real FrameProducer on the default head, offscreen
// (as the player and the editor wire it: edited() -> applyTo -> setScene): choosing a level or
// an advanced option restarts the tears with the options it claims, the cost label shows the
// mean of the frames fed to it, and display() shows a project's choice without emitting.
#include "../playback/PlaybackTestSupport.h"

#include <lacrima/playback/FrameProducer.h>
#include <lacrima/playback/TearQualityOptions.h>
#include <lacrima/rigging/DefaultHead.h>
#include <lacrima/tears/TearMethods.h>
#include <lacrima/viewport/EffectsPanel.h>

#include <QCheckBox>
#include <QComboBox>
#include <QLabel>
#include <QToolButton>
#include <QtTest>

using namespace lacrima;
using namespace lacrima::playback;
using lacrima::viewport::EffectsPanel;

namespace {

FapValues weeping(float perEye) {
  FapValues v{};
  v[static_cast<std::size_t>(channelIndex(kTearLeftFap))] = perEye;
  v[static_cast<std::size_t>(channelIndex(kTearRightFap))] = perEye;
  return v;
}

}  // namespace

class EffectsPanelTest : public QObject {
  Q_OBJECT

  std::unique_ptr<HeadRig> rig_;

  // `frames` frames of tears, each one's cost fed to the panel as the apps do; returns the
  // mean sub-steps per frame.
  static double play(FrameProducer& producer, EffectsPanel& panel, int frames) {
    long long substeps = 0;
    for (int f = 0; f < frames; ++f) {
      producer.produce(weeping(15), 1.0 / 22, 0);
      const ProducerTimes& t = producer.lastTimes();
      panel.addFrameCost(t.simulation + t.surface + t.trails, t.substeps);
      substeps += t.substeps;
    }
    return static_cast<double>(substeps) / frames;
  }

 private slots:
  void initTestCase() { LOAD_DEFAULT_HEAD_RIG(rig_); }

  void qualityDrivesTheProducer() {
    FrameProducer producer(*rig_);
    EffectsPanel panel;
    panel.display(producer.scene());
    QCOMPARE(panel.quality()->currentIndex(), static_cast<int>(TearQuality::Balanced));
    QCOMPARE(panel.quality()->count(), 3);
    QVERIFY(!panel.solver()->isVisibleTo(&panel));
    QObject::connect(&panel, &EffectsPanel::edited, &panel, [&] {
      SceneSettings scene = producer.scene();
      panel.applyTo(scene);
      producer.setScene(scene);
    });

    const double balanced = play(producer, panel, EffectsPanel::kCostFrames);
    QVERIFY(producer.particleCount() > 0);
    QVERIFY(balanced > 0);
    // The label is the mean of the frames fed: the sub-steps, rounded as shown.
    QVERIFY2(panel.cost()->text().contains(QStringLiteral("%1 sub-steps").arg(balanced, 0, 'f', 0)),
             qPrintable(panel.cost()->text()));
    QVERIFY(panel.cost()->text().contains("ms per frame"));

    // Reference: the tears restart with its shorter sub-steps, the old cost is forgotten.
    QSignalSpy edited(&panel, &EffectsPanel::edited);
    panel.quality()->setCurrentIndex(static_cast<int>(TearQuality::Reference));
    QCOMPARE(edited.count(), 1);
    QVERIFY(producer.scene().quality.level == TearQuality::Reference);
    QCOMPARE(producer.particleCount(), 0);
    QCOMPARE(producer.simulationOptions().lambdaCfl,
             simulationOptions({TearQuality::Reference, {}, {}, {}}).lambdaCfl);
    QVERIFY(!panel.cost()->text().contains("ms"));
    const double reference = play(producer, panel, EffectsPanel::kCostFrames);
    QVERIFY2(reference > balanced,
             qPrintable(QStringLiteral("%1 %2").arg(reference).arg(balanced)));

    // Advanced: shown on demand; an explicit solver replaces the level's.
    panel.advanced()->click();
    QVERIFY(panel.solver()->isVisibleTo(&panel));
    panel.solver()->setCurrentIndex(panel.solver()->findData(QStringLiteral("dfsph")));
    QVERIFY(producer.scene().quality.solver == "dfsph");
    QCOMPARE(producer.simulationOptions().pressureSolver.key, std::string("dfsph"));
    QCOMPARE(producer.particleCount(), 0);
    play(producer, panel, 3);
    QVERIFY(producer.particleCount() > 0);
    // "as the level", then every registered solver.
    QCOMPARE(
        panel.solver()->count(),
        1 + static_cast<int>(tears::registeredKeys(tears::MethodFamily::PressureSolver).size()));
    panel.solver()->setCurrentIndex(panel.solver()->findData(QStringLiteral("pbf")));
    QVERIFY(producer.scene().quality.solver == "pbf");
    QCOMPARE(producer.simulationOptions().pressureSolver.key, std::string("pbf"));
    QCOMPARE(panel.solver()->currentText(), QStringLiteral("PBF"));
    QCOMPARE(producer.particleCount(), 0);  // restarted with the new solver
    play(producer, panel, 3);
    QVERIFY(producer.particleCount() > 0);
    panel.solver()->setCurrentIndex(0);  // back to the level's own
    QVERIFY(!producer.scene().quality.solver);
    QCOMPARE(producer.simulationOptions().pressureSolver.key, std::string("wcsph"));

    // An effect toggle does not restart the tears.
    play(producer, panel, 3);
    const int particles = producer.particleCount();
    panel.particles()->click();
    QCOMPARE(producer.particleCount(), particles);
  }

  // A project's choice shows as it is, without edited(); explicit choices open Advanced.
  void displayShowsAProjectsChoice() {
    EffectsPanel panel;
    QSignalSpy edited(&panel, &EffectsPanel::edited);
    SceneSettings scene;
    scene.quality = {TearQuality::Preview, std::nullopt, "akinci", "octree"};
    scene.simulation["adhesion"] = 40;
    panel.display(scene);
    QCOMPARE(edited.count(), 0);
    QCOMPARE(panel.quality()->currentIndex(), static_cast<int>(TearQuality::Preview));
    QCOMPARE(panel.solver()->currentIndex(), 0);
    QVERIFY(panel.advanced()->isChecked() && panel.tension()->isVisibleTo(&panel));
    SceneSettings read;
    read.simulation["adhesion"] = 20;
    panel.applyTo(read);
    QVERIFY(read.quality == scene.quality);
    QCOMPARE(read.simulation.at("adhesion"), 20.0);  // the tear parameters are not the panel's
    // Frames without tears leave the cost as it was.
    panel.addFrameCost(3.0, 0);
    QVERIFY(!panel.cost()->text().contains("ms"));
    panel.addFrameCost(3.0, 10);
    panel.addFrameCost(5.0, 20);
    QCOMPARE(panel.cost()->text(), QStringLiteral("4.0 ms per frame, 15 sub-steps"));
  }
};

QTEST_MAIN(EffectsPanelTest)
#include "EffectsPanelTest.moc"
