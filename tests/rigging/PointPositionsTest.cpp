// Feature-point positions: stored beside each vertex, read back exactly, used to
// re-snap points when the mesh's vertex order changed, and to refuse a file placed on another
// mesh. The synthetic sheet makes every case small and exact; the default head checks that a
// re-snapped file rigs like the original.
#include "../support/FileErrors.h"
#include "../support/MissingData.h"
#include "TestHeadFiles.h"

#include <lacrima/common/AtomicSave.h>
#include <lacrima/common/FapTable.h>
#include <lacrima/rigging/DefaultHead.h>
#include <lacrima/rigging/FeaturePointFile.h>
#include <lacrima/rigging/MeshImport.h>
#include <lacrima/rigging/RigBuilder.h>

#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

using namespace lacrima;
using namespace lacrima::rigtest;

using lacrima::testsupport::fileErrorOf;

namespace {

// A wavy n x n sheet "skin" (spacing 0.1) and a 4 x 4 "lid" above it: two sub-meshes, enough
// for vertex and triangle points on each.
HeadMesh sheetMesh(int n = 12) {
  HeadMesh mesh;
  auto grid = [&](const std::string& name, int size, double z0) {
    HeadSubmesh s;
    s.name = name;
    s.firstVertex = mesh.vertexCount();
    s.vertexCount = size * size;
    mesh.positions.conservativeResize(3, s.firstVertex + s.vertexCount);
    for (int j = 0; j < size; ++j)
      for (int i = 0; i < size; ++i)
        mesh.positions.col(s.firstVertex + j * size + i) =
            Eigen::Vector3f(0.1f * static_cast<float>(i), 0.1f * static_cast<float>(j),
                            static_cast<float>(z0 + 0.03 * std::sin(i) * std::cos(0.7 * j)));
    for (int j = 0; j + 1 < size; ++j)
      for (int i = 0; i + 1 < size; ++i) {
        const int a = s.firstVertex + j * size + i;
        s.triangles.emplace_back(a, a + 1, a + size + 1);
        s.triangles.emplace_back(a, a + size + 1, a + size);
      }
    mesh.submeshes.push_back(std::move(s));
  };
  grid("skin", n, 0.0);
  grid("lid", 4, 0.5);
  mesh.computeNormals();
  return mesh;
}

// `mesh` with the vertices of every sub-mesh in reverse order (what a re-export may do);
// newIndex[v] is where old vertex v went.
HeadMesh reversed(const HeadMesh& mesh, std::vector<int>& newIndex) {
  HeadMesh out = mesh;
  newIndex.assign(static_cast<std::size_t>(mesh.vertexCount()), 0);
  for (const HeadSubmesh& s : mesh.submeshes)
    for (int v = 0; v < s.vertexCount; ++v)
      newIndex[static_cast<std::size_t>(s.firstVertex + v)] = s.firstVertex + s.vertexCount - 1 - v;
  for (int v = 0; v < mesh.vertexCount(); ++v) {
    const int to = newIndex[static_cast<std::size_t>(v)];
    out.positions.col(to) = mesh.positions.col(v);
    out.normals.col(to) = mesh.normals.col(v);
    if (mesh.uvs.cols() > 0) out.uvs.col(to) = mesh.uvs.col(v);
  }
  for (HeadSubmesh& s : out.submeshes)
    for (Eigen::Vector3i& t : s.triangles)
      for (int k = 0; k < 3; ++k) t[k] = newIndex[static_cast<std::size_t>(t[k])];
  return out;
}

rigging::SurfacePoint vertexPoint(const std::string& submesh, int vertex) {
  rigging::SurfacePoint p;
  p.submesh = submesh;
  p.vertex = vertex;
  return p;
}

rigging::SurfacePoint trianglePoint(const std::string& submesh, int triangle,
                                    const Eigen::Vector3d& barycentric) {
  rigging::SurfacePoint p;
  p.submesh = submesh;
  p.triangle = triangle;
  p.barycentric = barycentric;
  return p;
}

// A partial file on the sheet: vertex and triangle points on both sub-meshes and a tear source.
rigging::FeaturePointFile sheetFile() {
  rigging::FeaturePointFile f;
  f.skin = {"skin"};
  f.attached = {"lid"};
  f.points["2.1"].at = vertexPoint("skin", 5);
  f.points["2.10"].at = vertexPoint("skin", 77);
  f.points["8.3"].at = trianglePoint("skin", 40, {0.2, 0.3, 0.5});
  f.points["8.4"].at = vertexPoint("skin", 130);
  f.points["9.3"].at = vertexPoint("lid", 6);
  f.points["9.15"].at = trianglePoint("lid", 3, {0.6, 0.1, 0.3});
  f.tearLeft = vertexPoint("skin", 100);
  return f;
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

std::string joined(const Warnings& warnings) {
  std::string text;
  for (const Diagnostic& d : warnings) text += d.toString() + "\n";
  return text;
}

int countContaining(const Warnings& warnings, const std::string& part) {
  int n = 0;
  for (const Diagnostic& d : warnings) n += contains(d.message, part) ? 1 : 0;
  return n;
}

// Every point's binding leads to its stored position on `mesh`.
void verifyAtStoredPositions(const rigging::FeaturePointFile& f, const HeadMesh& mesh) {
  for (const auto& [id, spec] : f.points) {
    QVERIFY2(spec.at.position, id.c_str());
    QVERIFY2((rigging::surfacePosition(spec.at, mesh) - *spec.at.position).norm() < 1e-6,
             id.c_str());
  }
}

}  // namespace

class PointPositionsTest : public QObject {
  Q_OBJECT

