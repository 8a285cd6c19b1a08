// Typed numbers are read exactly as typed or refused with a reason (QSpinBox turned
// "-5" into 5, "abc1.5e3" into 153 and "999999" into 99999). parseNumber and parseTime alone.
#include <lacrima/common/FapChannels.h>
#include <lacrima/editing/NumberInput.h>

#include <QtTest>

#include <cmath>
#include <limits>

using namespace lacrima;
using namespace lacrima::editing;

namespace {

const NumberRange kTears{0, kMaxTearParticles, true, {}};
const NumberRange kOpenJaw{0, 10800, true, {}};
const NumberRange kMidlip{-18600, 18600, true, {}};
const NumberRange kFps{1, 240, false, QStringLiteral("fps")};

}  // namespace

class NumberInputTest : public QObject {
  Q_OBJECT

 private slots:
  void acceptsNumbersExactlyAsTyped_data() {
    QTest::addColumn<QString>("text");
    QTest::addColumn<double>("value");
    QTest::newRow("whole") << "44" << 44.0;
    QTest::newRow("spaces around") << "  44 " << 44.0;
    QTest::newRow("plus sign") << "+7" << 7.0;
    QTest::newRow("exponent") << "1.5e3" << 1500.0;
    QTest::newRow("capital exponent, signed") << "15E+2" << 1500.0;
    QTest::newRow("trailing point") << "12." << 12.0;
    QTest::newRow("zero") << "0" << 0.0;
    QTest::newRow("negative zero reads as zero") << "-0" << 0.0;
    QTest::newRow("the maximum itself") << "100000" << 100000.0;
  }
  void acceptsNumbersExactlyAsTyped() {
    QFETCH(QString, text);
    QFETCH(double, value);
    const NumberParse parse = parseNumber(text, kTears);
    QVERIFY2(parse.accepted(), qPrintable(parse.reason));
    QCOMPARE(*parse.value, value);
    QVERIFY(!std::signbit(*parse.value));
  }

  // The cases of the issue, and their neighbours: refused, never repaired.
  void refusesWhatTheRangeCannotTake_data() {
    QTest::addColumn<QString>("text");
    QTest::addColumn<QString>("reason");
    QTest::newRow("negative tear count") << "-5"
                                         << "below 0";
    QTest::newRow("letters before a number") << "abc1.5e3"
                                             << "not a number";
    QTest::newRow("beyond the maximum") << "999999"
                                        << "above 100000";
    QTest::newRow("half a particle") << "2.5"
                                     << "not a whole number";
    QTest::newRow("tiny fraction") << "1e-7"
                                   << "not a whole number";
    QTest::newRow("letters after") << "12abc"
                                   << "\"abc\" after the number";
    QTest::newRow("exponent without digits") << "2e"
                                             << "\"e\" after the number";
    QTest::newRow("decimal comma") << "1,5"
                                   << "use '.' for decimals and no thousands separators";
    QTest::newRow("thousands separator") << "99,999"
                                         << "use '.' for decimals and no thousands separators";
    QTest::newRow("two signs") << "--5"
                               << "not a number";
    QTest::newRow("sign alone") << "-"
                                << "not a number";
    QTest::newRow("point alone") << "."
                                 << "not a number";
    QTest::newRow("empty") << ""
                           << "empty";
    QTest::newRow("blank") << "   "
                           << "empty";
    QTest::newRow("infinity word") << "inf"
                                   << "not a number";
    QTest::newRow("nan word") << "nan"
                              << "not a number";
    QTest::newRow("hex") << "0x10"
                         << "\"x10\" after the number";
    QTest::newRow("overflow") << "1e400"
                              << "too large to be a number here";
    QTest::newRow("arabic-indic digits") << QString::fromUtf8("٥") << "not a number";
  }
  void refusesWhatTheRangeCannotTake() {
    QFETCH(QString, text);
    QFETCH(QString, reason);
    const NumberParse parse = parseNumber(text, kTears);
    QVERIFY2(!parse.accepted(), qPrintable(text));
    QCOMPARE(parse.reason, reason);
  }

  void signsAreKeptOrRefusedNeverDropped() {
    // open_jaw takes no negative value: -300 is refused, not read as 300.
    const NumberParse jaw = parseNumber(QStringLiteral("-300"), kOpenJaw);
    QVERIFY(!jaw.accepted());
    QCOMPARE(jaw.reason, QStringLiteral("below 0"));
    // A bidirectional channel takes it with its sign.
    const NumberParse midlip = parseNumber(QStringLiteral("-300"), kMidlip);
    QVERIFY(midlip.accepted());
    QCOMPARE(*midlip.value, -300.0);
    QCOMPARE(*parseNumber(QStringLiteral("-18600"), kMidlip).value, -18600.0);
    QVERIFY(!parseNumber(QStringLiteral("-18601"), kMidlip).accepted());
  }

