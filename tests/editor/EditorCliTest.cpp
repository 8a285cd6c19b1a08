// lacrima-editor's command line run as a process (offscreen): a number that is not one, or out
// of its range, is a usage error (exit status 2) whose message names the option and what it
// expects, as lacrima-player's are; valid numbers are taken.
#include "../support/RunProcess.h"

#include <QTemporaryDir>
#include <QtTest>

using namespace lacrima;

namespace {

const QString kEditor = QStringLiteral(LACRIMA_BIN_DIR "/lacrima-editor");

testsupport::ProcessRun run(const QStringList& arguments) {
  return testsupport::runProcess(kEditor, arguments, 120000);
}

}  // namespace

class EditorCliTest : public QObject {
  Q_OBJECT

  QTemporaryDir dir_;

 private slots:
  void initTestCase() { QVERIFY(dir_.isValid()); }

  void badNumbersAreUsageErrors_data() {
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<QString>("message");
    const QString time = QStringLiteral("lacrima-editor: --time: expected seconds from 0 to 86400");
    const QString focus =
        QStringLiteral("lacrima-editor: --focus: expected a FAP number from 1 to 70");
    const QString warm =
        QStringLiteral("lacrima-editor: --warm-up: expected frames from 0 to 13200");
    QTest::newRow("time word") << QStringList{"--time", "abc"} << time + ", not 'abc'";
    QTest::newRow("time trailing") << QStringList{"--time", "1.5s"} << time + ", not '1.5s'";
    QTest::newRow("time negative") << QStringList{"--time", "-1"} << time + ", not '-1'";
    QTest::newRow("time past a day") << QStringList{"--time", "86401"} << time + ", not '86401'";
    QTest::newRow("time nan") << QStringList{"--time", "nan"} << time + ", not 'nan'";
    QTest::newRow("time empty") << QStringList{"--time="} << time + ", not ''";
    QTest::newRow("focus word") << QStringList{"--focus", "jaw"} << focus + ", not 'jaw'";
    QTest::newRow("focus fraction") << QStringList{"--focus", "3.5"} << focus + ", not '3.5'";
    QTest::newRow("focus zero") << QStringList{"--focus", "0"} << focus + ", not '0'";
    QTest::newRow("focus past the tears") << QStringList{"--focus", "71"} << focus + ", not '71'";
    QTest::newRow("warm-up word") << QStringList{"--warm-up", "many"} << warm + ", not 'many'";
    QTest::newRow("warm-up negative") << QStringList{"--warm-up", "-3"} << warm + ", not '-3'";
    QTest::newRow("warm-up too many")
        << QStringList{"--warm-up", "99999"} << warm + ", not '99999'";
  }

  // Refused before any window opens, with the screenshot that would have been taken not written.
  void badNumbersAreUsageErrors() {
    QFETCH(QStringList, arguments);
    QFETCH(QString, message);
    const QString png = dir_.filePath(QString::fromUtf8(QTest::currentDataTag()) + ".png");
    const testsupport::ProcessRun r =
        run(arguments + QStringList{"--no-preview", "--screenshot", png});
    QCOMPARE(r.exitCode, 2);
    QVERIFY2(r.err.contains(message), qPrintable(r.err));
    QVERIFY(!QFile::exists(png));
  }

  // The bounds themselves are valid: the window comes up and is saved.
  void validNumbersAreTaken() {
    const QString png = dir_.filePath(QStringLiteral("valid.png"));
    const testsupport::ProcessRun r =
        run({"--time", "86400", "--focus", "70", "--warm-up", "0", "--no-preview", "--size",
             "640x480", "--screenshot", png});
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    QVERIFY(QFile::exists(png));
  }
};

QTEST_GUILESS_MAIN(EditorCliTest)
#include "EditorCliTest.moc"
