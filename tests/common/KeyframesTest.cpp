// Keyframe interpolation and baking: the maths of Keyframes.h, checked by value.
#include "../support/KeyBuilders.h"
#include "../support/WorstCaseInputs.h"

#include <lacrima/common/Keyframes.h>

#include <QtTest>

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

using namespace lacrima;
using lacrima::test::keyAt;

namespace {

constexpr int kOpenJaw = 3;
constexpr int kRaiseBLip = 5;  // stands in for "some other low-level channel"

// Keys on one channel at increasing random times with random values.
std::vector<Keyframe> randomCurve(std::mt19937& random, int fap, int count, Interpolation mode) {
  std::uniform_real_distribution<double> gap(0.01, 2.0);
  std::uniform_real_distribution<float> value(-500.0f, 500.0f);
  std::vector<Keyframe> keys;
  double time = gap(random);
  for (int i = 0; i < count; ++i) {
    keys.push_back(keyAt(time, {{fap, value(random)}}, mode));
    time += gap(random);
  }
  return keys;
}

// The two keys (of those setting `fap`) around t; t must lie within the keyed range.
std::pair<float, float> boundsAround(const std::vector<Keyframe>& keys, int fap, double t) {
  const Keyframe* before = nullptr;
  const Keyframe* after = nullptr;
  for (const Keyframe& key : keys) {
    if (!key.has(fap)) continue;
    if (key.time <= t) before = &key;
    if (key.time >= t && !after) after = &key;
  }
  const float a = before ? before->value(fap) : after->value(fap);
  const float b = after ? after->value(fap) : before->value(fap);
  return {std::min(a, b), std::max(a, b)};
}

}  // namespace

class KeyframesTest : public QObject {
  Q_OBJECT

 private slots:
  void interpolationNamesRoundTrip() {
    QCOMPARE(toString(Interpolation::Linear), std::string_view("linear"));
    QCOMPARE(toString(Interpolation::Smooth), std::string_view("smooth"));
    QVERIFY(interpolationFromString("linear") == Interpolation::Linear);
    QVERIFY(interpolationFromString("smooth") == Interpolation::Smooth);
    QVERIFY(!interpolationFromString("Linear").has_value());
    QVERIFY(!interpolationFromString("").has_value());
  }

  void keyEqualityComparesOnlySetChannels() {
    Keyframe a = keyAt(1.0, {{kOpenJaw, 10.0f}});
    Keyframe b = a;
    b.values[channelIndex(kRaiseBLip)] = 99.0f;  // not set, so not compared
    QVERIFY(a == b);
    b.set(kRaiseBLip, 99.0f);
    QVERIFY(!(a == b));
    Keyframe c = a;
    c.interpolation = Interpolation::Smooth;
    QVERIFY(!(a == c));
    Keyframe d = a;
    d.time = 1.5;
    QVERIFY(!(a == d));
    Keyframe e = a;
    e.set(kOpenJaw, 11.0f);
    QVERIFY(!(a == e));
    e.clear(kOpenJaw);
    QVERIFY(!e.has(kOpenJaw));
    QCOMPARE(e.value(kOpenJaw), 0.0f);
  }

  void linearIsExactAtKeysAndMidpoints() {
    const KeyframeSequence keys({keyAt(0.0, {{kOpenJaw, 0.0f}}), keyAt(2.0, {{kOpenJaw, 100.0f}}),
                                 keyAt(3.0, {{kOpenJaw, -50.0f}})});
    QCOMPARE(keys.evaluate(0.0)[channelIndex(kOpenJaw)], 0.0f);
    QCOMPARE(keys.evaluate(2.0)[channelIndex(kOpenJaw)], 100.0f);
    QCOMPARE(keys.evaluate(3.0)[channelIndex(kOpenJaw)], -50.0f);
    QCOMPARE(keys.evaluate(1.0)[channelIndex(kOpenJaw)], 50.0f);
    QCOMPARE(keys.evaluate(0.5)[channelIndex(kOpenJaw)], 25.0f);
    QCOMPARE(keys.evaluate(2.5)[channelIndex(kOpenJaw)], 25.0f);
  }

