// lacrima-player --export-tears: one PLY per frame, numbered by the file's frames, holding exactly
// the water and trails Lacrima's playback shows (vertex and face counts frame by frame, empty
// where it shows none), coloured by kind, in metres; Blender's PLY importer reads one. A dry file
// writes only empty frames; bad folders and ranges fail clearly.
#include "../support/MissingData.h"
#include "../support/RunProcess.h"
#include "../support/WeepingClip.h"

#include <lacrima/common/FapWriter.h>
#include <lacrima/playback/Playback.h>
#include <lacrima/rigging/DefaultHead.h>
#include <lacrima/tears/SurfaceMesher.h>
#include <lacrima/tears/TrailBuilder.h>

#include <QFile>
#include <QTemporaryDir>
#include <QtTest>

using namespace lacrima;

namespace {

const QString kPlayer = QStringLiteral(LACRIMA_BIN_DIR "/lacrima-player");
constexpr int kFrames = 24;

testsupport::ProcessRun run(const QString& program, const QStringList& arguments) {
  return testsupport::runProcess(program, arguments, 600000);
}

struct Ply {
  bool valid = false;
  long long vertices = -1, faces = -1;
  QByteArray body;  // after end_header
};

Ply readPly(const QString& path) {
  QFile file(path);
  Ply ply;
  if (!file.open(QIODevice::ReadOnly)) return ply;
  const QByteArray bytes = file.readAll();
  const qsizetype end = bytes.indexOf("end_header\n");
  if (!bytes.startsWith("ply\nformat binary_little_endian 1.0\n") || end < 0) return ply;
  for (const QByteArray& line : bytes.left(end).split('\n')) {
    if (line.startsWith("element vertex ")) ply.vertices = line.mid(15).toLongLong();
    if (line.startsWith("element face ")) ply.faces = line.mid(13).toLongLong();
  }
  ply.body = bytes.mid(end + 11);
  // 28 bytes a vertex (6 floats, 4 colour bytes), 13 a triangle (count and 3 indices).
  ply.valid = ply.body.size() == ply.vertices * 28 + ply.faces * 13;
  return ply;
}

QString frameFile(const QString& dir, int frame) {
  return dir + QStringLiteral("/tears_%1.ply").arg(frame, 4, 10, QLatin1Char('0'));
}

}  // namespace

class TearMeshExportTest : public QObject {
  Q_OBJECT

  QTemporaryDir dir_;
  QString weeping_, out_;

 private slots:
  void initTestCase() {
    if (!rigging::defaultHeadAvailable()) LACRIMA_SKIP_WITHOUT_DEFAULT_HEAD();
    QVERIFY(dir_.isValid());
    weeping_ = dir_.filePath("weeping.fap");
    FapWriter::save(testsupport::weepingClip(kFrames, 20, 25), weeping_.toStdString());
    out_ = dir_.filePath("tears");
    const testsupport::ProcessRun r = run(kPlayer, {"--export-tears", out_, weeping_});
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
  }

  // Every frame's file holds what the playback shows at that frame.
  void framesHoldThePlaybacksTears() {
    const auto rig = playback::loadDefaultHeadRig();
    playback::Playback playback(*rig);
    playback.open(weeping_.toStdString());
    int withTears = 0;
    for (int f = 0; f < kFrames; ++f) {
      const playback::FrameView& view = playback.seek(f / playback.frameRate());
      long long vertices = 0, faces = 0;
      for (const tears::TearSurface* water : {view.surface, view.drops})
        if (water) vertices += water->vertexCount(), faces += water->triangleCount();
      if (view.trails)
        vertices += view.trails->vertexCount(), faces += view.trails->triangleCount();
      const Ply ply = readPly(frameFile(out_, f));
      QVERIFY2(ply.valid, qPrintable(frameFile(out_, f)));
      QCOMPARE(ply.vertices, vertices);
      QCOMPARE(ply.faces, faces);
      withTears += vertices > 0;
      // Water is blue and opaque; positions are metres (a head is a few tenths of one).
      for (long long v = 0; v < ply.vertices; ++v) {
        float x;
        std::memcpy(&x, ply.body.constData() + v * 28, 4);
        QVERIFY(std::isfinite(x) && std::abs(x) < 0.5f);
      }
      if (view.surface && !view.surface->empty()) {
        const auto* colour = reinterpret_cast<const unsigned char*>(ply.body.constData() + 24);
        QCOMPARE(int(colour[2]), 255);
        QCOMPARE(int(colour[3]), 255);
      }
    }
    QVERIFY(withTears > kFrames / 2);
    QVERIFY(!QFile::exists(frameFile(out_, kFrames)));
  }

  void blenderReadsAFrame() {
    if (QStringLiteral(LACRIMA_BLENDER).isEmpty())
      LACRIMA_SKIP_WITHOUT_DATA(QStringLiteral("Blender is not installed"),
                                QStringLiteral("apt-get install blender"));
    const QString last = frameFile(out_, kFrames - 1);
    const Ply ply = readPly(last);
    QVERIFY(ply.vertices > 0);
    const testsupport::ProcessRun r =
        run(QStringLiteral(LACRIMA_BLENDER),
            {"-b", "--factory-startup", "--python-exit-code", "1", "--python",
             QStringLiteral(LACRIMA_SOURCE_DIR "/tests/export/blender-check-ply.py"), "--", last,
             QString::number(ply.vertices), QString::number(ply.faces)});
    QVERIFY2(r.exitCode == 0 && r.out.contains("PLY OK"), qPrintable(r.out.right(2000) + r.err));
  }

  void dryFileWritesEmptyFrames() {
    const QString dry = dir_.filePath("dry.fap"), out = dir_.filePath("dry");
    FapWriter::save(testsupport::weepingClip(6, 20, 0), dry.toStdString());
    const testsupport::ProcessRun r = run(kPlayer, {"--export-tears", out, dry});
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    QVERIFY2(r.err.contains("tears in 0"), qPrintable(r.err));
    for (int f = 0; f < 6; ++f) {
      const Ply ply = readPly(frameFile(out, f));
      QVERIFY(ply.valid);
      QCOMPARE(ply.vertices, 0);
    }
  }

  void badInputFailsClearly() {
    QFile blocker(dir_.filePath("a-file"));
    QVERIFY(blocker.open(QIODevice::WriteOnly));
    blocker.close();
    const QString unwritable = dir_.filePath("a-file/tears");
    testsupport::ProcessRun r = run(kPlayer, {"--export-tears", unwritable, weeping_});
    QCOMPARE(r.exitCode, 1);
    QVERIFY2(r.err.contains(unwritable), qPrintable(r.err));
    r = run(kPlayer, {"--export-tears", dir_.filePath("x"), "--frames", "3-1", weeping_});
    QCOMPARE(r.exitCode, 2);
  }
};

QTEST_GUILESS_MAIN(TearMeshExportTest)
#include "TearMeshExportTest.moc"
