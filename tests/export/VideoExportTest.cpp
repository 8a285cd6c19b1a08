// lacrima-player --video proven with ffprobe (Debian's FFmpeg): an H.264 stream in MP4, yuv420p,
// the file's frame rate at a constant rate, one video frame per animation frame and the matching
// duration; the first and last frames decode to different pictures. An odd size is a usage
// error, a folder that does not exist fails naming the path and leaves no temporary, and without
// a display the player says to use xvfb-run.
#include "../support/MissingData.h"
#include "../support/RunProcess.h"
#include "../support/WeepingClip.h"

#include <lacrima/common/FapTable.h>
#include <lacrima/common/FapWriter.h>
#include <lacrima/rigging/DefaultHead.h>

#include <QDir>
#include <QImage>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QtTest>

using namespace lacrima;

namespace {

const QString kPlayer = QStringLiteral(LACRIMA_BIN_DIR "/lacrima-player");
constexpr int kFrames = 30;

// Rendering 30 frames under xvfb on a loaded machine: minutes at most.
constexpr int kTimeoutMs = 600000;

testsupport::ProcessRun run(const QString& program, const QStringList& arguments) {
  return testsupport::runProcess(program, arguments, kTimeoutMs);
}

}  // namespace

class VideoExportTest : public QObject {
  Q_OBJECT

  QTemporaryDir dir_;
  QString animation_, video_;

 private slots:
  void initTestCase() {
    if (!rigging::defaultHeadAvailable()) LACRIMA_SKIP_WITHOUT_DEFAULT_HEAD();
    QVERIFY(dir_.isValid());
    // The jaw opens while both eyes weep.
    animation_ = dir_.filePath("short.fap");
    FapWriter::save(testsupport::weepingClip(kFrames, 25, 20), animation_.toStdString());
    video_ = dir_.filePath("short.mp4");
    const testsupport::ProcessRun r =
        run(kPlayer, {"--video", video_, "--size", "320x240", "--view", "front", animation_});
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
  }

  void ffprobeSeesH264AtTheFileRate() {
    if (QStringLiteral(LACRIMA_FFPROBE).isEmpty())
      LACRIMA_SKIP_WITHOUT_DATA(QStringLiteral("ffprobe is not installed"),
                                QStringLiteral("apt-get install ffmpeg"));
    const testsupport::ProcessRun r =
        run(QStringLiteral(LACRIMA_FFPROBE),
            {"-v", "error", "-count_frames", "-select_streams", "v:0", "-show_entries",
             "stream=codec_name,profile,pix_fmt,width,height,r_frame_rate,avg_frame_rate,"
             "nb_read_frames,duration:format=format_name",
             "-of", "json", video_});
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    const QJsonObject probe = QJsonDocument::fromJson(r.out.toUtf8()).object();
    const QJsonArray streams = probe["streams"].toArray();
    QCOMPARE(streams.size(), 1);  // video only
    const QJsonObject s = streams[0].toObject();
    QCOMPARE(s["codec_name"].toString(), QStringLiteral("h264"));
    QCOMPARE(s["pix_fmt"].toString(), QStringLiteral("yuv420p"));
    QCOMPARE(s["width"].toInt(), 320);
    QCOMPARE(s["height"].toInt(), 240);
    QCOMPARE(s["r_frame_rate"].toString(), QStringLiteral("22/1"));
    QCOMPARE(s["avg_frame_rate"].toString(), QStringLiteral("22/1"));  // constant rate
    QCOMPARE(s["nb_read_frames"].toString().toInt(), kFrames);
    QVERIFY2(std::abs(s["duration"].toString().toDouble() - kFrames / 22.0) < 0.5 / 22,
             qPrintable(s["duration"].toString()));
    QVERIFY(probe["format"]["format_name"].toString().contains("mp4"));
  }

  void framesDecodeToTheAnimation() {
    if (QStringLiteral(LACRIMA_FFMPEG).isEmpty())
      LACRIMA_SKIP_WITHOUT_DATA(QStringLiteral("ffmpeg is not installed"),
                                QStringLiteral("apt-get install ffmpeg"));
    const QString first = dir_.filePath("first.png"), last = dir_.filePath("last.png");
    QCOMPARE(run(QStringLiteral(LACRIMA_FFMPEG),
                 {"-v", "error", "-i", video_, "-vf", "select=eq(n\\,0)", "-frames:v", "1", first})
                 .exitCode,
             0);
    QCOMPARE(run(QStringLiteral(LACRIMA_FFMPEG),
                 {"-v", "error", "-i", video_, "-vf",
                  QStringLiteral("select=eq(n\\,%1)").arg(kFrames - 1), "-frames:v", "1", last})
                 .exitCode,
             0);
    const QImage a(first), b(last);
    QCOMPARE(a.size(), QSize(320, 240));
    QCOMPARE(b.size(), QSize(320, 240));
    QVERIFY(a != b);  // the jaw opened and the tears ran
    // A face, not a blank: the middle of the picture differs from the backdrop's corner.
    QVERIFY(a.pixelColor(160, 120) != a.pixelColor(2, 2));
  }

  void badInputFailsClearly() {
    testsupport::ProcessRun r =
        run(kPlayer, {"--video", dir_.filePath("odd.mp4"), "--size", "321x240", animation_});
    QCOMPARE(r.exitCode, 2);
    QVERIFY2(r.err.contains("even") && r.err.contains("321x240"), qPrintable(r.err));
    const QString unwritable = dir_.filePath("no/such/folder/x.mp4");
    r = run(kPlayer, {"--video", unwritable, "--size", "64x64", animation_});
    QCOMPARE(r.exitCode, 1);
    QVERIFY2(r.err.contains(unwritable), qPrintable(r.err));
    r = run(kPlayer, {"--video", dir_.filePath("x.mp4"), "--view", "sideways", animation_});
    QCOMPARE(r.exitCode, 2);
    QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
    environment.remove("DISPLAY");
    r = testsupport::runProcess(kPlayer, {"--video", dir_.filePath("x.mp4"), animation_},
                                kTimeoutMs, environment);
    QCOMPARE(r.exitCode, 1);
    QVERIFY2(r.err.contains("xvfb-run"), qPrintable(r.err));
    // Nothing half-written is left behind.
    for (const QString& name : QDir(dir_.path()).entryList(QDir::Files | QDir::Hidden))
      QVERIFY2(!name.contains(".part"), qPrintable(name));
    QVERIFY(!QFile::exists(dir_.filePath("x.mp4")));
  }
};

QTEST_GUILESS_MAIN(VideoExportTest)
#include "VideoExportTest.moc"
