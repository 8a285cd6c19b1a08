// Rig assembly end to end: feature-point files, RigBuilder on the default head and the ICT head,
// the exported files and the lacrima-rig command.
#include "../support/FileErrors.h"
#include "../support/MissingData.h"
#include "TestHeadFiles.h"

#include <lacrima/common/FapTable.h>
#include <lacrima/common/PoseSet.h>
#include <lacrima/exporters/GlbExport.h>
#include <lacrima/exporters/RigExport.h>
#include <lacrima/rigging/DefaultHead.h>
#include <lacrima/rigging/DijkstraGeodesics.h>
#include <lacrima/rigging/FeaturePointFile.h>
#include <lacrima/rigging/MeshImport.h>
#include <lacrima/rigging/RigBuilder.h>
#include <lacrima/rigging/RigDescription.h>
#include <lacrima/rigging/SurfaceGraph.h>

#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <assimp/Importer.hpp>

#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>
#include <memory>
#include <set>

using namespace lacrima;
using namespace lacrima::rigtest;

using lacrima::testsupport::fileErrorOf;

namespace {

void writeFile(const QString& path, const QByteArray& bytes) {
  QFile f(path);
  QVERIFY(f.open(QIODevice::WriteOnly | QIODevice::Truncate));
  f.write(bytes);
}

const VertexPose& poseOf(const rigging::BuiltRig& rig, int fap) {
  return rig.poses.poses[static_cast<std::size_t>(channelIndex(fap))];
}

// Offsets of a pose as a dense map vertex -> offset (repeated entries add up).
std::map<int, Eigen::Vector3f> dense(const VertexPose& pose) {
  std::map<int, Eigen::Vector3f> out;
  for (std::size_t k = 0; k < pose.vertices.size(); ++k) {
    auto [it, fresh] = out.try_emplace(pose.vertices[k], Eigen::Vector3f::Zero());
    it->second += pose.offsets.col(static_cast<Eigen::Index>(k));
  }
  return out;
}

}  // namespace

// QSKIP ends only the function it is written in, so the check must expand inside each test.
#define REQUIRE_DEFAULT_HEAD()                       \
  do {                                               \
    if (!head_) LACRIMA_SKIP_WITHOUT_DEFAULT_HEAD(); \
  } while (false)

class RigTest : public QObject {
  Q_OBJECT

  std::unique_ptr<HeadMesh> head_;
  std::unique_ptr<rigging::FeaturePointFile> fdp_;
  std::unique_ptr<rigging::BuiltRig> rig_;
  QTemporaryDir tmp_;

  const HeadMesh& head() { return *head_; }
  const rigging::BuiltRig& rig() { return *rig_; }
  Eigen::Vector3d point(const char* id) { return rig().featurePoints.at(id); }

 private slots:
  void initTestCase() {
    QVERIFY(tmp_.isValid());
    if (!rigging::defaultHeadAvailable()) return;
    head_ = std::make_unique<HeadMesh>(rigging::loadDefaultHead());
    Warnings warnings;
    fdp_ = std::make_unique<rigging::FeaturePointFile>(
        rigging::readFeaturePointFile(kDefaultFdp.toStdString(), &warnings));
    rigging::validateFeaturePoints(*fdp_, *head_, &warnings);
    for (const Diagnostic& w : warnings) qWarning("%s", w.toString().c_str());
    QVERIFY2(warnings.empty(), "the default head's feature-point file is complete");
    QElapsedTimer timer;
    timer.start();
    rig_ = std::make_unique<rigging::BuiltRig>(rigging::buildRig(*head_, *fdp_));
    qInfo("default head rigged in %lld ms (%d vertices)", static_cast<long long>(timer.elapsed()),
          head_->vertexCount());
    for (const std::string& w : rig_->warnings) qWarning("rig: %s", w.c_str());
  }

