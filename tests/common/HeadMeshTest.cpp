// HeadMesh: sub-mesh lookup, welding of uv-seam copies, area-weighted normals.
#include <lacrima/common/HeadMesh.h>

#include <QtTest>

#include <cmath>

using namespace lacrima;

namespace {

// A unit square in the z = 0 plane made of two triangles, split along a uv seam: vertices 4
// and 5 are bit-identical copies of 1 and 2, as a converter emits them at a texture seam.
HeadMesh seamedSquare() {
  HeadMesh mesh;
  mesh.positions.resize(3, 6);
  mesh.positions << 0, 1, 0, 1, 1, 0,  //
      0, 0, 1, 1, 0, 1,                //
      0, 0, 0, 0, 0, 0;
  HeadSubmesh a{"skin", -1, 0, 4, {{0, 1, 2}}};
  HeadSubmesh b{"patch", -1, 4, 2, {{5, 4, 3}}};
  mesh.submeshes = {a, b};
  return mesh;
}

}  // namespace

class HeadMeshTest : public QObject {
  Q_OBJECT

 private slots:
  void lookup() {
    const HeadMesh mesh = seamedSquare();
    QCOMPARE(mesh.vertexCount(), 6);
    QCOMPARE(mesh.triangleCount(), 2);
    QVERIFY(mesh.findSubmesh("patch") == &mesh.submeshes[1]);
    QVERIFY(mesh.findSubmesh("tongue") == nullptr);
    QCOMPARE(mesh.submeshOfVertex(3), 0);
    QCOMPARE(mesh.submeshOfVertex(5), 1);
    QCOMPARE(mesh.submeshOfVertex(6), -1);
    QCOMPARE(mesh.boundsMin(), Eigen::Vector3f(0, 0, 0));
    QCOMPARE(mesh.boundsMax(), Eigen::Vector3f(1, 1, 0));
  }

  void weldMapsSeamCopiesToTheFirst() {
    const std::vector<int> weld = weldCoincidentVertices(seamedSquare().positions);
    QCOMPARE(weld, (std::vector<int>{0, 1, 2, 3, 1, 2}));
  }

  void nonFinitePositionsWeldWithNothing() {
    Eigen::Matrix3Xf positions = seamedSquare().positions;
    positions(0, 1) = std::nanf("");
    positions(0, 4) = std::nanf("");
    const std::vector<int> weld = weldCoincidentVertices(positions);
    QCOMPARE(weld, (std::vector<int>{0, 1, 2, 3, 4, 2}));
  }

  void normalsAreSharedAcrossSeams() {
    HeadMesh mesh = seamedSquare();
    // Lift vertex 3 so the two halves are not coplanar: the seam vertices must still agree.
    mesh.positions(2, 3) = 0.5f;
    mesh.computeNormals();
    QCOMPARE(mesh.normals.cols(), Eigen::Index(6));
    for (int v = 0; v < 6; ++v) QVERIFY(std::abs(mesh.normals.col(v).norm() - 1.f) < 1e-6f);
    QVERIFY(mesh.normals.col(1).isApprox(mesh.normals.col(4)));
    QVERIFY(mesh.normals.col(2).isApprox(mesh.normals.col(5)));
    QVERIFY(mesh.normals.col(0).isApprox(Eigen::Vector3f::UnitZ()));   // flat half faces +z
    QVERIFY(!mesh.normals.col(1).isApprox(Eigen::Vector3f::UnitZ()));  // seam sees both halves
  }

  void degenerateTrianglesGiveFiniteNormals() {
    HeadMesh mesh;
    mesh.positions = Eigen::Matrix3Xf::Zero(3, 4);  // every triangle has zero area
    mesh.submeshes = {{"skin", -1, 0, 4, {{0, 1, 2}, {1, 2, 3}}}};
    mesh.computeNormals();
    QVERIFY(mesh.normals.allFinite());
    QCOMPARE(Eigen::Vector3f(mesh.normals.col(3)), Eigen::Vector3f::UnitZ());
  }
};

QTEST_GUILESS_MAIN(HeadMeshTest)
#include "HeadMeshTest.moc"
