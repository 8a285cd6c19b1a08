// Rig checks (RigChecks.h): the default head passes with no Error, and each check fires, with
// its figures, on a deliberately broken feature-point file; lacrima-rig --check prints them and
// exits 1 on an Error.
#include "DefaultRigFixture.h"
#include "TestHeadFiles.h"

#include <lacrima/common/AtomicSave.h>
#include <lacrima/common/FapTable.h>
#include <lacrima/rigging/DefaultHead.h>
#include <lacrima/rigging/FeaturePointFile.h>
#include <lacrima/rigging/RigBuilder.h>
#include <lacrima/rigging/RigChecks.h>

#include <Eigen/Geometry>

#include <QDir>
#include <QProcess>
#include <QTemporaryDir>
#include <QtTest>

#include <algorithm>
#include <limits>
#include <memory>

using namespace lacrima;
using namespace lacrima::rigtest;
using rigging::RigCheck;

namespace {

std::vector<RigCheck> ofKind(const std::vector<RigCheck>& checks, const std::string& kind) {
  std::vector<RigCheck> out;
  std::copy_if(checks.begin(), checks.end(), std::back_inserter(out),
               [&](const RigCheck& c) { return c.kind == kind; });
  return out;
}

bool concerns(const RigCheck& check, const std::string& id) {
  return std::find(check.points.begin(), check.points.end(), id) != check.points.end();
}

bool anyError(const std::vector<RigCheck>& checks) {
  return std::any_of(checks.begin(), checks.end(),
                     [](const RigCheck& c) { return c.severity == RigCheck::Severity::Error; });
}

QString listed(const std::vector<RigCheck>& checks) {
  QString out;
  for (const RigCheck& c : checks) out += QString::fromStdString(rigging::toString(c)) + "\n";
  return out;
}

}  // namespace

class RigChecksTest : public QObject {
  Q_OBJECT

  std::unique_ptr<HeadMesh> head_;
  std::unique_ptr<rigging::FeaturePointFile> fdp_;
  std::unique_ptr<rigging::BuiltRig> rig_;
  std::vector<RigCheck> checks_;
  QTemporaryDir tmp_;

  // The local skin vertex nearest to `p` among those `keep` accepts.
  template <class Keep>
  int nearestSkinVertex(const Eigen::Vector3d& p, Keep keep) const {
    const HeadSubmesh& skin = *head_->findSubmesh("skin");
    int best = -1;
    double bestD = std::numeric_limits<double>::infinity();
    for (int v = 0; v < skin.vertexCount; ++v) {
      const Eigen::Vector3d q = head_->positions.col(skin.firstVertex + v).cast<double>();
      if (!keep(q)) continue;
      if ((q - p).norm() < bestD) bestD = (q - p).norm(), best = v;
    }
    return best;
  }

  std::vector<RigCheck> checksOf(const rigging::FeaturePointFile& fdp,
                                 const rigging::RigCheckOptions& options = {}) const {
    Warnings warnings;
    rigging::validateFeaturePoints(fdp, *head_, &warnings);
    const rigging::BuiltRig rig = rigging::buildRig(*head_, fdp);
    return rigging::checkRig(*head_, fdp, rig, options);
  }

 private slots:
  void initTestCase() {
    QVERIFY(tmp_.isValid());
    if (!rigging::defaultHeadAvailable()) return;
    head_ = std::make_unique<HeadMesh>(rigging::loadDefaultHead());
    fdp_ = std::make_unique<rigging::FeaturePointFile>(
        rigging::readFeaturePointFile(kDefaultFdp.toStdString()));
    rig_ = std::make_unique<rigging::BuiltRig>(rigging::buildRig(*head_, *fdp_));
    checks_ = rigging::checkRig(*head_, *fdp_, *rig_);
    qInfo("default head checks:\n%s", qPrintable(listed(checks_)));
  }

