// lacrima-fap as scripts use it: real processes, exit codes, stdout and stderr.
#include <lacrima/common/FapReader.h>
#include <lacrima/common/FapWriter.h>
#include <lacrima/common/ProjectDocument.h>

#include <QProcess>
#include <QTemporaryDir>
#include <QtTest>

using namespace lacrima;

namespace {

struct Run {
  int exitCode = -1;
  QString out, err;
};

Run runFap(const QStringList& args) {
  QProcess process;
  process.start(QStringLiteral(LACRIMA_BIN_DIR "/lacrima-fap"), args);
  if (!process.waitForFinished(60000)) {
    process.kill();
    return {};
  }
  return {process.exitStatus() == QProcess::NormalExit ? process.exitCode() : -2,
          QString::fromUtf8(process.readAllStandardOutput()),
          QString::fromUtf8(process.readAllStandardError())};
}

// Two frames one second apart: open_jaw 0 -> 220, left tears 0 -> 22.
FapAnimation twoFrameAnimation() {
  FapAnimation anim;
  anim.name = "jaw";
  anim.fps = 1;
  anim.frames.resize(2, FapValues{});
  anim.frames[1][channelIndex(3)] = 220;
  anim.frames[1][channelIndex(kTearLeftFap)] = 22;
  anim.animated.set(channelIndex(3));
  anim.animated.set(channelIndex(kTearLeftFap));
  return anim;
}

}  // namespace

class FapCliTest : public QObject {
  Q_OBJECT

  QTemporaryDir dir_;
  QString path(const QString& name) const { return dir_.filePath(name); }
  QString writeTwoFrameFile() {
    const QString file = path("two.fap");
    FapWriter::save(twoFrameAnimation(), file.toStdString());
    return file;
  }

 private slots:
  void initTestCase() { QVERIFY(dir_.isValid()); }

  void helpAndUsage() {
    const Run help = runFap({"--help"});
    QCOMPARE(help.exitCode, 0);
    for (const char* command : {"check", "dump", "interpolate", "convert"})
      QVERIFY2(help.out.contains(command), command);
    QCOMPARE(runFap({}).exitCode, 2);
    const Run unknown = runFap({"frobnicate", "x"});
    QCOMPARE(unknown.exitCode, 2);
    QVERIFY(unknown.err.contains("unknown command 'frobnicate'"));
    QCOMPARE(runFap({"interpolate", "in.fap"}).exitCode, 2);  // no -o
    QCOMPARE(runFap({"interpolate", "in.fap", "-o", "x.fap", "--fps", "zero"}).exitCode, 2);
    const Run commandHelp = runFap({"convert", "--help"});
    QCOMPARE(commandHelp.exitCode, 0);
    QVERIFY(commandHelp.out.contains("--strict"));
  }

  void checkSummarisesOneLine() {
    const Run run = runFap({"check", writeTwoFrameFile()});
    QCOMPARE(run.exitCode, 0);
    QCOMPARE(run.out.count('\n'), 1);
    QVERIFY2(run.out.contains("FAP 2.1, 1 fps, 2 frames"), qPrintable(run.out));
    QVERIFY2(run.out.contains("2 channels masked (3 69)"), qPrintable(run.out));
    QVERIFY2(run.out.contains("0 warnings"), qPrintable(run.out));
    QVERIFY2(run.err.isEmpty(), qPrintable(run.err));  // a clean file says nothing on stderr
  }

  void checkCountsWarnings() {
    const QString file = path("gap.fap");
    QFile f(file);
    QVERIFY(f.open(QIODevice::WriteOnly));
    QByteArray mask = QByteArray("0 0 1") + QByteArray(" 0").repeated(65) + "\n";
    f.write("2.1 gap 10 3\n" + mask + "0 0\n" + mask + "2 100\n");
    f.close();
    const Run run = runFap({"check", file});
    QCOMPARE(run.exitCode, 0);
    QVERIFY2(run.out.contains("1 warning"), qPrintable(run.out));
    QVERIFY2(run.err.contains("gap.fap:"), qPrintable(run.err));
  }

  void checkRejectsMalformedWithLocation() {
    const QString file = path("bad.fap");
    QFile f(file);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write("2.1 bad 10 1\n0 0 2\n");  // mask token 2 on line 2, column 5
    f.close();
    const Run run = runFap({"check", file});
    QCOMPARE(run.exitCode, 1);
    QVERIFY2(run.err.contains(file + ":2:5:"), qPrintable(run.err));
    QVERIFY(run.out.isEmpty());
    QCOMPARE(runFap({"check", path("missing.fap")}).exitCode, 1);
  }

