// The Head workspace's document without windows: the role guesser's table; the ICT
// head (OBJ) and the default head written as GLB imported with their roles guessed; the ICT
// anchors placed from picks, the rest proposed, a point moved, undo and redo; the saved file
// validates, reads back to the same document and rigs; bad input leaves the document as it was.
#include "../rigging/TestHeadFiles.h"
#include "../support/MissingData.h"

#include <lacrima/common/AtomicSave.h>
#include <lacrima/common/PoseSet.h>
#include <lacrima/editing/HeadSetup.h>
#include <lacrima/exporters/GlbExport.h>
#include <lacrima/playback/HeadRig.h>
#include <lacrima/rigging/DefaultHead.h>
#include <lacrima/rigging/FeaturePointProposal.h>

#include <QFileInfo>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QtTest>

#include <memory>

using namespace lacrima;
using namespace lacrima::editing;
using namespace lacrima::rigtest;

Q_DECLARE_METATYPE(lacrima::editing::PartRole)
Q_DECLARE_METATYPE(lacrima::editing::HeadSide)

namespace {

int submeshNamed(const HeadMesh& mesh, const std::string& name) {
  for (std::size_t i = 0; i < mesh.submeshes.size(); ++i)
    if (mesh.submeshes[i].name == name) return static_cast<int>(i);
  return -1;
}

// What the viewport's pick returns for a click exactly on a vertex of a file's point: a
// triangle of the sub-mesh with that corner, weight 1 there.
SurfaceSpot spotAt(const HeadMesh& mesh, const rigging::SurfacePoint& at) {
  const int s = submeshNamed(mesh, at.submesh);
  const HeadSubmesh& part = mesh.submeshes[static_cast<std::size_t>(s)];
  const int global = part.firstVertex + at.vertex;
  for (std::size_t t = 0; t < part.triangles.size(); ++t)
    for (int c = 0; c < 3; ++c)
      if (part.triangles[t][c] == global) {
        SurfaceSpot spot{s, static_cast<int>(t), Eigen::Vector3d::Zero()};
        spot.barycentric[c] = 1.0;
        return spot;
      }
  return {};
}

}  // namespace

class HeadSetupTest : public QObject {
  Q_OBJECT

  std::shared_ptr<const ProposalReference> reference_;
  QTemporaryDir dir_;

  // The ICT head (the caller checked it is there) with its 8 anchors placed by hand.
  void placeIctAnchors(HeadSetup& setup, rigging::FeaturePointFile& hand) {
    setup.importFile(kIctMesh);
    hand = rigging::readFeaturePointFile(kIctFdp.toStdString());
    for (const std::string& id : rigging::proposalAnchors())
      setup.placePoint(id, spotAt(setup.mesh(), hand.points.at(id).at));
  }

 private slots:
  void initTestCase() {
    QVERIFY(dir_.isValid());
    if (rigging::defaultHeadAvailable()) reference_ = ProposalReference::loadDefault();
  }

