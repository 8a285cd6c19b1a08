// The skin does not fold under the brow FAPs 31-38 anywhere in their fold-free range, alone or
// together, nor in any frame of the demo (the pale shelf over the bridge of the nose
// when both inner brows rose past about 150).
//
// The measure, per skin triangle: the dot of its posed unit normal with its rest normal. A
// triangle that turns over has a negative dot; the bound asks for more than kSmallestCosine
// (the normal turned by less than 78 degrees), so a triangle about to turn over fails too.
// Poses go through PoseBlender, the player's blend; the rows are scanned every kStep FAP units
// over the range (docs/rig.md, "Folds"):
//   raises 31-36   -200 .. +400   (9.6 mm down, 19 mm up on the default head)
//   squeezes 37-38 -200 .. +100   (each inner end 12 mm out, 6 mm in: at +176 the two meet)
// Measured with the brows' stretched influences: worst 0.39 over the rows (every brow raised to
// +400: the upper lid's inner lining under 4.3/4.4, whose margin the middle brows lift by 65% of
// their rise), 0.91 at frame 137, 0.60 over the demo.
// Before (round influences of radius ES0 / 3) every raise row turned over, down to -0.999 (FAP
// 35 at +400), the inner brows at 208 (frame 137) to -0.848 and the demo to -0.887 (frame 158).
#include "DefaultRigFixture.h"

#include <lacrima/common/FapTable.h>

#include <Eigen/Geometry>

#include <QStringList>
#include <QtTest>

#include <limits>
#include <vector>

using namespace lacrima;

namespace {

constexpr double kSmallestCosine = 0.2;
constexpr int kStep = 10;

struct Range {
  int min = 0, max = 0;
};
constexpr Range kRaise{-200, 400};
constexpr Range kSqueeze{-200, 100};

// One row: FAPs set together to value * factor, value over `range`.
struct Row {
  QString name;
  std::vector<std::pair<int, double>> faps;  // FAP and its factor
  Range range;
  std::vector<std::pair<int, double>> fixed = {};  // other FAPs held at a value
};

Eigen::Vector3d unitNormal(const Eigen::Matrix3Xf& p, const Eigen::Vector3i& f) {
  const Eigen::Vector3d a = p.col(f[0]).cast<double>();
  return (p.col(f[1]).cast<double>() - a).cross(p.col(f[2]).cast<double>() - a).normalized();
}

}  // namespace

class SkinFoldTest : public QObject {
  Q_OBJECT

  testrig::DefaultRig fixture_;
  std::vector<Eigen::Vector3d> restNormals_;

  struct Worst {
    double cosine = std::numeric_limits<double>::infinity();
    int triangle = -1;
    QString pose;
  };

  // The smallest cosine between posed and rest normals over the skin.
  Worst worstAt(const FapValues& values, const QString& pose) const {
    Eigen::Matrix3Xf positions, normals;
    fixture_.blender->blend(values, positions, normals);
    Worst out;
    out.pose = pose;
    for (std::size_t t = 0; t < fixture_.skinTriangles.size(); ++t) {
      const double c = unitNormal(positions, fixture_.skinTriangles[t]).dot(restNormals_[t]);
      if (c < out.cosine) out.cosine = c, out.triangle = static_cast<int>(t);
    }
    return out;
  }

  QString triangleAt(int t) const {
    if (t < 0) return "-";
    const Eigen::Vector3i& f = fixture_.skinTriangles[static_cast<std::size_t>(t)];
    const Eigen::Vector3f c =
        (fixture_.head->positions.col(f[0]) + fixture_.head->positions.col(f[1]) +
         fixture_.head->positions.col(f[2])) /
        3.0f;
    return QString("skin triangle %1 at (%2, %3, %4)")
        .arg(t)
        .arg(c.x(), 0, 'f', 3)
        .arg(c.y(), 0, 'f', 3)
        .arg(c.z(), 0, 'f', 3);
  }

  // Logs the row's worst triangle and adds a failure when it is at or below the bound.
  void judge(const QString& row, const Worst& w, QStringList& failures) const {
    qInfo("%-44s worst cosine %6.3f at %s, %s", qPrintable(row), w.cosine, qPrintable(w.pose),
          qPrintable(triangleAt(w.triangle)));
    if (!(w.cosine > kSmallestCosine))
      failures << QString("%1: at %2 %3 turns to cosine %4 (bound %5)")
                      .arg(row, w.pose, triangleAt(w.triangle))
                      .arg(w.cosine, 0, 'f', 3)
                      .arg(kSmallestCosine);
  }

 private slots:
  void initTestCase() {
    fixture_ = testrig::loadDefaultRig();
    if (!fixture_) return;
    for (const Eigen::Vector3i& f : fixture_.skinTriangles)
      restNormals_.push_back(unitNormal(fixture_.head->positions, f));
    QVERIFY(restNormals_.size() > 8000);
  }