  void dumpPrintsCsv() {
    const Run run = runFap({"dump", writeTwoFrameFile()});
    QCOMPARE(run.exitCode, 0);
    const QStringList lines = run.out.split('\n', Qt::SkipEmptyParts);
    QCOMPARE(lines.size(), 3);
    QStringList header{"frame"};
    for (int fap = 1; fap <= kChannelCount; ++fap) header << QString("fap%1").arg(fap);
    QCOMPARE(lines[0], header.join(','));
    const QStringList row = lines[2].split(',');
    QCOMPARE(row.size(), 71);
    QCOMPARE(row[0], QString("1"));
    QCOMPARE(row[3], QString("220"));
    QCOMPARE(row[69], QString("22"));
    QCOMPARE(row[70], QString("0"));
  }

  void interpolateResamplesLinearly() {
    const QString out = path("dense.fap");
    const Run run = runFap({"interpolate", writeTwoFrameFile(), "-o", out, "--fps", "22"});
    QCOMPARE(run.exitCode, 0);
    const FapAnimation dense = FapReader::readFile(out.toStdString()).animation;
    QCOMPARE(dense.frameCount(), 23);
    QCOMPARE(dense.fps, 22.0);
    for (int i = 0; i < 23; ++i) {
      QCOMPARE(dense.frames[i][channelIndex(3)], float(10 * i));
      QCOMPARE(dense.frames[i][channelIndex(kTearLeftFap)], float(i));  // whole particles
    }
  }

  void interpolateSmoothStaysWithinKeys() {
    FapAnimation anim;
    anim.fps = 1;
    for (float v : {0.f, 100.f, 100.f, 0.f}) {
      FapValues frame{};
      frame[channelIndex(31)] = v;
      anim.frames.push_back(frame);
    }
    anim.animated.set(channelIndex(31));
    const QString in = path("plateau.fap"), out = path("plateau-smooth.fap");
    FapWriter::save(anim, in.toStdString());
    QCOMPARE(runFap({"interpolate", in, "-o", out, "--fps", "50", "--smooth"}).exitCode, 0);
    const FapAnimation dense = FapReader::readFile(out.toStdString()).animation;
    QCOMPARE(dense.frameCount(), 151);
    for (const FapValues& frame : dense.frames) {
      QVERIFY(frame[channelIndex(31)] >= 0.f);
      QVERIFY(frame[channelIndex(31)] <= 100.f);
    }
    // The plateau between the two 100-keys stays flat: no overshoot above it.
    QCOMPARE(dense.frames[75][channelIndex(31)], 100.f);
  }

  void convertRoundTripsThroughProject() {
    const QString json = path("two.json"), back = path("back.fap");
    QCOMPARE(runFap({"convert", writeTwoFrameFile(), "-o", json}).exitCode, 0);
    const ProjectDocument doc = ProjectDocument::load(json.toStdString());
    QCOMPARE(int(doc.keys.keys().size()), 2);
    QCOMPARE(runFap({"convert", json, "-o", back}).exitCode, 0);
    const FapAnimation original = twoFrameAnimation();
    const FapAnimation restored = FapReader::readFile(back.toStdString()).animation;
    QCOMPARE(restored.frameCount(), 2);
    QVERIFY(restored.frames == original.frames);
  }

  void convertStrictDropsTears() {
    const QString out = path("strict.fap");
    QCOMPARE(runFap({"convert", writeTwoFrameFile(), "-o", out, "--strict"}).exitCode, 0);
    QFile f(out);
    QVERIFY(f.open(QIODevice::ReadOnly));
    f.readLine();
    QCOMPARE(QString(f.readLine()).split(' ', Qt::SkipEmptyParts).size() - 1, 68);  // + "\n"
  }

  void convertBakesTheDemoProject() {
    const QString demo = QStringLiteral(LACRIMA_SOURCE_DIR "/media/demo/crying.json");
    const QString out = path("crying.fap");
    const Run run = runFap({"convert", demo, "-o", out});
    QVERIFY2(run.exitCode == 0, qPrintable(run.err));
    const FapReadResult read = FapReader::readFile(out.toStdString());
    QCOMPARE(read.animation.frameCount(), 14 * 22 + 1);  // the demo lasts 14 s
    QVERIFY(read.warnings.empty());
    QVERIFY(read.animation.hasTears());
  }