  void guessesRolesFromNames_data() {
    QTest::addColumn<QString>("mesh");
    QTest::addColumn<QString>("material");
    QTest::addColumn<HeadSide>("side");
    QTest::addColumn<PartRole>("expected");
    const auto row = [](const char* mesh, const char* material, HeadSide side, PartRole role) {
      QTest::addRow("%s/%s", mesh, material) << mesh << material << side << role;
    };
    const HeadSide none = HeadSide::Unknown;
    row("skin", "", none, PartRole::Skin);
    row("Body", "M_Face", none, PartRole::Skin);
    row("mesh", "M_BackHead", none, PartRole::Skin);
    row("eye_l", "", none, PartRole::EyeLeft);
    row("eye_r", "", none, PartRole::EyeRight);
    row("EyeL", "", none, PartRole::EyeLeft);
    row("EyeR", "", none, PartRole::EyeRight);
    row("R_eye", "", none, PartRole::EyeRight);
    row("mesh", "M_IrisLeft", none, PartRole::EyeLeft);
    row("mesh", "M_ScleraRight", none, PartRole::EyeRight);
    row("pupil.left", "", none, PartRole::EyeLeft);
    row("eyeball", "", HeadSide::Right, PartRole::EyeRight);
    row("eye", "", none, PartRole::EyeLeft);
    row("cornea_r", "", none, PartRole::CorneaRight);
    row("Cornea", "", HeadSide::Left, PartRole::CorneaLeft);
    row("eyelashes", "", none, PartRole::Attached);
    row("EyeBrow_L", "", none, PartRole::Attached);
    row("mesh", "M_EyeBlend", none, PartRole::Ignored);
    row("mesh", "M_EyeOcclusion", none, PartRole::Ignored);
    row("mesh", "M_LacrimalFluid", none, PartRole::Ignored);
    row("teeth_upper", "", none, PartRole::TeethUpper);
    row("UpperTeeth", "", none, PartRole::TeethUpper);
    row("teeth_lower", "", none, PartRole::TeethLower);
    row("LowerTeeth", "", none, PartRole::TeethLower);
    row("tooth_bottom", "", none, PartRole::TeethLower);
    row("jaw_teeth", "", none, PartRole::TeethLower);
    row("teeth", "", none, PartRole::TeethUpper);
    row("mesh", "M_GumsTongue", none, PartRole::TeethUpper);
    row("tongue", "", none, PartRole::Tongue);
    row("hair", "", none, PartRole::Rigid);
    row("mesh", "", none, PartRole::Rigid);
  }
  void guessesRolesFromNames() {
    QFETCH(QString, mesh);
    QFETCH(QString, material);
    QFETCH(HeadSide, side);
    QFETCH(PartRole, expected);
    const PartRole got = guessPartRole(mesh.toStdString(), material.toStdString(), side);
    QVERIFY2(got == expected, partRoleName(got).data());
  }

  void roleNamesRoundTrip() {
    for (PartRole role : kPartRoles) QCOMPARE(partRoleFromName(partRoleName(role)), role);
    QVERIFY(!partRoleFromName("eyes"));
  }

  // The ICT head's parts: skin in two pieces, sided eyes from material names, gums and teeth
  // with the skull, the films and lashes attached.
  void importsIctWithRoles() {
    LACRIMA_REQUIRE_SHARED(kIctMesh);
    HeadSetup setup;
    QSignalSpy meshSpy(&setup, &HeadSetup::meshChanged);
    setup.importFile(kIctMesh);
    QCOMPARE(meshSpy.count(), 1);
    const HeadMesh& mesh = setup.mesh();
    const auto roleOf = [&](const char* name) {
      const int s = submeshNamed(mesh, name);
      return s < 0 ? PartRole::Ignored : setup.role(s);
    };
    QCOMPARE(roleOf("M_Face"), PartRole::Skin);
    QCOMPARE(roleOf("M_BackHead"), PartRole::Skin);
    QCOMPARE(roleOf("M_ScleraLeft"), PartRole::EyeLeft);
    QCOMPARE(roleOf("M_IrisRight"), PartRole::EyeRight);
    QCOMPARE(roleOf("M_EyeLashes"), PartRole::Attached);
    QCOMPARE(roleOf("M_Teeth"), PartRole::TeethUpper);
    QCOMPARE(roleOf("M_GumsTongue"), PartRole::TeethUpper);
    // The same role lists as the hand-made file.
    const rigging::FeaturePointFile hand = rigging::readFeaturePointFile(kIctFdp.toStdString());
    const rigging::FeaturePointFile mine = setup.toFile();
    QCOMPARE(mine.skin, hand.skin);
    QCOMPARE(mine.eyeLeft.submeshes, hand.eyeLeft.submeshes);
    QCOMPARE(mine.eyeRight.submeshes, hand.eyeRight.submeshes);
  }

  // The default head as a GLB: materials name the parts without sides ("eye", "eye_2"), so the
  // side comes from the head and the teeth halves from their heights.
  void importsGlbWithRolesFromPositions() {
    if (!rigging::defaultHeadAvailable()) LACRIMA_SKIP_WITHOUT_DEFAULT_HEAD();
    const HeadMesh head = rigging::loadDefaultHead();
    PoseSet poses;
    poses.vertexCount = head.vertexCount();
    const QString glb = dir_.filePath(QStringLiteral("default-head.glb"));
    exporters::exportGlb(head, poses, glb.toStdString());
    HeadSetup setup;
    setup.importFile(glb);
    const HeadMesh& mesh = setup.mesh();
    QCOMPARE(mesh.submeshes.size(), head.submeshes.size());
    // The GLB keeps the order; compare with what the default head's own names say.
    for (std::size_t i = 0; i < head.submeshes.size(); ++i) {
      const PartRole expected = guessPartRole(head.submeshes[i].name, "");
      QVERIFY2(setup.role(static_cast<int>(i)) == expected,
               qPrintable(QStringLiteral("%1 (%2): %3")
                              .arg(QString::fromStdString(head.submeshes[i].name),
                                   QString::fromStdString(mesh.submeshes[i].name),
                                   QString::fromUtf8(partRoleName(setup.role(int(i))).data()))));
    }
  }

