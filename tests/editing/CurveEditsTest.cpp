// Graph editor edit planning (CurveEdits.h) and the handles it starts from (CurveHandles.h):
// auto Bézier equals Smooth, the drawn auto handles are the curve's tangents, the Aligned and
// Free rules, which segment a handle turns Bézier, handles that reach past their segment,
// moving channel keys (tears stay whole particles), and exact undo of every change.
#include "../support/BezierReference.h"

#include <lacrima/common/CurveHandles.h>
#include <lacrima/editing/CurveEdits.h>

#include <QtTest>

#include <cmath>
#include <random>

using namespace lacrima;
using namespace lacrima::editing;
using lacrima::test::Point2;

namespace {

constexpr int kJaw = 3;  // open_jaw
constexpr int kLip = 5;  // raise_b_midlip

// Keys at `times` setting `fap` to `values`, every segment of mode `mode` (auto handles).
KeyframeSequence curve(int fap, std::vector<double> times, std::vector<double> values,
                       Interpolation mode) {
  std::vector<Keyframe> keys;
  for (std::size_t i = 0; i < times.size(); ++i) {
    Keyframe key;
    key.time = times[i];
    key.interpolation = mode;
    key.set(fap, static_cast<float>(values[i]));
    keys.push_back(key);
  }
  return KeyframeSequence(std::move(keys));
}

KeyframeSequence applied(KeyframeSequence keys, const KeyChange& change, bool redo = true) {
  applyKeys(keys, change.times, redo ? change.after : change.before);
  return keys;
}

// Redo then undo gives back exactly the keys before (Keyframe == compares shapes too).
void requireExactUndo(const KeyframeSequence& before, const KeyChange& change) {
  const KeyframeSequence after = applied(before, change);
  const KeyframeSequence undone = applied(after, change, false);
  QCOMPARE(undone.keys(), before.keys());
}

double valueAt(const KeyframeSequence& keys, int fap, double t) {
  return keys.evaluate(t)[static_cast<std::size_t>(channelIndex(fap))];
}

// The segment's control points from the keys' effective handles.
std::array<Point2, 4> controlPoints(const KeyframeSequence& keys, int fap, int a, int b) {
  const Keyframe& ka = keys.keys()[static_cast<std::size_t>(a)];
  const Keyframe& kb = keys.keys()[static_cast<std::size_t>(b)];
  const Handle out = effectiveHandles(keys, fap, a).out;
  const Handle in = effectiveHandles(keys, fap, b).in;
  return {Point2{ka.time, ka.value(fap)}, Point2{ka.time + out.dt, ka.value(fap) + out.dv},
          Point2{kb.time + in.dt, kb.value(fap) + in.dv}, Point2{kb.time, kb.value(fap)}};
}

// Curves that exercise Steffen's cases: monotone runs, extrema, a plateau, uneven spacing,
// two keys only, negative values.
std::vector<std::pair<std::vector<double>, std::vector<double>>> testCurves() {
  std::vector<std::pair<std::vector<double>, std::vector<double>>> curves = {
      {{0.0, 1.0}, {0.0, 100.0}},
      {{0.0, 0.5, 2.0}, {-40.0, 300.0, 20.0}},
      {{0.0, 0.3, 0.4, 1.7, 2.0}, {0.0, 50.0, 50.0, 900.0, -100.0}},
      {{0.2, 1.1, 1.3, 2.5, 3.0, 3.1}, {10.0, 20.0, 400.0, 410.0, 420.0, -800.0}},
  };
  std::mt19937 random(14);
  std::uniform_real_distribution<double> gap(0.05, 1.0), value(-500.0, 500.0);
  for (int c = 0; c < 4; ++c) {
    std::vector<double> times{0.0}, values{value(random)};
    for (int k = 0; k < 7; ++k) {
      times.push_back(times.back() + gap(random));
      values.push_back(value(random));
    }
    curves.emplace_back(times, values);
  }
  return curves;
}

}  // namespace

class CurveEditsTest : public QObject {
  Q_OBJECT

 private slots:
  void autoBezierEqualsSmooth() {
    for (const auto& [times, values] : testCurves()) {
      const KeyframeSequence smooth = curve(kJaw, times, values, Interpolation::Smooth);
      const KeyframeSequence bezier = curve(kJaw, times, values, Interpolation::Bezier);
      for (double t = times.front() - 0.1; t <= times.back() + 0.1; t += 0.0071)
        QVERIFY2(std::abs(valueAt(smooth, kJaw, t) - valueAt(bezier, kJaw, t)) <= 1e-9,
                 qPrintable(QString("t = %1").arg(t)));
    }
  }

