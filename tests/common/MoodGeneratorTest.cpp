// The crying generator's properties (docs/mood.md), measured on the channels it writes: what
// each mood does to the face, when tears come and go, sob and blink rates, ranges, seeds.
#include <lacrima/common/Diagnostics.h>
#include <lacrima/common/mood/MoodGenerator.h>

#include <QtTest>

#include <cstring>
#include <type_traits>

using namespace lacrima;

namespace {

constexpr double kFps = 22;

MoodLevels only(Mood mood, double level) {
  MoodLevels levels;
  levels[mood] = level;
  return levels;
}

MoodTake constantTake(const MoodLevels& levels, double seconds, std::uint64_t seed = 7,
                      double fps = kFps) {
  return generateMoodTake(MoodScript::constant(levels), seed, seconds, fps);
}

double channelMean(const FapAnimation& animation, std::initializer_list<int> faps, double from) {
  double sum = 0;
  int count = 0;
  for (int i = 0; i < animation.frameCount(); ++i) {
    if (i / animation.fps < from) continue;
    for (int fap : faps) sum += animation.frames[static_cast<std::size_t>(i)][channelIndex(fap)];
    count += static_cast<int>(faps.size());
  }
  return count ? sum / count : 0;
}

float value(const MoodTake& take, double seconds, int fap) {
  const auto i = static_cast<std::size_t>(std::llround(seconds * take.animation.fps));
  return take.animation.frames.at(i)[channelIndex(fap)];
}

// Rising crossings of `up` after the channel has been below `down` (hysteresis).
int risingCrossings(const FapAnimation& animation, int fap, float up, float down, double from,
                    double to) {
  int crossings = 0;
  bool low = true;
  for (int i = 0; i < animation.frameCount(); ++i) {
    const double t = i / animation.fps;
    if (t < from || t > to) continue;
    const float v = animation.frames[static_cast<std::size_t>(i)][channelIndex(fap)];
    if (low && v >= up) {
      ++crossings;
      low = false;
    } else if (!low && v <= down) {
      low = true;
    }
  }
  return crossings;
}

int peakTears(const MoodTake& take) {
  float peak = 0;
  for (const FapValues& frame : take.animation.frames)
    peak = std::max({peak, frame[channelIndex(kTearLeftFap)], frame[channelIndex(kTearRightFap)]});
  return static_cast<int>(peak);
}

}  // namespace

class MoodGeneratorTest : public QObject {
  Q_OBJECT

 private slots:
  void sadnessRaisesTheInnerBrowsAndLowersTheLipCorners() {
    const MoodTake take = constantTake(only(Mood::Sadness, 0.8), 30);
    QVERIFY(channelMean(take.animation, {31, 32}, 2) > 100);
    QVERIFY(channelMean(take.animation, {12, 13, 59, 60}, 2) < -50);
  }

  void angerSqueezesAndLowersTheBrows() {
    const MoodTake take = constantTake(only(Mood::Anger, 0.8), 30);
    QVERIFY(channelMean(take.animation, {37, 38}, 2) > 50);           // squeeze
    QVERIFY(channelMean(take.animation, {31, 32, 33, 34}, 2) < -50);  // lower
  }

  void joyRaisesTheLipCornersAndLaughs() {
    MoodGenerator generator(3);
    FapAnimation animation;
    animation.fps = kFps;
    for (int i = 0; i <= 30 * 22; ++i)
      animation.frames.push_back(generator.step(i / kFps, only(Mood::Joy, 0.8)).channels);
    QVERIFY(channelMean(animation, {12, 13, 59, 60}, 2) > 100);
    QVERIFY(generator.laughter().boutsStarted() >= 3);
    QCOMPARE(generator.sobs().cyclesStarted(), 0);  // joy does not sob
  }