  // Every translational FAP 3-68 at 1024 moves its feature point by X0 along its direction.
  void translationsMoveTheirPointByX0() {
    REQUIRE_DEFAULT_HEAD();
    int checked = 0;
    for (int fap = 3; fap <= 68; ++fap) {
      const FapInfo& info = fapInfo(fap);
      if (info.motion != FapMotion::Translation) continue;
      const std::string id(info.featurePoint);
      QVERIFY2(!poseOf(rig(), fap).empty(), qPrintable(QString("FAP %1 has a pose").arg(fap)));
      const double x0 = rig().fapu.unitValue(info.unit) * 1024.0;
      const Eigen::Vector3d moved = rigging::featurePointDisplacement(rig(), id, fap, 1024.0);
      const Eigen::Vector3d expected = x0 * info.positiveMotion.cast<double>();
      QVERIFY2((moved - expected).norm() < 1e-4 * x0,
               qPrintable(QString("FAP %1 (%2): moved %3, expected %4")
                              .arg(fap)
                              .arg(id.c_str())
                              .arg(moved.norm())
                              .arg(x0)));
      ++checked;
    }
    QVERIFY(checked >= 55);
  }

  // Weights lie in (0, 1], are 1 at the point's vertices and vanish beyond the radius.
  void weightsAreBoundedAndLocal() {
    REQUIRE_DEFAULT_HEAD();
    const rigging::SurfaceGraph skin = rigging::buildSurfaceGraph(head(), fdp_->skin);
    for (const auto& [id, radius] : rig().radii) {
      const FeaturePointInfluence& inf = rig().input.influences.at(id);
      std::map<int, float> weight;
      for (std::size_t k = 0; k < inf.vertices.size(); ++k) {
        QVERIFY2(inf.weights[k] > 0.0f && inf.weights[k] <= 1.0f, id.c_str());
        weight[inf.vertices[k]] = inf.weights[k];
      }
      for (const auto& [v, w] : rig().bindings.at(id)) {
        Q_UNUSED(w);
        QVERIFY2(weight.count(v) && weight[v] == 1.0f,
                 qPrintable(QString("weight 1 at %1").arg(id.c_str())));
      }
      if (fdp_->points.at(id).at.submesh != "skin") continue;  // tongue points: own surface
      std::vector<int> sources;
      for (const auto& [v, w] : rig().bindings.at(id)) sources.push_back(v);
      const Eigen::VectorXd d = rigging::dijkstraDistances(
          skin, Eigen::Map<const Eigen::VectorXi>(sources.data(),
                                                  static_cast<Eigen::Index>(sources.size())));
      for (const auto& [v, w] : weight) {
        if (head().submeshOfVertex(v) != 0) continue;  // attachments and the jaw copy weights
        QVERIFY2(d[v] < radius, qPrintable(QString("%1: vertex %2 at %3 >= radius %4")
                                               .arg(id.c_str())
                                               .arg(v)
                                               .arg(d[v])
                                               .arg(radius)));
      }
    }
  }

  // Upper lip: skin vertices with |x| < 0.75 x(8.3) (clear of the corners, where the lips
  // meet), from the slit y(2.2) up to the nose base y(9.15), in front of the corner's depth
  // z(8.3). FAP 5 (lower lip up, at its full slider range) must not move any of them.
  void lowerLipLeavesTheUpperLip() {
    REQUIRE_DEFAULT_HEAD();
    const auto moved = dense(poseOf(rig(), 5));
    const HeadSubmesh& skin = *head().findSubmesh("skin");
    int upperLip = 0;
    for (int v = skin.firstVertex; v < skin.firstVertex + skin.vertexCount; ++v) {
      const Eigen::Vector3d p = head().positions.col(v).cast<double>();
      if (std::abs(p.x()) >= 0.75 * point("8.3").x() || p.y() < point("2.2").y() ||
          p.y() > point("9.15").y() || p.z() < point("8.3").z())
        continue;
      ++upperLip;
      const auto hit = moved.find(v);
      QVERIFY2(hit == moved.end() || hit->second.norm() == 0.0f,
               qPrintable(QString("upper-lip vertex %1").arg(v)));
    }
    QVERIFY(upperLip > 30);
  }

