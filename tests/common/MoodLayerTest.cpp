// A project's procedural crying layer (MoodLayer.h): how it is stored and refused, how its take
// mixes onto the keys, that muting and seeds do what they say, and that the cache generates only
// when an input changes.
#include <lacrima/common/Diagnostics.h>
#include <lacrima/common/ProjectDocument.h>

#include <QtTest>

#include <cstring>
#include <string>

using namespace lacrima;

namespace {

constexpr int kOpenJaw = 3;
constexpr int kInnerBrowLeft = 31;

// Keys on the jaw (which the generator also moves) and a rising sadness; a layer over 1..6 s.
ProjectDocument cryingDocument() {
  ProjectDocument document;
  Keyframe first, last;
  first.time = 0;
  first.set(kOpenJaw, 100);
  last.time = 10;
  last.set(kOpenJaw, 300);
  document.keys = KeyframeSequence({first, last});
  document.moods[Mood::Sadness] =
      IntensityCurve({{1, 0.2, Interpolation::Smooth}, {3, 0.9, Interpolation::Linear}});
  document.colours.redness = IntensityCurve({{0, 0.05, Interpolation::Linear}});
  document.moodLayer = MoodLayer{7, 1.0, 6.0, false};
  return document;
}

bool sameBits(const FapValues& a, const FapValues& b) {
  return std::memcmp(a.data(), b.data(), sizeof a) == 0;
}

QString refusal(const std::string& json, ProjectDocument::Use use = ProjectDocument::Use::Edit) {
  try {
    ProjectDocument::fromJson(json, "take.lacrima", use);
  } catch (const FileError& error) {
    return QString::fromUtf8(error.what());
  }
  return QStringLiteral("(loaded)");
}

}  // namespace

class MoodLayerTest : public QObject {
  Q_OBJECT

 private slots:
  void roundTripsAndOldProjectsLoadUnchanged() {
    ProjectDocument document = cryingDocument();
    document.moodLayer->muted = true;
    document.moodLayer->seed = MoodLayer::kMaxSeed;
    const std::string json = document.toJson();
    QVERIFY(json.find("\"moodLayer\"") != std::string::npos);
    QVERIFY(ProjectDocument::fromJson(json, "a.lacrima") == document);

    ProjectDocument old = cryingDocument();
    old.moodLayer.reset();
    QVERIFY(old.toJson().find("moodLayer") == std::string::npos);
    const ProjectDocument read = ProjectDocument::fromJson(old.toJson(), "old.lacrima");
    QVERIFY(!read.moodLayer);
    QVERIFY(read == old);
  }

  void badLayersAreRefusedWithTheirPlace_data() {
    QTest::addColumn<QString>("layer");
    QTest::addColumn<QString>("expected");
    QTest::newRow("unknown") << R"({"seed": 1, "start": 0, "end": 2, "loud": true})"
                             << "moodLayer.loud: unknown field";
    QTest::newRow("fraction") << R"({"seed": 1.5, "start": 0, "end": 2})"
                              << "moodLayer.seed: expected a whole number from 0 to "
                                 "9007199254740991, got 1.5";
    QTest::newRow("huge seed") << R"({"seed": 1e17, "start": 0, "end": 2})"
                               << "moodLayer.seed: expected a whole number";
    QTest::newRow("no seed") << R"({"start": 0, "end": 2})"
                             << "missing field \"seed\"";
    QTest::newRow("backwards") << R"({"seed": 1, "start": 4, "end": 2})"
                               << "moodLayer.end: expected a time in seconds from 4 to 86400, "
                                  "got 2";
    QTest::newRow("empty") << R"({"seed": 1, "start": 4, "end": 4})"
                           << "moodLayer.end: expected a time after the start's 4 s, got 4";
    QTest::newRow("negative") << R"({"seed": 1, "start": -1, "end": 4})"
                              << "moodLayer.start: expected a time in seconds from 0";
    QTest::newRow("not an object") << "[1, 2]"
                                   << "moodLayer: expected an object {\"seed\": n";
    QTest::newRow("muted text") << R"({"seed": 1, "start": 0, "end": 2, "muted": "yes"})"
                                << "moodLayer.muted";
  }

