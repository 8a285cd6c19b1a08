// Per-channel key shapes: constant holds, Bézier segments and their handles, and how shapes
// are stored on keys. Bézier values are checked against an independent evaluation from the
// definition (de Casteljau's construction, u found by bisection), not against the library's
// own Newton solver (tests/support/BezierReference.h).
#include "../support/BezierReference.h"
#include "../support/KeyBuilders.h"

#include <lacrima/common/Keyframes.h>

#include <QtTest>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>

using namespace lacrima;
using lacrima::test::bezierValueAtTime;
using lacrima::test::keyAt;
using lacrima::test::Point2;

namespace {

constexpr int kOpenJaw = 3;
constexpr int kRaiseBLip = 5;
constexpr int kTearsLeft = 69;
constexpr int kViseme = 1;

KeyShape freeShape(Handle in, Handle out) {
  return KeyShape{Interpolation::Bezier, HandleType::Free, in, out};
}

}  // namespace

class KeyShapesTest : public QObject {
  Q_OBJECT

 private slots:
  void namesRoundTrip() {
    for (Interpolation mode : {Interpolation::Linear, Interpolation::Smooth,
                               Interpolation::Constant, Interpolation::Bezier}) {
      QVERIFY(interpolationFromString(toString(mode)) == mode);
    }
    for (HandleType type : {HandleType::Auto, HandleType::Aligned, HandleType::Free}) {
      QVERIFY(handleTypeFromString(toString(type)) == type);
    }
    QCOMPARE(toString(Interpolation::Bezier), std::string_view("bezier"));
    QVERIFY(!handleTypeFromString("Auto").has_value());
  }

  void constantHoldsUntilTheNextKey() {
    const KeyframeSequence keys({keyAt(1.0, {{kOpenJaw, 10.0f}}, Interpolation::Constant),
                                 keyAt(2.0, {{kOpenJaw, 50.0f}})});
    QCOMPARE(keys.evaluate(1.0)[channelIndex(kOpenJaw)], 10.0f);
    QCOMPARE(keys.evaluate(1.999)[channelIndex(kOpenJaw)], 10.0f);
    QCOMPARE(keys.evaluate(2.0)[channelIndex(kOpenJaw)], 50.0f);
  }

  // Auto handles lie a third of the segment along the Smooth slope, which is the Hermite cubic.
  void autoBezierIsTheSmoothCurve() {
    std::mt19937 random(7);
    std::uniform_real_distribution<double> gap(0.02, 1.5);
    std::uniform_real_distribution<float> value(-400.0f, 400.0f);
    for (int curve = 0; curve < 20; ++curve) {
      std::vector<Keyframe> smooth, bezier;
      double t = 0.0;
      for (int k = 0; k < 7; ++k) {
        const float v = value(random);
        smooth.push_back(keyAt(t, {{kOpenJaw, v}}, Interpolation::Smooth));
        bezier.push_back(keyAt(t, {{kOpenJaw, v}}, Interpolation::Bezier));
        t += gap(random);
      }
      const KeyframeSequence a(smooth), b(bezier);
      for (double s = 0.0; s <= t; s += 0.013) {
        const double va = a.evaluate(s)[channelIndex(kOpenJaw)];
        const double vb = b.evaluate(s)[channelIndex(kOpenJaw)];
        QVERIFY2(std::abs(va - vb) <= 1e-4,
                 qPrintable(QString("t %1: %2 vs %3").arg(s).arg(va).arg(vb)));
      }
    }
  }

  void freeHandlesFollowTheBezierDefinition() {
    Keyframe a = keyAt(0.5, {{kOpenJaw, 20.0f}});
    a.setShape(kOpenJaw, freeShape({-0.1, 0.0}, {0.3, 150.0}));
    Keyframe b = keyAt(1.5, {{kOpenJaw, -40.0f}});
    b.setShape(kOpenJaw, freeShape({-0.6, 90.0}, {0.2, 0.0}));
    const KeyframeSequence keys({a, b});
    const std::array<Point2, 4> control{Point2{0.5, 20.0}, Point2{0.8, 170.0}, Point2{0.9, 50.0},
                                        Point2{1.5, -40.0}};
    const FapAnimation baked = keys.bake(22.0);
    for (std::size_t f = 0; f < baked.frames.size(); ++f) {
      const double t = 0.5 + static_cast<double>(f) / 22.0;
      const double expected = bezierValueAtTime(control, t);
      QVERIFY2(std::abs(baked.frames[f][channelIndex(kOpenJaw)] - expected) < 1e-3,
               qPrintable(QString("frame %1: %2, expected %3")
                              .arg(f)
                              .arg(baked.frames[f][channelIndex(kOpenJaw)])
                              .arg(expected)));
    }
  }

