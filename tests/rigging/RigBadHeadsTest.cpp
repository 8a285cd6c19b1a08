// Heads that are not what the rig expects: files with nothing to rig are a clear
// error; a head without eyes rigs with its eye FAPs and tears disabled, and the player's frame
// producer then simulates no tears; a skin in several pieces or with non-manifold edges,
// duplicate and zero-area triangles rigs with finite weights and poses, warning where a point's
// influence cannot reach. Most cases run on a small synthetic face (a curved grid with the
// FAPU points where a face has them), the playback one on the default head.
#include "../support/MissingData.h"
#include "TestHeadFiles.h"

#include <lacrima/common/FapTable.h>
#include <lacrima/common/PoseSet.h>
#include <lacrima/playback/FrameProducer.h>
#include <lacrima/playback/HeadRig.h>
#include <lacrima/rigging/DefaultHead.h>
#include <lacrima/rigging/FeaturePointFile.h>
#include <lacrima/rigging/MeshImport.h>
#include <lacrima/rigging/RigBuilder.h>
#include <lacrima/rigging/RigChecks.h>
#include <lacrima/rigging/RigDescription.h>

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QtTest>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

using namespace lacrima;

namespace {

// ---- the synthetic face ------------------------------------------------------------------------

// Face frame: +y up, +x the face's left, +z forward. The face spans x in [-0.5, 0.5] and y in
// [0, 1.4], bulging forward (z = 0.2 - 0.4 x^2) like a cheek-to-cheek curve.
constexpr double kStep = 0.025;
constexpr int kColumns = 40, kRows = 56;

Eigen::Vector3f facePoint(double x, double y) {
  return Eigen::Vector3d(x, y, 0.2 - 0.4 * x * x).cast<float>();
}

// Where each feature point goes on the face (x, y).
const std::map<std::string, Eigen::Vector2d>& pointTargets() {
  static const std::map<std::string, Eigen::Vector2d> targets = {
      {"2.1", {0, 0.15}},     {"2.10", {0, 0.2}},      {"2.2", {0, 0.45}},   {"2.3", {0, 0.4}},
      {"3.1", {0.2, 1.02}},   {"3.2", {-0.2, 1.02}},   {"3.3", {0.2, 0.92}}, {"3.4", {-0.2, 0.92}},
      {"3.5", {0.2, 0.97}},   {"3.6", {-0.2, 0.97}},   {"3.7", {0.3, 0.97}}, {"3.8", {-0.1, 0.97}},
      {"3.11", {0.1, 0.97}},  {"3.12", {-0.3, 0.97}},  {"4.1", {0.1, 1.12}}, {"4.2", {-0.1, 1.12}},
      {"4.3", {0.2, 1.15}},   {"4.4", {-0.2, 1.15}},   {"8.1", {0, 0.48}},   {"8.2", {0, 0.37}},
      {"8.3", {0.15, 0.425}}, {"8.4", {-0.15, 0.425}}, {"9.3", {0, 0.7}},    {"9.15", {0, 0.62}}};
  return targets;
}

// The lip patch of the multi-piece face: cells with |x| < 0.2 and 0.35 < y < 0.5.
bool inLips(int i, int j) {
  const double x = -0.5 + (i + 0.5) * kStep, y = (j + 0.5) * kStep;
  return std::abs(x) < 0.2 && y > 0.35 && y < 0.5;
}

// Appends the grid's cells that `keep` accepts as a sub-mesh with its own vertices, moved by
// `dz` in z (a lip piece lifted off the face is not welded to it).
template <class Keep>
void appendGrid(HeadMesh& head, const std::string& name, Keep keep, float dz = 0) {
  HeadSubmesh s;
  s.name = name;
  s.firstVertex = static_cast<int>(head.positions.cols());
  const int n = (kColumns + 1) * (kRows + 1);
  s.vertexCount = n;
  head.positions.conservativeResize(3, s.firstVertex + n);
  auto index = [&](int i, int j) { return s.firstVertex + j * (kColumns + 1) + i; };
  for (int j = 0; j <= kRows; ++j)
    for (int i = 0; i <= kColumns; ++i)
      head.positions.col(index(i, j)) =
          facePoint(-0.5 + i * kStep, j * kStep) + Eigen::Vector3f(0, 0, dz);
  for (int j = 0; j < kRows; ++j)
    for (int i = 0; i < kColumns; ++i) {
      if (!keep(i, j)) continue;
      s.triangles.emplace_back(index(i, j), index(i + 1, j), index(i + 1, j + 1));
      s.triangles.emplace_back(index(i, j), index(i + 1, j + 1), index(i, j + 1));
    }
  head.submeshes.push_back(std::move(s));
}

// The vertex of sub-mesh `s` nearest to (x, y) on the face, among those on its triangles.
int nearestLocalVertex(const HeadMesh& head, const HeadSubmesh& s, const Eigen::Vector2d& xy) {
  std::vector<char> used(static_cast<std::size_t>(s.vertexCount), 0);
  for (const Eigen::Vector3i& t : s.triangles)
    for (int k = 0; k < 3; ++k) used[static_cast<std::size_t>(t[k] - s.firstVertex)] = 1;
  const Eigen::Vector3f target = facePoint(xy.x(), xy.y());
  int best = -1;
  float bestD = std::numeric_limits<float>::infinity();
  for (int v = 0; v < s.vertexCount; ++v) {
    if (!used[static_cast<std::size_t>(v)]) continue;
    const float d = (head.positions.col(s.firstVertex + v) - target).norm();
    if (d < bestD) bestD = d, best = v;
  }
  return best;
}

struct SyntheticHead {
  HeadMesh head;
  rigging::FeaturePointFile fdp;
};

// The face as one skin sub-mesh "face" (and "lips" for the lip patch when `lipPiece`), every
// point of pointTargets on the nearest vertex of the piece it falls in, no eyes.
SyntheticHead syntheticFace(bool lipPiece = false) {
  SyntheticHead out;
  HeadMesh& head = out.head;
  head.positions.resize(3, 0);
  appendGrid(head, "face", [&](int i, int j) { return !lipPiece || !inLips(i, j); });
  if (lipPiece) appendGrid(head, "lips", inLips, 0.002f);
  rigging::FeaturePointFile& fdp = out.fdp;
  fdp.path = "synthetic.fdp.json";
  for (const HeadSubmesh& s : head.submeshes) fdp.skin.push_back(s.name);
  fdp.neckPivot = Eigen::Vector3d(0, -0.1, -0.2);
  for (const auto& [id, xy] : pointTargets()) {
    const bool onLips = lipPiece && (id.rfind("2.", 0) == 0 || id.rfind("8.", 0) == 0) &&
                        std::abs(xy.x()) < 0.2 && xy.y() > 0.35 && xy.y() < 0.5;
    const HeadSubmesh& s = head.submeshes[onLips ? 1 : 0];
    fdp.points[id].at = {s.name, nearestLocalVertex(head, s, xy), -1, Eigen::Vector3d::Zero(),
                         std::nullopt};
  }
  head.computeNormals();
  return out;
}

// ---- what every rig of a bad head must satisfy ------------------------------------------------

bool finiteInfluence(const FeaturePointInfluence& inf) {
  for (const float w : inf.weights)
    if (!(std::isfinite(w) && w > 0.0f && w <= 1.0f)) return false;
  return inf.weights.size() == inf.vertices.size();
}

// Weights in (0, 1], every pose and the blended head finite, FAP 3 and 19 posed.
void verifyFiniteRig(const HeadMesh& head, const rigging::BuiltRig& rig) {
  for (const auto& [id, inf] : rig.input.influences) QVERIFY2(finiteInfluence(inf), id.c_str());
  for (const auto& [fap, inf] : rig.input.fapInfluences)
    QVERIFY2(finiteInfluence(inf), qPrintable(QString("FAP %1").arg(fap)));
  for (const VertexPose& pose : rig.poses.poses) QVERIFY(pose.offsets.allFinite());
  for (int fap : {3, 19})
    QVERIFY(!rig.poses.poses[static_cast<std::size_t>(channelIndex(fap))].empty());
  const PoseBlender blender(head, rig.poses);
  FapValues values{};
  for (int fap = 3; fap <= 68; ++fap) {
    const FapInfo& info = fapInfo(fap);
    values[static_cast<std::size_t>(channelIndex(fap))] = static_cast<float>(info.sliderMax);
  }
  Eigen::Matrix3Xf positions, normals;
  blender.blend(values, positions, normals);
  QVERIFY(positions.allFinite());
  QVERIFY(normals.allFinite());
}

bool anyWarning(const rigging::BuiltRig& rig, const std::string& text) {
  return std::any_of(rig.warnings.begin(), rig.warnings.end(),
                     [&](const std::string& w) { return w.find(text) != std::string::npos; });
}

QString allWarnings(const rigging::BuiltRig& rig) {
  QString out;
  for (const std::string& w : rig.warnings) out += QString::fromStdString(w) + "\n";
  return out;
}

std::string importError(const QString& path) {
  try {
    rigging::importHeadMesh(path.toStdString());
  } catch (const FileError& e) {
    return e.what();
  }
  return {};
}

}  // namespace