  // The handles the graph editor draws for auto keys, put into an independent Bézier
  // evaluation, reproduce the Smooth curve: they are its tangents.
  void autoHandlesAreTheSmoothTangents() {
    for (const auto& [times, values] : testCurves()) {
      const KeyframeSequence keys = curve(kJaw, times, values, Interpolation::Smooth);
      for (int k = 0; k + 1 < static_cast<int>(times.size()); ++k) {
        const auto points = controlPoints(keys, kJaw, k, k + 1);
        for (int i = 1; i < 10; ++i) {
          const double t = times[k] + (times[k + 1] - times[k]) * i / 10.0;
          const double expected = lacrima::test::bezierValueAtTime(points, t);
          QVERIFY2(std::abs(valueAt(keys, kJaw, t) - expected) <= 1e-4 * (1 + std::abs(expected)),
                   qPrintable(QString("segment %1, t = %2").arg(k).arg(t)));
        }
      }
      // The slope the handles show is the one smoothSlope reports.
      for (int k = 1; k + 1 < static_cast<int>(times.size()); ++k) {
        const EffectiveHandles h = effectiveHandles(keys, kJaw, k);
        QVERIFY(h.hasIn && h.hasOut);
        QCOMPARE(h.out.dv / h.out.dt, smoothSlope(keys, kJaw, k));
        QCOMPARE(h.in.dt, -(times[k] - times[k - 1]) / 3.0);
      }
    }
  }

  void effectiveHandlesRefuseKeysWithoutTheChannel() {
    const KeyframeSequence keys = curve(kJaw, {0.0, 1.0}, {0.0, 10.0}, Interpolation::Bezier);
    QVERIFY_THROWS_EXCEPTION(std::out_of_range, effectiveHandles(keys, kLip, 0));
    QVERIFY_THROWS_EXCEPTION(std::out_of_range, effectiveHandles(keys, kJaw, 2));
    // A key alone has no segment: both handles flat and zero long, nothing to fail on.
    const KeyframeSequence single = curve(kJaw, {0.5}, {7.0}, Interpolation::Bezier);
    const EffectiveHandles h = effectiveHandles(single, kJaw, 0);
    QVERIFY(!h.hasIn && !h.hasOut);
    QCOMPARE(h.out, Handle{});
  }

  void draggingAnAutoHandleAlignsTheOther() {
    const KeyframeSequence keys =
        curve(kJaw, {0.0, 1.0, 2.0}, {0.0, 100.0, 40.0}, Interpolation::Smooth);
    const EffectiveHandles before = effectiveHandles(keys, kJaw, 1);
    const Handle dragged{0.25, 60.0};
    const KeyChange change = moveHandle(keys, kJaw, 1.0, HandleSide::Out, dragged);
    const KeyframeSequence after = applied(keys, change);
    const KeyShape shape = after.keys()[1].shape(kJaw);
    QVERIFY(shape.handles == HandleType::Aligned);
    QCOMPARE(shape.out, dragged);
    // The in handle: same length as before, pointing exactly away from the out handle.
    QVERIFY(std::abs(std::hypot(shape.in.dt, shape.in.dv) -
                     std::hypot(before.in.dt, before.in.dv)) < 1e-9);
    QVERIFY(std::abs(shape.in.dt * dragged.dv - shape.in.dv * dragged.dt) < 1e-9);
    QVERIFY(shape.in.dt < 0 && shape.in.dv < 0);
    // The out handle acts on this key's segment, which becomes Bézier; the one before keeps
    // its interpolation (its in handle is now aligned, but it is a Smooth segment).
    QVERIFY(shape.interpolation == Interpolation::Bezier);
    QVERIFY(after.keys()[0].shape(kJaw).interpolation == Interpolation::Smooth);
    requireExactUndo(keys, change);

    // Aligned again: the in handle follows, still keeping its length.
    const double inLength = std::hypot(shape.in.dt, shape.in.dv);
    const KeyframeSequence again =
        applied(after, moveHandle(after, kJaw, 1.0, HandleSide::Out, {0.1, -30.0}));
    const KeyShape aligned = again.keys()[1].shape(kJaw);
    QVERIFY(std::abs(std::hypot(aligned.in.dt, aligned.in.dv) - inLength) < 1e-9);
    QVERIFY(std::abs(aligned.in.dt * -30.0 - aligned.in.dv * 0.1) < 1e-9);
    QVERIFY(aligned.in.dt < 0 && aligned.in.dv > 0);
  }