  // Handles longer than their segment would make the curve turn back in time; they are cut to
  // the segment (each), then scaled together until they just meet.
  void handlesPastTheSegmentKeepOneValuePerTime() {
    Keyframe a = keyAt(0.0, {{kOpenJaw, 0.0f}});
    a.setShape(kOpenJaw, freeShape({-1.0, 0.0}, {5.0, 500.0}));  // cut to (1, 100)
    Keyframe b = keyAt(1.0, {{kOpenJaw, 0.0f}});
    b.setShape(kOpenJaw, freeShape({-0.75, 300.0}, {0.1, 0.0}));
    const KeyframeSequence keys({a, b});
    // Cut: out (1, 100), in (-0.75, 300); together 1.75 > 1, scaled by 1/1.75.
    const double s = 1.0 / 1.75;
    const std::array<Point2, 4> control{Point2{0.0, 0.0}, Point2{s, 100.0 * s},
                                        Point2{1.0 - 0.75 * s, 300.0 * s}, Point2{1.0, 0.0}};
    for (double t = 0.0; t <= 1.0; t += 1.0 / 64.0) {
      const double v = keys.evaluate(t)[channelIndex(kOpenJaw)];
      QVERIFY(std::isfinite(v));
      QVERIFY2(std::abs(v - bezierValueAtTime(control, t)) < 1e-3, qPrintable(QString::number(t)));
    }
  }

  void degenerateSegmentsStayFinite() {
    // Zero handles (x'(0) = 0: Newton has no slope to follow), a microsecond segment, the
    // largest values and handles a file may hold.
    Keyframe a = keyAt(0.0, {{kOpenJaw, 1e7f}, {kRaiseBLip, 0.0f}});
    a.setShape(kOpenJaw, freeShape({}, {}));
    a.setShape(kRaiseBLip, freeShape({-86400.0, 2e7}, {86400.0, -2e7}));
    Keyframe b = keyAt(1e-6, {{kOpenJaw, -1e7f}, {kRaiseBLip, 1e7f}});
    b.setShape(kOpenJaw, freeShape({}, {}));
    b.setShape(kRaiseBLip, freeShape({-86400.0, 2e7}, {86400.0, -2e7}));
    Keyframe c = keyAt(5.0, {{kOpenJaw, 3.0f}, {kRaiseBLip, -1e7f}}, Interpolation::Bezier);
    const KeyframeSequence keys({a, b, c});
    for (int i = 0; i <= 1000; ++i) {
      const double t = 5.0 * i / 1000.0 + (i % 3) * 1e-7;
      const FapValues v = keys.evaluate(t);
      for (int fap : {kOpenJaw, kRaiseBLip}) {
        QVERIFY(std::isfinite(v[channelIndex(fap)]));
        // A Bézier curve stays inside the hull of its control points.
        QVERIFY(std::abs(v[channelIndex(fap)]) <= 3e7f);
      }
    }
    const FapAnimation baked = keys.bake(1000.0);
    for (const FapValues& frame : baked.frames)
      QVERIFY(std::isfinite(frame[channelIndex(kOpenJaw)]));
  }

  void eachChannelFollowsItsOwnShape() {
    Keyframe a = keyAt(0.0, {{kOpenJaw, 0.0f}, {kRaiseBLip, 0.0f}});
    a.setShape(kRaiseBLip, KeyShape{Interpolation::Constant, HandleType::Auto, {}, {}});
    const KeyframeSequence keys({a, keyAt(1.0, {{kOpenJaw, 100.0f}, {kRaiseBLip, 100.0f}})});
    const FapValues half = keys.evaluate(0.5);
    QCOMPARE(half[channelIndex(kOpenJaw)], 50.0f);   // the key's linear default
    QCOMPARE(half[channelIndex(kRaiseBLip)], 0.0f);  // its own constant
  }

  void tearChannelsStayWholeAndNonNegative() {
    Keyframe a = keyAt(0.0, {{kTearsLeft, 10.0f}});
    a.setShape(kTearsLeft, freeShape({}, {0.5, -200.0}));  // dips far below zero
    const KeyframeSequence keys({a, keyAt(1.0, {{kTearsLeft, 30.0f}})});
    for (const FapValues& frame : keys.bake(22.0).frames) {
      const float v = frame[channelIndex(kTearsLeft)];
      QVERIFY(v >= 0.0f);
      QCOMPARE(v, std::round(v));
    }
  }

  void visemeCodesNeverBlendWhateverTheShape() {
    Keyframe a = keyAt(0.0, {{kViseme, 3.0f}});
    a.setShape(kViseme, freeShape({}, {0.3, 40.0}));
    const KeyframeSequence keys({a, keyAt(1.0, {{kViseme, 7.0f}})});
    QCOMPARE(keys.evaluate(0.99)[channelIndex(kViseme)], 3.0f);
  }