class RigBadHeadsTest : public QObject {
  Q_OBJECT

  QTemporaryDir tmp_;

  QString write(const char* name, const QByteArray& bytes) {
    const QString path = QDir(tmp_.path()).filePath(name);
    QFile f(path);
    if (f.open(QIODevice::WriteOnly)) f.write(bytes);
    return path;
  }

 private slots:
  // Files with nothing to rig: the message names the file, what it found and what was expected.
  void meshesWithoutFacesAreAClearError() {
    QVERIFY(tmp_.isValid());
    const struct {
      const char* name;
      QByteArray bytes;
      const char* found;
    } cases[] = {
        {"empty.obj", "", "the file is empty"},
        {"empty.glb", "", "the file is empty"},
        {"comment.obj", "# exported with no objects\n", "no mesh at all"},
        {"vertices.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n", "3 vertices and no face"},
        {"points.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\np 1 2 3\n", "3 points"},
        {"lines.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nl 1 2\nl 2 3\n", "2 lines"},
        {"vertices.ply",
         "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
         "property float z\nend_header\n0 0 0\n1 0 0\n0 1 0\n",
         "3 vertices and no face"},
        {"flat.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n", "zero area"},
    };
    for (const auto& c : cases) {
      const QString path = write(c.name, c.bytes);
      const std::string message = importError(path);
      QVERIFY2(message.find(path.toStdString()) != std::string::npos &&
                   message.find(c.found) != std::string::npos &&
                   message.find("expected a mesh with faces") != std::string::npos,
               qPrintable(QString("%1: %2").arg(c.name, message.c_str())));
    }
    // A single real triangle is a mesh (the rig decides whether it is a head).
    QCOMPARE(rigging::importHeadMesh(
                 write("one.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n").toStdString())
                 .triangleCount(),
             1);
  }