  void freeHandlesMoveAlone() {
    const KeyframeSequence keys =
        curve(kJaw, {0.0, 1.0, 2.0}, {0.0, 100.0, 40.0}, Interpolation::Bezier);
    const std::vector<ChannelKey> middle{{kJaw, 1.0}};
    const KeyframeSequence free =
        applied(keys, setChannelKeyShapes(keys, middle, HandleType::Free));
    const KeyShape freeShape = free.keys()[1].shape(kJaw);
    QVERIFY(freeShape.handles == HandleType::Free);
    // Switching the handle type does not move the curve.
    for (double t = 0.0; t <= 2.0; t += 0.05)
      QVERIFY(std::abs(valueAt(free, kJaw, t) - valueAt(keys, kJaw, t)) < 1e-3);
    // Dragging the in handle: the out handle stays, the previous key's segment is Bézier.
    const KeyChange change = moveHandle(free, kJaw, 1.0, HandleSide::In, {-0.2, 50.0});
    const KeyframeSequence after = applied(free, change);
    QCOMPARE(after.keys()[1].shape(kJaw).out, freeShape.out);
    QCOMPARE(after.keys()[1].shape(kJaw).in, (Handle{-0.2, 50.0}));
    requireExactUndo(free, change);
  }

  void inHandleMakesThePreviousSegmentBezier() {
    // Another channel between the keys must not count as "the previous key".
    KeyframeSequence keys = curve(kJaw, {0.0, 1.0}, {0.0, 100.0}, Interpolation::Linear);
    Keyframe other;
    other.time = 0.5;
    other.set(kLip, 10.0f);
    keys.insert(other);
    const KeyChange change = moveHandle(keys, kJaw, 1.0, HandleSide::In, {-0.3, -20.0});
    const KeyframeSequence after = applied(keys, change);
    QVERIFY(after.keys()[0].shape(kJaw).interpolation == Interpolation::Bezier);
    QVERIFY(after.keys()[2].shape(kJaw).interpolation == Interpolation::Linear);
    QVERIFY(!after.keys()[1].hasOwnShape(kLip));
    // A handle dragged across its key is stopped at the key's time.
    const KeyframeSequence crossed =
        applied(keys, moveHandle(keys, kJaw, 1.0, HandleSide::In, {0.4, 5.0}));
    QCOMPARE(crossed.keys()[2].shape(kJaw).in.dt, 0.0);
    // Nonsense is refused without a change.
    QVERIFY(moveHandle(keys, kJaw, 1.0, HandleSide::In, {NAN, 1.0}).times.empty());
    QVERIFY(moveHandle(keys, kJaw, 0.5, HandleSide::In, {-0.1, 1.0}).times.empty());
  }

  // The baked frames follow the Bézier maths: checked against de Casteljau with bisection.
  void bakedFramesFollowTheDraggedHandle() {
    const KeyframeSequence keys = curve(kJaw, {0.0, 1.0}, {0.0, 100.0}, Interpolation::Bezier);
    const KeyframeSequence after =
        applied(keys, moveHandle(keys, kJaw, 0.0, HandleSide::Out, {0.6, 250.0}));
    const FapAnimation baked = after.bake(25.0);
    // Key 1's in handle is still auto: with two keys, the Smooth slope is the secant.
    const std::array<Point2, 4> points{Point2{0.0, 0.0}, Point2{0.6, 250.0},
                                       Point2{1.0 - 1.0 / 3.0, 100.0 - 100.0 / 3.0},
                                       Point2{1.0, 100.0}};
    double largest = 0;
    for (std::size_t f = 0; f < baked.frames.size(); ++f) {
      const double expected = lacrima::test::bezierValueAtTime(points, f / 25.0);
      QVERIFY2(std::abs(baked.frames[f][channelIndex(kJaw)] - expected) < 1e-3,
               qPrintable(QString("frame %1").arg(f)));
      largest = std::max(largest, expected);
    }
    QVERIFY(largest > 100.0);  // the drag made it overshoot, as its handle says
  }

  // Handles far longer than their segment are shortened by the curve, so it stays a function
  // of time: finite everywhere and without jumps (a curve turning back in time would jump
  // from one branch to another). An absurd handle is bounded so the values stay floats.
  void handlesPastTheSegmentKeepTheCurveAFunction() {
    KeyframeSequence keys = curve(kJaw, {0.0, 0.5, 1.0}, {0.0, 100.0, 0.0}, Interpolation::Bezier);
    keys =
        applied(keys, setChannelKeyShapes(keys, std::vector<ChannelKey>{{kJaw, 0.0}, {kJaw, 0.5}},
                                          HandleType::Free));
    keys = applied(keys, moveHandle(keys, kJaw, 0.0, HandleSide::Out, {40.0, 5000.0}));
    keys = applied(keys, moveHandle(keys, kJaw, 0.5, HandleSide::In, {-1e6, -3e6}));
    keys = applied(keys, moveHandle(keys, kJaw, 0.5, HandleSide::Out, {1e-300, 1e300}));
    double previous = valueAt(keys, kJaw, 0.0);
    for (double t = 0.0; t <= 1.0; t += 1e-4) {
      const double v = valueAt(keys, kJaw, t);
      QVERIFY2(std::isfinite(v), qPrintable(QString("t = %1").arg(t)));
      if (t < 0.5)
        QVERIFY2(std::abs(v - previous) < 5.0, qPrintable(QString("jump at t = %1").arg(t)));
      previous = v;
    }
    const KeyShape vertical = keys.keys()[1].shape(kJaw);
    QVERIFY(std::isfinite(vertical.out.dv) && std::abs(vertical.out.dv) < 1e6);
  }