  QTemporaryDir tmp_;

  // `file` saved as `name` and read back, so that messages name its lines.
  rigging::FeaturePointFile saved(const rigging::FeaturePointFile& file, const QString& name) {
    const std::string path = QDir(tmp_.path()).filePath(name).toStdString();
    saveAtomically(path, rigging::featurePointFileJson(file));
    return rigging::readFeaturePointFile(path);
  }

 private slots:
  void initTestCase() { QVERIFY(tmp_.isValid()); }

  // Positions are written as the shortest text that reads back exactly, beside the vertex (or
  // triangle), for points and tear sources alike, and a file read back validates silently.
  void positionsRoundTrip() {
    const HeadMesh mesh = sheetMesh();
    rigging::FeaturePointFile f = sheetFile();
    rigging::recordPositions(f, mesh);
    const rigging::FeaturePointFile back = saved(f, "round.fdp.json");
    QVERIFY(contains(back.text, "\"position\": ["));
    QCOMPARE(back.points.size(), f.points.size());
    for (const auto& [id, spec] : f.points) {
      const rigging::SurfacePoint& read = back.points.at(id).at;
      QVERIFY2(read.position && *read.position == *spec.at.position, id.c_str());
      QCOMPARE(*read.position, rigging::surfacePosition(spec.at, mesh));
    }
    QVERIFY(back.tearLeft && back.tearLeft->position);
    QCOMPARE(*back.tearLeft->position, mesh.positions.col(100).cast<double>());
    Warnings warnings;
    const rigging::FeaturePointFile valid =
        rigging::validateFeaturePoints(back, mesh, &warnings, rigging::FeaturePointSet::Partial);
    QVERIFY2(warnings.empty(), joined(warnings).c_str());
    QCOMPARE(valid.points.at("8.3").at.triangle, 40);
  }

  // A file without positions is bound by index alone, as before: same binding, no warning.
  void filesWithoutPositionsStillLoad() {
    const HeadMesh mesh = sheetMesh();
    const rigging::FeaturePointFile back = saved(sheetFile(), "plain.fdp.json");
    QVERIFY(!contains(back.text, "position"));
    for (const auto& [id, spec] : back.points) QVERIFY2(!spec.at.position, id.c_str());
    Warnings warnings;
    // On the reversed sheet too: without positions nothing can tell (documented).
    std::vector<int> newIndex;
    for (const HeadMesh& m : {mesh, reversed(mesh, newIndex)}) {
      const rigging::FeaturePointFile valid =
          rigging::validateFeaturePoints(back, m, &warnings, rigging::FeaturePointSet::Partial);
      QVERIFY2(warnings.empty(), joined(warnings).c_str());
      QCOMPARE(valid.points.at("2.1").at.vertex, 5);
      QCOMPARE(valid.points.at("8.3").at.triangle, 40);
    }
  }