  // No eye roles: the rig builds, the eye FAPs and tears are disabled with one warning per eye,
  // the pupils (on the lids) move nothing, and the rest of the face is posed.
  void headWithoutEyesRigsWithEyeFapsAndTearsDisabled() {
    const SyntheticHead s = syntheticFace();
    Warnings warnings;
    rigging::validateFeaturePoints(s.fdp, s.head, &warnings);
    const rigging::BuiltRig rig = rigging::buildRig(s.head, s.fdp);
    verifyFiniteRig(s.head, rig);
    QCOMPARE(rig.disabledFaps, (std::vector<int>{23, 24, 25, 26, 27, 28, 29, 30, 69, 70}));
    for (const char* side : {"no left eye (no sub-mesh has the role eye_left)",
                             "no right eye (no sub-mesh has the role eye_right)"})
      QVERIFY2(anyWarning(rig, side), qPrintable(allWarnings(rig)));
    QVERIFY2(anyWarning(rig, "no eyes: tears need the eye's sub-meshes"),
             qPrintable(allWarnings(rig)));
    QVERIFY(rig.poses.eyeLeft.vertices.empty() && rig.poses.eyeRight.vertices.empty());
    for (int fap = 27; fap <= 30; ++fap)
      QVERIFY2(rig.poses.poses[static_cast<std::size_t>(channelIndex(fap))].empty(),
               qPrintable(QString("FAP %1").arg(fap)));
    QVERIFY(!rig.input.influences.count("3.5") && !rig.input.influences.count("3.6"));
    QVERIFY(rig.input.influences.count("3.1"));  // the lids still close
    // rig.json tells other tools what the head cannot play.
    const QJsonObject description =
        QJsonDocument::fromJson(QByteArray::fromStdString(rigging::rigDescriptionJson(s.head, rig)))
            .object();
    QCOMPARE(description.value("disabled_faps").toArray(),
             (QJsonArray{23, 24, 25, 26, 27, 28, 29, 30, 69, 70}));

    // The checks say it once per eye, and neither call the pupils misplaced nor the eye poses
    // empty.
    const auto checks = rigging::checkRig(s.head, s.fdp, rig);
    int noEyes = 0;
    for (const rigging::RigCheck& c : checks) {
      noEyes += c.kind == "no-eyes";
      QVERIFY2(c.kind != "wrong-part" && !(c.fap >= 23 && c.fap <= 30),
               rigging::toString(c).c_str());
    }
    QCOMPARE(noEyes, 2);
  }

