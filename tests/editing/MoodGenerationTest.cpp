// The editor's Generate...: a mood take written as reduced keys over a time range, one undo step;
// or kept as a procedural layer (MoodLayer.h) that follows the mood curves, undoably muted,
// re-seeded, removed and baked.
#include <lacrima/common/mood/MoodGenerator.h>
#include <lacrima/editing/EditorModel.h>
#include <lacrima/editing/MoodGeneration.h>

#include <QtTest>

#include <cstring>

using namespace lacrima;
using namespace lacrima::editing;

namespace {

constexpr int kOpenJaw = 3;
constexpr int kTongue = 43;  // never generated

Keyframe keyAt(double time, std::initializer_list<std::pair<int, float>> values) {
  Keyframe key;
  key.time = time;
  key.interpolation = Interpolation::Linear;
  for (const auto& [fap, value] : values) key.set(fap, value);
  return key;
}

ProjectDocument documentWithKeys() {
  ProjectDocument document;
  document.keys = KeyframeSequence({keyAt(0, {{kOpenJaw, 40}, {kTongue, 10}}),
                                    keyAt(5, {{kOpenJaw, 90}, {kTongue, 300}}),
                                    keyAt(20, {{kOpenJaw, 10}, {kTongue, 0}})});
  return document;
}

MoodGenerationRequest sadnessFrom2To14() {
  MoodGenerationRequest request;
  request.start = 2;
  request.end = 14;
  MoodLevels sad;
  sad[Mood::Sadness] = 0.9;
  request.script = MoodScript({{0, {}}, {1, sad}});
  request.seed = 12;
  return request;
}

// documentWithKeys() with a sadness keyed from 0 at 2 s to 0.9 at 6 s.
ProjectDocument documentWithMoods() {
  ProjectDocument document = documentWithKeys();
  document.moods[Mood::Sadness] =
      IntensityCurve({{2, 0, Interpolation::Smooth}, {6, 0.9, Interpolation::Linear}});
  return document;
}

MoodGenerationRequest layerFrom2To14(const ProjectDocument& document) {
  MoodGenerationRequest request = sadnessFrom2To14();
  request.curves = &document.moods;
  return request;
}

bool sameBits(const FapValues& a, const FapValues& b) {
  return std::memcmp(a.data(), b.data(), sizeof a) == 0;
}

}  // namespace

class MoodGenerationTest : public QObject {
  Q_OBJECT

 private slots:
  void keysFollowTheTakeWithinTheTolerance() {
    const ProjectDocument document = documentWithKeys();
    const MoodGenerationRequest request = sadnessFrom2To14();
    const MoodGenerationPlan plan = planMoodGeneration(document.keys, request);
    QCOMPARE(plan.frames, 12 * 22 + 1);
    QVERIFY2(plan.keys > 10 && plan.keys < plan.frames, qPrintable(QString::number(plan.keys)));
    QVERIFY(plan.channels.test(channelIndex(31)) && plan.channels.test(channelIndex(69)));
    QVERIFY(!plan.channels.test(channelIndex(kTongue)));

    KeyframeSequence keys = document.keys;
    applyKeys(keys, plan.change.times, plan.change.after);
    const MoodTake take =
        generateMoodTake(request.script, request.seed, request.end - request.start, request.fps);
    for (int frame = 0; frame < take.animation.frameCount(); ++frame) {
      const FapValues at = keys.evaluate(request.start + frame / request.fps);
      for (int fap = 1; fap <= kChannelCount; ++fap) {
        if (!plan.channels.test(channelIndex(fap))) continue;
        const float wanted =
            take.animation.frames[static_cast<std::size_t>(frame)][channelIndex(fap)];
        QVERIFY2(std::abs(at[channelIndex(fap)] - wanted) <= request.tolerance + 0.5f,
                 qPrintable(QString("frame %1 fap %2").arg(frame).arg(fap)));
      }
    }
    // The tongue keeps its key inside the range; keys outside it are untouched.
    QCOMPARE(keys.evaluate(5)[channelIndex(kTongue)], 300.0f);
    QCOMPARE(keys.keys().front(), document.keys.keys().front());
    QCOMPARE(keys.keys().back(), document.keys.keys().back());
  }