  void defaultHeadHasNoError() {
    REQUIRE_DEFAULT_RIG(head_);
    QVERIFY2(!anyError(checks_), qPrintable(listed(checks_)));
    // Its pair of outer eye corners is symmetric, which the broken file below relies on.
    for (const RigCheck& c : ofKind(checks_, "asymmetry")) QVERIFY(!concerns(c, "3.7"));
  }

  // 3.7 (outer corner of the left eye) moved up by 0.2 ES0: mirrored, it misses 3.12.
  void movedEyeCornerIsAsymmetric() {
    REQUIRE_DEFAULT_RIG(head_);
    rigging::FeaturePointFile fdp = *fdp_;
    const Eigen::Vector3d from = rig_->featurePoints.at("3.7");
    const double es0 = rig_->fapu.es0;
    const int v = nearestSkinVertex(from + Eigen::Vector3d(0, 0.2 * es0, 0),
                                    [](const Eigen::Vector3d&) { return true; });
    fdp.points["3.7"].at = {"skin", v, -1, Eigen::Vector3d::Zero(), std::nullopt};
    const auto checks = ofKind(checksOf(fdp), "asymmetry");
    const auto hit = std::find_if(checks.begin(), checks.end(),
                                  [](const RigCheck& c) { return concerns(c, "3.7"); });
    QVERIFY2(hit != checks.end(), qPrintable(listed(checks)));
    QCOMPARE(hit->points, (std::vector<std::string>{"3.7", "3.12"}));
    QCOMPARE(hit->severity, RigCheck::Severity::Warning);
    // The figure in the message is the offset in ES0, about the 0.2 it was moved by.
    const QString message = QString::fromStdString(hit->message);
    const QRegularExpressionMatch m = QRegularExpression("lands ([0-9.]+) ES0").match(message);
    QVERIFY2(m.hasMatch(), qPrintable(message));
    QVERIFY2(std::abs(m.captured(1).toDouble() - 0.2) < 0.05, qPrintable(message));
    // A looser tolerance lets it pass.
    rigging::RigCheckOptions loose;
    loose.asymmetryTolerance = 0.5;
    QVERIFY(ofKind(checksOf(fdp, loose), "asymmetry").empty());
  }

  // 2.3 (inner lower lip) put on the left eyeball. (2.2 cannot be: it defines MNS0, the nose
  // base 9.15 down to 2.2, and buildRig refuses a negative MNS0 before any check runs.)
  void lowerLipOnAnEyeIsOnTheWrongPart() {
    REQUIRE_DEFAULT_RIG(head_);
    rigging::FeaturePointFile fdp = *fdp_;
    fdp.points["2.3"].at = {"eye_l", 0, -1, Eigen::Vector3d::Zero(), std::nullopt};
    const auto checks = checksOf(fdp);
    const auto wrong = ofKind(checks, "wrong-part");
    QCOMPARE(static_cast<int>(wrong.size()), 1);
    QCOMPARE(wrong[0].severity, RigCheck::Severity::Error);
    QCOMPARE(wrong[0].points, std::vector<std::string>{"2.3"});
    QVERIFY2(wrong[0].message.find("eye_l") != std::string::npos &&
                 wrong[0].message.find("eye_left") != std::string::npos,
             wrong[0].message.c_str());
    // A pupil on the skin is wrong too.
    fdp = *fdp_;
    fdp.points["3.5"].at = fdp.points["3.7"].at;
    const auto pupil = ofKind(checksOf(fdp), "wrong-part");
    QVERIFY(pupil.size() == 1 && pupil[0].points == std::vector<std::string>{"3.5"});
  }