  // A project's crying layer (docs/mood.md#the-mood-layer) is baked into the .fap as the
  // editor evaluates it; a strict export stays the 68 standard FAPs.
  void convertBakesAMoodLayer() {
    ProjectDocument document;
    Keyframe key;
    key.set(3, 40);
    document.keys = KeyframeSequence({key});
    document.moods[Mood::Sadness] = IntensityCurve({{0, 0.9, Interpolation::Smooth}});
    document.moodLayer = MoodLayer{5, 0, 8, false};
    const QString project = path("layer.lacrima"), out = path("layer.fap");
    document.save(project.toStdString());
    const Run run = runFap({"convert", project, "-o", out});
    QVERIFY2(run.exitCode == 0, qPrintable(run.err));
    const FapReadResult read = FapReader::readFile(out.toStdString());
    QCOMPARE(read.animation.frameCount(), 8 * 22 + 1);
    QVERIFY(read.animation.hasTears());
    MoodLayerCache cache;
    for (int f = 0; f < read.animation.frameCount(); f += 11)
      QVERIFY(read.animation.frames[static_cast<std::size_t>(f)] ==
              document.evaluate(f / 22.0, cache));
    QCOMPARE(runFap({"convert", project, "-o", path("strict.fap"), "--strict"}).exitCode, 0);
    QCOMPARE(FapReader::readFile(path("strict.fap").toStdString()).animation.hasTears(), false);
  }

  void failedWriteNamesThePath() {
    const QString out = path("no/such/dir/out.fap");
    const Run run = runFap({"convert", writeTwoFrameFile(), "-o", out});
    QCOMPARE(run.exitCode, 1);
    QVERIFY2(run.err.contains(out), qPrintable(run.err));
  }

  // lacrima-fap generate (docs/mood.md): a take of the crying generator as a .fap or a project.
  void generateWritesAFapFileAndAProject() {
    const QString fap = path("sad.fap");
    const Run run = runFap({"generate", "--mood", "sadness=0.8,anger=0.2", "--seconds", "12",
                            "--seed", "5", "-o", fap});
    QVERIFY2(run.exitCode == 0, qPrintable(run.err));
    QVERIFY2(run.err.contains("265 frames at 22 fps"), qPrintable(run.err));
    const FapReadResult read = FapReader::readFile(fap.toStdString());
    QCOMPARE(read.animation.frameCount(), 12 * 22 + 1);
    QVERIFY(read.warnings.empty());
    QVERIFY(read.animation.hasTears());

    const QString project = path("sad.lacrima");
    QCOMPARE(runFap({"generate", "--mood", "sadness=0.8,anger=0.2", "--seconds", "12", "--seed",
                     "5", "-o", project})
                 .exitCode,
             0);
    const ProjectDocument document = ProjectDocument::load(project.toStdString());
    QCOMPARE(document.bake().frames, read.animation.frames);  // the same take, keyed
    QVERIFY(!document.colours.redness.empty() && !document.colours.blush.empty());
    QCOMPARE(document.colours.redness.endTime(), 12.0);
    QVERIFY(document.colours.blush.at(12) > 0.1);  // anger blushes
    QVERIFY(document.scene.blush);
  }