  // Anchors placed from picks, the rest proposed, a proposed point corrected by hand, undo and
  // redo, a second proposal keeps the hand points.
  void placesProposesMovesWithUndo() {
    if (!reference_) LACRIMA_SKIP_WITHOUT_DEFAULT_HEAD();
    HeadSetup setup;
    rigging::FeaturePointFile hand;
    LACRIMA_REQUIRE_SHARED(kIctMesh);
    placeIctAnchors(setup, hand);
    const HeadMesh& mesh = setup.mesh();
    QCOMPARE(setup.points().size(), rigging::proposalAnchors().size());
    for (const std::string& id : rigging::proposalAnchors()) {
      QVERIFY(setup.point(id)->byHand());
      QCOMPARE(setup.point(id)->spec.at.vertex, hand.points.at(id).at.vertex);
    }
    const int placed = setup.undoStack()->count();

    setup.propose(*reference_);
    QCOMPARE(setup.undoStack()->count(), placed + 1);  // one step
    // Every point of the hand-made file (the ICT head has no tongue or jaw part for the rest).
    QVERIFY(setup.points().size() >= hand.points.size());
    for (const auto& [id, p] : setup.points()) {
      const bool anchor =
          std::count(rigging::proposalAnchors().begin(), rigging::proposalAnchors().end(), id) > 0;
      QVERIFY2(p.byHand() == anchor, id.c_str());
    }
    // Proposed points land near the hand-made ones (docs/rig.md: mean 0.114 ES0 on ICT).
    const double es0 = (rigging::surfacePosition(hand.points.at("3.5").at, mesh) -
                        rigging::surfacePosition(hand.points.at("3.6").at, mesh))
                           .norm();
    double sum = 0;
    int n = 0;
    for (const auto& [id, spec] : hand.points)
      if (const auto at = setup.position(id)) {
        sum += (*at - rigging::surfacePosition(spec.at, mesh)).norm() / es0;
        ++n;
      }
    QCOMPARE(n, int(hand.points.size()));
    QVERIFY2(sum / n < 0.15, qPrintable(QString::number(sum / n)));

    // Drag a proposed chin point by hand: it snaps onto the skin and becomes a hand point.
    const std::string id = "2.1";
    const PlacedPoint before = *setup.point(id);
    QVERIFY(!before.byHand());
    const Eigen::Vector3d from = *setup.position(id);
    const Eigen::Vector3d target = from + Eigen::Vector3d(0.3, 0.2, 2.0);  // cm, off the surface
    setup.movePoint(id, target);
    const Eigen::Vector3d to = *setup.position(id);
    QVERIFY(setup.point(id)->byHand());
    QVERIFY((to - from).norm() > 0.1);
    QVERIFY((to - target).norm() <= (from - target).norm() + 1e-9);
    QCOMPARE(roleOfPoint(setup, id), PartRole::Skin);

    setup.undoStack()->undo();
    QVERIFY(!setup.point(id)->byHand());
    QVERIFY((*setup.position(id) - from).norm() < 1e-9);
    setup.undoStack()->redo();
    QVERIFY((*setup.position(id) - to).norm() < 1e-9);

    // Proposing again keeps every hand point, the moved one too.
    setup.propose(*reference_);
    QVERIFY(setup.point(id)->byHand());
    QVERIFY((*setup.position(id) - to).norm() < 1e-9);

    // Undo back to the anchors, then all the way, then redo everything.
    setup.undoStack()->setIndex(placed);
    QCOMPARE(setup.points().size(), rigging::proposalAnchors().size());
    setup.undoStack()->setIndex(0);
    QVERIFY(setup.points().empty());
    setup.undoStack()->setIndex(setup.undoStack()->count());
    QVERIFY((*setup.position(id) - to).norm() < 1e-9);

    // Roles are undoable too.
    const int teeth = submeshNamed(mesh, "M_Teeth");
    setup.setRole(teeth, PartRole::TeethLower);
    QCOMPARE(setup.toFile().jaw, std::vector<std::string>{"M_Teeth"});
    setup.undoStack()->undo();
    QCOMPARE(setup.role(teeth), PartRole::TeethUpper);
    QVERIFY(setup.toFile().jaw.empty());

    removesPoints(setup);
  }