  // Teeth points: 9.9 (lower teeth) on the jaw's teeth is right, 9.10 (upper teeth) there is not.
  void teethPointsBelongOnTheirTeeth() {
    REQUIRE_DEFAULT_RIG(head_);
    std::string jaw;
    for (const auto& [name, role] : rig_->roles)
      if (role == "jaw") jaw = name;
    QVERIFY2(!jaw.empty(), "the default head's lower teeth follow the jaw");
    rigging::FeaturePointFile fdp = *fdp_;
    fdp.points["9.9"].at = {jaw, 0, -1, Eigen::Vector3d::Zero(), std::nullopt};
    fdp.points["9.10"].at = {jaw, 1, -1, Eigen::Vector3d::Zero(), std::nullopt};
    const auto wrong = ofKind(checksOf(fdp), "wrong-part");
    QCOMPARE(static_cast<int>(wrong.size()), 1);
    QCOMPARE(wrong[0].points, std::vector<std::string>{"9.10"});
    QVERIFY2(wrong[0].message.find("upper teeth") != std::string::npos &&
                 wrong[0].message.find("role jaw") != std::string::npos,
             wrong[0].message.c_str());
  }

  // 2.3 bound to 2.2's vertex: the lips share it and cannot part.
  void lipsSharingAVertexAreJoined() {
    REQUIRE_DEFAULT_RIG(head_);
    rigging::FeaturePointFile fdp = *fdp_;
    fdp.points["2.3"].at = fdp.points["2.2"].at;
    const auto joined = ofKind(checksOf(fdp), "lips-joined");
    const auto hit = std::find_if(joined.begin(), joined.end(),
                                  [](const RigCheck& c) { return concerns(c, "2.3"); });
    QVERIFY2(hit != joined.end(), qPrintable(listed(joined)));
    QCOMPARE(hit->severity, RigCheck::Severity::Error);
    QCOMPARE(hit->fap, 3);
    QVERIFY2(hit->message.find("share vertex") != std::string::npos, hit->message.c_str());
  }

  // The chin 2.1 with a huge radius (50 ES0): its weight is ~1 on both lips, so the jaw drags the
  // upper lip along.
  void upperLipFollowingTheJawIsJoined() {
    REQUIRE_DEFAULT_RIG(head_);
    rigging::FeaturePointFile fdp = *fdp_;
    fdp.points["2.1"].radius = 50.0 * rig_->fapu.es0;
    const auto joined = ofKind(checksOf(fdp), "lips-joined");
    QVERIFY2(std::any_of(joined.begin(), joined.end(),
                         [](const RigCheck& c) {
                           return c.points == std::vector<std::string>{"2.2", "2.3"} &&
                                  c.message.find("share") == std::string::npos;
                         }),
             qPrintable(listed(joined)));
  }

  // FAPU: ES0 and each other X0 near zero (the rig's own, as closed eyes would give IRISD0 ~ 0;
  // computeFapu refuses exact zeros, so the files cannot get there).
  void nearZeroFapuIsAnError() {
    REQUIRE_DEFAULT_RIG(head_);
    rigging::BuiltRig rig = *rig_;
    rig.fapu.irisd0 = 0.01 * rig.fapu.es0;
    auto zero = ofKind(rigging::checkRig(*head_, *fdp_, rig), "zero-fapu");
    QCOMPARE(static_cast<int>(zero.size()), 1);
    QCOMPARE(zero[0].severity, RigCheck::Severity::Error);
    QVERIFY2(zero[0].message.rfind("IRISD0", 0) == 0 && concerns(zero[0], "3.1"),
             zero[0].message.c_str());
    rig = *rig_;
    rig.fapu.es0 = 1e-5;
    zero = ofKind(rigging::checkRig(*head_, *fdp_, rig), "zero-fapu");
    QVERIFY2(!zero.empty() && zero[0].message.rfind("ES0", 0) == 0, qPrintable(listed(zero)));
  }

  // 8.1 (outer upper lip, FAP 51) on a sub-mesh with no deforming role: its pose is empty.
  void pointOnARigidPartMovesNothing() {
    REQUIRE_DEFAULT_RIG(head_);
    std::string rigid;
    for (const auto& [name, role] : rig_->roles)
      if (role == "rigid") rigid = name;
    QVERIFY2(!rigid.empty(), "the default head has a rigid sub-mesh (the upper teeth)");
    rigging::FeaturePointFile fdp = *fdp_;
    fdp.points["8.1"].at = {rigid, 0, -1, Eigen::Vector3d::Zero(), std::nullopt};
    const auto checks = checksOf(fdp);
    const auto nothing = ofKind(checks, "pose-moves-nothing");
    QCOMPARE(static_cast<int>(nothing.size()), 1);
    QCOMPARE(nothing[0].fap, 51);
    QCOMPARE(nothing[0].points, std::vector<std::string>{"8.1"});
    QVERIFY(!ofKind(checks, "wrong-part").empty());
  }