  // Lower lid of the left eye: skin vertices within 40% of the eye's width of x(3.3), from
  // y(3.3) down by one IRISD0, in front of z(3.3) - IRISD0. FAP 19 must not move them.
  void upperLidLeavesTheLowerLid() {
    REQUIRE_DEFAULT_HEAD();
    const auto moved = dense(poseOf(rig(), 19));
    const HeadSubmesh& skin = *head().findSubmesh("skin");
    const double width = point("3.7").x() - point("3.11").x();
    const double irisd0 = rig().fapu.irisd0;
    int lowerLid = 0;
    for (int v = skin.firstVertex; v < skin.firstVertex + skin.vertexCount; ++v) {
      const Eigen::Vector3d p = head().positions.col(v).cast<double>();
      if (std::abs(p.x() - point("3.3").x()) > 0.4 * width || p.y() > point("3.3").y() + 1e-6 ||
          p.y() < point("3.3").y() - irisd0 || p.z() < point("3.3").z() - irisd0)
        continue;
      ++lowerLid;
      const auto hit = moved.find(v);
      QVERIFY2(hit == moved.end() || hit->second.norm() == 0.0f,
               qPrintable(QString("lower-lid vertex %1").arg(v)));
    }
    QVERIFY(lowerLid > 10);
  }

  // The head is mirror-symmetric: a left FAP's pose equals its right partner's pose mirrored
  // in x, compared through nearest mirrored vertices. Measured: identical to float precision
  // for all 40 pairs (the MakeHuman mesh and the feature points are mirror images), so 1% is
  // room for rounding only.
  void leftAndRightPosesMirror() {
    REQUIRE_DEFAULT_HEAD();
    const Eigen::Matrix3Xf& p = head().positions;
    for (int fap = 3; fap <= 68; ++fap) {
      const int partner = mirroredFap(fap);
      if (partner == fap || fapInfo(fap).motion != FapMotion::Translation) continue;
      const auto left = dense(poseOf(rig(), fap));
      const auto right = dense(poseOf(rig(), partner));
      float largest = 0, worst = 0;
      for (const auto& [v, offset] : left) {
        largest = std::max(largest, offset.norm());
        const Eigen::Vector3f mirrored(-p(0, v), p(1, v), p(2, v));
        int best = -1;
        float bestD = 1e30f;
        for (const auto& [w, o] : right) {
          Q_UNUSED(o);
          const float d = (p.col(w) - mirrored).squaredNorm();
          if (d < bestD) bestD = d, best = w;
        }
        Eigen::Vector3f expected = Eigen::Vector3f::Zero();
        if (best >= 0 && std::sqrt(bestD) < 1e-3f) expected = right.at(best);
        expected.x() = -expected.x();
        worst = std::max(worst, (offset - expected).norm());
      }
      QVERIFY2(!left.empty(), qPrintable(QString("FAP %1 has a pose").arg(fap)));
      QVERIFY2(worst <= 0.01f * largest,
               qPrintable(QString("FAP %1 vs %2: worst difference %3 of %4")
                              .arg(fap)
                              .arg(partner)
                              .arg(worst)
                              .arg(largest)));
    }
  }

  void fapuArePlausible() {
    REQUIRE_DEFAULT_HEAD();
    const FapuSet& f = rig().fapu;
    qInfo("FAPU (dm): IRISD0 %g ES0 %g ENS0 %g MNS0 %g MW0 %g", f.irisd0, f.es0, f.ens0, f.mns0,
          f.mw0);
    QVERIFY(f.irisd0 > 0.05 && f.irisd0 < 0.15);  // an eye opening of 5-15 mm
    QVERIFY(f.es0 > 0.5 && f.es0 < 0.75);         // pupils 5-7.5 cm apart
    QVERIFY(f.ens0 > 0.3 && f.ens0 < 0.7);
    QVERIFY(f.mns0 > 0.1 && f.mns0 < 0.3);
    QVERIFY(f.mw0 > 0.4 && f.mw0 < 0.65);
  }