  // Tears of joy still smile: once the crying form has taken over, the lip corners are no lower
  // than before the tears (the smile must not flatten into a neutral mouth), and the cheeks
  // rise higher.
  void tearsOfJoyStillSmile() {
    const MoodTake take = constantTake(only(Mood::Joy, 0.9), 30, 3);
    const auto mean = [&](std::initializer_list<int> faps, double from, double to) {
      FapAnimation part;
      part.fps = take.animation.fps;
      for (int i = 0; i < take.animation.frameCount(); ++i)
        if (i / kFps >= from && i / kFps < to)
          part.frames.push_back(take.animation.frames[static_cast<std::size_t>(i)]);
      return channelMean(part, faps, 0);
    };
    QVERIFY(value(take, 25, kTearLeftFap) > 20);  // crying by then
    const double smileBefore = mean({12, 13, 59, 60}, 2, 5);
    const double smileCrying = mean({12, 13, 59, 60}, 20, 30);
    qInfo("lip corners %.1f before the tears, %.1f with them", smileBefore, smileCrying);
    QVERIFY2(smileCrying >= smileBefore,
             qPrintable(QString("corners %1 before the tears, %2 with them")
                            .arg(smileBefore)
                            .arg(smileCrying)));
    QVERIFY(mean({41, 42}, 20, 30) > mean({41, 42}, 2, 5));
  }

  void noSobsForAngerOrJoyAtLowIntensity() {
    for (Mood mood : {Mood::Anger, Mood::Joy}) {
      MoodGenerator generator(5);
      for (int i = 0; i <= 20 * 22; ++i) generator.step(i / kFps, only(mood, 0.5));
      QCOMPARE(generator.sobs().cyclesStarted(), 0);
    }
  }

  // Sadness 0 -> 0.8 over the first second, held until 30 s, gone by 31 s.
  void tearsWellAfterAnOnsetDelayAndDryAfterTheMoodEnds() {
    const MoodScript script(
        {{0, {}}, {1, only(Mood::Sadness, 0.8)}, {30, only(Mood::Sadness, 0.8)}, {31, {}}});
    const MoodTake take = generateMoodTake(script, 11, 60, kFps);
    for (double t = 0; t < 3; t += 1 / kFps) {
      QCOMPARE(value(take, t, kTearLeftFap), 0.0f);
      QCOMPARE(value(take, t, kTearRightFap), 0.0f);
    }
    const int peak = peakTears(take);
    QVERIFY2(peak >= 60, qPrintable(QString::number(peak)));
    QVERIFY(value(take, 6, kTearLeftFap) > 0 &&
            value(take, 6, kTearLeftFap) < 0.5 * peak);   // welling
    QVERIFY(value(take, 20, kTearLeftFap) > 0.6 * peak);  // spilling
    QVERIFY(value(take, 45, kTearLeftFap) < 0.1 * peak);
    QCOMPARE(value(take, 59, kTearLeftFap) + value(take, 59, kTearRightFap), 0.0f);
    // Red eyes come after the tears and fade far slower than they do.
    QCOMPARE(take.colours.at(2 * 22).redness, 0.0);
    const double red = take.colours.at(31 * 22).redness;
    QVERIFY(red > 0.3);
    QVERIFY(take.colours.at(59 * 22).redness > 0.8 * red);
  }

