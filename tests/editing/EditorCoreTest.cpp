// The editor's core without windows: exact undo/redo, merging slider drags, mirroring and
// symmetric edits, presets files and their errors, key reduction, FAP import/export round
// trips, the channel filter, the clipboard and the recovery store.
#include "../support/MissingData.h"

#include <lacrima/common/FapReader.h>
#include <lacrima/common/FapTable.h>
#include <lacrima/common/FapWriter.h>
#include <lacrima/editing/ChannelFilter.h>
#include <lacrima/editing/EditorModel.h>
#include <lacrima/editing/FapTransfer.h>
#include <lacrima/editing/FrameStepClock.h>
#include <lacrima/editing/KeyClipboard.h>
#include <lacrima/editing/KeyReduction.h>
#include <lacrima/editing/Mirror.h>
#include <lacrima/editing/PresetLibrary.h>
#include <lacrima/editing/RecoveryStore.h>

#include <QDir>
#include <QFile>
#include <QMimeData>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>
#include <random>

using namespace lacrima;
using namespace lacrima::editing;

namespace {

QString sharedSample(const char* relative) {
  return testsupport::sharedPath(QStringLiteral("mpeg4/samples/") + QLatin1String(relative));
}

// A dense animation with smooth motion, steps, a held stretch and tears: the kinds of
// curves imported files hold.
FapAnimation syntheticAnimation(int frames, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> phase(0.0, 6.28);
  FapAnimation a;
  a.name = "synthetic";
  a.fps = 22;
  a.frames.assign(static_cast<std::size_t>(frames), FapValues{});
  const int channels[] = {3, 6, 7, 19, 20, 31, 32, 48, 53, 69, 70};
  for (int fap : channels) {
    a.animated.set(channelIndex(fap));
    const double p = phase(random);
    for (int i = 0; i < frames; ++i) {
      const double t = i / a.fps;
      double v = 0;
      if (fap == 69 || fap == 70)
        v = std::max(0.0, std::round(60 * std::sin(0.7 * t + p)));
      else if (fap == 48)
        v = i < frames / 2 ? 0 : 1500;  // a step
      else if (fap == 19 || fap == 20)
        v = std::round(300 * std::max(0.0, std::sin(2.1 * t + p)));
      else
        v = std::round(200 * std::sin(1.3 * t + p) + 40 * std::sin(5.1 * t));
      a.frames[static_cast<std::size_t>(i)][static_cast<std::size_t>(channelIndex(fap))] =
          static_cast<float>(v);
    }
  }
  return a;
}

std::string writeTemp(const QTemporaryDir& dir, const QString& name, const std::string& text) {
  const QString path = dir.filePath(name);
  QFile file(path);
  if (!file.open(QIODevice::WriteOnly)) qFatal("cannot write %s", qPrintable(path));
  file.write(text.data(), static_cast<qint64>(text.size()));
  return path.toStdString();
}

}  // namespace

class EditorCoreTest : public QObject {
  Q_OBJECT

 private slots:
  void initTestCase() { QStandardPaths::setTestModeEnabled(true); }

  // --- undo / redo ------------------------------------------------------------------------