  // A 60-degree head yaw turns every vertex rigidly about the neck pivot.
  void headYawIsRigid() {
    REQUIRE_DEFAULT_HEAD();
    const PoseBlender blender(head(), rig().poses);
    FapValues values{};
    values[static_cast<std::size_t>(channelIndex(49))] =
        static_cast<float>(60.0 * M_PI / 180.0 / 1e-5);
    Eigen::Matrix3Xf positions, normals;
    blender.blend(values, positions, normals);
    const Eigen::Vector3f pivot = rig().neckPivot.cast<float>();
    float worst = 0, turned = 0;
    for (int v = 0; v < head().vertexCount(); ++v) {
      worst = std::max(worst, std::abs((positions.col(v) - pivot).norm() -
                                       (head().positions.col(v) - pivot).norm()));
      turned = std::max(turned, (positions.col(v) - head().positions.col(v)).norm());
    }
    QVERIFY2(worst < 1e-4f, qPrintable(QString("distance to the pivot changed by %1").arg(worst)));
    QVERIFY(turned > 0.5f);  // it did turn
  }

  void glbLoadsBackWithItsMorphTargets() {
    REQUIRE_DEFAULT_HEAD();
    const std::string path = QDir(tmp_.path()).filePath("head.glb").toStdString();
    exporters::exportGlb(head(), rig().poses, path);
    const std::size_t poses = exporters::prepareRigExport(head(), rig().poses, path).size();
    Assimp::Importer importer;
    const aiScene* scene = importer.ReadFile(path, aiProcess_ValidateDataStructure);
    QVERIFY2(scene, importer.GetErrorString());
    QVERIFY(scene->mNumMeshes > 0);
    for (unsigned m = 0; m < scene->mNumMeshes; ++m)
      QCOMPARE(static_cast<std::size_t>(scene->mMeshes[m]->mNumAnimMeshes), poses);
    int linear = 0;
    for (const VertexPose& pose : rig().poses.poses) linear += !pose.empty();
    QCOMPARE(poses, static_cast<std::size_t>(linear));
    QVERIFY(poses >= 55);  // every translation, the pupils and the tongue roll
  }

  void rigJsonDescribesTheRig() {
    REQUIRE_DEFAULT_HEAD();
    const QJsonObject doc = QJsonDocument::fromJson(QByteArray::fromStdString(
                                                        rigging::rigDescriptionJson(head(), rig())))
                                .object();
    QCOMPARE(doc.value("format").toString(), QString("lacrima-rig"));
    QVERIFY(doc.value("fapu").toObject().value("ES0").toDouble() > 0);
    QVERIFY(doc.value("feature_points").toObject().contains("3.3"));
    QCOMPARE(doc.value("neck_pivot").toArray().size(), 3);
    // Tear sources: skin vertices just under the lower lids.
    for (const auto& [side, tear, lid] : {std::tuple{"left", &rig().tearLeft, "3.3"},
                                          std::tuple{"right", &rig().tearRight, "3.4"}}) {
      QVERIFY(doc.value("tear_sources").toObject().contains(side));
      QCOMPARE(head().submeshOfVertex(tear->vertex), 0);
      QVERIFY(tear->position.y() < point(lid).y());
      QVERIFY((tear->position - point(lid)).norm() < rig().fapu.irisd0);
    }
  }

  void ictHeadRigsEndToEnd() {
    LACRIMA_REQUIRE_SHARED(kIctMesh);
    QElapsedTimer timer;
    timer.start();
    const HeadMesh mesh = rigging::importHeadMesh(kIctMesh.toStdString());
    Warnings warnings;
    rigging::BuiltRig rig;
    const std::string error = fileErrorOf([&] {
      const rigging::FeaturePointFile fdp =
          rigging::readFeaturePointFile(kIctFdp.toStdString(), &warnings);
      rigging::validateFeaturePoints(fdp, mesh, &warnings);
      rig = rigging::buildRig(mesh, fdp);
    });
    QVERIFY2(error.empty(), error.c_str());
    qInfo("ICT head imported and rigged in %lld ms (%d vertices)",
          static_cast<long long>(timer.elapsed()), mesh.vertexCount());
    for (const Diagnostic& w : warnings) qInfo("fdp: %s", w.toString().c_str());
    QVERIFY(rig.fapu.es0 > 0 && rig.fapu.mw0 > 0 && rig.fapu.irisd0 > 0);
    for (int fap : {3, 4, 5, 19, 20, 31, 53}) {
      const FapInfo& info = fapInfo(fap);
      const double x0 = rig.fapu.unitValue(info.unit) * 1024.0;
      const Eigen::Vector3d moved =
          rigging::featurePointDisplacement(rig, std::string(info.featurePoint), fap, 1024.0);
      QVERIFY2((moved - x0 * info.positiveMotion.cast<double>()).norm() < 1e-4 * x0,
               qPrintable(QString("FAP %1").arg(fap)));
    }
    QVERIFY(!rig.input.eyeLeft.vertices.empty() && !rig.input.eyeRight.vertices.empty());
  }