  void generateFollowsAScriptAndTheSeed() {
    const QString script = path("moods.json");
    QFile file(script);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write(R"({"format": "lacrima-moods", "version": 1,
                   "keys": [{"time": 0, "joy": 0}, {"time": 2, "joy": 0.9}]})");
    file.close();
    const auto take = [&](const QString& seed, const QString& name, const QString& rate) {
      const QString out = path(name);
      const Run run = runFap({"generate", "--script", script, "--seconds", "6", "--seed", seed,
                              "--rate", rate, "-o", out});
      if (run.exitCode != 0) qWarning("%s", qPrintable(run.err));
      QFile f(out);
      return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
    };
    const QByteArray a = take("9", "a.fap", "22"), b = take("9", "b.fap", "22");
    QVERIFY(!a.isEmpty());
    QCOMPARE(a, b);  // same seed, same bytes
    QVERIFY(take("10", "c.fap", "22") != a);
    take("9", "d.fap", "50");
    QCOMPARE(FapReader::readFile(path("d.fap").toStdString()).animation.frameCount(), 301);
    // joy lifts the lip corners once the script has raised it
    const FapAnimation joy = FapReader::readFile(path("a.fap").toStdString()).animation;
    QVERIFY(joy.frames.back()[channelIndex(12)] > 100);
    QCOMPARE(joy.frames.front()[channelIndex(12)], 0.0f);
  }

  void generateStrictWritesTheStandardFaps() {
    const QString out = path("strict-sad.fap");
    QCOMPARE(runFap({"generate", "--mood", "sadness=1", "--seconds", "15", "--strict", "-o", out})
                 .exitCode,
             0);
    const FapAnimation strict = FapReader::readFile(out.toStdString()).animation;
    QVERIFY(!strict.hasTears());
    QVERIFY(!strict.animated.test(channelIndex(kTearLeftFap)));
  }

  void generateRefusesBadInputWithoutWriting() {
    const QString out = path("refused.fap");
    const auto usage = [&](const QStringList& args) {
      const Run run = runFap(QStringList{"generate"} + args + QStringList{"-o", out});
      return run.exitCode;
    };
    QCOMPARE(usage({"--seconds", "3"}), 2);                                           // no moods
    QCOMPARE(usage({"--mood", "joy=1", "--script", "x.json", "--seconds", "3"}), 2);  // both
    QCOMPARE(usage({"--mood", "grief=1", "--seconds", "3"}), 2);
    QCOMPARE(usage({"--mood", "joy=2", "--seconds", "3"}), 2);
    QCOMPARE(usage({"--mood", "joy=1"}), 2);  // no length
    QCOMPARE(usage({"--mood", "joy=1", "--seconds", "-1"}), 2);
    QCOMPARE(usage({"--mood", "joy=1", "--seconds", "3", "--rate", "0"}), 2);
    QCOMPARE(usage({"--mood", "joy=1", "--seconds", "3", "--seed", "-4"}), 2);
    QCOMPARE(runFap({"generate", "--mood", "joy=1", "--seconds", "3"}).exitCode, 2);  // no -o

    // Too many frames: refused before anything is generated.
    const Run longRun =
        runFap({"generate", "--mood", "joy=1", "--seconds", "86400", "--rate", "1000", "-o", out});
    QCOMPARE(longRun.exitCode, 1);
    QVERIFY2(longRun.err.contains("at most 1048576"), qPrintable(longRun.err));

    // Bad scripts name the file, line and what was expected.
    const struct {
      const char* json;
      const char* expected;
    } scripts[] = {
        {"{\"keys\": [\n{\"time\": 1},\n{\"time\": 0.5}]}",
         ":3:2: keys[1].time: expected a time after"},
        {"{\"keys\": [{\"time\": 0, \"sadness\": \"lots\"}]}",
         "keys[0].sadness: expected a number in [0, 1]"},
        {"{\"keys\": [{\"time\": 0, \"grief\": 1}]}", "keys[0].grief: unknown field"},
        {"{\"keys\": [{\"time\": 0}", "invalid JSON"},
        {"", "invalid JSON"},
    };
    for (const auto& bad : scripts) {
      const QString script = path("bad-moods.json");
      QFile file(script);
      QVERIFY(file.open(QIODevice::WriteOnly | QIODevice::Truncate));
      file.write(bad.json);
      file.close();
      const Run run = runFap({"generate", "--script", script, "--seconds", "3", "-o", out});
      QCOMPARE(run.exitCode, 1);
      QVERIFY2(run.err.startsWith(script + ":") && run.err.contains(bad.expected),
               qPrintable(run.err));
    }
    QVERIFY(!QFile::exists(out));
    const Run missing =
        runFap({"generate", "--script", path("none.json"), "--seconds", "3", "-o", out});
    QCOMPARE(missing.exitCode, 1);
    QVERIFY(missing.err.contains("none.json"));
    QVERIFY(!QFile::exists(out));
  }

  void generateKeepsTheOldFileWhenTheWriteFails() {
    const QString out = path("no/such/dir/take.fap");
    const Run run = runFap({"generate", "--mood", "sadness=1", "--seconds", "2", "-o", out});
    QCOMPARE(run.exitCode, 1);
    QVERIFY2(run.err.contains(out), qPrintable(run.err));
  }
};

QTEST_GUILESS_MAIN(FapCliTest)
#include "FapCliTest.moc"