  void bakeGivesFloorPlusOneFramesLinearlyInterpolated() {
    const float v0 = 12.0f;
    const float v1 = -310.0f;
    const KeyframeSequence keys({keyAt(0.0, {{kOpenJaw, v0}}), keyAt(1.0, {{kOpenJaw, v1}})});
    const FapAnimation baked = keys.bake(22.0);
    QCOMPARE(baked.frameCount(), 23);
    QCOMPARE(baked.fps, 22.0);
    QVERIFY(baked.animated.test(channelIndex(kOpenJaw)));
    QCOMPARE(baked.animated.count(), std::size_t{1});
    QVERIFY(baked.highLevel.empty());
    for (int i = 0; i < baked.frameCount(); ++i) {
      const float expected = static_cast<float>(v0 + (v1 - v0) * i / 22.0);
      QCOMPARE(baked.frames[i][channelIndex(kOpenJaw)], expected);
    }
    QCOMPARE(baked.frames.front()[channelIndex(kOpenJaw)], v0);
    QCOMPARE(baked.frames.back()[channelIndex(kOpenJaw)], v1);
  }

  void bakeStartsAtTheFirstKey() {
    // Keys from 0.5 s to 1.5 s at 10 fps: 11 frames, frame i at 0.5 + i / 10.
    const KeyframeSequence keys({keyAt(0.5, {{kOpenJaw, 0.0f}}), keyAt(1.5, {{kOpenJaw, 10.0f}})});
    const FapAnimation baked = keys.bake(10.0);
    QCOMPARE(baked.frameCount(), 11);
    for (int i = 0; i < baked.frameCount(); ++i) {
      QCOMPARE(baked.frames[i][channelIndex(kOpenJaw)], static_cast<float>(i));
    }
  }

  void channelsSetOnlyBySomeKeysInterpolateAcrossOthers() {
    // open_jaw is keyed at 0 s and 2 s only; the key at 1 s sets another channel.
    const KeyframeSequence keys({keyAt(0.0, {{kOpenJaw, 0.0f}, {kRaiseBLip, 5.0f}}),
                                 keyAt(1.0, {{kRaiseBLip, 7.0f}}),
                                 keyAt(2.0, {{kOpenJaw, 200.0f}})});
    QCOMPARE(keys.evaluate(1.0)[channelIndex(kOpenJaw)], 100.0f);
    QCOMPARE(keys.evaluate(1.5)[channelIndex(kOpenJaw)], 150.0f);
    QCOMPARE(keys.evaluate(0.5)[channelIndex(kRaiseBLip)], 6.0f);
    QCOMPARE(keys.evaluate(2.0)[channelIndex(kRaiseBLip)], 7.0f);  // held after its last key
    const FapAnimation baked = keys.bake(4.0);
    QCOMPARE(baked.frameCount(), 9);
    QCOMPARE(baked.frames[4][channelIndex(kOpenJaw)], 100.0f);
    QCOMPARE(baked.frames[6][channelIndex(kOpenJaw)], 150.0f);
    QCOMPARE(baked.frames[8][channelIndex(kRaiseBLip)], 7.0f);
  }

  void holdsBeforeTheFirstAndAfterTheLastKey() {
    const KeyframeSequence keys({keyAt(1.0, {{kOpenJaw, 40.0f}}, Interpolation::Smooth),
                                 keyAt(2.0, {{kOpenJaw, 80.0f}}, Interpolation::Smooth)});
    QCOMPARE(keys.evaluate(-100.0)[channelIndex(kOpenJaw)], 40.0f);
    QCOMPARE(keys.evaluate(0.999)[channelIndex(kOpenJaw)], 40.0f);
    QCOMPARE(keys.evaluate(2.001)[channelIndex(kOpenJaw)], 80.0f);
    QCOMPARE(keys.evaluate(1e9)[channelIndex(kOpenJaw)], 80.0f);
    QCOMPARE(keys.evaluate(INFINITY)[channelIndex(kOpenJaw)], 80.0f);
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, keys.evaluate(NAN));

