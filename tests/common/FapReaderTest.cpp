// FapReader: the public samples, every tolerated variation, every rejected one, and inputs that
// try to make the reader crash, hang or allocate.
#include "../support/FapMaskLine.h"
#include "../support/MissingData.h"
#include "../support/WorstCaseInputs.h"

#include <lacrima/common/FapReader.h>
#include <lacrima/common/FapWriter.h>

#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <QtTest>

#include <sys/resource.h>

#include <cmath>
#include <fstream>
#include <initializer_list>
#include <random>
#include <string>

using namespace lacrima;

namespace {

const std::string kName = "t.fap";

using lacrima::test::mask;

FapReadResult parse(const std::string& text) { return FapReader::parse(text, kName); }

float at(const FapAnimation& animation, int frame, int fap) {
  return animation.frames.at(static_cast<std::size_t>(frame))[channelIndex(fap)];
}

ChannelMask channels(std::initializer_list<std::pair<int, int>> ranges) {
  ChannelMask m;
  for (auto [first, last] : ranges)
    for (int fap = first; fap <= last; ++fap) m.set(channelIndex(fap));
  return m;
}

bool anyWarningContains(const Warnings& warnings, const std::string& text, int line = -1) {
  for (const Diagnostic& d : warnings)
    if (d.message.find(text) != std::string::npos && (line < 0 || d.where.line == line))
      return true;
  return false;
}

QString describe(const Warnings& warnings) {
  QStringList lines;
  for (const Diagnostic& d : warnings) lines << QString::fromStdString(d.toString());
  return lines.join('\n');
}

// Caps the address space a little above what the process already maps, so an allocation
// sized by a number in a file throws std::bad_alloc instead of quietly succeeding.
class AddressSpaceCap {
 public:
  explicit AddressSpaceCap(long long headroomBytes) {
    getrlimit(RLIMIT_AS, &saved_);
    std::ifstream status("/proc/self/status");
    std::string key;
    long long kib = 0;
    while (status >> key) {
      if (key == "VmSize:") {
        status >> kib;
        break;
      }
    }
    rlimit capped = saved_;
    capped.rlim_cur = static_cast<rlim_t>(kib * 1024 + headroomBytes);
    active_ = kib > 0 && setrlimit(RLIMIT_AS, &capped) == 0;
  }
  ~AddressSpaceCap() {
    if (active_) setrlimit(RLIMIT_AS, &saved_);
  }
  bool active() const { return active_; }

 private:
  rlimit saved_{};
  bool active_ = false;
};

}  // namespace