  void undoAndRedoRestoreEveryStateExactly() {
    editing::EditorModel model;
    const editing::PresetLibrary presets = editing::PresetLibrary::builtIn();
    std::mt19937 random(20240517);
    std::uniform_int_distribution<int> op(0, 10);
    std::uniform_int_distribution<int> frame(0, 60);
    std::uniform_int_distribution<int> fap(3, 70);
    std::uniform_real_distribution<double> value(-300, 300);
    std::vector<ProjectDocument> states{model.document()};
    for (int step = 0; step < 300; ++step) {
      model.setCurrentTime(frame(random) / 22.0);
      const int before = model.undoStack()->count();
      switch (op(random)) {
        case 0:
        case 1:
        case 2:
          model.setChannel(fap(random), value(random));
          break;
        case 3:
          model.addKey();
          break;
        case 4: {
          const auto& keys = model.document().keys.keys();
          if (!keys.empty())
            model.moveKeys({keys[static_cast<std::size_t>(step) % keys.size()].time},
                           frame(random) - 30);
          break;
        }
        case 5: {
          const auto& keys = model.document().keys.keys();
          if (!keys.empty())
            model.deleteKeys({keys[static_cast<std::size_t>(step) % keys.size()].time});
          break;
        }
        case 6: {
          model.selectAll();
          const auto clip = editing::copyKeys(model.document().keys, model.selectedTimes());
          model.pasteKeys(clip, frame(random) / 22.0);
          break;
        }
        case 7:
          model.selectAll();
          model.setInterpolation(model.selectedTimes(),
                                 step % 2 ? Interpolation::Smooth : Interpolation::Linear);
          break;
        case 8:
          model.mirror();
          break;
        case 9:
          model.applyPreset(
              presets.presets()[static_cast<std::size_t>(step) % presets.presets().size()], 0.8,
              step % 3 == 0);
          break;
        case 10: {
          ProjectDocument settings = model.document();
          settings.fps = step % 2 ? 22 : 25;
          settings.name = "take " + std::to_string(step);
          model.setSettings(settings, QStringLiteral("settings"));
          break;
        }
      }
      if (model.undoStack()->count() > before) states.push_back(model.document());
    }
    QVERIFY(states.size() > 150);
    QCOMPARE(model.undoStack()->count(), static_cast<int>(states.size()) - 1);
    for (int i = static_cast<int>(states.size()) - 2; i >= 0; --i) {
      model.undoStack()->undo();
      QVERIFY2(model.document() == states[static_cast<std::size_t>(i)],
               qPrintable(QStringLiteral("undo to state %1").arg(i)));
    }
    for (std::size_t i = 1; i < states.size(); ++i) {
      model.undoStack()->redo();
      QVERIFY2(model.document() == states[i],
               qPrintable(QStringLiteral("redo to state %1").arg(i)));
    }
  }

  void sliderDragIsOneUndoStep() {
    editing::EditorModel model;
    model.setChannel(3, 50);  // an earlier, separate edit
    const ProjectDocument beforeDrag = model.document();
    const int session = model.beginDragSession();
    for (int v = 60; v <= 400; v += 20) model.setChannel(3, v, session);
    QCOMPARE(model.undoStack()->count(), 2);
    QCOMPARE(model.currentValue(3), 400.0f);
    model.undoStack()->undo();
    QVERIFY(model.document() == beforeDrag);
    QCOMPARE(model.currentValue(3), 50.0f);
    // A new drag is a new step, even on the same channel.
    const int next = model.beginDragSession();
    model.setChannel(3, 70, next);
    model.setChannel(3, 90, next);
    QCOMPARE(model.undoStack()->count(), 2);
    QCOMPARE(model.undoStack()->index(), 2);
    // A drag that returns to where it started leaves no step behind.
    const int back = model.beginDragSession();
    model.setChannel(3, 200, back);
    model.setChannel(3, 90, back);
    QCOMPARE(model.undoStack()->count(), 2);
  }

  void sliderKeysOnlyItsChannelAtTheCurrentTime() {
    editing::EditorModel model;
    model.setChannel(31, 100);
    model.setCurrentTime(2.0);
    model.setChannel(31, 300);
    model.setCurrentTime(1.0);
    QCOMPARE(model.currentValue(31), 200.0f);  // linear between the keys
    model.setChannel(3, 500);                  // a key at 1 s holding only open_jaw
    const Keyframe& middle = model.document().keys.keys()[1];
    QCOMPARE(middle.time, 1.0);
    QVERIFY(middle.has(3));
    QVERIFY(!middle.has(31));
    QCOMPARE(model.currentValue(31), 200.0f);  // still interpolating through
  }

  void timeSnapsToFramesAndNearbyKeys() {
    editing::EditorModel model;
    QCOMPARE(model.snapTime(0.51), 11.0 / 22.0);
    ProjectDocument doc;
    Keyframe offGrid;
    offGrid.time = 7.2;  // 158.4 frames
    offGrid.set(3, 10);
    doc.keys.insert(offGrid);
    model.resetDocument(doc, true);
    model.setCurrentTime(7.19);
    QCOMPARE(model.currentTime(), 7.2);  // the key, exactly, so editing it does not add another
    model.setChannel(3, 20);
    QCOMPARE(model.document().keys.keys().size(), std::size_t{1});
  }

  // Keys stay within the day a project file may hold, so what the editor saves loads again.
  void keysStayWithinADay() {
    editing::EditorModel model;
    for (double far : {1e9, 6e66, 86400.01}) {
      model.setCurrentTime(far);
      QCOMPARE(model.currentTime(), kMaxKeyTime);
    }
    model.setChannel(3, 20);
    model.moveKeys({kMaxKeyTime}, 100);
    QCOMPARE(model.document().keys.endTime(), kMaxKeyTime);
    const ProjectDocument reread = ProjectDocument::fromJson(model.document().toJson(), "day.json");
    QCOMPARE(reread.keys.endTime(), kMaxKeyTime);
  }