  // The sheet re-exported with its vertices in reverse order: every point is re-snapped to the
  // vertex (or surface point) at its stored position, with a warning naming the file, line,
  // column, JSON path, the point and how far it moved.
  void reorderedVerticesAreResnapped() {
    const HeadMesh mesh = sheetMesh();
    rigging::FeaturePointFile f = sheetFile();
    rigging::recordPositions(f, mesh);
    const rigging::FeaturePointFile back = saved(f, "reordered.fdp.json");
    std::vector<int> newIndex;
    const HeadMesh moved = reversed(mesh, newIndex);
    Warnings warnings;
    const rigging::FeaturePointFile snapped =
        rigging::validateFeaturePoints(back, moved, &warnings, rigging::FeaturePointSet::Partial);
    // Vertex points: the new index of the same vertex. Triangle points keep their triangle
    // (the triangle order did not change) and are where they were: no warning for them.
    for (const char* id : {"2.1", "2.10", "8.4", "9.3"}) {
      const rigging::SurfacePoint& old = back.points.at(id).at;
      const HeadSubmesh& s = *mesh.findSubmesh(old.submesh);
      QCOMPARE(snapped.points.at(id).at.vertex,
               newIndex[static_cast<std::size_t>(s.firstVertex + old.vertex)] - s.firstVertex);
    }
    QCOMPARE(snapped.points.at("8.3").at.triangle, 40);
    QCOMPARE(snapped.tearLeft->vertex, mesh.findSubmesh("skin")->vertexCount - 1 - 100);
    verifyAtStoredPositions(snapped, moved);
    QCOMPARE(countContaining(warnings, "re-snapped"), 5);  // 4 vertex points and the tear
    qInfo("e.g. %s", warnings.front().toString().c_str());
    const std::string text = joined(warnings);
    const std::string path = back.path;
    // e.g. "file:14:12: points."2.1": point 2.1 (vertex 5 of "skin", stored at [...]) is 0.7
    // from its stored position: re-snapped to vertex 138 of "skin", moved 0.7, 0 from ..."
    QVERIFY2(contains(text, path + ":"), text.c_str());
    QVERIFY2(contains(text, "points.\"2.1\".position: point 2.1 (vertex 5 of \"skin\""),
             text.c_str());
    QVERIFY2(contains(text, "re-snapped to vertex 138 of \"skin\", moved "), text.c_str());
    QVERIFY2(contains(text, "tear_sources.left.position: tear source left"), text.c_str());
    for (const Diagnostic& d : warnings)
      QVERIFY2(d.where.line > 0 && d.where.column > 0, d.toString().c_str());
    // The corrected file validates silently: it now says where each point is.
    Warnings again;
    rigging::validateFeaturePoints(snapped, moved, &again, rigging::FeaturePointSet::Partial);
    QVERIFY2(again.empty(), joined(again).c_str());
  }

  // Triangle points re-snap to the closest surface point when their triangle moved, and an
  // index beyond the sub-mesh is re-snapped rather than refused when the file has a position.
  void trianglePointsAndLostIndicesAreResnapped() {
    const HeadMesh mesh = sheetMesh();
    rigging::FeaturePointFile f = sheetFile();
    rigging::recordPositions(f, mesh);
    f.points["8.3"].at.triangle = 7;  // somewhere else on the sheet
    f.points["2.10"].at.vertex = 5000;
    const rigging::FeaturePointFile back = saved(f, "lost.fdp.json");
    Warnings warnings;
    const rigging::FeaturePointFile snapped =
        rigging::validateFeaturePoints(back, mesh, &warnings, rigging::FeaturePointSet::Partial);
    QCOMPARE(snapped.points.at("8.3").at.triangle, 40);
    QVERIFY((snapped.points.at("8.3").at.barycentric - Eigen::Vector3d(0.2, 0.3, 0.5)).norm() <
            1e-6);
    QCOMPARE(snapped.points.at("2.10").at.vertex, 77);
    verifyAtStoredPositions(snapped, mesh);
    const std::string text = joined(warnings);
    QVERIFY2(contains(text, "has no place on this mesh: re-snapped to vertex 77"), text.c_str());
    QVERIFY2(contains(text, "re-snapped to triangle 40 of \"skin\""), text.c_str());
    // Without a position the out-of-range index stays an error.
    f.points["2.10"].at.position.reset();
    const rigging::FeaturePointFile plain = saved(f, "range.fdp.json");
    const std::string error = fileErrorOf([&] {
      rigging::validateFeaturePoints(plain, mesh, nullptr, rigging::FeaturePointSet::Partial);
    });
    QVERIFY2(contains(error, "points.\"2.10\".vertex: index 5000 out of range"), error.c_str());
    QVERIFY2(!contains(error, "another mesh"), error.c_str());
  }

