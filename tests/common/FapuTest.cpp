#include <lacrima/common/Fapu.h>

#include <QtTest>
#include <limits>
#include <stdexcept>
#include <string>

using namespace lacrima;

namespace {

// A face with whole-number distances (exact in binary): left eye 12 high, right eye 14
// high (IRISD0 13), pupils 64 apart at mean y 0, nose bottom 48 below the pupils, inner
// upper lip 20 below the nose, lip corners 50 apart. The other coordinates are deliberately
// uneven so that only the documented components can give these values.
FapuReferencePoints syntheticFace() {
  FapuReferencePoints p;
  p.upperLidLeft = {31, 6, 9};
  p.lowerLidLeft = {33, -6, 10};
  p.upperLidRight = {-30, 8, 9};
  p.lowerLidRight = {-34, -6, 8};
  p.pupilLeft = {32, 1, 12};
  p.pupilRight = {-32, -1, 11};
  p.noseBottom = {0.5, -48, 20};
  p.innerUpperLip = {-0.25, -68, 15};
  p.lipCornerLeft = {25, -70, 5};
  p.lipCornerRight = {-25, -71, 6};
  return p;
}

FapuReferencePoints transformed(const FapuReferencePoints& p, double scale,
                                const Eigen::Vector3d& offset) {
  auto t = [&](const Eigen::Vector3d& v) -> Eigen::Vector3d { return scale * v + offset; };
  return {t(p.upperLidLeft),  t(p.upperLidRight), t(p.lowerLidLeft), t(p.lowerLidRight),
          t(p.pupilLeft),     t(p.pupilRight),    t(p.noseBottom),   t(p.innerUpperLip),
          t(p.lipCornerLeft), t(p.lipCornerRight)};
}

// The message of the std::invalid_argument computeFapu throws, or "" if it does not throw.
std::string errorOf(const FapuReferencePoints& p) {
  try {
    computeFapu(p);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return {};
}

bool mentions(const std::string& message, std::initializer_list<const char*> parts) {
  for (const char* part : parts)
    if (message.find(part) == std::string::npos) return false;
  return true;
}

}  // namespace

class FapuTest : public QObject {
  Q_OBJECT

 private slots:
  void syntheticFaceGivesExactUnits() {
    const FapuSet f = computeFapu(syntheticFace());
    QVERIFY(f.irisd0 == 13.0);  // mean of the two eyes
    QVERIFY(f.es0 == 64.0);
    QVERIFY(f.ens0 == 48.0);  // from the mean pupil height
    QVERIFY(f.mns0 == 20.0);
    QVERIFY(f.mw0 == 50.0);
  }

  void unitValueForEveryUnit() {
    const FapuSet f = computeFapu(syntheticFace());
    QVERIFY(f.unitValue(FapUnit::IRISD) == 13.0 / 1024);
    QVERIFY(f.unitValue(FapUnit::ES) == 64.0 / 1024);
    QVERIFY(f.unitValue(FapUnit::ENS) == 48.0 / 1024);
    QVERIFY(f.unitValue(FapUnit::MNS) == 20.0 / 1024);
    QVERIFY(f.unitValue(FapUnit::MW) == 50.0 / 1024);
    QVERIFY(f.unitValue(FapUnit::AU) == 1e-5);
    QVERIFY(f.unitValue(FapUnit::Particles) == 1.0);
    QVERIFY(f.unitValue(FapUnit::None) == 0.0);
  }

  void translatedAndScaledFaceScalesUnits() {
    const double s = 2.5;
    const FapuSet a = computeFapu(syntheticFace());
    const FapuSet b = computeFapu(transformed(syntheticFace(), s, {3, -7, 11}));
    QCOMPARE(b.irisd0, s * a.irisd0);
    QCOMPARE(b.es0, s * a.es0);
    QCOMPARE(b.ens0, s * a.ens0);
    QCOMPARE(b.mns0, s * a.mns0);
    QCOMPARE(b.mw0, s * a.mw0);
    QCOMPARE(b.unitValue(FapUnit::MW), s * a.unitValue(FapUnit::MW));
    QCOMPARE(b.unitValue(FapUnit::AU), a.unitValue(FapUnit::AU));  // angles do not scale
  }

  void swappedLeftRightIsRejected() {
    FapuReferencePoints p = syntheticFace();
    std::swap(p.pupilLeft, p.pupilRight);
    std::swap(p.lipCornerLeft, p.lipCornerRight);
    const std::string message = errorOf(p);
    QVERIFY2(mentions(message, {"ES0 = -64 is not positive", "3.5", "3.6", "+x"}), message.c_str());
    QVERIFY2(mentions(message, {"MW0 = -50 is not positive", "8.3", "8.4"}), message.c_str());
    QVERIFY2(!mentions(message, {"ENS0"}) && !mentions(message, {"MNS0"}), message.c_str());
  }

  void closedEyeIsRejectedEvenIfTheMeanIsPositive() {
    FapuReferencePoints p = syntheticFace();
    p.lowerLidRight.y() = p.upperLidRight.y();  // right eye zero height, left eye still 12
    const std::string message = errorOf(p);
    QVERIFY2(mentions(message, {"IRISD0", "right eye", "3.2", "3.4"}), message.c_str());
    QVERIFY2(!mentions(message, {"3.1"}), message.c_str());
  }

  void upsideDownFaceIsRejected() {
    FapuReferencePoints p = syntheticFace();
    for (Eigen::Vector3d* v :
         {&p.upperLidLeft, &p.upperLidRight, &p.lowerLidLeft, &p.lowerLidRight, &p.pupilLeft,
          &p.pupilRight, &p.noseBottom, &p.innerUpperLip, &p.lipCornerLeft, &p.lipCornerRight})
      v->y() = -v->y();
    const std::string message = errorOf(p);
    QVERIFY2(mentions(message, {"IRISD0 left eye", "3.1", "3.3", "ENS0", "9.15", "MNS0", "2.2"}),
             message.c_str());
    QVERIFY2(!mentions(message, {"ES0 ="}), message.c_str());  // x was left alone
  }

  void coincidentAndNonFinitePointsAreRejected() {
    const std::string allZero = errorOf(FapuReferencePoints{
        Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(),
        Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(),
        Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(),
        Eigen::Vector3d::Zero()});
    QVERIFY2(mentions(allZero, {"IRISD0", "ES0 = 0 is not positive", "ENS0", "MNS0", "MW0"}),
             allZero.c_str());

    FapuReferencePoints p = syntheticFace();
    p.noseBottom.y() = std::numeric_limits<double>::quiet_NaN();
    const std::string nan = errorOf(p);
    QVERIFY2(mentions(nan, {"ENS0", "MNS0", "not finite", "9.15"}), nan.c_str());
  }
};

QTEST_GUILESS_MAIN(FapuTest)
#include "FapuTest.moc"