  // The rate SobCycle cites: kRestRate to kFullRate cycles a minute, each cycle 0.8 to 1.25 of
  // its period. Counted on the face: every sob's inhale tips the head back (FAP 48 < 0) and its
  // exhale brings it forward again.
  void sobCyclesComeWithinTheCitedRate() {
    MoodGenerator generator(7);
    FapAnimation animation;
    animation.fps = kFps;
    int startedBefore = 0;
    for (int i = 0; i <= 62 * 22; ++i) {
      if (i == 2 * 22) startedBefore = generator.sobs().cyclesStarted();
      FapValues face = generator.step(i / kFps, only(Mood::Sadness, 0.8)).channels;
      face[channelIndex(48)] = -face[channelIndex(48)];
      animation.frames.push_back(face);
    }
    const int headSobs = risingCrossings(animation, 48, 1500, 300, 2, 62);
    QVERIFY2(headSobs >= SobCycle::kRestRate * 0.8 && headSobs <= SobCycle::kFullRate * 1.25,
             qPrintable(QString::number(headSobs)));
    const int started = generator.sobs().cyclesStarted() - startedBefore;
    QVERIFY2(std::abs(started - headSobs) <= 1,
             qPrintable(QString("%1 %2").arg(started).arg(headSobs)));
    // Deeper sadness sobs faster.
    MoodGenerator mild(7);
    for (int i = 0; i <= 62 * 22; ++i) mild.step(i / kFps, only(Mood::Sadness, 0.45));
    QVERIFY(mild.sobs().cyclesStarted() > 0);
    QVERIFY(mild.sobs().cyclesStarted() < generator.sobs().cyclesStarted());
  }

  void sobsAndBlinksFallAtTheSameTimesAtAnyFrameRate() {
    MoodGenerator slow(9), fast(9);
    for (int i = 0; i <= 40 * 22; ++i) slow.step(i / 22.0, only(Mood::Sadness, 0.9));
    for (int i = 0; i <= 40 * 60; ++i) fast.step(i / 60.0, only(Mood::Sadness, 0.9));
    QVERIFY(std::abs(slow.sobs().cyclesStarted() - fast.sobs().cyclesStarted()) <= 1);
    QVERIFY(std::abs(slow.blinks().blinks() - fast.blinks().blinks()) <= 1);
  }

  void blinksOccurAndShutTheEyes() {
    const MoodTake take = constantTake(only(Mood::Sadness, 0.8), 60);
    const int shut = risingCrossings(take.animation, 19, 900, 800, 0, 60);
    // 17 to 26 a minute, intervals 0.3 to 1.7 of the mean
    QVERIFY2(shut >= 8 && shut <= 45, qPrintable(QString::number(shut)));
    const MoodTake calm = constantTake({}, 60);
    QVERIFY(risingCrossings(calm.animation, 19, 900, 800, 0, 60) >= 8);
  }

  void sadnessAndShameLookDownAndBlushFollowsShameAndAnger() {
    const MoodTake sad = constantTake(only(Mood::Sadness, 0.8), 20);
    QVERIFY(channelMean(sad.animation, {25, 26}, 2) > 2000);
    const MoodTake ashamed = constantTake(only(Mood::Shame, 0.8), 20);
    QVERIFY(channelMean(ashamed.animation, {25, 26}, 2) > 4000);
    QVERIFY(channelMean(ashamed.animation, {48}, 2) > 1500);  // head bowed
    QVERIFY(ashamed.colours.back().blush > 0.6);
    QVERIFY(constantTake(only(Mood::Anger, 0.8), 20).colours.back().blush > 0.3);
    QCOMPARE(sad.colours.back().blush, 0.0);
    QCOMPARE(constantTake(only(Mood::Joy, 0.8), 20).colours.back().blush, 0.0);
  }

  void angryCryingAndTearsOfJoyDifferFromSadCrying() {
    const int sad = peakTears(constantTake(only(Mood::Sadness, 1), 40));
    const int angry = peakTears(constantTake(only(Mood::Anger, 1), 40));
    const int joyful = peakTears(constantTake(only(Mood::Joy, 1), 40));
    QVERIFY(angry > 0 && joyful > 0);
    QVERIFY(sad > angry && angry > joyful);
    QCOMPARE(peakTears(constantTake(only(Mood::Joy, 0.5), 40)), 0);  // no tears of mild joy
    QCOMPARE(peakTears(constantTake(only(Mood::Shame, 1), 40)), 0);
  }