  void bakeAndEvaluateAgree() {
    std::mt19937 random(11);
    std::uniform_real_distribution<double> gap(0.05, 0.8), handle(0.0, 0.6), lift(-300, 300);
    std::uniform_real_distribution<float> value(-200.0f, 200.0f);
    std::uniform_int_distribution<int> mode(0, 3), type(0, 2);
    std::vector<Keyframe> list;
    double t = 0.0;
    for (int k = 0; k < 12; ++k) {
      Keyframe key = keyAt(t, {{kOpenJaw, value(random)}, {kRaiseBLip, value(random)}});
      for (int fap : {kOpenJaw, kRaiseBLip}) {
        key.setShape(fap, KeyShape{static_cast<Interpolation>(mode(random)),
                                   static_cast<HandleType>(type(random)),
                                   {-handle(random), lift(random)},
                                   {handle(random), lift(random)}});
      }
      list.push_back(key);
      t += gap(random);
    }
    const KeyframeSequence keys(list);
    const FapAnimation baked = keys.bake(60.0);
    for (std::size_t f = 0; f < baked.frames.size(); ++f) {
      const FapValues at = keys.evaluate(static_cast<double>(f) / 60.0);
      QCOMPARE(baked.frames[f][channelIndex(kOpenJaw)], at[channelIndex(kOpenJaw)]);
      QCOMPARE(baked.frames[f][channelIndex(kRaiseBLip)], at[channelIndex(kRaiseBLip)]);
    }
  }

  void shapesEqualToTheKeysDefaultAreNotStored() {
    Keyframe key = keyAt(0.0, {{kOpenJaw, 1.0f}}, Interpolation::Smooth);
    key.setShape(kOpenJaw, KeyShape{Interpolation::Smooth, HandleType::Auto, {}, {}});
    QVERIFY(key.ownShapes().empty());
    // Auto handles store no offsets, so they compare by type alone.
    key.setShape(kOpenJaw, KeyShape{Interpolation::Bezier, HandleType::Auto, {-1, 2}, {3, 4}});
    QCOMPARE(key.shape(kOpenJaw).in, Handle{});
    QCOMPARE(key.ownShapes().size(), std::size_t{1});
    key.clear(kOpenJaw);
    QVERIFY(key.ownShapes().empty());
  }

  void changingTheKeysModeResetsEveryChannelsModeButKeepsHandles() {
    Keyframe key = keyAt(0.0, {{kOpenJaw, 1.0f}, {kRaiseBLip, 2.0f}});
    key.setShape(kOpenJaw, freeShape({-0.1, 1.0}, {0.1, 1.0}));
    key.setShape(kRaiseBLip, KeyShape{Interpolation::Constant, HandleType::Auto, {}, {}});
    key.setInterpolationOfAll(Interpolation::Smooth);
    QVERIFY(key.shape(kRaiseBLip).interpolation == Interpolation::Smooth);
    QVERIFY(key.shape(kOpenJaw).interpolation == Interpolation::Smooth);
    QCOMPARE(key.shape(kOpenJaw).out, (Handle{0.1, 1.0}));
    QCOMPARE(key.ownShapes().size(), std::size_t{1});  // only the free handles remain its own
  }

  void takeChannelMovesValueAndShape() {
    Keyframe from = keyAt(1.0, {{kOpenJaw, 42.0f}}, Interpolation::Smooth);
    from.setShape(kOpenJaw, freeShape({-0.2, 3.0}, {0.4, -1.0}));
    Keyframe to = keyAt(2.0, {{kRaiseBLip, 5.0f}});
    to.takeChannel(from, kOpenJaw);
    QCOMPARE(to.value(kOpenJaw), 42.0f);
    QVERIFY(to.shape(kOpenJaw) == from.shape(kOpenJaw));
    QVERIFY(to.shape(kRaiseBLip).interpolation == Interpolation::Linear);
    to.takeChannel(keyAt(0.0, {}), kOpenJaw);  // a key without the channel removes it
    QVERIFY(!to.has(kOpenJaw));
    QVERIFY(to.ownShapes().empty());
  }

  void equalityComparesEffectiveShapes() {
    Keyframe a = keyAt(0.0, {{kOpenJaw, 1.0f}});
    Keyframe b = a;
    b.setShape(kOpenJaw, KeyShape{Interpolation::Constant, HandleType::Auto, {}, {}});
    QVERIFY(!(a == b));
    b.setShape(kOpenJaw, a.shape(kOpenJaw));
    QVERIFY(a == b);
  }

  // Keying one more channel into an existing key: a channel with its own shape brings it, one
  // without takes the existing key's default (so it cannot reshape its neighbours' curves).
  void insertingIntoAKeyKeepsItsDefault() {
    KeyframeSequence keys({keyAt(1.0, {{kRaiseBLip, 1.0f}}, Interpolation::Smooth)});
    keys.insert(keyAt(1.0, {{kOpenJaw, 9.0f}}, Interpolation::Linear));
    const Keyframe& merged = keys.keys().front();
    QVERIFY(merged.interpolation == Interpolation::Smooth);
    QVERIFY(merged.shape(kOpenJaw).interpolation == Interpolation::Smooth);
    Keyframe shaped = keyAt(1.0, {{kTearsLeft, 4.0f}});
    shaped.setShape(kTearsLeft, KeyShape{Interpolation::Constant, HandleType::Auto, {}, {}});
    keys.insert(shaped);
    QVERIFY(keys.keys().front().shape(kTearsLeft).interpolation == Interpolation::Constant);
  }
};

QTEST_GUILESS_MAIN(KeyShapesTest)
#include "KeyShapesTest.moc"