  // The checks of the feature points' layout do not depend on the head's frame: the broken
  // file of movedEyeCornerIsAsymmetric, its mesh and rig turned to Z-up and scaled by 100
  // (as a mm head would be), gives the same asymmetry, part and FAPU checks.
  void checksIgnoreTheFrame() {
    REQUIRE_DEFAULT_RIG(head_);
    rigging::FeaturePointFile fdp = *fdp_;
    const Eigen::Vector3d from = rig_->featurePoints.at("3.7");
    const int v = nearestSkinVertex(from + Eigen::Vector3d(0, 0.2 * rig_->fapu.es0, 0),
                                    [](const Eigen::Vector3d&) { return true; });
    fdp.points["3.7"].at = {"skin", v, -1, Eigen::Vector3d::Zero(), std::nullopt};
    const rigging::BuiltRig upright = rigging::buildRig(*head_, fdp);
    const auto before = rigging::checkRig(*head_, fdp, upright);

    const double scale = 100;
    const Eigen::Matrix3d toZUp =
        scale * Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitX()).toRotationMatrix();
    HeadMesh turned = *head_;
    turned.positions = toZUp.cast<float>() * head_->positions;
    rigging::BuiltRig rig = upright;
    for (auto& [id, p] : rig.featurePoints) p = toZUp * p;
    for (double* x0 :
         {&rig.fapu.irisd0, &rig.fapu.es0, &rig.fapu.ens0, &rig.fapu.mns0, &rig.fapu.mw0})
      *x0 *= scale;
    const auto after = rigging::checkRig(turned, fdp, rig);
    auto layout = [](const std::vector<RigCheck>& checks) {
      std::vector<std::pair<std::string, std::vector<std::string>>> out;
      for (const RigCheck& c : checks)
        if (c.kind == "asymmetry" || c.kind == "wrong-part" || c.kind == "zero-fapu")
          out.emplace_back(c.kind, c.points);
      return out;
    };
    QVERIFY(!layout(before).empty());
    QCOMPARE(layout(after), layout(before));
  }

  // lacrima-rig --check: one line per check, exit 0 without Error, 1 with one.
  void commandLineCheck() {
    REQUIRE_DEFAULT_RIG(head_);
    QProcess good;
    good.start(kRigTool, {"--default", "--check"});
    QVERIFY(good.waitForFinished(120000));
    const QString goodOut = QString::fromUtf8(good.readAllStandardOutput());
    QVERIFY2(good.exitCode() == 0, qPrintable(goodOut + good.readAllStandardError()));
    QCOMPARE(goodOut.count('\n'), static_cast<qsizetype>(checks_.size()) + 1);  // + summary

    rigging::FeaturePointFile fdp = *fdp_;
    fdp.points["2.3"].at = {"eye_l", 0, -1, Eigen::Vector3d::Zero(), std::nullopt};
    const QString broken = QDir(tmp_.path()).filePath("broken.fdp.json");
    saveAtomically(broken.toStdString(), rigging::featurePointFileJson(fdp));
    QProcess bad;
    bad.start(kRigTool, {"--default", "--fdp", broken, "--check"});
    QVERIFY(bad.waitForFinished(120000));
    const QString badOut = QString::fromUtf8(bad.readAllStandardOutput());
    QVERIFY2(bad.exitCode() == 1, qPrintable(badOut + bad.readAllStandardError()));
    QVERIFY2(badOut.contains("error: wrong-part (2.3): feature point 2.3 belongs on the skin"),
             qPrintable(badOut));
  }
};

QTEST_GUILESS_MAIN(RigChecksTest)
#include "RigChecksTest.moc"
