// lacrima-player --render --alpha --masks as a process (under xvfb-run): frames with a
// transparent background whose face is opaque and whose colours are the plain render's there,
// and beside each frame a mask of the same size from the ID pass: only the three labels, tear
// water and wet trails where the tears run, none in a clip without tears, and water where the
// tears change the picture.
#include "../support/MissingData.h"
#include "../support/RunProcess.h"
#include "../support/WeepingClip.h"

#include <lacrima/common/FapWriter.h>
#include <lacrima/rigging/DefaultHead.h>

#include <QImage>
#include <QTemporaryDir>
#include <QtTest>

#include <map>

using namespace lacrima;

namespace {

const QString kPlayer = QStringLiteral(LACRIMA_BIN_DIR "/lacrima-player");
constexpr int kFrames = 24;

testsupport::ProcessRun render(const QStringList& arguments) {
  return testsupport::runProcess(kPlayer, arguments, 600000);
}

QString numbered(const QString& dir, const char* stem, int frame) {
  return dir +
         QStringLiteral("/%1_%2.png").arg(QLatin1String(stem)).arg(frame, 4, 10, QLatin1Char('0'));
}

// Pixels of each label in a mask.
std::map<int, int> labelCounts(const QImage& mask) {
  std::map<int, int> counts;
  for (int y = 0; y < mask.height(); ++y)
    for (int x = 0; x < mask.width(); ++x) ++counts[qGray(mask.pixel(x, y))];
  return counts;
}

}  // namespace

class RenderLayersCliTest : public QObject {
  Q_OBJECT

  QTemporaryDir dir_;
  QString layers_, plain_;

 private slots:
  void initTestCase() {
    if (!rigging::defaultHeadAvailable()) LACRIMA_SKIP_WITHOUT_DEFAULT_HEAD();
    QVERIFY(dir_.isValid());
    const QString clip = dir_.filePath("weeping.fap");
    FapWriter::save(testsupport::weepingClip(kFrames, 10, 30), clip.toStdString());
    layers_ = dir_.filePath("layers");
    plain_ = dir_.filePath("plain");
    const QStringList common{"--size", "320x240", "--view", "close-left", clip};
    testsupport::ProcessRun r =
        render(QStringList{"--render", layers_, "--alpha", "--masks"} + common);
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    r = render(QStringList{"--render", plain_} + common);
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
  }

  void alphaFramesAreTransparentAroundTheFace() {
    const QImage frame(numbered(layers_, "frame", kFrames - 1));
    QCOMPARE(frame.size(), QSize(320, 240));
    QVERIFY(frame.hasAlphaChannel());
    const QImage rgba = frame.convertToFormat(QImage::Format_RGBA8888);
    const QImage plain =
        QImage(numbered(plain_, "frame", kFrames - 1)).convertToFormat(QImage::Format_RGBA8888);
    int transparent = 0, opaque = 0, partial = 0, sameColour = 0;
    for (int y = 0; y < rgba.height(); ++y) {
      for (int x = 0; x < rgba.width(); ++x) {
        const QRgb p = rgba.pixel(x, y);
        if (qAlpha(p) == 0) ++transparent;
        if (qAlpha(p) > 0 && qAlpha(p) < 255) ++partial;
        if (qAlpha(p) == 255) {
          ++opaque;
          sameColour += (p & 0xffffff) == (plain.pixel(x, y) & 0xffffff);
        }
      }
    }
    // Close up on the cheek the face fills most of the picture; the background shows at the
    // side. Where the face is opaque it is the plain render's picture.
    QVERIFY2(transparent > 0 && opaque > rgba.width() * rgba.height() / 2,
             qPrintable(QStringLiteral("%1 transparent, %2 opaque").arg(transparent).arg(opaque)));
    QVERIFY2(sameColour > opaque * 99 / 100, qPrintable(QString::number(sameColour)));
    // Lashes and brows over the skin leave it opaque (their alpha blends as "over"); only edges
    // against the background are partly transparent.
    QVERIFY2(partial < opaque / 100,
             qPrintable(QStringLiteral("%1 partly transparent of %2").arg(partial).arg(opaque)));
    qInfo("%d transparent, %d partly, %d opaque pixels", transparent, partial, opaque);
  }

  void masksLabelTearsFromTheIdPass() {
    int water = 0, trail = 0;
    for (int f = 0; f < kFrames; ++f) {
      const QImage mask(numbered(layers_, "mask", f));
      QCOMPARE(mask.size(), QSize(320, 240));
      const std::map<int, int> counts = labelCounts(mask);
      for (const auto& [label, n] : counts)
        QVERIFY2(
            label == 0 || label == 128 || label == 255,
            qPrintable(QStringLiteral("frame %1: grey %2 (%3 pixels)").arg(f).arg(label).arg(n)));
      water += counts.count(255) ? counts.at(255) : 0;
      trail += counts.count(128) ? counts.at(128) : 0;
    }
    QVERIFY2(water > 0 && trail > 0, qPrintable(QStringLiteral("%1 %2").arg(water).arg(trail)));
  }

  // Where the mask says water, the picture is the tears': it differs from the same frame of the
  // same clip without tears. (The mask comes from the ID pass, not from these colours.)
  void waterInTheMaskIsWhereTheTearsAreDrawn() {
    const QString dryClip = dir_.filePath("dry.fap"), dry = dir_.filePath("dry");
    FapWriter::save(testsupport::weepingClip(kFrames, 10, 0), dryClip.toStdString());
    const testsupport::ProcessRun r =
        render({"--render", dry, "--masks", "--size", "320x240", "--view", "close-left", dryClip});
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    // Without tears every mask is "the rest" throughout.
    for (int f = 0; f < kFrames; ++f)
      QCOMPARE(labelCounts(QImage(numbered(dry, "mask", f))).size(), std::size_t{1});
    const QImage mask(numbered(layers_, "mask", kFrames - 1));
    const QImage wet(numbered(plain_, "frame", kFrames - 1));
    const QImage withoutTears(numbered(dry, "frame", kFrames - 1));
    int water = 0, drawn = 0;
    for (int y = 0; y < mask.height(); ++y)
      for (int x = 0; x < mask.width(); ++x)
        if (qGray(mask.pixel(x, y)) == 255) {
          ++water;
          drawn += wet.pixel(x, y) != withoutTears.pixel(x, y);
        }
    QVERIFY(water > 0);
    QVERIFY2(drawn > water * 9 / 10, qPrintable(QStringLiteral("%1 of %2").arg(drawn).arg(water)));
  }

  void layersNeedRender() {
    const testsupport::ProcessRun r =
        testsupport::runProcess(kPlayer, {"--masks", dir_.filePath("x.fap")}, 60000);
    QCOMPARE(r.exitCode, 2);
    QVERIFY2(r.err.contains("--render"), qPrintable(r.err));
  }
};

QTEST_GUILESS_MAIN(RenderLayersCliTest)
#include "RenderLayersCliTest.moc"