  void unitsMayFollowTheNumber() {
    QCOMPARE(*parseNumber(QStringLiteral("25 fps"), kFps).value, 25.0);
    QCOMPARE(*parseNumber(QStringLiteral("23.976fps"), kFps).value, 23.976);
    QCOMPARE(*parseNumber(QStringLiteral("30 FPS"), kFps).value, 30.0);
    QCOMPARE(*parseNumber(QStringLiteral("30"), kFps).value, 30.0);
    QVERIFY(!parseNumber(QStringLiteral("30 f"), kFps).accepted());
    QVERIFY(!parseNumber(QStringLiteral("fps 30"), kFps).accepted());
    // A field without a unit takes none.
    QVERIFY(!parseNumber(QStringLiteral("30 fps"), kTears).accepted());
    // Fractions where the field takes them, checked against the range, not rounded into it.
    QCOMPARE(*parseNumber(QStringLiteral("0.5e1"), kFps).value, 5.0);
    QCOMPARE(parseNumber(QStringLiteral("0.5"), kFps).reason, QStringLiteral("below 1"));
    QCOMPARE(parseNumber(QStringLiteral("240.01"), kFps).reason, QStringLiteral("above 240"));
  }

  void rangesAndValuesReadAsTyped() {
    QCOMPARE(describeRange(kTears), QStringLiteral("0 … 100000, whole numbers"));
    QCOMPARE(describeRange(kFps), QStringLiteral("1 … 240 fps"));
    QCOMPARE(describeRange(kMidlip, QStringLiteral("AU")), QStringLiteral("-18600 … 18600 AU"));
    QCOMPARE(formatNumber(1500.0, 2), QStringLiteral("1500"));
    QCOMPARE(formatNumber(2.5, 3), QStringLiteral("2.5"));
    QCOMPARE(formatNumber(-0.0, 3), QStringLiteral("0"));
    QCOMPARE(formatNumber(-0.0001, 3), QStringLiteral("0"));
    QCOMPARE(formatNumber(1.0 / 22.0, 3), QStringLiteral("0.045"));
    QCOMPARE(formatNumber(std::numeric_limits<double>::infinity(), 3), QStringLiteral("?"));
  }

  void timesInSecondsOrFrames() {
    // 22 fps, the field showing seconds: "2.5" and "2.5s" are seconds, "55f" frames.
    QCOMPARE(*parseTime(QStringLiteral("2.5"), 22, TimeUnit::Seconds).seconds, 2.5);
    QCOMPARE(*parseTime(QStringLiteral("2.5s"), 22, TimeUnit::Seconds).seconds, 2.5);
    QCOMPARE(*parseTime(QStringLiteral(" 2.5 S "), 22, TimeUnit::Frames).seconds, 2.5);
    QCOMPARE(*parseTime(QStringLiteral("55f"), 22, TimeUnit::Seconds).seconds, 2.5);
    QCOMPARE(*parseTime(QStringLiteral("55 F"), 22, TimeUnit::Seconds).seconds, 2.5);
    // Showing frames, a bare number is frames.
    QCOMPARE(*parseTime(QStringLiteral("55"), 22, TimeUnit::Frames).seconds, 2.5);
    QCOMPARE(*parseTime(QStringLiteral("0"), 22, TimeUnit::Frames).seconds, 0.0);
    QCOMPARE(*parseTime(QStringLiteral("3600"), 22, TimeUnit::Seconds).seconds, 3600.0);
  }

  void timesThatCannotBeReached() {
    const auto reason = [](const char* text, TimeUnit unit) {
      const TimeParse parse = parseTime(QString::fromUtf8(text), 22, unit);
      return parse.accepted() ? QStringLiteral("accepted") : parse.reason;
    };
    QCOMPARE(reason("-1", TimeUnit::Seconds), QStringLiteral("before 0 s"));
    QCOMPARE(reason("-3f", TimeUnit::Seconds), QStringLiteral("before 0 s"));
    QCOMPARE(reason("2.5f", TimeUnit::Seconds), QStringLiteral("frames are whole"));
    QCOMPARE(reason("2.5", TimeUnit::Frames), QStringLiteral("frames are whole"));
    QCOMPARE(reason("3600.5", TimeUnit::Seconds), QStringLiteral("after 3600 s"));
    QCOMPARE(reason("79201f", TimeUnit::Seconds), QStringLiteral("after 3600 s"));
    QCOMPARE(reason("2 min", TimeUnit::Seconds),
             QStringLiteral("\"min\" after the number (units: s or f)"));
    QCOMPARE(reason("abc", TimeUnit::Seconds), QStringLiteral("not a number"));
    QCOMPARE(reason("1e400", TimeUnit::Seconds), QStringLiteral("too large to be a number here"));
    // A broken frame rate is reported, not divided by.
    QCOMPARE(parseTime(QStringLiteral("55f"), 0, TimeUnit::Seconds).reason,
             QStringLiteral("the project has no frame rate"));
    QVERIFY(!parseTime(QStringLiteral("1"), std::nan(""), TimeUnit::Seconds).accepted());
  }
};

QTEST_APPLESS_MAIN(NumberInputTest)
#include "NumberInputTest.moc"
