// FapWriter: the exact portable text, round trips through FapReader, and atomic saving.
#include <lacrima/common/FapReader.h>
#include <lacrima/common/FapWriter.h>

#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <QtTest>

#include <sys/resource.h>

#include <csignal>
#include <random>
#include <string>

using namespace lacrima;

namespace {

std::string repeat(const std::string& piece, int times) {
  std::string out;
  for (int i = 0; i < times; ++i) out += piece;
  return out;
}

// Three frames: FAP 3 and 5 animated, FAP 4 non-zero in frame 1 only (so used, not animated).
FapAnimation smallAnimation() {
  FapAnimation a;
  a.name = "my face";
  a.fps = 25;
  a.frames.resize(3, FapValues{});
  auto set = [&](int frame, int fap, float v) { a.frames[frame][channelIndex(fap)] = v; };
  set(0, 3, 1.5f);   // rounds away from zero: 2
  set(0, 5, -0.4f);  // rounds to 0, written "0" not "-0"
  set(1, 3, -1.5f);
  set(1, 4, 2.49f);
  set(1, 5, 10.f);
  set(2, 5, -7.6f);
  a.animated.set(channelIndex(3));
  a.animated.set(channelIndex(5));
  return a;
}

bool anyWarningContains(const Warnings& warnings, const std::string& text) {
  for (const Diagnostic& d : warnings)
    if (d.message.find(text) != std::string::npos) return true;
  return false;
}

QByteArray fileBytes(const QString& path) {
  QFile file(path);
  return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

}  // namespace

class FapWriterTest : public QObject {
  Q_OBJECT

  QTemporaryDir tmp_;

 private slots:
  void initTestCase() { QVERIFY(tmp_.isValid()); }

  void writesThePortableProfile() {
    Warnings warnings;
    const std::string text = FapWriter::toText(smallAnimation(), {}, &warnings);
    const std::string mask = "0 0 1 1 1 " + repeat("0 ", 63) + "\n";
    const std::string expected =
        "2.1 my_face 25 3\n" + mask + "0 2 0 0\n" + mask + "1 -2 2 10\n" + mask + "2 0 0 -8\n";
    QCOMPARE(QString::fromStdString(text), QString::fromStdString(expected));
    QVERIFY(warnings.empty());
  }

  void writesSeventyTokensForTears() {
    FapAnimation a = smallAnimation();
    a.frames[1][channelIndex(kTearLeftFap)] = 3.4f;
    const std::string text = FapWriter::toText(a);
    const std::string mask = "0 0 1 1 1 " + repeat("0 ", 63) + "1 0 \n";
    const std::string expected = "2.1 my_face 25 3\n" + mask + "0 2 0 0 0\n" + mask +
                                 "1 -2 2 10 3\n" + mask + "2 0 0 -8 0\n";
    QCOMPARE(QString::fromStdString(text), QString::fromStdString(expected));

    Warnings warnings;
    const std::string strict = FapWriter::toText(a, FapWriteOptions{.strict = true}, &warnings);
    QCOMPARE(QString::fromStdString(strict),
             QString::fromStdString(FapWriter::toText(smallAnimation())));
    QVERIFY(anyWarningContains(warnings, "tear"));
  }

  void dropsHighLevelFapsWithAWarning() {
    FapAnimation a = smallAnimation();
    a.frames[0][channelIndex(1)] = 5;  // viseme 5, mirrored from highLevel
    a.animated.set(channelIndex(1));
    a.highLevel.resize(3);
    a.highLevel[0].viseme.select1 = 5;
    Warnings warnings;
    const std::string text = FapWriter::toText(a, {}, &warnings);
    QCOMPARE(QString::fromStdString(text),
             QString::fromStdString(FapWriter::toText(smallAnimation())));
    QCOMPARE(warnings.size(), std::size_t(1));
    QVERIFY(anyWarningContains(warnings, "FAP 1"));

    // High-level data alone, with channels 1/2 at 0, is still data that gets dropped.
    FapAnimation expressionOnly = smallAnimation();
    expressionOnly.highLevel.resize(3);
    expressionOnly.highLevel[2].expression.intensity1 = 40;
    warnings.clear();
    FapWriter::toText(expressionOnly, {}, &warnings);
    QVERIFY(anyWarningContains(warnings, "FAP 2"));
  }

  void sanitisesNameAndFps() {
    FapAnimation a;
    a.frames.resize(1, FapValues{});
    a.name = "a b\tc\x01";
    a.fps = 29.97;
    Warnings warnings;
    QCOMPARE(QString::fromStdString(FapWriter::toText(a, {}, &warnings)),
             QString::fromStdString("2.1 a_b_c_ 30 1\n" + repeat("0 ", 68) + "\n0\n"));
    QCOMPARE(warnings.size(), std::size_t(1));
    QVERIFY(anyWarningContains(warnings, "29.97"));

    a.name = "";
    a.fps = 22;
    warnings.clear();
    QVERIFY(FapWriter::toText(a, {}, &warnings).starts_with("2.1 lacrima 22 1\n"));
    QVERIFY(warnings.empty());

    a.name = "#1";  // would read as a comment token
    QVERIFY(FapWriter::toText(a).starts_with("2.1 _1 22 1\n"));

    a.frames.clear();
    QCOMPARE(QString::fromStdString(FapWriter::toText(a)), QString("2.1 _1 22 0\n"));
  }