  void generateIsOneUndoStep() {
    EditorModel model;
    model.resetDocument(documentWithKeys(), true);
    const KeyframeSequence before = model.document().keys;
    const MoodGenerationPlan plan = planMoodGeneration(before, sadnessFrom2To14());
    model.editKeys(plan.change, "Generate crying");
    QCOMPARE(model.undoStack()->count(), 1);
    QVERIFY(model.isModified());
    const KeyframeSequence after = model.document().keys;
    QCOMPARE(static_cast<int>(after.keys().size()), 2 + plan.keys);  // 0 s and 20 s stay
    model.undoStack()->undo();
    QCOMPARE(model.document().keys.keys(), before.keys());
    model.undoStack()->redo();
    QCOMPARE(model.document().keys.keys(), after.keys());
  }

  // Generate... from the project's mood curves: a keyed sadness ramp over the range gives an
  // inner-brow raise (FAP 31/32) that grows with the curve; the curves are read at document
  // time, frame by frame, so a constant curve gives the very keys a constant script does.
  void moodCurvesDriveTheTakeFrameByFrame() {
    MoodCurves curves;
    curves[Mood::Sadness] =
        IntensityCurve({{10, 0, Interpolation::Linear}, {30, 1, Interpolation::Linear}});
    MoodGenerationRequest request;
    request.start = 10;
    request.end = 30;
    request.fps = 10;
    request.seed = 3;
    request.tolerance = 0;  // every frame a key: the keys are the take
    request.curves = &curves;
    const MoodGenerationPlan plan = planMoodGeneration({}, request);
    KeyframeSequence keys;
    applyKeys(keys, plan.change.times, plan.change.after);
    const auto innerBrows = [&](double from, double to) {
      double sum = 0;
      int n = 0;
      for (double t = from; t < to; t += 0.1, ++n)
        sum += keys.evaluate(t)[channelIndex(31)] + keys.evaluate(t)[channelIndex(32)];
      return sum / n;
    };
    const double early = innerBrows(10, 14), middle = innerBrows(18, 22), late = innerBrows(26, 30);
    QVERIFY2(early < middle && middle < late && late > 0,
             qPrintable(QString("%1 %2 %3").arg(early).arg(middle).arg(late)));

    curves[Mood::Sadness] = IntensityCurve({{0, 0.5, Interpolation::Linear}});
    MoodLevels half;
    half[Mood::Sadness] = 0.5;
    MoodGenerationRequest constant = request;
    constant.curves = nullptr;
    constant.script = MoodScript::constant(half);
    QCOMPARE(planMoodGeneration({}, request).change.after,
             planMoodGeneration({}, constant).change.after);
  }