  // --- mirror and symmetric editing --------------------------------------------------------

  void mirrorMapsStretchLeftToRight() {
    editing::EditorModel model;
    model.setChannel(6, 150);  // stretch_l_cornerlip
    QCOMPARE(fapInfo(6).name, std::string_view("stretch_l_cornerlip"));
    model.mirror();
    const Keyframe& key = model.document().keys.keys().front();
    QVERIFY(key.has(7));
    QVERIFY(!key.has(6));
    QCOMPARE(key.value(7), 150.0f);
    QCOMPARE(model.currentValue(7), 150.0f);
    QCOMPARE(model.currentValue(6), 0.0f);
    model.mirror();
    QCOMPARE(model.currentValue(6), 150.0f);
    QVERIFY(!model.document().keys.keys().front().has(7));
  }

  void mirrorNegatesSidewaysCentreChannelsAndIsAnInvolution() {
    Keyframe key;
    key.set(15, 80);    // shift_jaw: centre, sideways
    key.set(49, -900);  // head_yaw
    key.set(23, 1200);  // yaw_l_eyeball -> yaw_r_eyeball, negated
    key.set(31, 210);   // raise_l_i_eyebrow -> raise_r_i_eyebrow
    key.set(69, 40);    // tears_l_eye -> tears_r_eye
    key.set(3, 300);    // open_jaw stays
    const Keyframe m = editing::mirrored(key);
    QCOMPARE(m.value(15), -80.0f);
    QCOMPARE(m.value(49), 900.0f);
    QCOMPARE(m.value(24), -1200.0f);
    QCOMPARE(m.value(32), 210.0f);
    QCOMPARE(m.value(70), 40.0f);
    QCOMPARE(m.value(3), 300.0f);
    QVERIFY(editing::mirrored(m) == key);
  }

  void mirrorWithoutAKeyMirrorsTheCurrentPose() {
    editing::EditorModel model;
    model.setChannel(6, 100);
    model.setCurrentTime(1.0);
    model.setChannel(6, 300);
    model.setCurrentTime(0.5);  // no key here: pose is 200 on FAP 6
    model.mirror();
    const int index = model.currentKeyIndex();
    QVERIFY(index >= 0);
    QCOMPARE(model.document().keys.keys()[static_cast<std::size_t>(index)].value(7), 200.0f);
  }

  void symmetricEditMovesTheMirrorChannel() {
    editing::EditorModel model;
    model.setSymmetricEdit(true);
    model.setChannel(6, 120);
    QCOMPARE(model.currentValue(7), 120.0f);
    // The History names both channels.
    QCOMPARE(model.undoStack()->text(0),
             QStringLiteral("Set stretch_l_cornerlip and stretch_r_cornerlip"));
    model.setChannel(23, 5000);  // eyeballs mirror with the sign flipped
    QCOMPARE(model.currentValue(24), -5000.0f);
    model.setChannel(3, 200);  // centre channel: alone
    QCOMPARE(model.undoStack()->text(2), QStringLiteral("Set open_jaw"));
    QCOMPARE(model.keyedAtCurrentTime().count(), std::size_t{5});
    QCOMPARE(model.undoStack()->count(), 3);
    model.setSymmetricEdit(false);
    model.setChannel(6, 10);
    QCOMPARE(model.currentValue(7), 120.0f);
  }

  // --- presets -----------------------------------------------------------------------------

  void builtInPresetsHoldTheSixExpressionsAndCrying() {
    const editing::PresetLibrary library = editing::PresetLibrary::builtIn();
    const char* expressions[] = {"joy", "sadness", "anger", "fear", "disgust", "surprise"};
    for (int code = 1; code <= 6; ++code) {
      const editing::Preset* p = library.forExpression(code);
      QVERIFY2(p, expressions[code - 1]);
      QCOMPARE(QString::fromStdString(p->id), QString::fromLatin1(expressions[code - 1]));
      QVERIFY(!p->isSequence());
      QVERIFY(p->keys.front().channels.count() >= 8);
    }
    for (const char* id : {"sad-crying", "angry-crying", "tears-of-joy"}) {
      const editing::Preset* p = library.find(id);
      QVERIFY2(p, id);
      QVERIFY(p->keys.front().value(kTearLeftFap) > 0);
      QVERIFY(p->keys.front().value(kTearRightFap) > 0);
    }
    const editing::Preset* sob = library.find("sobbing-cycle");
    QVERIFY(sob && sob->isSequence());
    QVERIFY(sob->keys.back().value(kTearLeftFap) > sob->keys.front().value(kTearLeftFap));
    QCOMPARE(sob->keys.front().value(48),
             sob->keys.back().value(48));  // returns to its start: repeatable
    // The disgust pose is one-sided (what mirroring is for).
    const Keyframe& disgust = library.find("disgust")->keys.front();
    QVERIFY(disgust.value(8) != disgust.value(9));
  }