  // An eye that cannot turn: a flat card (no sphere to fit, no centre given) on the left, an
  // empty sub-mesh on the right. Both are absent eyes, each with its reason.
  void unusableEyesAreAbsentEyes() {
    SyntheticHead s = syntheticFace();
    HeadSubmesh card;
    card.name = "eye_card";
    card.firstVertex = static_cast<int>(s.head.positions.cols());
    card.vertexCount = 4;
    s.head.positions.conservativeResize(3, card.firstVertex + 4);
    for (int k = 0; k < 4; ++k)
      s.head.positions.col(card.firstVertex + k) =
          facePoint(0.2 + 0.03 * (k % 2), 0.96 + 0.03 * (k / 2)) - Eigen::Vector3f(0, 0, 0.01f);
    card.triangles = {{card.firstVertex, card.firstVertex + 1, card.firstVertex + 3},
                      {card.firstVertex, card.firstVertex + 3, card.firstVertex + 2}};
    s.head.submeshes.push_back(card);
    HeadSubmesh empty;
    empty.name = "eye_empty";
    empty.firstVertex = static_cast<int>(s.head.positions.cols());
    s.head.submeshes.push_back(empty);
    s.head.computeNormals();
    s.fdp.eyeLeft.submeshes = {"eye_card"};
    s.fdp.eyeRight.submeshes = {"eye_empty"};
    Warnings warnings;
    rigging::validateFeaturePoints(s.fdp, s.head, &warnings);
    const rigging::BuiltRig rig = rigging::buildRig(s.head, s.fdp);
    verifyFiniteRig(s.head, rig);
    QVERIFY2(anyWarning(rig, "do not span a sphere"), qPrintable(allWarnings(rig)));
    QVERIFY2(anyWarning(rig, "eye_right are missing or have no vertices"),
             qPrintable(allWarnings(rig)));
    QVERIFY(rig.disabled(23) && rig.disabled(24) && rig.disabled(69) && rig.disabled(70));
  }

  // A lip piece not welded to the face: points on it warn that their influence stops at its
  // edge, points near it on the face likewise, points far from it do not; the weights stay on
  // their own piece.
  void multiPieceSkinWarnsWhereInfluenceCannotReach() {
    const SyntheticHead s = syntheticFace(true);
    Warnings warnings;
    rigging::validateFeaturePoints(s.fdp, s.head, &warnings);
    for (const auto method : {rigging::GeodesicMethod::Dijkstra, rigging::GeodesicMethod::Heat}) {
      rigging::RigOptions options;
      options.geodesics = method;
      const rigging::BuiltRig rig = rigging::buildRig(s.head, s.fdp, options);
      verifyFiniteRig(s.head, rig);
      // 8.1, on the lip piece 0.02 below its upper edge, cannot reach the face just above.
      QVERIFY2(anyWarning(rig, "feature point 8.1: its influence cannot reach") &&
                   anyWarning(rig, "another piece of the skin (\"face\")"),
               qPrintable(allWarnings(rig)));
      // 2.2's weights stay on the lip piece.
      const HeadSubmesh& lips = s.head.submeshes[1];
      for (int v : rig.input.influences.at("2.2").vertices)
        QVERIFY(v >= lips.firstVertex && v < lips.firstVertex + lips.vertexCount);
      // The forehead is one piece with the face: no warning for the brows.
      QVERIFY(!anyWarning(rig, "feature point 4.3:"));
    }
  }