  // "ignored" parts (the ICT head's occlusion and blend shells and tear film) lose their
  // triangles, so nothing draws, picks or collides with them, keep their vertices, so every
  // index means what it meant, and survive a write and a read; a part cannot be ignored and
  // something else.
  void ignoredPartsAreLeftOut() {
    LACRIMA_REQUIRE_SHARED(kIctMesh);
    HeadMesh mesh = rigging::importHeadMesh(kIctMesh.toStdString());
    const rigging::FeaturePointFile fdp = rigging::validateFeaturePoints(
        rigging::readFeaturePointFile(kIctFdp.toStdString()), mesh, nullptr);
    QCOMPARE(fdp.ignored,
             (std::vector<std::string>{"M_LacrimalFluid", "M_EyeBlend", "M_EyeOcclusion"}));
    const int vertices = mesh.vertexCount();
    const int triangles = mesh.triangleCount();
    const int shells = static_cast<int>(mesh.findSubmesh("M_EyeOcclusion")->triangles.size());
    QVERIFY(shells > 0);
    rigging::dropIgnoredParts(mesh, fdp);
    QCOMPARE(mesh.vertexCount(), vertices);
    QVERIFY(mesh.triangleCount() <= triangles - shells);
    for (const std::string& name : fdp.ignored)
      QVERIFY2(mesh.findSubmesh(name)->triangles.empty(), name.c_str());
    QVERIFY(!mesh.findSubmesh("M_EyeLashes")->triangles.empty());
    const rigging::BuiltRig rig = rigging::buildRig(mesh, fdp);
    QCOMPARE(rig.roles.at("M_EyeBlend"), std::string("ignored"));

    QTemporaryDir dir;
    const QString path = dir.filePath("ict.fdp.json");
    writeFile(path, QByteArray::fromStdString(rigging::featurePointFileJson(fdp)));
    QCOMPARE(rigging::readFeaturePointFile(path.toStdString()).ignored, fdp.ignored);

    rigging::FeaturePointFile twice = fdp;
    twice.attached.push_back("M_EyeBlend");
    const std::string error =
        fileErrorOf([&] { rigging::validateFeaturePoints(twice, mesh, nullptr); });
    QVERIFY2(error.find("already has role \"ignored\"") != std::string::npos ||
                 error.find("already has role \"attached\"") != std::string::npos,
             error.c_str());
  }