  void randomRoundTrips() {
    for (int seed = 0; seed < 100; ++seed) {
      std::mt19937 random(static_cast<unsigned>(seed));
      std::uniform_int_distribution<int> frames(1, 60), fps(1, 60), coin(0, 3), value(-2000, 2000),
          tears(0, 200);
      FapAnimation original;
      original.name = "seed" + std::to_string(seed);
      original.fps = fps(random);
      original.frames.resize(static_cast<std::size_t>(frames(random)), FapValues{});
      for (int fap = 3; fap <= kChannelCount; ++fap) {
        if (coin(random) != 0) continue;  // about a quarter of the channels
        const int c = channelIndex(fap);
        original.animated.set(c);
        for (FapValues& frame : original.frames)
          frame[c] = float(isTearChannel(fap)  ? tears(random)
                           : coin(random) == 0 ? 0
                                               : value(random));
        // A tear channel that is 0 everywhere is not written (68 tokens): keep one particle.
        if (isTearChannel(fap)) original.frames.front()[c] = 1;
      }
      const QString path = tmp_.filePath(QString("round-%1.fap").arg(seed));
      Warnings warnings;
      FapWriter::save(original, path.toStdString(), {}, &warnings);
      QVERIFY(warnings.empty());
      const FapReadResult read = FapReader::readFile(path.toStdString());
      QVERIFY(read.warnings.empty());
      QCOMPARE(read.animation.name, original.name);
      QCOMPARE(read.animation.fps, original.fps);
      QCOMPARE(read.animation.animated, original.animated);
      QVERIFY2(read.animation.frames == original.frames, qPrintable(QString("seed %1").arg(seed)));
      QCOMPARE(read.animation.hasTears(), original.hasTears());

      // Strict: the same, minus the tear channels.
      const FapReadResult strict =
          FapReader::parse(FapWriter::toText(original, FapWriteOptions{.strict = true}), "strict");
      FapAnimation withoutTears = original;
      for (FapValues& frame : withoutTears.frames)
        frame[channelIndex(kTearLeftFap)] = frame[channelIndex(kTearRightFap)] = 0;
      QVERIFY(strict.animation.frames == withoutTears.frames);
      QVERIFY(!strict.animation.animated.test(channelIndex(kTearLeftFap)));
    }
  }

  void failedSaveKeepsTheOldFile() {
    const QString folder = tmp_.filePath("atomic");
    QVERIFY(QDir().mkpath(folder));
    const QString path = folder + "/anim.fap";
    FapWriter::save(smallAnimation(), path.toStdString());
    const QByteArray before = fileBytes(path);
    QVERIFY(!before.isEmpty());

    FapAnimation large;
    large.frames.resize(2000, FapValues{});
    for (FapValues& frame : large.frames) frame.fill(123);

    // Root ignores file permissions, but not a file size limit: writes past it fail (EFBIG).
    rlimit saved{};
    QVERIFY(getrlimit(RLIMIT_FSIZE, &saved) == 0);
    const auto previousHandler = std::signal(SIGXFSZ, SIG_IGN);
    rlimit limited = saved;
    limited.rlim_cur = 400;
    QVERIFY(setrlimit(RLIMIT_FSIZE, &limited) == 0);
    bool threw = false;
    std::string message;
    try {
      FapWriter::save(large, path.toStdString());
    } catch (const FileError& e) {
      threw = true;
      message = e.what();
    }
    setrlimit(RLIMIT_FSIZE, &saved);
    std::signal(SIGXFSZ, previousHandler);

    QVERIFY(threw);
    QVERIFY2(message.find(path.toStdString()) != std::string::npos, message.c_str());
    QCOMPARE(fileBytes(path), before);
    QCOMPARE(QDir(folder).entryList(QDir::Files | QDir::Hidden | QDir::System),
             QStringList{"anim.fap"});
  }

  void saveIntoMissingFolderNamesThePath() {
    const std::string path = tmp_.filePath("no/such/folder/anim.fap").toStdString();
    try {
      FapWriter::save(smallAnimation(), path);
      QFAIL("saved into a folder that does not exist");
    } catch (const FileError& e) {
      QCOMPARE(e.where().file, path);
      QVERIFY2(std::string(e.what()).find(path) != std::string::npos, e.what());
    }
  }
};

QTEST_GUILESS_MAIN(FapWriterTest)
#include "FapWriterTest.moc"