  // Each brow FAP alone, both sides together, one whole brow, all brows, and the demo's brows
  // (inner brows raised with the outer brows lowered and the brows drawn in, as at 6.2 s, frame
  // 137) with the inner raise over its range.
  void browPosesDoNotFold() {
    REQUIRE_DEFAULT_RIG(fixture_);
    std::vector<Row> rows;
    for (int fap = 31; fap <= 38; ++fap)
      rows.push_back({QString("FAP %1 (%2)").arg(fap).arg(fapInfo(fap).name.data()),
                      {{fap, 1.0}},
                      fap <= 36 ? kRaise : kSqueeze});
    rows.push_back({"inner brows 31 + 32", {{31, 1.0}, {32, 1.0}}, kRaise});
    rows.push_back({"middle brows 33 + 34", {{33, 1.0}, {34, 1.0}}, kRaise});
    rows.push_back({"outer brows 35 + 36", {{35, 1.0}, {36, 1.0}}, kRaise});
    rows.push_back({"squeezes 37 + 38", {{37, 1.0}, {38, 1.0}}, kSqueeze});
    rows.push_back({"left brow 31 + 33 + 35", {{31, 1.0}, {33, 1.0}, {35, 1.0}}, kRaise});
    rows.push_back({"all raises 31-36",
                    {{31, 1.0}, {32, 1.0}, {33, 1.0}, {34, 1.0}, {35, 1.0}, {36, 1.0}},
                    kRaise});
    rows.push_back({"inner raise, demo's 35/36 = -90, 37/38 = 56",
                    {{31, 1.0}, {32, 1.0}},
                    {0, kRaise.max},
                    {{35, -90}, {36, -90}, {37, 56}, {38, 56}}});

    QStringList failures;
    for (const Row& row : rows) {
      Worst worst;
      for (int value = row.range.min; value <= row.range.max; value += kStep) {
        FapValues v{};
        for (const auto& [fap, factor] : row.faps)
          v[static_cast<std::size_t>(channelIndex(fap))] = static_cast<float>(value * factor);
        for (const auto& [fap, held] : row.fixed)
          v[static_cast<std::size_t>(channelIndex(fap))] = static_cast<float>(held);
        const Worst w = worstAt(v, QString("value %1").arg(value));
        if (w.cosine < worst.cosine) worst = w;
      }
      judge(row.name, worst, failures);
    }
    QVERIFY2(failures.isEmpty(), qPrintable(failures.join("\n")));
  }

  // The pose of the report (6.2 s, frame 137) and every frame of the demo, all channels.
  void demoDoesNotFoldTheBrows() {
    REQUIRE_DEFAULT_RIG(fixture_);
    QStringList failures;
    judge("the demo at 6.2 s (31/32 = 208)",
          worstAt(
              testrig::fapValues({{31, 208}, {32, 208}, {35, -90}, {36, -90}, {37, 56}, {38, 56}}),
              "frame 137"),
          failures);

    // Every frame, judged on the skin the brow FAPs move: the demo also presses the lips
    // together (FAPs 4, 5, 59, 60), where one lip triangle turns to a cosine of 0.04 at frame
    // 158 whatever the brows do; that is the mouth's business, not this suite's.
    std::vector<char> browSkin(fixture_.skinTriangles.size(), 0);
    std::vector<char> moved(static_cast<std::size_t>(fixture_.head->vertexCount()), 0);
    for (int fap = 31; fap <= 38; ++fap)
      for (int v : fixture_.rig->poses.poses[static_cast<std::size_t>(channelIndex(fap))].vertices)
        moved[static_cast<std::size_t>(v)] = 1;
    for (std::size_t t = 0; t < browSkin.size(); ++t)
      for (int c = 0; c < 3; ++c)
        if (moved[static_cast<std::size_t>(fixture_.skinTriangles[t][c])]) browSkin[t] = 1;

    const std::vector<FapValues> demo = testrig::demoFrames();
    QVERIFY(demo.size() > 200);
    Worst worst;
    for (std::size_t k = 0; k < demo.size(); ++k) {
      Eigen::Matrix3Xf positions, normals;
      fixture_.blender->blend(demo[k], positions, normals);
      for (std::size_t t = 0; t < fixture_.skinTriangles.size(); ++t) {
        if (!browSkin[t]) continue;
        const double c = unitNormal(positions, fixture_.skinTriangles[t]).dot(restNormals_[t]);
        if (c < worst.cosine)
          worst = {c, static_cast<int>(t), QString("frame %1").arg(static_cast<int>(k))};
      }
    }
    judge("the demo, every frame, skin the brows move", worst, failures);
    QVERIFY2(failures.isEmpty(), qPrintable(failures.join("\n")));
  }
};

QTEST_APPLESS_MAIN(SkinFoldTest)
#include "SkinFoldTest.moc"