  // Absurd stored positions (far beyond any float) give a clear error, never a crash or NaN.
  void absurdPositionsAreRefused() {
    const HeadMesh mesh = sheetMesh();
    rigging::FeaturePointFile f = sheetFile();
    rigging::recordPositions(f, mesh);
    f.points["2.1"].at.position = Eigen::Vector3d(1e300, 0, 0);
    f.points["8.3"].at.position = Eigen::Vector3d(0, -1e300, 1e300);
    const rigging::FeaturePointFile back = saved(f, "absurd.fdp.json");
    Warnings warnings;
    const std::string error = fileErrorOf([&] {
      rigging::validateFeaturePoints(back, mesh, &warnings, rigging::FeaturePointSet::Partial);
    });
    QVERIFY2(contains(error, "points.\"2.1\".position") && contains(error, "nothing to snap it to"),
             error.c_str());
    QVERIFY2(contains(error, "points.\"8.3\".position"), error.c_str());
    QVERIFY2(!contains(error, "nan"), error.c_str());
  }

  // Within kPositionMatch of the diagonal a point is where the file says (float rounding of a
  // re-export); well beyond it, it is re-snapped.
  void toleranceIsRelativeToTheMesh() {
    for (double scale : {1.0, 1000.0}) {  // the same sheet in metres and in millimetres
      HeadMesh mesh = sheetMesh();
      mesh.positions *= static_cast<float>(scale);
      const double diagonal = (mesh.boundsMax() - mesh.boundsMin()).cast<double>().norm();
      rigging::FeaturePointFile f = sheetFile();
      rigging::recordPositions(f, mesh);
      // Move vertex 5 (point 2.1) towards its neighbour 6, 0.5 x then 20 x the tolerance.
      const Eigen::Vector3f along = (mesh.positions.col(6) - mesh.positions.col(5)).normalized();
      for (const auto& [factor, resnapped] : {std::pair{0.5, false}, std::pair{20.0, true}}) {
        HeadMesh nudged = mesh;
        nudged.positions.col(5) +=
            static_cast<float>(factor * rigging::kPositionMatch * diagonal) * along;
        Warnings warnings;
        rigging::validateFeaturePoints(f, nudged, &warnings, rigging::FeaturePointSet::Partial);
        QVERIFY2(countContaining(warnings, "re-snapped") == (resnapped ? 1 : 0),
                 joined(warnings).c_str());
      }
    }
  }

  // A file placed on another mesh is refused, saying so, with the file, the mesh and the first
  // mismatches: when most positions have nothing near them, and when the names or vertex
  // counts do not fit. A single lost point in a fitting file is re-snapped with a warning.
  void fileForAnotherMeshIsRefused() {
    const HeadMesh mesh = sheetMesh();
    rigging::FeaturePointFile f = sheetFile();
    f.meshNote = "the sheet";
    rigging::recordPositions(f, mesh);
    const rigging::FeaturePointFile back = saved(f, "other.fdp.json");

    // Same names and vertex counts, another shape: the sheet stretched to 3 times its size.
    HeadMesh bigger = mesh;
    bigger.positions *= 3.0f;
    bigger.positions.row(2).array() += 1.0f;
    const std::string error = fileErrorOf([&] {
      rigging::validateFeaturePoints(back, bigger, nullptr, rigging::FeaturePointSet::Partial,
                                     "big-sheet.obj");
    });
    QVERIFY2(contains(error, back.path + ": this feature-point file was placed on another mesh"),
             error.c_str());
    QVERIFY2(contains(error, "big-sheet.obj (160 vertices; sub-meshes skin 144, lid 16)"),
             error.c_str());
    QVERIFY2(contains(error, "the file says it is for \"the sheet\""), error.c_str());
    QVERIFY2(contains(error, "points.\"2.1\".position: point 2.1"), error.c_str());
    QVERIFY2(contains(error, "and 2 more"), error.c_str());  // 7 mismatches, 5 shown
    qInfo("%s", error.c_str());

    // Names that do not fit: the same file on a head whose sub-meshes are called otherwise.
    HeadMesh renamed = mesh;
    renamed.submeshes[0].name = "M_Face";
    const std::string names = fileErrorOf([&] {
      rigging::validateFeaturePoints(back, renamed, nullptr, rigging::FeaturePointSet::Partial,
                                     "renamed.glb");
    });
    QVERIFY2(contains(names, "this feature-point file was placed on another mesh"), names.c_str());
    QVERIFY2(contains(names, "unknown sub-mesh \"skin\""), names.c_str());

    // Vertex counts that do not fit (no positions to re-snap with): a smaller sheet.
    const rigging::FeaturePointFile plain = saved(sheetFile(), "plain-other.fdp.json");
    const std::string counts = fileErrorOf([&] {
      rigging::validateFeaturePoints(plain, sheetMesh(5), nullptr,
                                     rigging::FeaturePointSet::Partial);
    });
    QVERIFY2(contains(counts,
                      "this feature-point file was placed on another mesh: 4 of 7 points "
                      "do not fit this mesh (41 vertices"),
             counts.c_str());
    QVERIFY2(contains(counts, "out of range"), counts.c_str());

    // One point lost, the rest in place: an edited mesh, re-snapped with a warning.
    HeadMesh edited = mesh;
    edited.positions.col(5).z() += 0.4f;  // far above the sheet
    Warnings warnings;
    const rigging::FeaturePointFile snapped =
        rigging::validateFeaturePoints(back, edited, &warnings, rigging::FeaturePointSet::Partial);
    QVERIFY(snapped.points.at("2.1").at.vertex != 5);
    const std::string text = joined(warnings);
    QCOMPARE(warnings.size(), std::size_t{1});
    QVERIFY2(contains(text, "points.\"2.1\".position: point 2.1") &&
                 contains(text, "a re-exported mesh allows; check this point"),
             text.c_str());
  }

