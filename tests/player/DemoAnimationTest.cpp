// The committed demo (media/demo/crying.fap) is what lacrima-fap makes of the demo project
// (media/demo/crying.json) today, byte for byte, so the two never drift apart; and it tells
// the story the README and docs/player.md promise: a sad face building up, tears welling in both
// eyes, a sob, tears drying.
#include <lacrima/common/FapReader.h>
#include <lacrima/common/FapTable.h>

#include <QFile>
#include <QProcess>
#include <QTemporaryDir>
#include <QtTest>

#include <algorithm>

using namespace lacrima;

namespace {

const QString kProject = QStringLiteral(LACRIMA_SOURCE_DIR "/media/demo/crying.json");
const QString kCommitted = QStringLiteral(LACRIMA_SOURCE_DIR "/media/demo/crying.fap");

float value(const FapAnimation& a, int frame, const char* name) {
  return a.frames[static_cast<std::size_t>(frame)]
                 [static_cast<std::size_t>(channelIndex(*fapByName(name)))];
}

int frameAt(const FapAnimation& a, double seconds) {
  return static_cast<int>(seconds * a.fps + 0.5);
}

}  // namespace

class DemoAnimationTest : public QObject {
  Q_OBJECT

 private slots:
  void committedFileIsAFreshConversion() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString fresh = dir.filePath("crying.fap");
    QProcess fap;
    fap.start(QStringLiteral(LACRIMA_BIN_DIR "/lacrima-fap"), {"convert", kProject, "-o", fresh});
    QVERIFY(fap.waitForFinished(60000));
    QVERIFY2(fap.exitStatus() == QProcess::NormalExit && fap.exitCode() == 0,
             fap.readAllStandardError().constData());
    QFile a(kCommitted), b(fresh);
    QVERIFY2(a.open(QIODevice::ReadOnly), "media/demo/crying.fap is missing");
    QVERIFY(b.open(QIODevice::ReadOnly));
    QVERIFY2(
        a.readAll() == b.readAll(),
        "media/demo/crying.fap differs from a fresh conversion of crying.json; regenerate it with "
        "lacrima-fap convert media/demo/crying.json -o media/demo/crying.fap");
  }

  void tellsTheStory() {
    const FapAnimation a = FapReader::readFile(kCommitted.toStdString()).animation;
    QVERIFY(a.hasTears());
    QVERIFY(a.duration() >= 10);
    const int last = a.frameCount() - 1;
    // Neutral and dry at the start.
    QCOMPARE(value(a, 0, "raise_l_i_eyebrow"), 0.0f);
    QCOMPARE(value(a, 0, "tears_l_eye"), 0.0f);
    // Sadness builds: inner brows up, lip corners down, before any tear.
    const int sad = frameAt(a, 3.0);
    QVERIFY(value(a, sad, "raise_l_i_eyebrow") > 150 && value(a, sad, "raise_r_i_eyebrow") > 150);
    QVERIFY(value(a, sad, "raise_l_cornerlip") < -100 && value(a, sad, "raise_r_cornerlip") < -100);
    QCOMPARE(value(a, sad, "tears_l_eye"), 0.0f);
    // Tears well in both eyes and grow.
    float peakL = 0, peakR = 0;
    int peakFrame = 0;
    for (int f = 0; f <= last; ++f) {
      if (value(a, f, "tears_l_eye") > peakL) peakFrame = f;
      peakL = std::max(peakL, value(a, f, "tears_l_eye"));
      peakR = std::max(peakR, value(a, f, "tears_r_eye"));
    }
    QVERIFY(peakL >= 60 && peakR >= 60);
    // A sob: the jaw drops and the head jerks while the tears flow.
    int sob = 0;
    for (int f = 0; f <= last; ++f)
      if (value(a, f, "open_jaw") > value(a, sob, "open_jaw")) sob = f;
    QVERIFY(value(a, sob, "open_jaw") > 200);
    QVERIFY(value(a, sob, "tears_l_eye") > 0 && value(a, sob, "tears_r_eye") > 0);
    QVERIFY(sob > sad);
    // The tears dry: after the peak the counts fall to zero by the end.
    QVERIFY(peakFrame < last);
    QCOMPARE(value(a, last, "tears_l_eye"), 0.0f);
    QCOMPARE(value(a, last, "tears_r_eye"), 0.0f);
  }
};

QTEST_GUILESS_MAIN(DemoAnimationTest)
#include "DemoAnimationTest.moc"