  // Saved: validates as a complete file, marks hand points, reads back to the same document,
  // and rigs.
  void savesReopensAndRigs() {
    if (!reference_) LACRIMA_SKIP_WITHOUT_DEFAULT_HEAD();
    HeadSetup setup;
    rigging::FeaturePointFile hand;
    LACRIMA_REQUIRE_SHARED(kIctMesh);
    placeIctAnchors(setup, hand);
    setup.propose(*reference_);
    setup.movePoint("8.1", *setup.position("8.1") + Eigen::Vector3d(0, 0.2, 0));
    const QString path = dir_.filePath(QStringLiteral("ict.fdp.json"));
    setup.save(path);
    QVERIFY(setup.undoStack()->isClean());
    QCOMPARE(setup.fdpPath(), path);

    Warnings warnings;
    const rigging::FeaturePointFile saved =
        rigging::readFeaturePointFile(path.toStdString(), &warnings);
    QVERIFY2(warnings.empty(), warnings.empty() ? "" : warnings.front().toString().c_str());
    rigging::validateFeaturePoints(saved, setup.mesh(), &warnings);
    int handCount = 0;
    for (const auto& [id, spec] : saved.points) handCount += spec.placedByHand ? 1 : 0;
    QCOMPARE(handCount, int(rigging::proposalAnchors().size()) + 1);
    QVERIFY(saved.points.at("8.1").placedByHand);

    HeadSetup reopened;
    reopened.setMesh(kIctMesh, HeadMesh(setup.mesh()));
    reopened.openFeaturePoints(path);
    QVERIFY(reopened.roles() == setup.roles());
    QCOMPARE(reopened.points().size(), setup.points().size());
    for (const auto& [id, p] : setup.points()) {
      QCOMPARE(reopened.point(id)->byHand(), p.byHand());
      QVERIFY((*reopened.position(id) - *setup.position(id)).norm() < 1e-6);
    }

    const auto rig = playback::rigHead(HeadMesh(setup.mesh()), saved);
    QVERIFY(rig->blender);
    QVERIFY(rig->rig.featurePoints.count("2.1"));
    QVERIFY(rig->rig.fapu.es0 > 0);
  }

  // The same head exported Z-up in millimetres (x, y, z) cm -> (x, -z, y) * 10 mm: the same
  // clicks give the same proposal, point for point, and it rigs (turned upright by the rig).
  void zUpMillimetreHeadGivesTheSameProposal() {
    if (!reference_) LACRIMA_SKIP_WITHOUT_DEFAULT_HEAD();
    HeadSetup upright;
    rigging::FeaturePointFile hand;
    LACRIMA_REQUIRE_SHARED(kIctMesh);
    placeIctAnchors(upright, hand);
    upright.propose(*reference_);

    HeadMesh turned = upright.mesh();
    const auto toZUp = [](const Eigen::Vector3d& p) {
      return Eigen::Vector3d(10 * p.x(), -10 * p.z(), 10 * p.y());
    };
    for (Eigen::Index i = 0; i < turned.positions.cols(); ++i)
      turned.positions.col(i) = toZUp(turned.positions.col(i).cast<double>()).cast<float>();
    turned.computeNormals();
    HeadSetup zUp;
    zUp.setMesh(QStringLiteral("ict-z-up-mm.obj"), std::move(turned));
    QVERIFY(zUp.roles() == upright.roles());
    for (const std::string& id : rigging::proposalAnchors())
      zUp.placePoint(id, spotAt(zUp.mesh(), hand.points.at(id).at));
    zUp.propose(*reference_);

    QCOMPARE(zUp.points().size(), upright.points().size());
    const double size = (zUp.mesh().boundsMax() - zUp.mesh().boundsMin()).norm();
    for (const auto& [id, p] : upright.points()) {
      const Eigen::Vector3d expected = toZUp(*upright.position(id));
      QVERIFY2((*zUp.position(id) - expected).norm() < 1e-4 * size, id.c_str());
      QCOMPARE(zUp.point(id)->byHand(), p.byHand());
    }
    const auto rig = playback::rigHead(HeadMesh(zUp.mesh()), zUp.toFile());
    QVERIFY(!rig->rig.featurePoints.empty());
    QVERIFY(!rig->frame.rotation.isIdentity());
    const auto uprightRig = playback::rigHead(HeadMesh(upright.mesh()), upright.toFile());
    QVERIFY(std::abs(rig->rig.fapu.es0 - 10 * uprightRig->rig.fapu.es0) < 1e-4 * rig->rig.fapu.es0);
  }

