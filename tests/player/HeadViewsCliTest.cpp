// `lacrima-player --render --view` on a project that names its own head: the ICT-FaceKit head in
// its centimetres and scaled to millimetres. close-left must show the left cheek with its tear
// running down the middle of the picture (before the views fitted any head it showed the neck,
// the tear a sliver at the left edge), and front the whole face. The tears are found as the
// pixels that differ from the same animation without tears. Runs under xvfb-run; skips without
// ../shared (the ICT-FaceKit head).
#include "../editor/IctProject.h"

#include <QImage>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <QtTest>

namespace {

const QString kPlayer = QStringLiteral(LACRIMA_BIN_DIR "/lacrima-player");
const QString kLastFrame = QStringLiteral("/frame_0013.png");

// 0.6 s at 22 fps (14 frames), both eyes shedding `tears` particles.
QByteArray keysWithTears(int tears) {
  return QStringLiteral(R"([{"time": 0, "values": {"tears_l_eye": %1, "tears_r_eye": %1}},
                            {"time": 0.6, "values": {"tears_l_eye": %1, "tears_r_eye": %1}}])")
      .arg(tears)
      .toUtf8();
}

bool render(const QStringList& arguments, QString* err) {
  QProcess process;
  process.start(kPlayer, arguments);
  if (!process.waitForFinished(120000)) {
    process.kill();
    *err = QStringLiteral("timed out");
    return false;
  }
  *err = QString::fromLocal8Bit(process.readAllStandardError());
  return process.exitStatus() == QProcess::NormalExit && process.exitCode() == 0;
}

// The ICT head's feature-point file for the head scaled by `scale`: its lengths scaled.
QByteArray scaledFdp(double scale) {
  QFile file(lacrima::rigtest::kIctFdp);
  if (!file.open(QIODevice::ReadOnly)) return {};
  QJsonObject fdp = QJsonDocument::fromJson(file.readAll()).object();
  QJsonArray pivot = fdp["neck_pivot"].toArray();
  for (int i = 0; i < pivot.size(); ++i) pivot[i] = pivot[i].toDouble() * scale;
  fdp["neck_pivot"] = pivot;
  QJsonObject points = fdp["points"].toObject();
  for (auto it = points.begin(); it != points.end(); ++it) {
    QJsonObject point = it->toObject();
    if (point.contains("radius")) point["radius"] = point["radius"].toDouble() * scale;
    *it = point;
  }
  fdp["points"] = points;
  return QJsonDocument(fdp).toJson();
}

// Rewrites the OBJ's vertex positions ("v x y z") scaled by `scale`.
bool scaleObj(const QString& path, double scale) {
  QFile file(path);
  if (!file.open(QIODevice::ReadOnly)) return false;
  QByteArray out;
  for (const QByteArray& line : file.readAll().split('\n')) {
    if (line.startsWith("v ")) {
      const QList<QByteArray> xyz = line.simplified().split(' ');
      if (xyz.size() < 4) return false;
      out += "v " + QByteArray::number(xyz[1].toDouble() * scale, 'g', 9) + ' ' +
             QByteArray::number(xyz[2].toDouble() * scale, 'g', 9) + ' ' +
             QByteArray::number(xyz[3].toDouble() * scale, 'g', 9) + '\n';
    } else {
      out += line + '\n';
    }
  }
  file.close();
  return file.open(QIODevice::WriteOnly | QIODevice::Truncate) && file.write(out) == out.size();
}

// The pixels where two pictures differ (the tears), as a fraction of the picture and their
// mean position (0..1 across, 0..1 down).
struct Difference {
  double fraction = 0;
  QPointF centre;
};

Difference difference(const QImage& a, const QImage& b) {
  Difference d;
  if (a.size() != b.size() || a.isNull()) return d;
  const QImage x = a.convertToFormat(QImage::Format_RGB32);
  const QImage y = b.convertToFormat(QImage::Format_RGB32);
  long long changed = 0;
  double sumX = 0, sumY = 0;
  for (int row = 0; row < x.height(); ++row) {
    const auto* p = reinterpret_cast<const QRgb*>(x.constScanLine(row));
    const auto* q = reinterpret_cast<const QRgb*>(y.constScanLine(row));
    for (int col = 0; col < x.width(); ++col)
      if (std::abs(qGray(p[col]) - qGray(q[col])) > 12) {
        ++changed;
        sumX += col;
        sumY += row;
      }
  }
  if (changed == 0) return d;
  d.fraction = static_cast<double>(changed) / (x.width() * x.height());
  d.centre = QPointF(sumX / changed / x.width(), sumY / changed / x.height());
  return d;
}

}  // namespace

class HeadViewsCliTest : public QObject {
  Q_OBJECT

  QTemporaryDir dir_;

 private slots:
  void initTestCase() {
    LACRIMA_REQUIRE_SHARED(lacrima::rigtest::kIctMesh);
    QVERIFY(dir_.isValid());
  }

  void closeLeftShowsTheTearOnAnyHead_data() {
    QTest::addColumn<double>("scale");
    QTest::newRow("centimetres") << 1.0;
    QTest::newRow("millimetres") << 10.0;
  }

  void closeLeftShowsTheTearOnAnyHead() {
    QFETCH(double, scale);
    const QString name = QString::number(scale);
    QString projects[2];
    for (int wet = 0; wet < 2; ++wet) {
      const QString folder = dir_.filePath(name + (wet ? "-wet" : "-dry"));
      projects[wet] =
          lacrima::rigtest::writeIctProject(folder, keysWithTears(wet ? 80 : 0), scaledFdp(scale));
      QVERIFY(!projects[wet].isEmpty());
      QVERIFY(scaleObj(folder + "/heads/ict.obj", scale));
    }
    QImage pictures[2][2];  // [view: close-left, front][dry, wet]
    const char* views[2] = {"close-left", "front"};
    for (int v = 0; v < 2; ++v)
      for (int wet = 0; wet < 2; ++wet) {
        const QString out = dir_.filePath(name + views[v] + QString::number(wet));
        QString err;
        QVERIFY2(
            render({"--render", out, "--view", views[v], "--size", "320x180", projects[wet]}, &err),
            qPrintable(err));
        pictures[v][wet] = QImage(out + kLastFrame);
        QCOMPARE(pictures[v][wet].size(), QSize(320, 180));
      }
    const Difference close = difference(pictures[0][1], pictures[0][0]);
    const Difference front = difference(pictures[1][1], pictures[1][0]);
    qInfo("tears: close-left %.2f%% of the picture, centred at (%.2f, %.2f); front %.2f%%",
          100 * close.fraction, close.centre.x(), close.centre.y(), 100 * front.fraction);
    // The left tear runs down the middle of the close-up (the face's left shows on the right of
    // a view from the front; the close view is aimed at it), and close up it covers more of the
    // picture than from the front.
    QVERIFY2(close.centre.x() > 0.3 && close.centre.x() < 0.7 && close.centre.y() > 0.4,
             "the tear is not in the middle");
    QVERIFY(close.fraction > 2 * front.fraction);
    // Front: both tears, either side of the middle, so they average near it.
    QVERIFY(front.fraction > 0);
    QVERIFY(std::abs(front.centre.x() - 0.5) < 0.1);
  }
};

QTEST_MAIN(HeadViewsCliTest)
#include "HeadViewsCliTest.moc"