  void loaderErrorsNameThePoint() {
    const QString path = QDir(tmp_.path()).filePath("bad.fdp.json");
    const QByteArray head =
        R"({"format": "lacrima-fdp", "version": 1, "submeshes": {"skin": ["skin"]}, "points": {)";
    const QByteArray required =
        R"("2.2": {"submesh": "skin", "vertex": 0}, "3.1": {"submesh": "skin", "vertex": 1},
           "3.2": {"submesh": "skin", "vertex": 2}, "3.3": {"submesh": "skin", "vertex": 3},
           "3.4": {"submesh": "skin", "vertex": 0}, "3.5": {"submesh": "skin", "vertex": 1},
           "3.6": {"submesh": "skin", "vertex": 2}, "8.3": {"submesh": "skin", "vertex": 3},
           "8.4": {"submesh": "skin", "vertex": 0})";
    HeadMesh mesh;
    mesh.positions = Eigen::Matrix3Xf::Random(3, 4);
    mesh.submeshes.push_back({"skin", -1, 0, 4, {{0, 1, 2}, {0, 2, 3}}});
    auto errorFor = [&](const QByteArray& points) {
      writeFile(path, head + points + "}}");
      return fileErrorOf([&] {
        const rigging::FeaturePointFile f = rigging::readFeaturePointFile(path.toStdString());
        rigging::validateFeaturePoints(f, mesh, nullptr);
      });
    };
    const std::string missing = errorFor(required);
    QVERIFY2(
        missing.find("9.15") != std::string::npos && missing.find("missing") != std::string::npos,
        missing.c_str());
    const std::string unknown =
        errorFor(required + R"(, "9.15": {"submesh": "nose", "vertex": 0})");
    QVERIFY2(unknown.find("\"9.15\"") != std::string::npos &&
                 unknown.find("unknown sub-mesh \"nose\"") != std::string::npos,
             unknown.c_str());
    const std::string range = errorFor(required + R"(, "9.15": {"submesh": "skin", "vertex": 4})");
    QVERIFY2(range.find("\"9.15\".vertex") != std::string::npos &&
                 range.find("0..3") != std::string::npos,
             range.c_str());
    const std::string bary =
        errorFor(required +
                 R"(, "9.15": {"submesh": "skin", "triangle": 0, "barycentric": [0.5, 0.5, 0.5]})");
    QVERIFY2(bary.find("\"9.15\".barycentric") != std::string::npos, bary.c_str());
    QVERIFY(errorFor(required + R"(, "9.15": {"submesh": "skin", "vertex": 2})").empty());
    // Errors found while reading and while validating both name the line and column.
    const std::string located =
        errorFor(required + ",\n  \"9.15\": {\"submesh\": \"skin\", \"vertex\": 4}");
    QVERIFY2(located.starts_with(path.toStdString() +
                                 ":6:31: points.\"9.15\".vertex: index 4 out of range"),
             located.c_str());
    writeFile(path, head + "\n  \"3.1\": {\"submesh\": \"skin\", \"vertex\": -1}}}");
    QCOMPARE(
        fileErrorOf([&] { rigging::readFeaturePointFile(path.toStdString()); }),
        path.toStdString() +
            ":2:30: points.\"3.1\".vertex: expected a whole number in [0, 2147483647], got -1");
    writeFile(path, "{\"format\": \"lacrima-fdp\",\n  \"version\": 1,,}");
    const std::string syntax =
        fileErrorOf([&] { rigging::readFeaturePointFile(path.toStdString()); });
    QVERIFY2(syntax.find(path.toStdString() + ":2:") != std::string::npos, syntax.c_str());
  }

  void commandLineTool() {
    QProcess help;
    help.start(kRigTool, {"--help"});
    QVERIFY(help.waitForFinished(30000));
    QCOMPARE(help.exitCode(), 0);
    QVERIFY(help.readAllStandardOutput().contains("--fdp"));

    QProcess usage;
    usage.start(kRigTool, {"--report"});
    QVERIFY(usage.waitForFinished(30000));
    QCOMPARE(usage.exitCode(), 2);

    const QString bad = QDir(tmp_.path()).filePath("broken.fdp.json");
    writeFile(bad, "{\"format\": \"lacrima-fdp\", \"version\": 1}");
    QProcess broken;
    broken.start(kRigTool,
                 {"--mesh", QDir(tmp_.path()).filePath("none.obj"), "--fdp", bad, "--report"});
    QVERIFY(broken.waitForFinished(30000));
    QCOMPARE(broken.exitCode(), 1);
    QVERIFY(broken.readAllStandardError().contains("error"));

    REQUIRE_DEFAULT_HEAD();
    QProcess badFdp;
    badFdp.start(kRigTool, {"--default", "--fdp", bad, "--report"});
    QVERIFY(badFdp.waitForFinished(60000));
    QCOMPARE(badFdp.exitCode(), 1);
    const QByteArray message = badFdp.readAllStandardError();
    QVERIFY2(message.contains(bad.toUtf8()) && message.contains("submeshes"), message.constData());

    const QString out = QDir(tmp_.path()).filePath("rig-out");
    QProcess rig;
    rig.start(kRigTool, {"--default", "-o", out});
    QVERIFY(rig.waitForFinished(120000));
    QVERIFY2(rig.exitCode() == 0, rig.readAllStandardError().constData());
    for (const char* file : {"head.mesh", "head.material", "head.glb", "rig.json"})
      QVERIFY2(QFileInfo(QDir(out).filePath(file)).size() > 0, file);
  }
};

QTEST_GUILESS_MAIN(RigTest)
#include "RigTest.moc"
