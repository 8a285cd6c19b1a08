// lacrima-player --render run as a process (under xvfb-run): a short animation gives one PNG
// per frame and a contact sheet, progress on stderr; a bad file and a missing display fail
// with a clear message.
#include "../support/MissingData.h"
#include "../support/RunProcess.h"
#include "../support/WeepingClip.h"

#include <lacrima/common/FapTable.h>
#include <lacrima/common/FapWriter.h>
#include <lacrima/rigging/DefaultHead.h>

#include <QDir>
#include <QImage>
#include <QTemporaryDir>
#include <QtTest>

#include <fstream>

using namespace lacrima;

namespace {

const QString kPlayer = QStringLiteral(LACRIMA_BIN_DIR "/lacrima-player");

using Run = testsupport::ProcessRun;

Run run(const QStringList& arguments,
        const QProcessEnvironment& environment = QProcessEnvironment::systemEnvironment()) {
  return testsupport::runProcess(kPlayer, arguments, 300000, environment);
}

}  // namespace

class RenderCliTest : public QObject {
  Q_OBJECT

  QTemporaryDir dir_;
  QString animation_;

 private slots:
  void initTestCase() {
    if (!rigging::defaultHeadAvailable()) LACRIMA_SKIP_WITHOUT_DEFAULT_HEAD();
    QVERIFY(dir_.isValid());
    // 14 frames: the jaw opens while tears appear at both eyes.
    animation_ = dir_.filePath("short.fap");
    FapWriter::save(testsupport::weepingClip(14, 30, 20), animation_.toStdString());
  }

  void writesFramesAndContactSheet() {
    const QString out = dir_.filePath("render");
    const Run r = run({"--render", out, "--size", "320x240", animation_});
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    for (int f = 0; f < 14; ++f) {
      const QImage image(out + QStringLiteral("/frame_%1.png").arg(f, 4, 10, QLatin1Char('0')));
      QVERIFY2(!image.isNull(), qPrintable(QStringLiteral("frame %1 missing").arg(f)));
      QCOMPARE(image.size(), QSize(320, 240));
    }
    QVERIFY(!QFile::exists(out + "/frame_0014.png"));
    const QImage sheet(out + "/contact_sheet.png");
    QVERIFY(!sheet.isNull());
    QVERIFY(sheet.width() > 4 * 320 && sheet.height() > 3 * 240);  // 12 labelled thumbnails, 4 by 3
    QVERIFY2(r.err.contains("14/14"), qPrintable(r.err));          // progress reached the end
    QVERIFY(r.out.contains("contact_sheet.png"));
    // Frames differ: the jaw moves and the tears grow.
    QVERIFY(QImage(out + "/frame_0000.png") != QImage(out + "/frame_0013.png"));
  }

  // --frames renders part of the file, numbered by the file's frames.
  void frameRangeRendersPartOfTheFile() {
    const QString out = dir_.filePath("part");
    const Run r = run({"--render", out, "--frames", "3-5", "--size", "64x64", animation_});
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    QCOMPARE(QDir(out).entryList({"frame_*.png"}),
             QStringList({"frame_0003.png", "frame_0004.png", "frame_0005.png"}));
    QCOMPARE(run({"--render", out, "--frames", "3-99", animation_}).exitCode, 1);
  }

  // --view close-left frames the left cheek: a different picture of the same frame, at the
  // same size.
  void namedViewChangesTheCamera() {
    const QString out = dir_.filePath("close-left");
    const Run r = run({"--render", out, "--size", "320x240", "--view", "close-left", animation_});
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    const QImage close(out + "/frame_0013.png");
    QCOMPARE(close.size(), QSize(320, 240));
    const QImage framed(dir_.filePath("render") + "/frame_0013.png");
    QVERIFY(!framed.isNull());
    QVERIFY(close != framed);
  }

  // --quality reference: the same animation simulated with shorter sub-steps, so the tears
  // (and only they) land elsewhere.
  void qualityChangesTheTears() {
    const QString out = dir_.filePath("reference");
    const Run r = run({"--render", out, "--size", "320x240", "--quality", "reference", animation_});
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    const QImage reference(out + "/frame_0013.png");
    const QImage balanced(dir_.filePath("render") + "/frame_0013.png");
    QCOMPARE(reference.size(), QSize(320, 240));
    QVERIFY(!balanced.isNull());
    QVERIFY(reference != balanced);
    QCOMPARE(QImage(out + "/frame_0000.png").size(), QSize(320, 240));
  }

  void unknownQualityIsAUsageError() {
    const Run r = run({"--render", dir_.filePath("x"), "--quality", "ultra", animation_});
    QCOMPARE(r.exitCode, 2);
    QVERIFY2(r.err.contains("--quality") && r.err.contains("reference") && r.err.contains("ultra"),
             qPrintable(r.err));
  }

  void unknownViewIsAUsageError() {
    const Run r = run({"--render", dir_.filePath("x"), "--view", "sideways", animation_});
    QCOMPARE(r.exitCode, 2);
    QVERIFY2(r.err.contains("close-left") && r.err.contains("sideways"), qPrintable(r.err));
  }

  void badFileFailsNamingTheLine() {
    const QString bad = dir_.filePath("bad.fap");
    std::ofstream(bad.toStdString()) << "2.1 bad 22 1\n0 0 2\n";
    const Run r = run({"--render", dir_.filePath("bad-out"), bad});
    QCOMPARE(r.exitCode, 1);
    QVERIFY2(r.err.contains(bad + ":2"), qPrintable(r.err));
  }

  void noDisplaySuggestsXvfb() {
    QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
    environment.remove("DISPLAY");
    const Run r = run({"--render", dir_.filePath("no-display"), animation_}, environment);
    QCOMPARE(r.exitCode, 1);
    QVERIFY2(r.err.contains("xvfb-run"), qPrintable(r.err));
  }

  void threadsOutsideOneTo256IsAUsageError() {
    for (const char* text : {"0", "x"}) {
      const Run r = run({"--render", dir_.filePath("x"), "--threads", text, animation_});
      QCOMPARE(r.exitCode, 2);
      QVERIFY2(r.err.contains("--threads: expected threads from 1 to 256"), qPrintable(r.err));
    }
  }

  void wrongUsage() {
    QCOMPARE(run({"--render", dir_.filePath("x"), "--size", "big", animation_}).exitCode, 2);
    QCOMPARE(run({"--render", dir_.filePath("x")}).exitCode, 2);
  }
};

QTEST_GUILESS_MAIN(RenderCliTest)
#include "RenderCliTest.moc"