  // The match tolerance never confuses two vertices of a real head: the shortest edge between
  // distinct positions is far longer (FeaturePointFile.h states the figures).
  void matchToleranceIsBelowEveryEdge() {
    std::vector<std::pair<const char*, HeadMesh>> heads;
    if (rigging::defaultHeadAvailable()) heads.emplace_back("default", rigging::loadDefaultHead());
    if (QFileInfo::exists(kIctMesh))
      heads.emplace_back("ICT", rigging::importHeadMesh(kIctMesh.toStdString()));
    for (const auto& [name, mesh] : heads) {
      const double diagonal = (mesh.boundsMax() - mesh.boundsMin()).cast<double>().norm();
      double shortest = std::numeric_limits<double>::infinity();
      for (const HeadSubmesh& s : mesh.submeshes)
        for (const Eigen::Vector3i& t : s.triangles)
          for (int k = 0; k < 3; ++k) {
            const double edge = (mesh.positions.col(t[k]) - mesh.positions.col(t[(k + 1) % 3]))
                                    .cast<double>()
                                    .norm();
            if (edge > 0) shortest = std::min(shortest, edge);
          }
      qInfo("%s head: shortest edge %.3g of the diagonal (match tolerance %.0e)", name,
            shortest / diagonal, rigging::kPositionMatch);
      QVERIFY(shortest > 10 * rigging::kPositionMatch * diagonal);
    }
    // Each head that was there is checked; a missing one is named.
    if (!rigging::defaultHeadAvailable()) LACRIMA_SKIP_WITHOUT_DEFAULT_HEAD();
    LACRIMA_REQUIRE_SHARED(kIctMesh);
  }

  // lacrima-rig writes positions into the file --complete saves, rig.json says which face
  // frame it rigged in, and a file for another head is refused with the message.
  void commandLine() {
    if (!rigging::defaultHeadAvailable()) LACRIMA_SKIP_WITHOUT_DEFAULT_HEAD();
    LACRIMA_REQUIRE_SHARED(kIctMesh);
    rigging::FeaturePointFile partial = rigging::readFeaturePointFile(kIctFdp.toStdString());
    std::erase_if(partial.points, [](const auto& point) { return point.first[0] == '4'; });
    const QString partialPath = QDir(tmp_.path()).filePath("ict-partial.fdp.json");
    saveAtomically(partialPath.toStdString(), rigging::featurePointFileJson(partial));
    const QString complete = QDir(tmp_.path()).filePath("ict-complete.fdp.json");
    const QString out = QDir(tmp_.path()).filePath("ict-rig");
    QProcess run;
    run.start(kRigTool,
              {"--mesh", kIctMesh, "--fdp", partialPath, "--complete", complete, "-o", out});
    QVERIFY(run.waitForFinished(240000));
    QVERIFY2(run.exitCode() == 0, run.readAllStandardError().constData());
    const rigging::FeaturePointFile written = rigging::readFeaturePointFile(complete.toStdString());
    QVERIFY(written.points.size() > partial.points.size());
    for (const auto& [id, spec] : written.points) QVERIFY2(spec.at.position, id.c_str());
    QFile rigJson(QDir(out).filePath("rig.json"));
    QVERIFY(rigJson.open(QIODevice::ReadOnly));
    const QJsonObject frame =
        QJsonDocument::fromJson(rigJson.readAll()).object().value("face_frame").toObject();
    QCOMPARE(frame.value("measured").toBool(), true);
    QCOMPARE(frame.value("rotation").toArray().at(1).toArray().at(1).toDouble(), 1.0);

    QProcess other;
    other.start(kRigTool, {"--default", "--fdp", complete, "--report"});
    QVERIFY(other.waitForFinished(120000));
    QCOMPARE(other.exitCode(), 1);
    const QByteArray message = other.readAllStandardError();
    QVERIFY2(message.contains(complete.toUtf8() +
                              ": this feature-point file was placed on another mesh") &&
                 message.contains("do not fit the default head ("),
             message.constData());
  }