  void applyingPresetsKeysTheirValues() {
    editing::EditorModel model;
    const editing::PresetLibrary library = editing::PresetLibrary::builtIn();
    model.setChannel(61, 77);  // stretch_l_nose, not in joy
    model.applyPreset(*library.find("joy"), 0.5, true);
    QCOMPARE(model.currentValue(41), 80.0f);  // lift_l_cheek 160 at 50 %
    QCOMPARE(model.currentValue(61), 0.0f);   // replaced
    model.undoStack()->undo();
    model.applyPreset(*library.find("joy"), 1.0, false);
    QCOMPARE(model.currentValue(61), 77.0f);  // kept
    model.setCurrentTime(2.0);
    model.applyPreset(*library.find("sobbing-cycle"), 1.0, false);
    const editing::Preset& sob = *library.find("sobbing-cycle");
    QCOMPARE(model.document().keys.endTime(), model.snapTime(2.0 + sob.duration()));
    model.setCurrentTime(model.snapTime(2.3));
    QCOMPARE(model.currentValue(3), 320.0f);
  }

  void presetErrorsNameFileLineAndExpectation_data() {
    QTest::addColumn<QString>("json");
    QTest::addColumn<QString>("expected");
    const QString head = QStringLiteral(
        "{\n  \"format\": \"lacrima-presets\",\n  \"version\": 1,\n  \"presets\": [\n");
    const QString pose = QStringLiteral(
        "    { \"id\": \"a\", \"name\": \"A\", \"category\": \"C\",\n      \"values\": %1 }\n  "
        "]\n}\n");
    QTest::newRow("unknown FAP")
        << head + pose.arg(QStringLiteral("{ \"opn_jaw\": 10 }"))
        << QStringLiteral(
               "bad.json:6:19: presets[0].values.opn_jaw: unknown FAP name; expected a name");
    QTest::newRow("out of range")
        << head + pose.arg(QStringLiteral("{ \"open_jaw\": -5 }"))
        << QStringLiteral(
               "bad.json:6:19: presets[0].values.open_jaw: expected a number in [0, 10800]");
    QTest::newRow("fractional tears")
        << head + pose.arg(QStringLiteral("{ \"tears_l_eye\": 2.5 }"))
        << QStringLiteral("presets[0].values.tears_l_eye: expected a whole number in [0, 100000]");
    QTest::newRow("not a number")
        << head + pose.arg(QStringLiteral("{ \"open_jaw\": \"wide\" }"))
        << QStringLiteral(
               "bad.json:6:19: presets[0].values.open_jaw: expected a finite number, got \"wide\"");
    QTest::newRow("syntax") << head +
                                   QStringLiteral("    { \"id\": \"a\" \"name\": \"A\" }\n  ]\n}\n")
                            << QStringLiteral("bad.json:5:17: invalid JSON");
    QTest::newRow("no format")
        << QStringLiteral("{ \"version\": 1, \"presets\": [] }")
        << QStringLiteral(
               "bad.json:1:1: missing field \"format\"; this is not a Lacrima presets file");
    QTest::newRow("both values and keys")
        << head + QStringLiteral(
                      "    { \"id\": \"a\", \"name\": \"A\", \"category\": \"C\", \"values\": "
                      "{\"open_jaw\": 1},\n"
                      "      \"keys\": [] }\n  ]\n}\n")
        << QStringLiteral(
               "bad.json:5:5: presets[0]: expected exactly one of \"values\" (a pose) and \"keys\" "
               "(a sequence)");
    QTest::newRow("bad id")
        << head + QStringLiteral(
                      "    { \"id\": \"Big Smile\", \"name\": \"A\", \"category\": \"C\", "
                      "\"values\": {\"open_jaw\": 1} }\n  ]\n}\n")
        << QStringLiteral(
               "bad.json:5:7: presets[0].id: expected lower-case letters, digits and '-'");
    QTest::newRow("keys out of order")
        << head + QStringLiteral(
                      "    { \"id\": \"s\", \"name\": \"S\", \"category\": \"C\", \"keys\": [\n"
                      "      { \"time\": 0, \"values\": {\"open_jaw\": 1} },\n"
                      "      { \"time\": 0, \"values\": {\"open_jaw\": 2} } ] }\n  ]\n}\n")
        << QStringLiteral(
               "bad.json:7:9: presets[0].keys[1].time: expected a time after the previous key's 0 "
               "s, got 0");
    QTest::newRow("duplicate id") << head +
                                         QStringLiteral(
                                             "    { \"id\": \"a\", \"name\": \"A\", \"category\": "
                                             "\"C\", \"values\": {\"open_jaw\": 1} },\n"
                                             "    { \"id\": \"a\", \"name\": \"B\", \"category\": "
                                             "\"C\", \"values\": {\"open_jaw\": 1} }\n  ]\n}\n")
                                  << QStringLiteral(
                                         "bad.json:6:7: presets[1].id: expected a unique id");
    QTest::newRow("unknown field")
        << head + QStringLiteral("    { \"id\": \"a\", \"nmae\": \"A\" }\n  ]\n}\n")
        << QStringLiteral(
               "bad.json:5:18: presets[0].nmae: unknown field; expected one of id, name");
  }