  // Bad input: an unreadable file, a mesh without faces, a feature-point file for another
  // mesh. Each gives a message naming the file; the document stays as it was.
  void badInputLeavesDocumentAlone() {
    LACRIMA_REQUIRE_SHARED(kIctMesh);
    HeadSetup setup;
    setup.importFile(kIctMesh);
    setup.placePoint("9.3", SurfaceSpot{0, 0, Eigen::Vector3d(0.2, 0.3, 0.5)});
    const std::size_t parts = setup.mesh().submeshes.size();
    const auto unchanged = [&] {
      QCOMPARE(setup.meshPath(), kIctMesh);
      QCOMPARE(setup.mesh().submeshes.size(), parts);
      QCOMPARE(setup.points().size(), std::size_t{1});
    };

    const QString missing = dir_.filePath(QStringLiteral("no-such-head.obj"));
    try {
      setup.importFile(missing);
      QFAIL("imported a missing file");
    } catch (const std::exception& e) {
      QVERIFY2(QString::fromUtf8(e.what()).contains(missing), e.what());
    }
    unchanged();

    const QString noFaces = dir_.filePath(QStringLiteral("points-only.obj"));
    saveAtomically(noFaces.toStdString(), "v 0 0 0\nv 1 0 0\nv 0 1 0\n");
    try {
      setup.importFile(noFaces);
      QFAIL("imported a mesh with no faces");
    } catch (const std::exception& e) {
      QVERIFY2(QString::fromUtf8(e.what()).contains(noFaces), e.what());
    }
    unchanged();
    try {
      setup.setMesh(noFaces, HeadMesh{});
      QFAIL("took an empty mesh");
    } catch (const std::invalid_argument& e) {
      QVERIFY2(QString::fromUtf8(e.what()).contains(QStringLiteral("no triangles")), e.what());
    }
    unchanged();

    // The default head's feature points name sub-meshes the ICT head does not have.
    try {
      setup.openFeaturePoints(kDefaultFdp);
      QFAIL("opened another mesh's feature points");
    } catch (const FileError& e) {
      QVERIFY2(QString::fromUtf8(e.what()).contains(QStringLiteral("unknown sub-mesh")), e.what());
    }
    unchanged();

    // A "placed" that is neither "hand" nor "proposed" is a located error.
    const QString oddPlaced = dir_.filePath(QStringLiteral("odd-placed.fdp.json"));
    saveAtomically(oddPlaced.toStdString(),
                   R"({ "format": "lacrima-fdp", "version": 1,
  "submeshes": { "skin": ["M_Face"] },
  "points": { "9.3": { "submesh": "M_Face", "vertex": 10, "placed": "robot" } } })");
    try {
      setup.openFeaturePoints(oddPlaced);
      QFAIL("took an unknown placement");
    } catch (const FileError& e) {
      const QString message = QString::fromUtf8(e.what());
      QVERIFY2(
          message.contains(QStringLiteral("odd-placed.fdp.json:3:59: points.\"9.3\".placed:")) &&
              message.contains(QStringLiteral("expected \"hand\" or \"proposed\"")),
          e.what());
    }
    unchanged();

    // A pick off the mesh is refused, not stored.
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                             setup.placePoint("2.1", SurfaceSpot{99, 0, {1, 0, 0}}));
    unchanged();
  }

 private:
  static PartRole roleOfPoint(const HeadSetup& setup, const std::string& id) {
    return setup.role(submeshNamed(setup.mesh(), setup.point(id)->spec.at.submesh));
  }

  static void removesPoints(HeadSetup& setup) {
    const std::size_t count = setup.points().size();
    setup.removePoint("2.1");
    QCOMPARE(setup.points().size(), count - 1);
    QVERIFY(!setup.point("2.1"));
    setup.undoStack()->undo();
    QVERIFY(setup.point("2.1"));
  }
};

QTEST_GUILESS_MAIN(HeadSetupTest)
#include "HeadSetupTest.moc"