  void interpolationAppliesToTheChosenChannelKeysOnly() {
    KeyframeSequence keys = curve(kJaw, {0.0, 1.0, 2.0}, {0.0, 50.0, 0.0}, Interpolation::Linear);
    const KeyframeSequence lip =
        curve(kLip, {0.0, 1.0, 2.0}, {5.0, 6.0, 7.0}, Interpolation::Linear);
    for (const Keyframe& key : lip.keys()) keys.insert(key);
    const std::vector<ChannelKey> chosen{{kJaw, 1.0}, {kLip, 0.0}, {kLip, 0.7 /* no key */}};
    const KeyChange change = setChannelKeyShapes(keys, chosen, Interpolation::Constant);
    const KeyframeSequence after = applied(keys, change);
    QVERIFY(after.keys()[1].shape(kJaw).interpolation == Interpolation::Constant);
    QVERIFY(after.keys()[0].shape(kLip).interpolation == Interpolation::Constant);
    QVERIFY(after.keys()[0].shape(kJaw).interpolation == Interpolation::Linear);
    QVERIFY(after.keys()[1].shape(kLip).interpolation == Interpolation::Linear);
    QCOMPARE(valueAt(after, kJaw, 1.9), 50.0);  // held
    requireExactUndo(keys, change);
    // Back to auto forgets the handles.
    const KeyframeSequence aligned =
        applied(after, setChannelKeyShapes(after, chosen, HandleType::Aligned));
    QVERIFY(aligned.keys()[1].shape(kJaw).handles == HandleType::Aligned);
    const KeyframeSequence autoAgain =
        applied(aligned, setChannelKeyShapes(aligned, chosen, HandleType::Auto));
    QCOMPARE(autoAgain.keys(), after.keys());
  }

  void movingChannelKeys() {
    KeyframeSequence keys = curve(kJaw, {0.0, 0.2, 0.4}, {0.0, 50.0, 10.0}, Interpolation::Smooth);
    const KeyframeSequence tears =
        curve(kTearLeftFap, {0.0, 0.2}, {0.0, 30.0}, Interpolation::Linear);
    for (const Keyframe& key : tears.keys()) keys.insert(key);
    // The jaw key at 0.2 s moves two frames later (25 fps) onto nothing; the tear key with it
    // takes a fractional value, which stays a whole particle count.
    const std::vector<ChannelKeyMove> moves{{{kJaw, 0.2}, 61.25}, {{kTearLeftFap, 0.2}, 41.6}};
    const ChannelKeyMoveResult result = moveChannelKeys(keys, moves, 2, 25.0, false);
    const KeyframeSequence after = applied(keys, result.change);
    const std::vector<ChannelKey> expectedMoved{{kJaw, 0.28}, {kTearLeftFap, 0.28}};
    QCOMPARE(result.moved.size(), expectedMoved.size());
    QCOMPARE(findKey(after, 0.2), -1);  // emptied, so gone
    const int landed = findKey(after, 0.28);
    QVERIFY(landed >= 0);
    QCOMPARE(after.keys()[landed].value(kJaw), 61.25f);
    QCOMPARE(after.keys()[landed].value(kTearLeftFap), 42.0f);
    requireExactUndo(keys, result.change);

    // Ctrl: whole values. Landing on a key of the same channel replaces it.
    const KeyChange onto = moveChannelKeyTime(keys, kJaw, 0.2, 5, 25.0);
    const KeyframeSequence replaced = applied(keys, onto);
    QCOMPARE(replaced.keys().back().value(kJaw), 50.0f);
    QCOMPARE(replaced.keys().size(), std::size_t{3});
    const KeyframeSequence whole = applied(keys, moveChannelKeyValue(keys, kJaw, 0.4, 12.6, true));
    QCOMPARE(whole.keys().back().value(kJaw), 13.0f);
    // Out of range and non-finite values are kept inside the channel's limits.
    const KeyframeSequence limited =
        applied(keys, moveChannelKeyValue(keys, kTearLeftFap, 0.2, -7.0));
    QCOMPARE(limited.keys()[1].value(kTearLeftFap), 0.0f);
    const KeyframeSequence nan = applied(keys, moveChannelKeyValue(keys, kJaw, 0.2, NAN));
    QCOMPARE(nan.keys()[1].value(kJaw), 0.0f);
  }
};

QTEST_GUILESS_MAIN(CurveEditsTest)
#include "CurveEditsTest.moc"