  void everyChannelStaysInRangeAtIntensityOneForEveryMix() {
    for (int mix = 1; mix < (1 << kMoodCount); ++mix) {
      MoodLevels levels;
      for (int m = 0; m < kMoodCount; ++m) levels.level[m] = (mix >> m) & 1 ? 1.0 : 0.0;
      const MoodTake take = constantTake(levels, 25, 100 + mix);
      for (const FapValues& frame : take.animation.frames) {
        for (int fap = 1; fap <= kChannelCount; ++fap) {
          const ChannelRange range = generatedRange(fap);
          const float v = frame[channelIndex(fap)];
          QVERIFY2(std::isfinite(v) && v >= range.min && v <= range.max,
                   qPrintable(QString("mix %1 fap %2 value %3").arg(mix).arg(fap).arg(v)));
        }
      }
      for (const FaceColours& colours : take.colours) {
        QVERIFY(colours.redness >= 0 && colours.redness <= 1);
        QVERIFY(colours.blush >= 0 && colours.blush <= 1);
      }
    }
  }

  void wildInputStaysFiniteAndBounded() {
    MoodGenerator generator(1);
    MoodLevels wild;
    wild.level = {std::numeric_limits<double>::quiet_NaN(), 1e300, -5,
                  std::numeric_limits<double>::infinity()};
    for (double t : {0.0, 1e-9, 0.5, 0.4, 3600.0, 3600.0, 1e9, 1e9 + 1, 1e300,
                     std::numeric_limits<double>::infinity()}) {
      const MoodFrame frame = generator.step(t, wild);
      for (int fap = 1; fap <= kChannelCount; ++fap) {
        const float v = frame.channels[channelIndex(fap)];
        QVERIFY(std::isfinite(v) && v >= generatedRange(fap).min && v <= generatedRange(fap).max);
      }
      QVERIFY(std::isfinite(frame.colours.redness) && std::isfinite(frame.colours.blush));
    }
  }

  void sameSeedSameBitsOtherSeedAnotherTake() {
    const MoodScript script({{0, {}}, {2, only(Mood::Sadness, 0.9)}, {12, only(Mood::Anger, 0.6)}});
    const MoodTake a = generateMoodTake(script, 42, 20, kFps);
    const MoodTake b = generateMoodTake(script, 42, 20, kFps);
    const MoodTake c = generateMoodTake(script, 43, 20, kFps);
    QCOMPARE(a.animation.frames.size(), b.animation.frames.size());
    QVERIFY(std::memcmp(a.animation.frames.data(), b.animation.frames.data(),
                        a.animation.frames.size() * sizeof(FapValues)) == 0);
    QVERIFY(a.colours == b.colours);
    int differing = 0;
    for (std::size_t i = 0; i < a.animation.frames.size(); ++i)
      differing += a.animation.frames[i] != c.animation.frames[i];
    QVERIFY(differing > static_cast<int>(a.animation.frames.size()) / 2);
  }

  void noTwoSecondsAreTheSame() {
    const MoodTake take = constantTake(only(Mood::Sadness, 0.3), 10);
    for (int s = 0; s + 1 < 10; ++s)
      QVERIFY(take.animation.frames[static_cast<std::size_t>(s * 22)] !=
              take.animation.frames[static_cast<std::size_t>((s + 1) * 22)]);
  }