  void badLayersAreRefusedWithTheirPlace() {
    QFETCH(QString, layer);
    QFETCH(QString, expected);
    const QString what = refusal(
        "{\"format\": \"lacrima-project\", \"version\": 2, \"keys\": [],\n"
        " \"moodLayer\": " +
        layer.toStdString() + "}\n");
    QVERIFY2(what.startsWith(QStringLiteral("take.lacrima:2:")), qPrintable(what));
    QVERIFY2(what.contains(expected), qPrintable(what));
  }

  void versionAndLengthAreBounded() {
    QString what = refusal(
        "{\"format\": \"lacrima-project\", \"version\": 1, \"keys\": [],\n"
        " \"moodLayer\": {\"seed\": 1, \"start\": 0, \"end\": 2}}");
    QVERIFY2(what.contains("take.lacrima:2:") && what.contains("version 2"), qPrintable(what));
    // A day at 1,000 fps is 86 million frames: refused to play before anything is generated;
    // the editor opens it (so that it can be shortened), and the layer adds nothing there.
    const std::string day =
        "{\"format\": \"lacrima-project\", \"version\": 2, \"fps\": 1000, \"keys\": [],\n"
        " \"moodLayer\": {\"seed\": 1, \"start\": 0,\n \"end\": 86400}}";
    what = refusal(day, ProjectDocument::Use::Bake);
    QVERIFY2(what.startsWith("take.lacrima:3:") && what.contains("moodLayer.end") &&
                 what.contains("at most 1048576 frames"),
             qPrintable(what));
    const ProjectDocument opened = ProjectDocument::fromJson(day, "take.lacrima");
    MoodLayerCache cache;
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, opened.moodTake(cache));
    QCOMPARE(cache.generations(), 0);
  }

  void theTakeIsAddedOntoTheKeysWithinItsRange() {
    const ProjectDocument document = cryingDocument();
    MoodLayerCache cache;
    const MoodTake take =
        generateMoodTake([&](double t) { return document.moods.at(1.0 + t); }, 7, 5.0, 22);
    QCOMPARE(document.moodTake(cache)->frameCount(), take.animation.frameCount());
    for (int f = 0; f < take.animation.frameCount(); f += 7) {
      const double t = 1.0 + f / 22.0;
      const FapValues expected = addMoodFrame(document.keys.evaluate(t), take.animation.frames[f],
                                              take.animation.animated);
      QVERIFY2(sameBits(document.evaluate(t, cache), expected), qPrintable(QString::number(f)));
      const KeyedColours colours = document.coloursAt(t, cache);
      QCOMPARE(*colours.redness, take.colours[f].redness);
      QCOMPARE(*colours.blush, take.colours[f].blush);
    }
    // The sadness shows: the inner brows rise over the keys' face, and tears are whole.
    const FapValues late = document.evaluate(5.5, cache);
    QVERIFY(late[channelIndex(kInnerBrowLeft)] > 0);
    QCOMPARE(late[channelIndex(kTearLeftFap)], std::round(late[channelIndex(kTearLeftFap)]));
    // Outside the range the layer adds nothing and the keyed colours are back.
    for (double t : {0.5, 6.5, 9.0}) {
      QVERIFY(sameBits(document.evaluate(t, cache), document.keys.evaluate(t)));
      QCOMPARE(float(*document.coloursAt(t, cache).redness), 0.05f);
    }
    // Baking (the player, lacrima-fap, exports) gives the very values evaluation gives.
    const FapAnimation baked = document.bake(22.0, cache);
    QCOMPARE(document.bakeRange(), std::make_pair(0.0, 10.0));
    QVERIFY(baked.animated.test(channelIndex(kInnerBrowLeft)));
    for (int f = 0; f < baked.frameCount(); f += 5)
      QVERIFY2(sameBits(baked.frames[f], document.evaluate(f / 22.0, cache)),
               qPrintable(QString::number(f)));
    // Between frames the take is read linearly.
    const FapValues a = document.evaluate(1.0 + 40 / 22.0, cache);
    const FapValues b = document.evaluate(1.0 + 41 / 22.0, cache);
    const FapValues mid = document.evaluate(1.0 + 40.5 / 22.0, cache);
    const int i = channelIndex(kInnerBrowLeft);
    QVERIFY(std::abs(mid[i] - 0.5f * (a[i] + b[i])) < 1e-3f);
    QCOMPARE(cache.generations(), 1);
  }

  void aMutedLayerAddsNothing() {
    ProjectDocument document = cryingDocument();
    document.moodLayer->muted = true;
    MoodLayerCache cache;
    QVERIFY(!document.moodTake(cache));
    for (double t : {1.0, 3.3, 5.9})
      QVERIFY(sameBits(document.evaluate(t, cache), document.keys.evaluate(t)));
    ProjectDocument without = document;
    without.moodLayer.reset();
    QCOMPARE(document.bake().frames, without.bake().frames);
    QCOMPARE(float(*document.coloursAt(3, cache).redness), 0.05f);
  }

  void theSeedPicksTheTake() {
    ProjectDocument document = cryingDocument();
    const FapAnimation first = document.bake();
    QCOMPARE(document.bake().frames, first.frames);  // the same seed, the same bits
    document.moodLayer->seed = 8;
    const FapAnimation other = document.bake();
    QCOMPARE(other.frameCount(), first.frameCount());
    QVERIFY(other.frames != first.frames);
  }

  void theCacheGeneratesOnlyWhenAnInputChanges() {
    ProjectDocument document = cryingDocument();
    MoodLayerCache cache;
    const MoodLayerTake* take = document.moodTake(cache);
    document.evaluate(2, cache);
    document.bake(30.0, cache);
    QCOMPARE(document.moodTake(cache), take);
    QCOMPARE(cache.generations(), 1);
    document.moodLayer->muted = true;  // kept while muted: unmuting is instant
    QVERIFY(!document.moodTake(cache));
    document.moodLayer->muted = false;
    QCOMPARE(document.moodTake(cache), take);
    QCOMPARE(cache.generations(), 1);
    const FapValues before = document.evaluate(4, cache);
    document.moods[Mood::Sadness] = IntensityCurve({{1, 0.2, Interpolation::Smooth}});
    QVERIFY(!sameBits(document.evaluate(4, cache), before));
    QCOMPARE(cache.generations(), 2);
    document.moodLayer->seed = 9;
    document.moodTake(cache);
    document.fps = 30;
    document.moodTake(cache);
    document.moodLayer->end = 5;
    document.moodTake(cache);
    QCOMPARE(cache.generations(), 5);
    document.moodLayer.reset();
    QVERIFY(!document.moodTake(cache));
    QVERIFY(!cache.shared());
  }

  // Ten minutes at 22 fps: 13,201 frames, held once (the frames and their colours, nothing per
  // evaluation). The figures in time are lacrima-bench's (docs/mood.md#the-mood-layer).
  void aTenMinuteLayerIsBoundedInMemory() {
    ProjectDocument document;
    document.moods[Mood::Sadness] = IntensityCurve({{0, 0.8, Interpolation::Smooth}});
    document.moodLayer = MoodLayer{3, 0, 600, false};
    MoodLayerCache cache;
    const MoodLayerTake* take = document.moodTake(cache);
    QCOMPARE(take->frameCount(), 13201);
    QCOMPARE(take->bytes(), std::size_t(13201) * (sizeof(FapValues) + sizeof(FaceColours)));
    for (int k = 0; k < 600; ++k) {
      const FapValues values = document.evaluate(k + 0.37, cache);
      for (float v : values) QVERIFY(std::isfinite(v));
    }
    QCOMPARE(cache.generations(), 1);
  }
};

QTEST_APPLESS_MAIN(MoodLayerTest)
#include "MoodLayerTest.moc"