#define EXPECT_EXACT(actual, expected)                                                \
  QVERIFY2((actual) == (expected), qPrintable(QStringLiteral("%1 is %2, expected %3") \
                                                  .arg(#actual)                       \
                                                  .arg(double(actual))                \
                                                  .arg(double(expected))))

class FapReaderTest : public QObject {
  Q_OBJECT

  QString samples_ = testsupport::sharedPath(QStringLiteral("mpeg4/samples"));
  QTemporaryDir tmp_;

  FapReadResult readSample(const char* relative) {
    return FapReader::readFile(QDir(samples_).filePath(relative).toStdString());
  }

  void expectError(const std::string& text, int line, int column, const std::string& part) {
    try {
      const FapReadResult result = parse(text);
      QFAIL(qPrintable("parsed without error; warnings:\n" + describe(result.warnings)));
    } catch (const FileError& e) {
      QVERIFY2(e.message().find(part) != std::string::npos, e.what());
      QVERIFY2(std::string(e.what()).rfind(kName, 0) == 0, e.what());
      QCOMPARE(e.where().line, line);
      QCOMPARE(e.where().column, column);
    }
  }

 private slots:
  void initTestCase() { QVERIFY(tmp_.isValid()); }

  // ---- the public samples (facts from samples/SOURCES.md, values read from the files) ----

  void fearSample() {
    LACRIMA_REQUIRE_SHARED(samples_);
    const FapReadResult r = readSample("vreng/fear.fap");
    const FapAnimation& a = r.animation;
    QVERIFY2(r.warnings.empty(), qPrintable(describe(r.warnings)));
    QCOMPARE(a.version, std::string("2.1"));
    QCOMPARE(a.name, std::string("fear.fap"));
    QCOMPARE(a.fps, 10.0);
    QCOMPARE(r.headerFrameCount, 14);
    QCOMPARE(a.frameCount(), 14);
    QCOMPARE(a.animated, channels({{31, 38}, {51, 60}}));
    QVERIFY(a.highLevel.empty());
    QVERIFY(!a.hasTears());
    EXPECT_EXACT(at(a, 0, 31), 0.f);
    EXPECT_EXACT(at(a, 1, 51), -17.f);
    EXPECT_EXACT(at(a, 1, 55), -17.f);
    EXPECT_EXACT(at(a, 2, 31), -19.f);
    EXPECT_EXACT(at(a, 2, 33), 19.f);
    EXPECT_EXACT(at(a, 2, 51), -35.f);
    EXPECT_EXACT(at(a, 13, 31), 341.f);
    EXPECT_EXACT(at(a, 13, 38), -99.f);
    EXPECT_EXACT(at(a, 13, 60), -69.f);
  }

  void eyesSampleIsOneBased() {
    LACRIMA_REQUIRE_SHARED(samples_);
    const FapReadResult r = readSample("vreng/eyes.fap");
    const FapAnimation& a = r.animation;
    QCOMPARE(a.version, std::string("2.0"));
    QCOMPARE(a.name, std::string("eyes.fap"));
    QCOMPARE(a.fps, 2.0);
    QCOMPARE(r.headerFrameCount, 52);
    QCOMPARE(a.frameCount(), 53);  // frames 1..52 placed by number, frame 0 filled
    QCOMPARE(a.animated, channels({{19, 26}}));
    // Exactly two warnings: the missing frame 0, and frame 52 at/beyond nframes.
    QCOMPARE(int(r.warnings.size()), 2);
    QVERIFY2(anyWarningContains(r.warnings, "frame 0 is missing", 3),
             qPrintable(describe(r.warnings)));
    QVERIFY2(anyWarningContains(r.warnings, "frame 52", 105), qPrintable(describe(r.warnings)));
    QVERIFY(a.frames[0] == a.frames[1]);  // held from the first present frame
    EXPECT_EXACT(at(a, 6, 19), 1080.f);
    EXPECT_EXACT(at(a, 6, 21), 600.f);
    EXPECT_EXACT(at(a, 16, 23), 200.f);
    EXPECT_EXACT(at(a, 16, 26), 100.f);
    EXPECT_EXACT(at(a, 52, 19), -500.f);  // the last line has no final newline
    EXPECT_EXACT(at(a, 52, 26), -100.f);
  }

  void joySampleHasCrlfAndAPathAsName() {
    LACRIMA_REQUIRE_SHARED(samples_);
    QFile raw(QDir(samples_).filePath("xface/joy.fap"));
    QVERIFY(raw.open(QIODevice::ReadOnly));
    QCOMPARE(raw.readAll().count("\r\n"), 217);  // header + 108 mask/value pairs, all CRLF

    const FapReadResult r = readSample("xface/joy.fap");
    const FapAnimation& a = r.animation;
    QVERIFY2(r.warnings.empty(), qPrintable(describe(r.warnings)));
    QCOMPARE(a.name, std::string("C:\\Users\\balci\\Work\\FACE\\exml2fap\\files\\TempFile"));
    QCOMPARE(a.fps, 25.0);
    QCOMPARE(a.frameCount(), 108);
    QCOMPARE(a.animated, channels({{3, 26}, {39, 42}, {48, 60}, {63, 63}}));
    QVERIFY(a.highLevel.empty());
    EXPECT_EXACT(at(a, 0, 4), 10.f);
    EXPECT_EXACT(at(a, 1, 25), -3.f);
    EXPECT_EXACT(at(a, 50, 3), 82.f);
    EXPECT_EXACT(at(a, 50, 19), 128.f);
    EXPECT_EXACT(at(a, 50, 25), -2435.f);
    EXPECT_EXACT(at(a, 50, 49), -354.f);
    EXPECT_EXACT(at(a, 107, 51), 10.f);
  }

  // ---- tolerated variations ----

  void headerVariants() {
    const std::string body = std::string("\n") + mask({3}) + "\n0 7\n";
    FapReadResult r = parse("2.1 t 29.97 1" + body);
    QCOMPARE(r.animation.fps, 29.97);
    QVERIFY(r.warnings.empty());

    r = parse("2.1 my happy face 25 1" + body);
    QCOMPARE(r.animation.name, std::string("my happy face"));
    QCOMPARE(r.animation.fps, 25.0);
    QVERIFY(anyWarningContains(r.warnings, "spaces", 1));

    r = parse("2 t 25 1" + body);
    QCOMPARE(r.animation.version, std::string("2"));
    QVERIFY(r.warnings.empty());

    r = parse("3.5 t 25 1" + body);
    QCOMPARE(r.animation.version, std::string("3.5"));
    QCOMPARE(r.warnings.size(), std::size_t(1));
    QCOMPARE(r.warnings[0].where.line, 1);
    QVERIFY(anyWarningContains(r.warnings, "version 3.5"));

    r = parse(
        "\xEF\xBB\xBF"
        "2.1 t 25 1" +
        body);  // UTF-8 byte order mark
    QCOMPARE(r.animation.version, std::string("2.1"));
  }

  void commentsAndBlankLinesAnywhere() {
    const std::string text =
        "# made by hand\n\n   \t\n  # indented comment\n"
        "2.1 t 25 2 # trailing comment\n"
        "\n# before a mask\n" +
        mask({3, 4}) +
        " # mask comment\n"
        "# between mask and values\n\n"
        "0 1 2 #values comment\n" +
        mask({3, 4}) + "\n" + "1 3 4\n\n# the end\n";
    const FapReadResult r = parse(text);
    QVERIFY2(r.warnings.empty(), qPrintable(describe(r.warnings)));
    QCOMPARE(r.animation.frameCount(), 2);
    EXPECT_EXACT(at(r.animation, 0, 4), 2.f);
    EXPECT_EXACT(at(r.animation, 1, 3), 3.f);
  }

  void tabsCrlfAndMissingFinalNewline() {
    std::string maskTabs = mask({3, 5});
    for (char& c : maskTabs)
      if (c == ' ') c = '\t';
    const std::string text = "2.1\tt\t25 \t 3\r\n" + maskTabs + "\r\n0\t10 \t-20\r\n" +
                             mask({3, 5}) + "\r\n1 11 -21 \r\n" + mask({3, 5}) +
                             "\r\n2 12 -22\r";  // lone final CR
    const FapReadResult r = parse(text);
    QVERIFY2(r.warnings.empty(), qPrintable(describe(r.warnings)));
    QCOMPARE(r.animation.frameCount(), 3);
    EXPECT_EXACT(at(r.animation, 0, 5), -20.f);
    EXPECT_EXACT(at(r.animation, 2, 3), 12.f);
    EXPECT_EXACT(at(r.animation, 2, 5), -22.f);

    const FapReadResult noNewline = parse("2.1 t 25 1\n" + mask({3}) + "\n0 42");
    EXPECT_EXACT(at(noNewline.animation, 0, 3), 42.f);
  }

  void decimalValues() {
    const FapReadResult r =
        parse("2.1 t 25 1\n" + mask({3, 4, 5, 6, 7, 8}) + "\n0 1.5 -2.25 +3 1e2 .5 -0\n");
    const FapAnimation& a = r.animation;
    EXPECT_EXACT(at(a, 0, 3), 1.5f);
    EXPECT_EXACT(at(a, 0, 4), -2.25f);
    EXPECT_EXACT(at(a, 0, 5), 3.f);
    EXPECT_EXACT(at(a, 0, 6), 100.f);
    EXPECT_EXACT(at(a, 0, 7), 0.5f);
    EXPECT_EXACT(at(a, 0, 8), 0.f);
  }

  void seventyTokenMasksCarryTears() {
    const std::string text = "2.1 t 25 2\n" + mask({3, 69, 70}, kChannelCount) + "\n0 5 12 0\n" +
                             mask({3}) + "\n1 6\n";  // a 68-token frame: no tears in it
    const FapReadResult r = parse(text);
    const FapAnimation& a = r.animation;
    QVERIFY2(r.warnings.empty(), qPrintable(describe(r.warnings)));
    QCOMPARE(a.animated, channels({{3, 3}, {69, 70}}));
    QVERIFY(a.hasTears());
    EXPECT_EXACT(at(a, 0, kTearLeftFap), 12.f);
    EXPECT_EXACT(at(a, 0, kTearRightFap), 0.f);
    EXPECT_EXACT(at(a, 1, kTearLeftFap), 0.f);
    EXPECT_EXACT(at(a, 1, 3), 6.f);

    const FapReadResult most = parse("2.1 t 25 1\n" + mask({70}, kChannelCount) + "\n0 100000.0\n");
    EXPECT_EXACT(at(most.animation, 0, kTearRightFap), float(kMaxTearParticles));
  }

  void groupedHighLevelFaps() {
    const std::string text =
        "2.1 t 25 1\n" + mask({1, 2, 3}) + "\n0 3 7 40 1  2 50 4 10 1 0  -12\n";
    const FapReadResult r = parse(text);
    const FapAnimation& a = r.animation;
    QCOMPARE(a.highLevel.size(), std::size_t(1));
    const HighLevelFrame& h = a.highLevel[0];
    QCOMPARE(h.viseme, (VisemeParams{3, 7, 40, true}));
    QCOMPARE(h.expression, (ExpressionParams{2, 50, 4, 10, true, false}));
    EXPECT_EXACT(at(a, 0, 1), 3.f);  // mirrors viseme_select1
    EXPECT_EXACT(at(a, 0, 2), 2.f);  // mirrors expression_select1
    EXPECT_EXACT(at(a, 0, 3), -12.f);
    QVERIFY(a.animated.test(channelIndex(1)) && a.animated.test(channelIndex(2)));
  }

  void scalarHighLevelFaps() {
    const std::string text =
        "2.1 t 25 2\n" + mask({1, 2, 3}) + "\n0 5 2 -12\n" + mask({1}) + "\n1 9\n";
    const FapReadResult r = parse(text);
    const FapAnimation& a = r.animation;
    QCOMPARE(a.highLevel.size(), std::size_t(2));
    QCOMPARE(a.highLevel[0].viseme, (VisemeParams{5, 0, 63, false}));
    QCOMPARE(a.highLevel[0].expression, (ExpressionParams{2, 63, 0, 0, false, false}));
    QCOMPARE(a.highLevel[1].viseme.select1, 9);
    QCOMPARE(a.highLevel[1].expression, ExpressionParams{});  // masked off in frame 1
    EXPECT_EXACT(at(a, 0, 1), 5.f);
    EXPECT_EXACT(at(a, 0, 2), 2.f);
    EXPECT_EXACT(at(a, 0, 3), -12.f);
    EXPECT_EXACT(at(a, 1, 1), 9.f);
    EXPECT_EXACT(at(a, 1, 2), 0.f);
  }

  void maskedOffIsZeroInThatFrame() {
    const std::string text = "2.1 t 25 3\n" + mask({3}) + "\n0 50\n" + mask({4}) + "\n1 60\n" +
                             mask({3, 4}) + "\n2 70 80\n";
    const FapReadResult r = parse(text);
    const FapAnimation& a = r.animation;
    QCOMPARE(a.animated, channels({{3, 4}}));
    EXPECT_EXACT(at(a, 0, 4), 0.f);
    EXPECT_EXACT(at(a, 1, 3), 0.f);  // not held from frame 0
    EXPECT_EXACT(at(a, 1, 4), 60.f);
    EXPECT_EXACT(at(a, 2, 3), 70.f);
  }

  void framesPlacedByNumber() {
    const std::string m = mask({3});
    const FapReadResult r =
        parse("2.1 t 25 3\n" + m + "\n2 30\n" + m + "\n0 10\n" + m + "\n1 20\n");
    QVERIFY2(r.warnings.empty(), qPrintable(describe(r.warnings)));
    QCOMPARE(r.animation.frameCount(), 3);
    for (int f = 0; f < 3; ++f) EXPECT_EXACT(at(r.animation, f, 3), 10.f * (f + 1));
  }

  void duplicateFrameLaterWins() {
    const std::string m = mask({3});
    const FapReadResult r =
        parse("2.1 t 25 2\n" + m + "\n0 10\n" + m + "\n1 20\n" + m + "\n1 21\n");
    QCOMPARE(r.animation.frameCount(), 2);
    EXPECT_EXACT(at(r.animation, 1, 3), 21.f);
    QCOMPARE(r.warnings.size(), std::size_t(1));
    QCOMPARE(r.warnings[0].where.line, 7);
    QVERIFY(anyWarningContains(r.warnings, "frame 1 appears again (first at line 5)"));
  }

  void gapsAreInterpolated() {
    // Frames 2 and 6 present, nframes 8: 0-1 held, 3-5 interpolated, 7 held.
    const std::string m = mask({1, 3, 69}, kChannelCount);
    const std::string text = "2.1 t 25 8\n" + m + "\n2 4 0 0\n" + m + "\n6 9 100 3\n";
    const FapReadResult r = parse(text);
    const FapAnimation& a = r.animation;
    QCOMPARE(a.frameCount(), 8);
    for (int f : {0, 1}) QVERIFY(a.frames[f] == a.frames[2]);
    EXPECT_EXACT(at(a, 3, 3), 25.f);
    EXPECT_EXACT(at(a, 4, 3), 50.f);
    EXPECT_EXACT(at(a, 5, 3), 75.f);
    EXPECT_EXACT(at(a, 3, kTearLeftFap), 1.f);  // 0.75 -> whole particles
    EXPECT_EXACT(at(a, 4, kTearLeftFap), 2.f);  // 1.5
    EXPECT_EXACT(at(a, 5, kTearLeftFap), 2.f);  // 2.25
    for (int f : {3, 4, 5}) {
      EXPECT_EXACT(at(a, f, 1), 4.f);  // codes are held, not blended
      QCOMPARE(a.highLevel[f], a.highLevel[2]);
    }
    QVERIFY(a.frames[7] == a.frames[6]);
    QCOMPARE(a.highLevel[7], a.highLevel[6]);
    QCOMPARE(a.highLevel[0].viseme.select1, 4);

    QCOMPARE(r.warnings.size(), std::size_t(3));  // one per gap run
    QVERIFY2(anyWarningContains(r.warnings, "frames 0-1 are missing", 3),
             qPrintable(describe(r.warnings)));
    QVERIFY2(anyWarningContains(r.warnings, "frames 3-5 are missing", 5),
             qPrintable(describe(r.warnings)));
    QVERIFY2(anyWarningContains(r.warnings, "frame 7 is missing", 1),
             qPrintable(describe(r.warnings)));
  }

  void framesBeyondHeaderExtend() {
    const std::string m = mask({3});
    const FapReadResult r =
        parse("2.1 t 25 2\n" + m + "\n0 1\n" + m + "\n1 2\n" + m + "\n2 3\n" + m + "\n3 4\n");
    QCOMPARE(r.headerFrameCount, 2);
    QCOMPARE(r.animation.frameCount(), 4);
    QCOMPARE(r.warnings.size(), std::size_t(1));
    QCOMPARE(r.warnings[0].where.line, 7);
    QVERIFY(anyWarningContains(r.warnings, "extended to 4 frames"));
  }

  void headerWithoutFrames() {
    FapReadResult r = parse("2.1 t 25 0\n");
    QCOMPARE(r.animation.frameCount(), 0);
    QVERIFY(r.warnings.empty());
    r = parse("2.1 t 25 3\n# nothing else\n");
    QCOMPARE(r.animation.frameCount(), 0);
    QVERIFY(anyWarningContains(r.warnings, "holds none", 1));
  }

  void sampledBetweenFrames() {
    // What a player rendering faster than the file does with what the reader returns.
    const std::string m = mask({1, 3, 69}, kChannelCount);
    const FapAnimation a = parse("2.1 t 2 2\n" + m + "\n0 4 0 0\n" + m + "\n1 9 100 3\n").animation;
    const FapValues quarter = a.sample(0.125);  // a quarter of the way: 2 fps
    EXPECT_EXACT(quarter[channelIndex(3)], 25.f);
    EXPECT_EXACT(quarter[channelIndex(kTearLeftFap)], 1.f);  // 0.75 particles -> 1
    EXPECT_EXACT(quarter[channelIndex(1)], 4.f);             // viseme code held
    QVERIFY(a.sample(-1) == a.frames[0]);
    QVERIFY(a.sample(0) == a.frames[0]);
    QVERIFY(a.sample(0.5) == a.frames[1]);
    QVERIFY(a.sample(60) == a.frames[1]);
    QVERIFY(a.sample(std::nan("")) == a.frames[0]);
    QVERIFY(FapAnimation{}.sample(1) == FapValues{});
  }

  // ---- rejected input: file:line:column and what was expected ----

  void malformed_data() {
    QTest::addColumn<QByteArray>("text");
    QTest::addColumn<int>("line");
    QTest::addColumn<int>("column");
    QTest::addColumn<QString>("part");
    const std::string h = "2.1 t 25 1\n";
    const std::string m = mask({3, 5});
    const std::string mt = mask({3, 69}, kChannelCount);
    auto row = [](const char* name, const std::string& text, int line, int column,
                  const char* part) {
      QTest::newRow(name) << QByteArray(text.data(), qsizetype(text.size())) << line << column
                          << QString(part);
    };
    row("empty", "", 0, 0, "empty file");
    row("only comments", "# x\n\n  # y\n", 0, 0, "no header");
    row("header too short", "2.1 t 25\n", 1, 10, "expected the header");
    row("header cut by comment", "2.1 t #25 1\n", 1, 7, "found 2 tokens");
    row("version not a number", "v2.1 t 25 1\n", 1, 1, "version");
    row("version zero", "0 t 25 1\n", 1, 1, "positive");
    row("fps not a number", "2.1 t fast 1\n", 1, 7, "frame rate");
    row("fps zero", "2.1 t 0 1\n", 1, 7, "above 0");
    row("fps too high", "2.1 t 1000.5 1\n", 1, 7, "at most 1000");
    row("fps nan", "2.1 t nan 1\n", 1, 7, "not finite");
    row("fps inf", "2.1 t inf 1\n", 1, 7, "not finite");
    row("nframes negative", "2.1 t 25 -3\n", 1, 10, "negative");
    row("nframes absurd", "2.1 t 25 10000001\n", 1, 10, "absurd");
    row("nframes decimal", "2.1 t 25 1.5\n", 1, 10, "whole number");
    row("NUL in header", std::string("2.1 t\0 25 1\n", 12), 1, 6, "binary data");
    row("ELF file",
        std::string("\x7f"
                    "ELF\x02\x01\x01\0\0\0",
                    10),
        1, 1, "binary data");
    row("UTF-16 file",
        std::string("\xff\xfe"
                    "2\0.\0"
                    "1\0",
                    8),
        1, 4, "binary data");
    row("control byte in comment", h + "# ok\x01\n", 2, 5, "binary data");
    row("control byte in values", h + m + "\n0 1\x02 2\n", 3, 4, "binary data");
    row("mask token 2", h + "0 0 1 0 1 0 0 0 2" + mask({}).substr(17) + "\n0 1 2\n", 2, 17,
        "0 or 1");
    row("mask token 00", h + "00" + mask({}).substr(1) + "\n0\n", 2, 1, "'00'");
    row("bad mask token before count", h + "0 0 2\n0\n", 2, 5, "0 or 1");  // both faults
    row("mask of 67 tokens", h + mask({}).substr(2) + "\n0\n", 2, 135, "68 or 70");
    row("mask of 69 tokens", h + mask({}) + " 0\n0\n", 2, 137, "found 69");
    row("mask of 71 tokens", h + mask({}, kChannelCount) + " 0\n0\n", 2, 141, "found 71");
    row("too few values", h + m + "\n0 10\n", 3, 6, "expected 3 tokens");
    row("too many values", h + m + "\n0 10 20 30\n", 3, 9, "found 4");
    row("value not a number", h + m + "\n0 10 abc\n", 3, 6, "found 'abc'");
    row("long token cut", h + m + "\n0 10 abcdefghijklmnopqrstuvwxyz\n", 3, 6,
        "'abcdefghijklmnopqrst...'");
    row("value nan", h + m + "\n0 nan 1\n", 3, 3, "not finite");
    row("value -inf", h + m + "\n0 1 -inf\n", 3, 5, "not finite");
    row("value beyond float", h + m + "\n0 1 1e39\n", 3, 5, "out of range");
    row("value beyond double", h + m + "\n0 1 1e400\n", 3, 5, "out of range");
    row("value +-5", h + m + "\n0 1 +-5\n", 3, 5, "found '+-5'");
    row("value hex", h + m + "\n0 1 0x10\n", 3, 5, "found '0x10'");
    row("frame negative", h + m + "\n-1 10 20\n", 3, 1, "start at 0");
    row("frame decimal", h + m + "\n1.5 10 20\n", 3, 1, "frame number");
    row("frame absurd", h + m + "\n2000000000 10 20\n", 3, 1, "absurd");
    row("frame too far", h + m + "\n0 1 2\n" + m + "\n500000 10 20\n", 5, 1, "too far beyond");
    row("header fill too far", "2.1 t 25 500000\n" + m + "\n0 1 2\n", 1, 10, "announces 500000");
    row("mask at end", h + m + "\n", 2, 0, "ends after a mask line");
    row("mask at end, comments after", h + "# c\n" + m + "\n# c\n\n", 3, 0,
        "ends after a mask line");
    row("tear fraction", h + mt + "\n0 1 2.5\n", 3, 5, "tear channel 69");
    row("tear negative", h + mt + "\n0 1 -1\n", 3, 5, "whole number of particles");
    row("tear too many", h + mt + "\n0 1 100001\n", 3, 5, "from 0 to 100000");
    row("FAP 1/2 neither dialect", h + mask({1, 3}) + "\n0 1 2 3\n", 3, 7, "expected 6 tokens");
    row("FAP 1 code not whole", h + mask({1}) + "\n0 2.5\n", 3, 3, "viseme_select1");
    row("FAP 2 code negative", h + mask({2}) + "\n0 1 2 3 4 -1 0\n", 3, 11, "init_face");
    row("line too long", h + std::string(FapReader::kMaxLineLength + 1, '0') + "\n", 2,
        int(FapReader::kMaxLineLength) + 1, "longer than");
  }

  void malformed() {
    QFETCH(QByteArray, text);
    QFETCH(int, line);
    QFETCH(int, column);
    QFETCH(QString, part);
    expectError(text.toStdString(), line, column, part.toStdString());
  }

  // Refused at the line's limit, in text and from a file. How long the refusal takes is a
  // figure of `lacrima-bench worst-cases`.
  void anEightMegabyteLineIsRefused() {
    const std::string text = test::eightMebibyteLineFap();
    expectError(text, 3, int(FapReader::kMaxLineLength) + 1, "longer than");
    if (QTest::currentTestFailed()) return;

    const QString path = tmp_.filePath("long-line.fap");
    {
      std::ofstream out(path.toStdString(), std::ios::binary);
      out << text;
    }
    try {
      FapReader::readFile(path.toStdString());
      QFAIL("read an 8 MB line");
    } catch (const FileError& e) {
      QCOMPARE(e.where().line, 3);
    }
  }

  void hugeFrameNumbersAllocateNothing() {
    AddressSpaceCap cap(64ll << 20);  // 64 MiB: far below a frame array for these numbers
    if (!cap.active()) QSKIP("cannot limit the address space here");
    const std::string m = mask({3});
    for (const char* number : {"2000000000", "9999999", "500000"}) {
      const std::string text = "2.1 t 25 1\n" + m + "\n" + number + " 5\n";
      try {
        parse(text);
        QFAIL("accepted a lone far frame");
      } catch (const FileError& e) {
        QCOMPARE(e.where().line, 3);
      } catch (const std::bad_alloc&) {
        QFAIL(qPrintable(QString("allocated for frame %1").arg(number)));
      }
    }
    try {
      parse("2.1 t 25 9999999\n" + m + "\n0 5\n");
      QFAIL("accepted nframes far beyond the frames present");
    } catch (const FileError& e) {
      QCOMPARE(e.where().line, 1);
    } catch (const std::bad_alloc&) {
      QFAIL("allocated for nframes");
    }
  }

  // ---- files on disk ----

  void readFileMatchesParseAcrossChunks() {
    // ~1.4 MB with comments and CRLF: many lines straddle the reader's 64 KiB chunks.
    FapAnimation animation;
    std::mt19937 random(7);
    std::uniform_int_distribution<int> value(-500, 500);
    for (int f = 0; f < 2500; ++f) {
      FapValues frame{};
      for (int fap = 3; fap <= 70; ++fap)
        frame[channelIndex(fap)] = isTearChannel(fap) ? f % 50 : value(random);
      animation.frames.push_back(frame);
    }
    animation.animated = channels({{3, 70}});
    std::string text = FapWriter::toText(animation);
    std::string mixed;
    int line = 0;
    for (std::size_t start = 0; start < text.size();) {
      const std::size_t end = text.find('\n', start);
      mixed.append(text, start, end - start);
      mixed += (++line % 3 == 0) ? "\r\n# note\n" : "\r\n";
      start = end + 1;
    }
    const QString path = tmp_.filePath("chunks.fap");
    {
      std::ofstream out(path.toStdString(), std::ios::binary);
      out << mixed;
    }
    const FapReadResult fromFile = FapReader::readFile(path.toStdString());
    const FapReadResult fromMemory = FapReader::parse(mixed, path.toStdString());
    QVERIFY(fromFile.warnings.empty());
    QCOMPARE(fromFile.animation.frameCount(), 2500);
    QVERIFY(fromFile.animation.frames == animation.frames);
    QVERIFY(fromMemory.animation.frames == animation.frames);
    QCOMPARE(fromFile.animation.animated, animation.animated);
  }

  void readFileReportsMissingAndUnreadable() {
    const std::string missing = tmp_.filePath("no-such.fap").toStdString();
    try {
      FapReader::readFile(missing);
      QFAIL("read a missing file");
    } catch (const FileError& e) {
      QCOMPARE(e.where().file, missing);
      QVERIFY2(std::string(e.what()).find("No such file") != std::string::npos, e.what());
    }
    const std::string folder = tmp_.path().toStdString();
    try {
      FapReader::readFile(folder);
      QFAIL("read a directory");
    } catch (const FileError& e) {
      QCOMPARE(e.where().file, folder);
      QVERIFY2(std::string(e.what()).find("cannot read") != std::string::npos, e.what());
    }
  }

  // ---- hostile input: parses or throws FileError, never anything else ----

  void randomInputNeverCrashes() {
    AddressSpaceCap cap(256ll << 20);
    const std::string valid = "2.1 t 25 3\n" + mask({1, 3, 4}) + "\n0 1 2 3\n" + mask({2, 69}, 70) +
                              "\n1 4 5 6 7 0 1 3\n# c\n" + mask({3}) + "\n2 9\n";
    const std::vector<std::string> soup = {"0",       "1",      "2.1",     "25",
                                           " ",       "  ",     "\t",      "\n",
                                           "\r\n",    "\r",     "#",       "# c\n",
                                           "-1",      "1e39",   "nan",     "+",
                                           "-",       ".",      "1.5",     "2000000000",
                                           "99999",   "70",     "68",      std::string(1, '\0'),
                                           "\xff",    "e5",     mask({3}), mask({1, 2}, 70),
                                           "0 0 0 0", "100000", "100001"};
    int parsed = 0;
    for (int seed = 0; seed < 600; ++seed) {
      std::mt19937 random(static_cast<unsigned>(seed));
      std::string text;
      if (seed < 200) {  // random bytes, mostly printable so they reach past the first checks
        std::uniform_int_distribution<int> length(0, 3000), byte(0, 255), printable(32, 126);
        const int n = length(random);
        for (int i = 0; i < n; ++i)
          text += static_cast<char>(i % 7 == 0   ? byte(random)
                                    : i % 5 == 0 ? '\n'
                                                 : printable(random));
      } else if (seed < 400) {  // token soup after a plausible header
        std::uniform_int_distribution<std::size_t> pick(0, soup.size() - 1);
        std::uniform_int_distribution<int> length(0, 400);
        text = seed % 2 ? "2.1 t 25 3\n" : "";
        for (int i = length(random); i > 0; --i) text += soup[pick(random)] + (i % 3 ? " " : "");
      } else {  // a valid file with a few bytes changed, cut or repeated
        text = valid;
        std::uniform_int_distribution<std::size_t> where(0, text.size() - 1);
        std::uniform_int_distribution<int> byte(0, 255), edits(1, 4);
        for (int e = edits(random); e > 0 && !text.empty(); --e) {
          const std::size_t i = where(random) % text.size();
          switch (byte(random) % 3) {
            case 0:
              text[i] = static_cast<char>(byte(random));
              break;
            case 1:
              text.erase(i, 1 + i % 5);
              break;
            default:
              text.insert(i, text.substr(i / 2, 7));
              break;
          }
        }
      }
      try {
        const FapReadResult r = parse(text);
        ++parsed;
        const FapAnimation& a = r.animation;
        QVERIFY(a.fps > 0 && a.fps <= 1000);
        QVERIFY(a.highLevel.empty() || a.highLevel.size() == a.frames.size());
        // Memory follows the input, plus at most the documented number of invented frames.
        QVERIFY(a.frames.size() <= text.size() + FapReader::kMaxFilledFrames);
        for (const FapValues& frame : a.frames)
          for (float v : frame) QVERIFY(std::isfinite(v));
      } catch (const FileError& e) {
        QVERIFY(!e.message().empty());
      } catch (const std::exception& e) {
        QFAIL(qPrintable(QString("seed %1: %2").arg(seed).arg(e.what())));
      }
    }
    QVERIFY(parsed > 0);  // some mutations stay valid: the loop exercised the success path too
  }
};

QTEST_GUILESS_MAIN(FapReaderTest)
#include "FapReaderTest.moc"