  // Ten minutes at 22 fps: exactly one frame and one colour pair per frame, allocated once, and
  // a generator that holds no heap memory of its own (whatever the length, it is the same size).
  void tenMinutesAreBoundedInMemory() {
    static_assert(std::is_trivially_copyable_v<MoodGenerator>);
    static_assert(sizeof(MoodGenerator) < 1024);
    const MoodTake take = constantTake(only(Mood::Sadness, 0.7), 600);
    QCOMPARE(take.animation.frames.size(), std::size_t{600 * 22 + 1});
    QCOMPARE(take.animation.frames.capacity(), take.animation.frames.size());
    QCOMPARE(take.colours.capacity(), take.colours.size());
    QCOMPARE(take.colours.size(), take.animation.frames.size());
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                             constantTake({}, 86400, 1, 1000));  // 86 million frames
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, constantTake({}, 10, 1, 0));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, constantTake({}, -1));
  }

  void moodLevelsParse() {
    const MoodLevels levels = parseMoodLevels("sadness=0.8,anger=0.2");
    QCOMPARE(levels[Mood::Sadness], 0.8);
    QCOMPARE(levels[Mood::Anger], 0.2);
    QCOMPARE(levels[Mood::Joy], 0.0);
    QCOMPARE(toString(levels), std::string("sadness=0.8,anger=0.2"));
    for (const char* bad : {"", "sadness", "grief=0.5", "sadness=1.5", "sadness=x",
                            "sadness=0.5,sadness=0.2", "sadness=0.5,"}) {
      try {
        parseMoodLevels(bad);
        QFAIL(bad);
      } catch (const std::invalid_argument& error) {
        QVERIFY(std::strlen(error.what()) > 10);
      }
    }
  }

  void scriptsEaseBetweenKeysAndHoldOutside() {
    const MoodScript script = MoodScript::parse(
        R"({"format": "lacrima-moods", "version": 1,
            "keys": [{"time": 1, "sadness": 0.2}, {"time": 3, "sadness": 1, "joy": 0.5}]})",
        "moods.json");
    QCOMPARE(script.at(0)[Mood::Sadness], 0.2);
    QCOMPARE(script.at(2)[Mood::Sadness], 0.6);
    QCOMPARE(script.at(2)[Mood::Joy], 0.25);
    QCOMPARE(script.at(9)[Mood::Sadness], 1.0);
    QCOMPARE(script.endTime(), 3.0);
  }

  void badScriptsNameTheLineAndWhatWasExpected() {
    const struct {
      const char* json;
      const char* expected;
    } cases[] = {
        {"{\"keys\": [{\"time\": 0, \"grief\": 1}]}", "moods.json:1:"},
        {"{\"keys\": [{\"time\": 0, \"sadness\": 1.5}]}", "expected a number in [0, 1]"},
        {"{\"keys\": [\n {\"time\": 2},\n {\"time\": 1}]}",
         "moods.json:3:3: keys[1].time: expected a time after the previous key's 2 s, got 1"},
        {"{\"keys\": []}", "expected at least one key"},
        {"{\"keys\": [{\"sadness\": 1}]}", "missing field \"time\""},
        {"{\"format\": \"lacrima-project\", \"keys\": [{\"time\": 0}]}", "lacrima-moods"},
        {"{\"keys\": [{\"time\": 0}], \"extra\": 1}", "unknown field"},
        {"{\"keys\": [{\"time\": 1e9}]}", "expected a number in [0, 86400]"},
        {"[1, 2]", "expected a JSON object"},
        {"{\"keys\": [", "invalid JSON"},
    };
    for (const auto& c : cases) {
      try {
        MoodScript::parse(c.json, "moods.json");
        QFAIL(c.json);
      } catch (const FileError& error) {
        QVERIFY2(std::string(error.what()).find(c.expected) != std::string::npos, error.what());
        QVERIFY2(std::string(error.what()).rfind("moods.json", 0) == 0, error.what());
      }
    }
    // The key count is bounded before anything is built from it.
    std::string many = "{\"keys\": [";
    for (std::size_t i = 0; i <= MoodScript::kMaxKeys; ++i)
      many += (i ? ",{\"time\":" : "{\"time\":") + std::to_string(i % 86400) + "}";
    many += "]}";
    QVERIFY_THROWS_EXCEPTION(FileError, MoodScript::parse(many, "many.json"));
  }
};

QTEST_GUILESS_MAIN(MoodGeneratorTest)
#include "MoodGeneratorTest.moc"