  void badRangesAreRefusedBeforeGenerating() {
    MoodGenerationRequest request = sadnessFrom2To14();
    request.end = request.start;
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, planMoodGeneration({}, request));
    request.end = 1e6;
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, planMoodGeneration({}, request));
    request = sadnessFrom2To14();
    request.fps = 0;
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, planMoodGeneration({}, request));
  }

  // Bake to keys keeps the face: the keys plus the layer, reduced at tolerance 1, evaluated at
  // every frame of the range give the values the layer gave there (tears within half a particle
  // more: keys round them), and the colours become keys. One undo step restores it all exactly.
  void bakingKeepsWhatTheLayerShows() {
    EditorModel model;
    model.resetDocument(documentWithMoods(), true);
    model.addMoodLayer(layerFrom2To14(model.document()));
    QCOMPARE(model.undoStack()->count(), 1);
    const ProjectDocument layered = model.document();
    QVERIFY(layered.moodLayer && layered.moodLayer->seed == 12);
    MoodLayerCache cache;
    std::vector<FapValues> shown;
    for (int f = 0; f <= 12 * 22; ++f) shown.push_back(layered.evaluate(2 + f / 22.0, cache));

    model.bakeMoodLayer();
    QCOMPARE(model.undoStack()->count(), 2);
    const ProjectDocument baked = model.document();
    QVERIFY(!baked.moodLayer);
    QVERIFY(baked.colours.redness.keys().size() > 40);
    float worst = 0, worstTears = 0;
    for (int f = 0; f <= 12 * 22; ++f) {
      const FapValues now = baked.evaluate(2 + f / 22.0, cache);
      for (int i = 0; i < kChannelCount; ++i) {
        const bool tears = i == channelIndex(kTearLeftFap) || i == channelIndex(kTearRightFap);
        float& largest = tears ? worstTears : worst;
        largest = std::max(largest, std::abs(now[i] - shown[static_cast<std::size_t>(f)][i]));
      }
    }
    QVERIFY2(worst <= 1.0f && worstTears <= 1.5f,
             qPrintable(QString("%1 %2").arg(worst).arg(worstTears)));
    // The tongue, which the generator never moves, keeps its keys.
    QCOMPARE(baked.keys.evaluate(5)[channelIndex(kTongue)], 300.0f);
    const KeyedColours colours = baked.colours.at(10);
    QVERIFY(std::abs(*colours.blush - *layered.coloursAt(10, cache).blush) < 0.01);

    model.undoStack()->undo();
    QVERIFY(model.document() == layered);
    model.undoStack()->undo();
    QVERIFY(model.document() == documentWithMoods());
  }

  // The layer follows the mood curves: a key edited in the Moods view changes the face at once,
  // and undo brings back the very bits. Only a change of an input generates the take again.
  void aMoodKeyEditChangesTheLayerAndUndoRestoresIt() {
    EditorModel model;
    model.resetDocument(documentWithMoods(), true);
    model.addMoodLayer(layerFrom2To14(model.document()));
    model.setCurrentTime(10);
    const FapValues before = model.currentValues();
    const int generations = model.moodGenerations();
    model.setCurrentTime(6);
    model.keyMood(Mood::Sadness, 0.1);
    model.setCurrentTime(10);
    QVERIFY(!sameBits(model.currentValues(), before));
    QCOMPARE(model.moodGenerations(), generations + 1);
    model.undoStack()->undo();
    QVERIFY(sameBits(model.currentValues(), before));
    model.undoStack()->redo();
    QVERIFY(!sameBits(model.currentValues(), before));
    model.undoStack()->undo();

    model.setMoodLayerMuted(true);
    QVERIFY(sameBits(model.currentValues(), model.keyedValues()));
    model.undoStack()->undo();
    QVERIFY(sameBits(model.currentValues(), before));
    model.setMoodLayerSeed(13);
    QVERIFY(!sameBits(model.currentValues(), before));
    model.undoStack()->undo();
    QVERIFY(sameBits(model.currentValues(), before));
    model.setMoodLayerSeed(MoodLayer::kMaxSeed + 1);  // refused, with a message
    QCOMPARE(model.document().moodLayer->seed, std::uint64_t(12));
    model.removeMoodLayer();
    QVERIFY(!model.document().moodLayer);
    QVERIFY(sameBits(model.currentValues(), model.keyedValues()));
    model.undoStack()->undo();
    QVERIFY(sameBits(model.currentValues(), before));
  }

  // From constant moods, the layer keys them as curves over the range (its ease-in included),
  // in the same undo step, so they can be edited; a seed a project cannot store is refused.
  void constantMoodsBecomeCurvesForTheLayer() {
    EditorModel model;
    model.resetDocument(documentWithKeys(), true);
    model.addMoodLayer(sadnessFrom2To14());
    QCOMPARE(model.undoStack()->count(), 1);
    const IntensityCurve& sadness = model.document().moods[Mood::Sadness];
    QCOMPARE(sadness.keys().size(), std::size_t(2));
    QCOMPARE(sadness.at(2), 0.0);
    QCOMPARE(float(sadness.at(3)), 0.9f);
    QVERIFY(model.document().moods[Mood::Anger].at(5) == 0.0);
    model.undoStack()->undo();
    QVERIFY(model.document().moods.empty() && !model.document().moodLayer);

    MoodGenerationRequest request = sadnessFrom2To14();
    request.seed = MoodLayer::kMaxSeed + 1;
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, model.addMoodLayer(request));
    QCOMPARE(model.undoStack()->count(), 1);  // the undone step, nothing new
  }
};

QTEST_GUILESS_MAIN(MoodGenerationTest)
#include "MoodGenerationTest.moc"
