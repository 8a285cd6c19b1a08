// Presets applied as layers, layer edits with undo, and presets applied as keys leaving the
// animation before them alone.
#include <lacrima/editing/EditorModel.h>
#include <lacrima/editing/PresetLibrary.h>

#include <QSignalSpy>
#include <QtTest>

using namespace lacrima;
using namespace lacrima::editing;

namespace {

constexpr int kOpenJaw = 3;  // in Surprise, not in Sadness
constexpr int kLiftLeftCheek = 41;

const Preset& preset(const char* id) {
  static const PresetLibrary library = PresetLibrary::builtIn();
  const Preset* found = library.find(id);
  if (!found) qFatal("no preset %s", id);
  return *found;
}

}  // namespace

class PresetLayersTest : public QObject {
  Q_OBJECT

 private slots:
  void aPoseBecomesALayerRisingToItsIntensity() {
    EditorModel model;
    model.setCurrentTime(4.0);
    model.applyPresetAsLayer(preset("joy"), 0.5);
    QCOMPARE(model.document().layers.size(), std::size_t{1});
    const PoseLayer& layer = model.document().layers.front();
    QCOMPARE(layer.name, std::string("Joy"));
    QCOMPARE(layer.intensityKeys().size(), std::size_t{2});
    QCOMPARE(layer.intensityKeys().front().time, model.snapTime(3.5));
    QCOMPARE(layer.intensityKeys().front().value, 0.0);
    QCOMPARE(layer.intensityKeys().back().value, 0.5);
    // The face shows it, the keys do not hold it.
    QCOMPARE(model.currentValue(kLiftLeftCheek), 80.0f);  // 160 at 50 %
    QCOMPARE(model.keyedValues()[channelIndex(kLiftLeftCheek)], 0.0f);
    QVERIFY(model.document().keys.empty());
    model.setCurrentTime(3.0);
    QCOMPARE(model.currentValue(kLiftLeftCheek), 0.0f);
    // A second Joy gets its own name.
    model.applyPresetAsLayer(preset("joy"), 1.0);
    QCOMPARE(model.document().layers.back().name, std::string("Joy 2"));
  }

  void layerEditsUndoAndRedoExactly() {
    EditorModel model;
    model.setCurrentTime(1.0);
    model.applyPresetAsLayer(preset("sadness"), 1.0);
    const ProjectDocument added = model.document();
    model.setCurrentTime(2.0);
    model.keyLayerIntensity(0, 0.25);
    model.setLayerMuted(0, true);
    const ProjectDocument edited = model.document();
    QCOMPARE(edited.layers.front().intensityKeys().size(), std::size_t{3});
    QVERIFY(edited.layers.front().muted);
    model.undoStack()->undo();
    model.undoStack()->undo();
    QVERIFY(model.document() == added);
    model.undoStack()->redo();
    model.undoStack()->redo();
    QVERIFY(model.document() == edited);
    model.unkeyLayerIntensity(0);
    QCOMPARE(model.document().layers.front().intensityKeys().size(), std::size_t{2});
    model.removeLayer(0);
    QVERIFY(model.document().layers.empty());
    model.undoStack()->undo();
    QCOMPARE(model.document().layers.size(), std::size_t{1});
  }

  void slidersKeyWhatMakesTheMixTheValueAsked() {
    EditorModel model;
    model.setCurrentTime(1.0);
    model.applyPresetAsLayer(preset("joy"), 1.0);  // lift_l_cheek +160
    model.setChannel(kLiftLeftCheek, 200.0);
    QCOMPARE(model.currentValue(kLiftLeftCheek), 200.0f);
    QCOMPARE(model.keyedValues()[channelIndex(kLiftLeftCheek)], 40.0f);
  }

  void refusedLayersSayWhy() {
    EditorModel model;
    QSignalSpy messages(&model, &EditorModel::message);
    model.applyPresetAsLayer(preset("sobbing-cycle"), 1.0);
    QVERIFY(model.document().layers.empty());
    QCOMPARE(messages.count(), 1);
    QVERIFY(messages.front().front().toString().contains("sequence"));
    QCOMPARE(model.undoStack()->count(), 0);
    model.applyPresetAsLayer(preset("joy"), 1.0);
    model.keyLayerIntensity(0, 1e9);
    QCOMPARE(messages.count(), 2);
    QCOMPARE(model.undoStack()->count(), 1);
  }

  // The reported surprise: a pose at 4 s after a Sadness pose at 0 s put the new pose's
  // open_jaw on frame 0 as well.
  void aPoseKeyedLaterLeavesTheEarlierAnimationAlone() {
    EditorModel model;
    model.applyPreset(preset("sadness"), 1.0, false);
    const FapValues atStart = model.document().keys.evaluate(0.0);
    model.setCurrentTime(4.0);
    const ProjectDocument sadOnly = model.document();
    model.applyPreset(preset("surprise"), 1.0, false);
    QVERIFY(model.document().keys.evaluate(0.0) == atStart);
    QVERIFY(model.currentValue(kOpenJaw) != atStart[channelIndex(kOpenJaw)]);
    // One undo step removes both the pose and the key that protected the start.
    model.undoStack()->undo();
    QVERIFY(model.document() == sadOnly);
  }

  void aFirstPoseNeedsNoHold() {
    EditorModel model;
    model.setCurrentTime(2.0);
    model.applyPreset(preset("joy"), 1.0, false);
    QCOMPARE(model.document().keys.keys().size(), std::size_t{1});
  }
};

QTEST_MAIN(PresetLayersTest)
#include "PresetLayersTest.moc"