  // Edges shared by three triangles (fins), duplicate triangles, zero-area triangles (collinear
  // corners and repeated corners): both geodesic methods give finite weights and poses.
  void nonManifoldSkinStaysFinite() {
    SyntheticHead s = syntheticFace();
    HeadSubmesh& face = s.head.submeshes[0];
    const std::vector<Eigen::Vector3i> original = face.triangles;
    int next = static_cast<int>(s.head.positions.cols());
    s.head.positions.conservativeResize(3, next + 80);
    face.vertexCount += 80;
    for (std::size_t k = 100; k < original.size(); k += original.size() / 40) {
      const Eigen::Vector3i& t = original[k];
      const Eigen::Vector3f a = s.head.positions.col(t[0]), b = s.head.positions.col(t[1]);
      // A fin on edge a-b (its third triangle), and a collinear sliver a-m-b on the same edge.
      s.head.positions.col(next) = 0.5f * (a + b) + Eigen::Vector3f(0, 0, 0.03f);
      s.head.positions.col(next + 1) = 0.5f * (a + b);
      face.triangles.emplace_back(t[0], t[1], next);
      face.triangles.emplace_back(t[0], next + 1, t[1]);
      face.triangles.emplace_back(t[0], t[0], t[1]);  // repeated corner
      face.triangles.push_back(t);                    // duplicate
      next += 2;
      if (next >= static_cast<int>(s.head.positions.cols())) break;
    }
    face.vertexCount = next - face.firstVertex;
    s.head.positions.conservativeResize(3, next);
    s.head.computeNormals();
    QVERIFY(s.head.normals.allFinite());
    Warnings warnings;
    rigging::validateFeaturePoints(s.fdp, s.head, &warnings);
    for (const auto method : {rigging::GeodesicMethod::Dijkstra, rigging::GeodesicMethod::Heat}) {
      rigging::RigOptions options;
      options.geodesics = method;
      const rigging::BuiltRig rig = rigging::buildRig(s.head, s.fdp, options);
      verifyFiniteRig(s.head, rig);
      // The brows' influences stretched along their motion (DirectionalGeodesics) were built
      // on the damaged surface too.
      QVERIFY(!rig.input.fapInfluences.empty());
      const auto checks = rigging::checkRig(s.head, s.fdp, rig);
      for (const rigging::RigCheck& c : checks)
        QVERIFY2(c.message.find("nan") == std::string::npos &&
                     c.message.find("inf") == std::string::npos,
                 c.message.c_str());
    }
  }

  // The default head with its eyes taken out of the roles (pupils left on the lids): the
  // player's frame producer, asked for tears, simulates none and keeps posing the face; with
  // the eyes, the same frames do weep (so the first half would notice tears that slip through).
  void playerSimulatesNoTearsWithoutEyes() {
    if (!rigging::defaultHeadAvailable()) LACRIMA_SKIP_WITHOUT_DEFAULT_HEAD();
    rigging::FeaturePointFile fdp =
        rigging::readFeaturePointFile(rigtest::kDefaultFdp.toStdString());
    const HeadMesh head = rigging::loadDefaultHead();
    auto weep = [](const playback::HeadRig& rig) {
      playback::FrameProducer producer(rig);
      FapValues values{};
      values[static_cast<std::size_t>(channelIndex(kTearLeftFap))] = 20;
      values[static_cast<std::size_t>(channelIndex(kTearRightFap))] = 20;
      values[static_cast<std::size_t>(channelIndex(3))] = 300;
      for (int frame = 0; frame < 5; ++frame) producer.produce(values, 1.0 / 25, 0);
      return std::pair{producer.particleCount(), producer.counters().blends};
    };
    const auto withEyes = weep(*playback::rigHead(head, fdp));
    QVERIFY(withEyes.first > 0);

    fdp.eyeLeft.submeshes.clear();
    fdp.eyeRight.submeshes.clear();
    fdp.eyeLeft.centre.reset();
    fdp.eyeRight.centre.reset();
    fdp.points["3.5"].at = fdp.points["3.1"].at;
    fdp.points["3.6"].at = fdp.points["3.2"].at;
    const auto rig = playback::rigHead(head, fdp);
    QVERIFY(rig->rig.disabled(kTearLeftFap) && rig->rig.disabled(kTearRightFap));
    QVERIFY(std::any_of(rig->warnings.begin(), rig->warnings.end(), [](const std::string& w) {
      return w.find("no eyes: tears need") != std::string::npos;
    }));
    const auto withoutEyes = weep(*rig);
    QCOMPARE(withoutEyes.first, 0);
    QVERIFY(withoutEyes.second >= 1);  // the face was still posed
  }
};

QTEST_GUILESS_MAIN(RigBadHeadsTest)
#include "RigBadHeadsTest.moc"
