// The editor's Generate...: a mood take written as reduced keys over a time range, one undo step.
#include <lacrima/common/mood/MoodGenerator.h>
#include <lacrima/editing/EditorModel.h>
#include <lacrima/editing/MoodGeneration.h>

#include <QtTest>

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
};

QTEST_GUILESS_MAIN(MoodGenerationTest)
#include "MoodGenerationTest.moc"