  // The default head's file with positions, on the head with every sub-mesh's vertices in
  // reverse order: all points re-snap, and the rig is the same (FAPU, feature points, poses).
  void reorderedDefaultHeadRigsTheSame() {
    if (!rigging::defaultHeadAvailable()) LACRIMA_SKIP_WITHOUT_DEFAULT_HEAD();
    const HeadMesh head = rigging::loadDefaultHead();
    rigging::FeaturePointFile fdp = rigging::validateFeaturePoints(
        rigging::readFeaturePointFile(kDefaultFdp.toStdString()), head, nullptr);
    rigging::recordPositions(fdp, head);
    const rigging::FeaturePointFile back = saved(fdp, "default.fdp.json");
    std::vector<int> newIndex;
    const HeadMesh moved = reversed(head, newIndex);
    Warnings warnings;
    QElapsedTimer timer;
    timer.start();
    const rigging::FeaturePointFile snapped =
        rigging::validateFeaturePoints(back, moved, &warnings);
    qInfo("default head, vertices reversed: %d points re-snapped in %.1f ms",
          countContaining(warnings, "re-snapped"), static_cast<double>(timer.nsecsElapsed()) / 1e6);
    QVERIFY2(countContaining(warnings, "re-snapped") >= static_cast<int>(back.points.size()) - 2,
             joined(warnings).c_str());
    verifyAtStoredPositions(snapped, moved);

    const rigging::BuiltRig original = rigging::buildRig(head, back);
    const rigging::BuiltRig resnapped = rigging::buildRig(moved, snapped);
    QCOMPARE(resnapped.featurePoints.size(), original.featurePoints.size());
    for (const auto& [id, p] : original.featurePoints)
      QVERIFY2((resnapped.featurePoints.at(id) - p).norm() < 1e-12, id.c_str());
    for (double FapuSet::*unit :
         {&FapuSet::es0, &FapuSet::ens0, &FapuSet::mns0, &FapuSet::mw0, &FapuSet::irisd0})
      QCOMPARE(resnapped.fapu.*unit, original.fapu.*unit);
    // Poses, vertex by vertex through the reordering.
    double worst = 0, largest = 0;
    for (int fap : {3, 4, 5, 19, 31, 53, 59}) {
      const std::size_t c = static_cast<std::size_t>(channelIndex(fap));
      Eigen::Matrix3Xd a = Eigen::Matrix3Xd::Zero(3, head.vertexCount());
      Eigen::Matrix3Xd b = a;
      const VertexPose& pa = original.poses.poses[c];
      const VertexPose& pb = resnapped.poses.poses[c];
      QVERIFY2(!pa.empty(), qPrintable(QString("FAP %1 has no pose").arg(fap)));
      for (std::size_t k = 0; k < pa.vertices.size(); ++k)
        a.col(newIndex[static_cast<std::size_t>(pa.vertices[k])]) +=
            pa.offsets.col(static_cast<Eigen::Index>(k)).cast<double>();
      for (std::size_t k = 0; k < pb.vertices.size(); ++k)
        b.col(pb.vertices[k]) += pb.offsets.col(static_cast<Eigen::Index>(k)).cast<double>();
      worst = std::max(worst, (a - b).colwise().norm().maxCoeff());
      largest = std::max(largest, a.colwise().norm().maxCoeff());
    }
    qInfo("re-snapped default head: largest pose difference %.3g of the largest offset %.3g", worst,
          largest);
    QVERIFY(largest > 0);
    QVERIFY2(worst <= 1e-4 * largest, qPrintable(QString::number(worst)));
  }
};

QTEST_GUILESS_MAIN(PointPositionsTest)
#include "PointPositionsTest.moc"