  void presetErrorsNameFileLineAndExpectation() {
    QFETCH(QString, json);
    QFETCH(QString, expected);
    const std::string text = json.toStdString();
    try {
      editing::PresetLibrary::fromJson(text, "bad.json");
      QFAIL("accepted an invalid presets file");
    } catch (const FileError& e) {
      QVERIFY2(QString::fromUtf8(e.what()).contains(expected), e.what());
    }
  }

  void presetFileThatCannotBeReadIsAnError() {
    try {
      editing::PresetLibrary::load("/nonexistent/presets.json");
      QFAIL("loaded a missing file");
    } catch (const FileError& e) {
      QVERIFY2(QString::fromUtf8(e.what()).startsWith(
                   QStringLiteral("/nonexistent/presets.json: cannot open")),
               e.what());
    }
  }

  // --- key reduction -------------------------------------------------------------------------

  void keyReductionReproducesEveryFrameWithinTheTolerance() {
    for (const double tolerance : {0.0, 0.5, 2.0, 10.0}) {
      const FapAnimation animation = syntheticAnimation(400, 7);
      const std::vector<int> kept = editing::reduceKeyFrames(animation, tolerance);
      QCOMPARE(kept.front(), 0);
      QCOMPARE(kept.back(), 399);
      QVERIFY(editing::reductionError(animation, kept) <= tolerance);
      // Check the guarantee the way the editor plays it: bake the reduced keys.
      editing::FapImportResult imported =
          editing::importAnimation(animation, editing::FapImportOptions{tolerance});
      QCOMPARE(imported.keys, static_cast<int>(kept.size()));
      const FapAnimation baked = imported.document.bake();
      QCOMPARE(baked.frameCount(), animation.frameCount());
      for (int i = 0; i < animation.frameCount(); ++i)
        for (int c = 0; c < kChannelCount; ++c)
          QVERIFY2(std::abs(baked.frames[i][c] - animation.frames[i][c]) <= tolerance + 1e-4,
                   qPrintable(QStringLiteral("frame %1 channel %2 tolerance %3")
                                  .arg(i)
                                  .arg(c + 1)
                                  .arg(tolerance)));
      qInfo("tolerance %g: %zu of 400 frames kept", tolerance, kept.size());
      if (tolerance >= 10.0) QVERIFY(kept.size() < 150);
    }
  }

  void keyReductionKeepsExactlyTheCornersOfPiecewiseLinearMotion() {
    FapAnimation a;
    a.fps = 22;
    a.frames.assign(101, FapValues{});
    a.animated.set(channelIndex(3));
    a.animated.set(channelIndex(69));
    for (int i = 0; i <= 100; ++i) {
      const double v = i <= 40 ? 10.0 * i : i <= 70 ? 400.0 - 5.0 * (i - 40) : 250.0;
      a.frames[static_cast<std::size_t>(i)][channelIndex(3)] = static_cast<float>(v);
      a.frames[static_cast<std::size_t>(i)][channelIndex(69)] =
          i < 50 ? 0.0f : 30.0f;  // a jump at 50
    }
    const std::vector<int> kept = editing::reduceKeyFrames(a, 0.0);
    QCOMPARE(kept, (std::vector<int>{0, 40, 49, 50, 70, 100}));
  }