    // A channel keyed later than the sequence starts holds its first value until then.
    const KeyframeSequence late({keyAt(0.0, {{kRaiseBLip, 1.0f}}), keyAt(1.0, {{kOpenJaw, 9.0f}}),
                                 keyAt(2.0, {{kOpenJaw, 19.0f}})});
    const FapAnimation baked = late.bake(2.0);
    QCOMPARE(baked.frameCount(), 5);
    QCOMPARE(baked.frames[0][channelIndex(kOpenJaw)], 9.0f);
    QCOMPARE(baked.frames[1][channelIndex(kOpenJaw)], 9.0f);
    QCOMPARE(baked.frames[3][channelIndex(kOpenJaw)], 14.0f);
  }

  void unsetChannelsStayZero() {
    const KeyframeSequence keys({keyAt(0.0, {{kOpenJaw, 3.0f}}), keyAt(1.0, {{kOpenJaw, 8.0f}})});
    const FapAnimation baked = keys.bake(22.0);
    for (const FapValues& frame : baked.frames) {
      for (int fap = 1; fap <= kChannelCount; ++fap) {
        if (fap != kOpenJaw) QCOMPARE(frame[channelIndex(fap)], 0.0f);
      }
    }
    const FapValues value = keys.evaluate(0.3);
    for (int fap = 1; fap <= kChannelCount; ++fap) {
      if (fap != kOpenJaw) QCOMPARE(value[channelIndex(fap)], 0.0f);
    }
    QCOMPARE(KeyframeSequence().evaluate(1.0), FapValues{});
  }

  void smoothIsExactAtKeys() {
    std::mt19937 random(7);
    const std::vector<Keyframe> list = randomCurve(random, kOpenJaw, 12, Interpolation::Smooth);
    const KeyframeSequence keys(list);
    for (const Keyframe& key : list) {
      QCOMPARE(keys.evaluate(key.time)[channelIndex(kOpenJaw)], key.value(kOpenJaw));
    }
  }

  void smoothOfMonotoneDataIsMonotone() {
    std::mt19937 random(11);
    std::uniform_real_distribution<double> gap(0.05, 1.5);
    std::uniform_real_distribution<float> rise(0.0f, 100.0f);
    for (int seed = 0; seed < 20; ++seed) {
      std::vector<Keyframe> list;
      double time = 0.0;
      float value = -1000.0f;
      for (int i = 0; i < 10; ++i) {
        // Include flat stretches: a repeated value must stay exactly flat.
        value += (i % 4 == 2) ? 0.0f : rise(random);
        list.push_back(keyAt(time, {{kOpenJaw, value}}, Interpolation::Smooth));
        time += gap(random);
      }
      const FapAnimation baked = KeyframeSequence(list).bake(200.0);
      for (int f = 1; f < baked.frameCount(); ++f) {
        QVERIFY2(
            baked.frames[f][channelIndex(kOpenJaw)] >= baked.frames[f - 1][channelIndex(kOpenJaw)],
            qPrintable(QString("seed %1 frame %2").arg(seed).arg(f)));
      }
    }
  }

  void smoothNeverLeavesTheRangeOfItsKeys() {
    for (unsigned seed = 1; seed <= 200; ++seed) {
      std::mt19937 random(seed);
      std::vector<Keyframe> list = randomCurve(random, kOpenJaw, 8, Interpolation::Smooth);
      // A second channel keyed on a random subset, so windows skip keys that don't set it.
      std::bernoulli_distribution coin(0.6);
      std::uniform_real_distribution<float> value(0.0f, 1.0f);
      for (Keyframe& key : list) {
        if (coin(random)) key.set(kRaiseBLip, value(random));
      }
      const KeyframeSequence keys(list);
      const double start = keys.startTime();
      const double end = keys.endTime();
      for (int i = 0; i <= 2000; ++i) {
        const double t = start + (end - start) * i / 2000.0;
        const FapValues values = keys.evaluate(t);
        for (int fap : {kOpenJaw, kRaiseBLip}) {
          if (std::none_of(list.begin(), list.end(),
                           [&](const Keyframe& k) { return k.has(fap); })) {
            continue;
          }
          const auto [low, high] = boundsAround(list, fap, t);
          const float v = values[channelIndex(fap)];
          QVERIFY2(v >= low && v <= high,
                   qPrintable(QString("seed %1 fap %2 t %3: %4 outside [%5, %6]")
                                  .arg(seed)
                                  .arg(fap)
                                  .arg(t)
                                  .arg(v)
                                  .arg(low)
                                  .arg(high)));
        }
      }
    }
  }

  void bakeAgreesWithEvaluate() {
    std::mt19937 random(5);
    std::vector<Keyframe> list = randomCurve(random, kOpenJaw, 30, Interpolation::Smooth);
    std::bernoulli_distribution coin(0.5);
    for (Keyframe& key : list) {
      if (coin(random)) key.interpolation = Interpolation::Linear;
      if (coin(random)) key.set(kRaiseBLip, static_cast<float>(key.time * 3.0));
    }
    const KeyframeSequence keys(list);
    const FapAnimation baked = keys.bake(30.0);
    for (int f = 0; f < baked.frameCount(); ++f) {
      QVERIFY2(baked.frames[f] == keys.evaluate(keys.startTime() + f / 30.0),
               qPrintable(QString("frame %1").arg(f)));
    }
  }

  void modesAreChosenPerKey() {
    // 0 s linear -> 1 s smooth -> 2 s. The first segment is a straight line; the second is
    // a Hermite cubic with slope 0 at the peak (Steffen) and, at the end, the one-sided
    // slope -20 (parabola through the three keys, within twice the secant).
    const KeyframeSequence keys({keyAt(0.0, {{kOpenJaw, 0.0f}}, Interpolation::Linear),
                                 keyAt(1.0, {{kOpenJaw, 10.0f}}, Interpolation::Smooth),
                                 keyAt(2.0, {{kOpenJaw, 0.0f}}, Interpolation::Linear)});
    QCOMPARE(keys.evaluate(0.5)[channelIndex(kOpenJaw)], 5.0f);
    QCOMPARE(keys.evaluate(0.25)[channelIndex(kOpenJaw)], 2.5f);
    QCOMPARE(keys.evaluate(1.5)[channelIndex(kOpenJaw)], 7.5f);
    // Same keys, all linear: the second segment is straight.
    KeyframeSequence straight = keys;
    Keyframe middle = straight.keys()[1];
    middle.interpolation = Interpolation::Linear;
    straight.remove(1);
    straight.insert(middle);
    QCOMPARE(straight.evaluate(1.5)[channelIndex(kOpenJaw)], 5.0f);
  }

  void tearChannelsAreWholeAndNonNegative() {
    const KeyframeSequence keys(
        {keyAt(0.0, {{kTearLeftFap, 0.0f}}), keyAt(1.0, {{kTearLeftFap, 5.0f}})});
    const FapAnimation baked = keys.bake(22.0);
    QCOMPARE(baked.frameCount(), 23);
    for (int i = 0; i < baked.frameCount(); ++i) {
      const float v = baked.frames[i][channelIndex(kTearLeftFap)];
      QCOMPARE(v, std::round(5.0f * i / 22.0f));
      QVERIFY(v >= 0.0f);
    }
    QCOMPARE(baked.frames[11][channelIndex(kTearLeftFap)], 3.0f);  // 2.5 rounds to 3
    QCOMPARE(baked.frames.back()[channelIndex(kTearLeftFap)], 5.0f);

    // Smooth tears over a peak stay whole and never negative, whatever the random data.
    for (unsigned seed = 1; seed <= 20; ++seed) {
      std::mt19937 random(seed);
      std::uniform_int_distribution<int> count(0, 40);
      std::vector<Keyframe> list;
      for (int i = 0; i < 8; ++i) {
        list.push_back(keyAt(i * 0.37, {{kTearRightFap, static_cast<float>(count(random))}},
                             Interpolation::Smooth));
      }
      const FapAnimation smooth = KeyframeSequence(list).bake(60.0);
      for (const FapValues& frame : smooth.frames) {
        const float v = frame[channelIndex(kTearRightFap)];
        QVERIFY(v >= 0.0f);
        QCOMPARE(v, std::round(v));
      }
    }
  }

  void highLevelCodesHoldAndFillHighLevelFrames() {
    const KeyframeSequence keys({keyAt(0.0, {{1, 3.0f}}), keyAt(1.0, {{1, 7.0f}})});
    const FapAnimation baked = keys.bake(4.0);
    QCOMPARE(baked.frameCount(), 5);
    QCOMPARE(baked.highLevel.size(), std::size_t{5});
    for (int i = 0; i < 4; ++i) {
      QCOMPARE(baked.frames[i][channelIndex(1)], 3.0f);
      QCOMPARE(baked.highLevel[i].viseme.select1, 3);
      QCOMPARE(baked.highLevel[i].viseme.blend, 63);
    }
    QCOMPARE(baked.frames[4][channelIndex(1)], 7.0f);
    QCOMPARE(baked.highLevel[4].viseme.select1, 7);
  }

  void insertMergesKeysAtTheSameTime() {
    KeyframeSequence keys;
    QCOMPARE(keys.insert(keyAt(1.0, {{kOpenJaw, 10.0f}}, Interpolation::Smooth)), 0);
    QCOMPARE(keys.insert(keyAt(0.0, {{kOpenJaw, 0.0f}})), 0);
    QCOMPARE(keys.insert(keyAt(2.0, {{kOpenJaw, 20.0f}})), 2);
    // Within 1e-9 s of the key at 1 s: merged into it, keeping its time and mode.
    QCOMPARE(keys.insert(keyAt(1.0 + 5e-10, {{kRaiseBLip, 4.0f}, {kOpenJaw, 11.0f}})), 1);
    QCOMPARE(keys.keys().size(), std::size_t{3});
    const Keyframe& merged = keys.keys()[1];
    QCOMPARE(merged.time, 1.0);
    QVERIFY(merged.interpolation == Interpolation::Smooth);
    QCOMPARE(merged.value(kOpenJaw), 11.0f);
    QCOMPARE(merged.value(kRaiseBLip), 4.0f);
    QCOMPARE(merged.channels.count(), std::size_t{2});
    // 2e-9 s away is a different key.
    QCOMPARE(keys.insert(keyAt(1.0 + 2e-9, {{kOpenJaw, 1.0f}})), 2);
    QCOMPARE(keys.keys().size(), std::size_t{4});
    QCOMPARE(keys.startTime(), 0.0);
    QCOMPARE(keys.endTime(), 2.0);
    keys.remove(0);
    QCOMPARE(keys.startTime(), 1.0);
    QVERIFY_THROWS_EXCEPTION(std::out_of_range, keys.remove(3));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, keys.insert(keyAt(NAN, {})));
  }

  void constructorSortsAndTheLastDuplicateWins() {
    const KeyframeSequence keys({keyAt(2.0, {{kOpenJaw, 2.0f}}), keyAt(0.0, {{kOpenJaw, 0.0f}}),
                                 keyAt(2.0, {{kRaiseBLip, 9.0f}}), keyAt(1.0, {{kOpenJaw, 1.0f}})});
    QCOMPARE(keys.keys().size(), std::size_t{3});
    QCOMPARE(keys.keys()[0].time, 0.0);
    QCOMPARE(keys.keys()[1].time, 1.0);
    QCOMPARE(keys.keys()[2].time, 2.0);
    QVERIFY(keys.keys()[2].has(kRaiseBLip));
    QVERIFY(!keys.keys()[2].has(kOpenJaw));
    QVERIFY(KeyframeSequence().empty());
    QCOMPARE(KeyframeSequence().startTime(), 0.0);
    QCOMPARE(KeyframeSequence().endTime(), 0.0);
  }

  void fromAnimationThenBakeReproducesTheFrames() {
    std::mt19937 random(3);
    std::uniform_real_distribution<float> value(-800.0f, 800.0f);
    std::uniform_int_distribution<int> tears(0, 300);
    FapAnimation animation;
    animation.fps = 25.0;
    animation.animated.set(channelIndex(kOpenJaw));
    animation.animated.set(channelIndex(kRaiseBLip));
    animation.animated.set(channelIndex(kTearLeftFap));
    animation.frames.resize(500);
    for (FapValues& frame : animation.frames) {
      frame[channelIndex(kOpenJaw)] = value(random);
      frame[channelIndex(kRaiseBLip)] = value(random);
      frame[channelIndex(kTearLeftFap)] = static_cast<float>(tears(random));
    }
    for (Interpolation mode : {Interpolation::Linear, Interpolation::Smooth}) {
      const KeyframeSequence keys = KeyframeSequence::fromAnimation(animation, mode);
      QCOMPARE(keys.keys().size(), animation.frames.size());
      QVERIFY(keys.keys()[1].interpolation == mode);
      const FapAnimation baked = keys.bake(animation.fps);
      QCOMPARE(baked.frameCount(), animation.frameCount());
      QCOMPARE(baked.animated, animation.animated);
      QVERIFY(baked.frames == animation.frames);
    }

    // Without an `animated` mask, the channels that are non-zero somewhere become keys.
    FapAnimation unmasked = animation;
    unmasked.animated.reset();
    unmasked.frames[0][channelIndex(10)] = 0.0f;
    unmasked.frames[7][channelIndex(10)] = 2.0f;
    const KeyframeSequence keys = KeyframeSequence::fromAnimation(unmasked);
    QCOMPARE(keys.keys()[0].channels.count(), std::size_t{4});
    QVERIFY(keys.keys()[0].has(10));
    QVERIFY(keys.bake(unmasked.fps).frames == unmasked.frames);

    QVERIFY(KeyframeSequence::fromAnimation(FapAnimation{}).empty());
  }

  void invalidFpsThrows() {
    const KeyframeSequence keys({keyAt(0.0, {{kOpenJaw, 1.0f}})});
    for (double fps : {0.0, -22.0, double(NAN), double(INFINITY)}) {
      QVERIFY_THROWS_EXCEPTION(std::invalid_argument, keys.bake(fps));
      QVERIFY_THROWS_EXCEPTION(std::invalid_argument, KeyframeSequence().bake(fps));
      FapAnimation animation;
      animation.fps = fps;
      QVERIFY_THROWS_EXCEPTION(std::invalid_argument, KeyframeSequence::fromAnimation(animation));
    }
    // Absurd lengths are refused instead of exhausting memory.
    const KeyframeSequence huge({keyAt(0.0, {{kOpenJaw, 1.0f}}), keyAt(1e9, {{kOpenJaw, 1.0f}})});
    QVERIFY_THROWS_EXCEPTION(std::length_error, huge.bake(1000.0));
    // One frame past the limit is refused; a count beyond every integer type is reported
    // as it is (it once went through a long long cast: undefined, printed negative).
    const double limitSeconds = (kMaxBakedFrames - 1) / 100.0;
    QCOMPARE(
        KeyframeSequence({keyAt(0.0, {{kOpenJaw, 1.0f}}), keyAt(limitSeconds, {{kOpenJaw, 2.0f}})})
            .bake(100.0)
            .frames.size(),
        static_cast<std::size_t>(kMaxBakedFrames));
    QVERIFY_THROWS_EXCEPTION(std::length_error,
                             KeyframeSequence({keyAt(0.0, {{kOpenJaw, 1.0f}}),
                                               keyAt(limitSeconds + 0.01, {{kOpenJaw, 2.0f}})})
                                 .bake(100.0));
    try {
      KeyframeSequence({keyAt(0.0, {{kOpenJaw, 1.0f}}), keyAt(6e66, {{kOpenJaw, 1.0f}})})
          .bake(1000.0);
      QFAIL("a bake of 6e69 frames was accepted");
    } catch (const std::length_error& e) {
      QVERIFY2(QByteArray(e.what()).startsWith("bake: 6e+69 frames exceed the limit of 1048576"),
               e.what());
    }
  }

  void bakeOfEmptyOrSingleKey() {
    const FapAnimation empty = KeyframeSequence().bake(30.0);
    QCOMPARE(empty.frameCount(), 0);
    QCOMPARE(empty.fps, 30.0);
    QVERIFY(empty.animated.none());
    const FapAnimation single = KeyframeSequence({keyAt(4.0, {{kOpenJaw, 6.0f}})}).bake(22.0);
    QCOMPARE(single.frameCount(), 1);
    QCOMPARE(single.frames[0][channelIndex(kOpenJaw)], 6.0f);
  }

  // Ten minutes of keys (one per frame at 22 fps) bake to one frame per key, each the
  // sequence's value at that frame's time. How long it takes is a figure of
  // `lacrima-bench worst-cases`.
  void bakesTenMinutesOfKeys() {
    const KeyframeSequence keys = test::tenMinutesOfKeys();
    const FapAnimation baked = keys.bake(22.0);
    QCOMPARE(baked.frameCount(), 13200);
    for (const int frame : {0, 1, 4321, 6605, 13199}) {
      const FapValues expected = keys.evaluate(frame / 22.0);
      for (const int fap : test::kTenMinutesChannels) {
        const float value = baked.frames[static_cast<std::size_t>(frame)][channelIndex(fap)];
        QVERIFY2(std::abs(value - expected[channelIndex(fap)]) <= 1e-3f,
                 qPrintable(QString("frame %1, FAP %2: %3").arg(frame).arg(fap).arg(value)));
      }
    }
  }
};

QTEST_GUILESS_MAIN(KeyframesTest)
#include "KeyframesTest.moc"