  void keyReductionRejectsBadTolerances() {
    const FapAnimation a = syntheticAnimation(10, 1);
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, editing::reduceKeyFrames(a, -1.0));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, editing::reduceKeyFrames(a, std::nan("")));
  }

  // --- FAP import and export -----------------------------------------------------------------

  void keysAtZeroAndOneSecondExport23LinearFrames() {
    QTemporaryDir dir;
    editing::EditorModel model;
    model.setChannel(3, 0);
    model.setChannel(69, 0);
    model.setCurrentTime(1.0);
    model.setChannel(3, 440);
    model.setChannel(69, 22);
    const std::string path = dir.filePath(QStringLiteral("out.fap")).toStdString();
    const editing::FapExportResult result = editing::exportFap(model.document(), path, {});
    QCOMPARE(result.frames, 23);
    QVERIFY(result.wroteTears);
    const FapReadResult read = FapReader::readFile(path);
    QCOMPARE(read.animation.frameCount(), 23);
    QCOMPARE(read.animation.fps, 22.0);
    for (int i = 0; i < 23; ++i) {
      QCOMPARE(read.animation.frames[i][channelIndex(3)], 20.0f * i);
      QCOMPARE(read.animation.frames[i][channelIndex(69)], static_cast<float>(i));
    }
    // Strict: 68 FAPs, the tears left out.
    const std::string strict = dir.filePath(QStringLiteral("strict.fap")).toStdString();
    editing::exportFap(model.document(), strict, {22.0, true});
    const FapReadResult strictRead = FapReader::readFile(strict);
    QVERIFY(!strictRead.animation.hasTears());
    QCOMPARE(strictRead.animation.frames[22][channelIndex(3)], 440.0f);
  }

  void exportWithoutKeysIsAClearError() {
    QTemporaryDir dir;
    const ProjectDocument empty;
    try {
      editing::exportFap(empty, dir.filePath(QStringLiteral("x.fap")).toStdString(), {});
      QFAIL("exported nothing");
    } catch (const FileError& e) {
      QVERIFY(QString::fromUtf8(e.what()).contains(QStringLiteral("no keys")));
    }
  }

  void importThenExportRoundTripsExactly() {
    QTemporaryDir dir;
    const FapAnimation original = syntheticAnimation(300, 3);
    const std::string in = dir.filePath(QStringLiteral("in.fap")).toStdString();
    FapWriter::save(original, in);
    const editing::FapImportResult imported = editing::importFap(in);
    QCOMPARE(imported.keys, 300);
    const std::string out = dir.filePath(QStringLiteral("out.fap")).toStdString();
    editing::exportFap(imported.document, out, {});
    const FapAnimation a = FapReader::readFile(in).animation;
    const FapAnimation b = FapReader::readFile(out).animation;
    QCOMPARE(b.frameCount(), a.frameCount());
    QCOMPARE(b.animated, a.animated);
    QVERIFY(a.frames == b.frames);
  }

  void importWithReductionRoundTripsWithinTheTolerance() {
    QTemporaryDir dir;
    const FapAnimation original = syntheticAnimation(300, 11);
    const std::string in = dir.filePath(QStringLiteral("in.fap")).toStdString();
    FapWriter::save(original, in);
    const editing::FapImportResult imported =
        editing::importFap(in, editing::FapImportOptions{0.5});
    QVERIFY(imported.keys < 300);
    const std::string out = dir.filePath(QStringLiteral("out.fap")).toStdString();
    editing::exportFap(imported.document, out, {});
    const FapAnimation a = FapReader::readFile(in).animation;
    const FapAnimation b = FapReader::readFile(out).animation;
    QCOMPARE(b.frameCount(), a.frameCount());
    // Within 0.5 before the writer rounds; integer files come back within one unit.
    for (int i = 0; i < a.frameCount(); ++i)
      for (int c = 0; c < kChannelCount; ++c)
        QVERIFY(std::abs(a.frames[i][c] - b.frames[i][c]) <= 1.0f);
  }

  void aBakedKeyedAnimationReducesBackToFewKeys() {
    // The demo: a dozen smooth keys baked to ~300 integer frames. Linear keys within a unit
    // need far fewer keys than frames, though more than the smooth originals.
    QTemporaryDir dir;
    const ProjectDocument demo =
        ProjectDocument::load(LACRIMA_SOURCE_DIR "/media/demo/crying.json");
    const std::string baked = dir.filePath(QStringLiteral("demo.fap")).toStdString();
    editing::exportFap(demo, baked, {});
    for (const double tolerance : {0.5, 1.0, 4.0}) {
      const editing::FapImportResult imported =
          editing::importFap(baked, editing::FapImportOptions{tolerance});
      QVERIFY(imported.maxError <= tolerance);
      // Integer rounding puts a half-unit staircase on every smooth curve: from one unit up,
      // the keys follow the motion, not the rounding.
      if (tolerance >= 1.0) QVERIFY(imported.keys * 4 < imported.frames);
      qInfo("demo baked to %d frames -> %d keys at tolerance %g (%zu keys in the project)",
            imported.frames, imported.keys, tolerance, demo.keys.keys().size());
    }
  }

  void publicSampleFilesRoundTrip_data() {
    QTest::addColumn<QString>("sample");
    QTest::newRow("xface joy") << QStringLiteral("xface/joy.fap");
    QTest::newRow("vreng fear") << QStringLiteral("vreng/fear.fap");
    QTest::newRow("vreng eyes") << QStringLiteral("vreng/eyes.fap");
  }

  void publicSampleFilesRoundTrip() {
    QFETCH(QString, sample);
    const QString samplePath = sharedSample(qPrintable(sample));
    LACRIMA_REQUIRE_SHARED(samplePath);
    const std::string path = samplePath.toStdString();
    QTemporaryDir dir;
    const editing::FapImportResult imported = editing::importFap(path);
    const std::string out = dir.filePath(QStringLiteral("out.fap")).toStdString();
    editing::exportFap(imported.document, out,
                       editing::FapExportOptions{imported.document.fps, false});
    const FapAnimation a = FapReader::readFile(path).animation;
    const FapAnimation b = FapReader::readFile(out).animation;
    QCOMPARE(b.frameCount(), a.frameCount());
    // Low-level FAPs come back as the reader decoded them (rounded: the writer writes integers);
    // FAP 1 and 2 are not written in the portable profile.
    for (int i = 0; i < a.frameCount(); ++i)
      for (int fap = 3; fap <= kChannelCount; ++fap)
        QCOMPARE(b.frames[i][channelIndex(fap)], std::round(a.frames[i][channelIndex(fap)]));
    // What key reduction makes of a real file, within its guarantee.
    for (const double tolerance : {0.5, 2.0, 10.0}) {
      const editing::FapImportResult reduced =
          editing::importFap(path, editing::FapImportOptions{tolerance});
      QVERIFY(reduced.maxError <= tolerance);
      qInfo("%s: %d frames -> %d keys at tolerance %g (largest error %g)", qPrintable(sample),
            reduced.frames, reduced.keys, tolerance, reduced.maxError);
    }
  }

  void importOfABrokenFileNamesTheLine() {
    QTemporaryDir dir;
    const std::string path =
        writeTemp(dir, QStringLiteral("broken.fap"), "2.1 x 22 2\n1 0 1\n0 5\n");
    try {
      editing::importFap(path);
      QFAIL("imported a broken file");
    } catch (const FileError& e) {
      QVERIFY2(QString::fromUtf8(e.what()).contains(QStringLiteral("broken.fap:2")), e.what());
    }
  }

  // --- filter, clipboard, playback, recovery --------------------------------------------------

  void channelFilterFindsByNameNumberRangeSideAndGroup() {
    const auto numbers = [](const char* text) {
      std::vector<int> out;
      const ChannelMask mask = editing::ChannelFilter(text).matching();
      for (int fap = 1; fap <= kChannelCount; ++fap)
        if (mask.test(channelIndex(fap))) out.push_back(fap);
      return out;
    };
    QCOMPARE(numbers("jaw"), (std::vector<int>{3, 14, 15}));
    QCOMPARE(numbers("31"), (std::vector<int>{31}));
    QCOMPARE(numbers("19-22"), (std::vector<int>{19, 20, 21, 22}));
    QCOMPARE(numbers("left brow"), (std::vector<int>{31, 33, 35, 37}));
    QCOMPARE(numbers("tears"), (std::vector<int>{69, 70}));
    QCOMPARE(numbers("cheeks"), (std::vector<int>{39, 40, 41, 42}));
    QCOMPARE(numbers("OPEN JAW"), (std::vector<int>{3}));
    QCOMPARE(numbers("jaw, 69"), (std::vector<int>{3, 14, 15, 69}));
    // Words the names abbreviate are found in the descriptions: "inner" is the _i_ of 31, 32.
    QCOMPARE(numbers("inner brow"), (std::vector<int>{31, 32}));
    QCOMPARE(numbers("nose"), (std::vector<int>{61, 62, 63, 64}));  // names first
    QCOMPARE(numbers("").size(), std::size_t{70});
    QVERIFY(numbers("no such channel").empty());
  }

  void clipboardRoundTripsKeys() {
    KeyframeSequence keys;
    for (int i = 0; i < 4; ++i) {
      Keyframe k;
      k.time = 1.0 + i * 0.5;
      k.interpolation = i % 2 ? Interpolation::Smooth : Interpolation::Linear;
      k.set(3 + i, 10.5f * i);
      k.set(70, static_cast<float>(i));
      keys.insert(k);
    }
    const std::vector<double> times{1.5, 2.5};
    const std::vector<Keyframe> clip = editing::copyKeys(keys, times);
    QCOMPARE(clip.size(), std::size_t{2});
    QCOMPARE(clip[0].time, 0.0);
    QCOMPARE(clip[1].time, 1.0);
    std::unique_ptr<QMimeData> data(editing::keysToMimeData(clip));
    const auto back = editing::keysFromMimeData(data.get());
    QVERIFY(back);
    QVERIFY(*back == clip);
    QMimeData text;
    text.setText(QStringLiteral("hello"));
    QVERIFY(!editing::keysFromMimeData(&text));
  }

  void playbackAdvancesOneFrameAtTheRateAndLoops() {
    editing::EditorModel model;
    model.setChannel(3, 0);
    model.setCurrentTime(1.0);
    model.setChannel(3, 100);
    model.setCurrentTime(0.0);
    editing::FrameStepClock clock(model);
    QCOMPARE(clock.rate(), 22.0);
    clock.play();
    QVERIFY(clock.isPlaying());
    for (int i = 0; i < 11; ++i) clock.advance();
    QVERIFY(std::abs(model.currentTime() - 0.5) < 1e-9);
    QVERIFY(std::abs(model.currentValue(3) - 50.0f) < 1e-3f);
    for (int i = 0; i < 12; ++i) clock.advance();  // past the end: loops to the first key
    QVERIFY(model.currentTime() < 0.1);
    clock.setLoop(false);
    for (int i = 0; i < 40; ++i) clock.advance();
    QVERIFY(!clock.isPlaying());
    QCOMPARE(model.currentTime(), 1.0);
  }

  void recoveryFileErrorsNameLineColumnAndPath() {
    QTemporaryDir dir;
    const QString file = dir.filePath(QStringLiteral("session-1.json"));
    QFile out(file);
    QVERIFY(out.open(QIODevice::WriteOnly));
    out.write(
        "{\"format\": \"lacrima-recovery\", \"version\": 1, \"sourcePath\": \"\", \"savedAt\": "
        "\"\",\n"
        " \"project\": {\"format\": \"lacrima-project\", \"version\": 1,\n"
        "  \"keys\": [{\"time\": 0, \"values\": {\"opn_jaw\": 1}}]}}\n");
    out.close();
    try {
      editing::RecoveryStore::read(file);
      QFAIL("a recovery file with an unknown FAP name was read");
    } catch (const FileError& e) {
      QCOMPARE(QString::fromUtf8(e.what()),
               file + QStringLiteral(":3:35: project.keys[0].values.opn_jaw: unknown FAP name; did "
                                     "you mean open_jaw?"));
    }
  }

  void recoveryFilesRoundTripAndOrphansNeedTheirEditorGone() {
    QTemporaryDir dir;
    ProjectDocument document = ProjectDocument::load(LACRIMA_SOURCE_DIR "/media/demo/crying.json");
    auto live = std::make_unique<editing::RecoveryStore>(dir.path());
    live->save(document, QStringLiteral("/somewhere/crying.json"));
    QVERIFY(QFile::exists(live->filePath()));
    editing::RecoveryStore other(dir.path());
    QVERIFY(other.orphans().empty());  // its editor still runs
    const QString file = live->filePath();
    live.reset();  // ended without a clean exit
    const auto orphans = other.orphans();
    QCOMPARE(orphans.size(), std::size_t{1});
    QCOMPARE(orphans.front().file, file);
    QCOMPARE(orphans.front().sourcePath, QStringLiteral("/somewhere/crying.json"));
    QString source;
    QVERIFY(editing::RecoveryStore::read(file, &source) == document);
    editing::RecoveryStore::remove(file);
    QVERIFY(other.orphans().empty());
    // A clean session leaves nothing behind.
    editing::RecoveryStore clean(dir.path());
    clean.save(document, {});
    clean.discard();
    QVERIFY(QDir(dir.path()).entryList(QDir::Files).isEmpty());
  }
};

QTEST_MAIN(EditorCoreTest)
#include "EditorCoreTest.moc"
