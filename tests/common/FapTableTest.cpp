#include <lacrima/common/FapTable.h>

#include <Eigen/Geometry>
#include <QtTest>
#include <algorithm>
#include <set>
#include <stdexcept>
#include <string>

using namespace lacrima;

namespace {

// Directions as the standard words them, in the face frame (+x = the face's own left).
Eigen::Vector3f direction(const QString& word) {
  if (word == "up") return {0, 1, 0};
  if (word == "down") return {0, -1, 0};
  if (word == "left") return {1, 0, 0};
  if (word == "right") return {-1, 0, 0};
  if (word == "forward") return {0, 0, 1};
  if (word == "axis+x") return {1, 0, 0};
  if (word == "axis+y") return {0, 1, 0};
  if (word == "axis+z") return {0, 0, 1};
  return Eigen::Vector3f::Zero();
}

bool contains(std::initializer_list<int> list, int fap) {
  return std::find(list.begin(), list.end(), fap) != list.end();
}

bool isSpatial(const FapInfo& info) {
  return info.motion == FapMotion::Translation || info.motion == FapMotion::Rotation;
}

// The counterpart's name by the standard's spelling of sides: "_l_" / "_r_" and the
// "_lm" / "_rm" lip points (lower_t_lip_lm, raise_b_lip_lm_o, ...).
std::string swapSide(std::string name) {
  for (auto [from, to] : {std::pair{"_l_", "_r_"}, std::pair{"_r_", "_l_"}, std::pair{"_lm", "_rm"},
                          std::pair{"_rm", "_lm"}}) {
    if (auto at = name.find(from); at != std::string::npos) {
      name.replace(at, std::string(from).size(), to);
      return name;
    }
  }
  return name;
}

// How the mirror x -> -x carries a channel's positive motion. A translation is a plain
// vector; a rotation axis is a pseudo-vector, so it picks up the reflection's determinant -1.
Eigen::Vector3f mirrored(const FapInfo& info) {
  const Eigen::Vector3f m(-info.positiveMotion.x(), info.positiveMotion.y(),
                          info.positiveMotion.z());
  return info.motion == FapMotion::Rotation ? Eigen::Vector3f(-m) : m;
}

Eigen::Vector3f rotate(const FapInfo& info, float radians, const Eigen::Vector3f& v) {
  return Eigen::AngleAxisf(radians, info.positiveMotion) * v;
}

}  // namespace

class FapTableTest : public QObject {
  Q_OBJECT

 private slots:
  void spotChecks_data() {
    QTest::addColumn<int>("fap");
    QTest::addColumn<QString>("name");
    QTest::addColumn<int>("unit");
    QTest::addColumn<bool>("bidirectional");
    QTest::addColumn<int>("motion");
    QTest::addColumn<QString>("positive");
    QTest::addColumn<int>("group");
    QTest::addColumn<QString>("featurePoint");

    using U = FapUnit;
    using M = FapMotion;
    auto row = [](int fap, const char* name, U unit, bool bi, M motion, const char* positive,
                  int group, const char* fp) {
      QTest::addRow("%d %s", fap, name) << fap << QString(name) << int(unit) << bi << int(motion)
                                        << QString(positive) << group << QString(fp);
    };
    row(1, "viseme", U::None, false, M::HighLevel, "", 1, "");
    row(2, "expression", U::None, false, M::HighLevel, "", 1, "");
    row(3, "open_jaw", U::MNS, false, M::Translation, "down", 2, "2.1");
    row(6, "stretch_l_cornerlip", U::MW, true, M::Translation, "left", 2, "2.4");
    row(15, "shift_jaw", U::MW, true, M::Translation, "right", 2, "2.1");
    row(18, "depress_chin", U::MNS, true, M::Translation, "up", 2, "2.10");
    row(19, "close_t_l_eyelid", U::IRISD, true, M::Translation, "down", 3, "3.1");
    row(22, "close_b_r_eyelid", U::IRISD, true, M::Translation, "up", 3, "3.4");
    row(23, "yaw_l_eyeball", U::AU, true, M::Rotation, "axis+y", 3, "3.5");
    row(26, "pitch_r_eyeball", U::AU, true, M::Rotation, "axis+x", 3, "3.6");
    row(28, "thrust_r_eyeball", U::ES, true, M::Translation, "forward", 3, "3.6");
    row(29, "dilate_l_pupil", U::IRISD, true, M::Dilation, "", 3, "3.5");
    row(31, "raise_l_i_eyebrow", U::ENS, true, M::Translation, "up", 4, "4.1");
    row(37, "squeeze_l_eyebrow", U::ES, true, M::Translation, "right", 4, "4.1");
    row(38, "squeeze_r_eyebrow", U::ES, true, M::Translation, "left", 4, "4.2");
    row(41, "lift_l_cheek", U::ENS, false, M::Translation, "up", 5, "5.3");
    row(45, "thrust_tongue_tip", U::MW, true, M::Translation, "forward", 6, "6.1");
    row(47, "tongue_roll", U::AU, false, M::Curl, "", 6, "6.3;6.4");
    row(48, "head_pitch", U::AU, true, M::Rotation, "axis+x", 7, "7.1");
    row(49, "head_yaw", U::AU, true, M::Rotation, "axis+y", 7, "7.1");
    row(50, "head_roll", U::AU, true, M::Rotation, "axis+z", 7, "7.1");
    row(53, "stretch_l_cornerlip_o", U::MW, true, M::Translation, "left", 8, "8.3");
    row(57, "raise_b_lip_lm_o", U::MNS, true, M::Translation, "up", 8, "8.7");
    row(61, "stretch_l_nose", U::ENS, true, M::Translation, "left", 9, "9.1");
    row(64, "bend_nose", U::ENS, true, M::Translation, "right", 9, "9.3");
    row(68, "pull_r_ear", U::ENS, true, M::Translation, "right", 10, "10.4");
    row(69, "tears_l_eye", U::Particles, false, M::TearCount, "", 11, "3.3");
    row(70, "tears_r_eye", U::Particles, false, M::TearCount, "", 11, "3.4");
  }

  void spotChecks() {
    QFETCH(int, fap);
    QFETCH(QString, name);
    QFETCH(int, unit);
    QFETCH(bool, bidirectional);
    QFETCH(int, motion);
    QFETCH(QString, positive);
    QFETCH(int, group);
    QFETCH(QString, featurePoint);

    const FapInfo& info = fapInfo(fap);
    QCOMPARE(info.number, fap);
    QCOMPARE(QString::fromUtf8(std::string(info.name).c_str(), qsizetype(info.name.size())), name);
    QCOMPARE(int(info.unit), unit);
    QCOMPARE(info.bidirectional, bidirectional);
    QCOMPARE(int(info.motion), motion);
    QVERIFY2(info.positiveMotion == direction(positive), qPrintable(positive));
    QCOMPARE(int(info.group), group);
    QCOMPARE(QString::fromUtf8(info.featurePoint.data(), qsizetype(info.featurePoint.size())),
             featurePoint);
  }

  void tearChannels() {
    for (int fap : {kTearLeftFap, kTearRightFap}) {
      const FapInfo& info = fapInfo(fap);
      QVERIFY(isTearChannel(fap));
      QCOMPARE(info.quantizerStep, 1);
      QCOMPARE(info.sliderMin, 0);
      QCOMPARE(info.sliderMax, 1000);
      QVERIFY(info.sliderMax <= kMaxTearParticles);
      QVERIFY(info.positiveMotion.isZero());
    }
    QCOMPARE(fapInfo(69).name, std::string_view("tears_l_eye"));
    QCOMPARE(fapInfo(70).name, std::string_view("tears_r_eye"));
  }

  void numbersInOrder() {
    const auto table = fapTable();
    QCOMPARE(int(table.size()), kChannelCount);
    for (int i = 0; i < kChannelCount; ++i) {
      QCOMPARE(table[i].number, fapNumber(i));
      QCOMPARE(&fapInfo(fapNumber(i)), &table[i]);
    }
  }

  void namesAreUniqueAndLookedUpExactly() {
    std::set<std::string_view> names;
    for (const FapInfo& info : fapTable()) {
      QVERIFY(!info.name.empty());
      QVERIFY2(names.insert(info.name).second, std::string(info.name).c_str());
      QCOMPARE(fapByName(info.name), std::optional<int>(info.number));
    }
    QCOMPARE(fapByName("Open_Jaw"), std::optional<int>());
    QCOMPARE(fapByName("open_jaw "), std::optional<int>());
    QCOMPARE(fapByName(""), std::optional<int>());
    QCOMPARE(fapByName("stretch_l_corner"), std::optional<int>());  // BIFS spelling
  }

  void descriptionsAreShortSentences() {
    for (const FapInfo& info : fapTable()) {
      const std::string_view d = info.description;
      QVERIFY2(!d.empty() && d.size() <= 100, std::string(info.name).c_str());
      QVERIFY2(d.back() == '.' && d.find('\n') == std::string_view::npos,
               std::string(info.name).c_str());
    }
  }

  void motionVectors() {
    for (const FapInfo& info : fapTable()) {
      if (isSpatial(info)) {
        QVERIFY2(qFuzzyCompare(info.positiveMotion.norm(), 1.0f), std::string(info.name).c_str());
        // Axis-aligned: exactly one non-zero component.
        QCOMPARE((info.positiveMotion.array() != 0.0f).count(), Eigen::Index(1));
      } else {
        QVERIFY2(info.positiveMotion.isZero(0.0f), std::string(info.name).c_str());
      }
      const bool rotation = contains({23, 24, 25, 26, 48, 49, 50}, info.number);
      QCOMPARE(info.motion == FapMotion::Rotation, rotation);
    }
    QCOMPARE(fapInfo(30).motion, FapMotion::Dilation);
    QCOMPARE(fapInfo(47).motion, FapMotion::Curl);
  }

  void groupsMatchStandardRanges() {
    const int firstOfGroup[] = {1, 3, 19, 31, 39, 43, 48, 51, 61, 65, 69, 71};
    for (int g = 0; g < 11; ++g)
      for (int fap = firstOfGroup[g]; fap < firstOfGroup[g + 1]; ++fap)
        QCOMPARE(int(fapInfo(fap).group), g + 1);
  }

  void unitsMatchStandardLists() {
    auto range = [](std::initializer_list<std::pair<int, int>> spans) {
      std::set<int> s;
      for (auto [a, b] : spans)
        for (int f = a; f <= b; ++f) s.insert(f);
      return s;
    };
    const std::pair<FapUnit, std::set<int>> lists[] = {
        {FapUnit::IRISD, range({{19, 22}, {29, 30}})},
        {FapUnit::ES, range({{27, 28}, {37, 40}})},
        {FapUnit::ENS, range({{31, 36}, {41, 42}, {61, 68}})},
        {FapUnit::MNS, range({{3, 5}, {8, 14}, {16, 18}, {44, 44}, {46, 46}, {51, 52}, {55, 60}})},
        {FapUnit::MW, range({{6, 7}, {15, 15}, {43, 43}, {45, 45}, {53, 54}})},
        {FapUnit::AU, range({{23, 26}, {47, 50}})},
        {FapUnit::None, range({{1, 2}})},
        {FapUnit::Particles, range({{69, 70}})},
    };
    int covered = 0;
    for (const auto& [unit, faps] : lists) {
      covered += int(faps.size());
      for (int fap : faps) QVERIFY2(fapInfo(fap).unit == unit, qPrintable(QString::number(fap)));
    }
    QCOMPARE(covered, kChannelCount);
  }

  void sliderRanges() {
    for (const FapInfo& info : fapTable()) {
      QVERIFY2(info.sliderMin < info.sliderMax, std::string(info.name).c_str());
      QVERIFY2(info.quantizerStep > 0, std::string(info.name).c_str());
      // Other editors write negative values on 41, 42 and 47 despite U, so we accept them.
      if (!info.bidirectional && !contains({41, 42, 47}, info.number))
        QVERIFY2(info.sliderMin >= 0, std::string(info.name).c_str());
      if (info.bidirectional)
        QVERIFY2(info.sliderMin < 0 && info.sliderMax > 0, std::string(info.name).c_str());
    }
    QCOMPARE(fapInfo(3).sliderMin, 0);
    QCOMPARE(fapInfo(3).sliderMax, 1080);
    QCOMPARE(fapInfo(23).quantizerStep, 128);
    QCOMPARE(fapInfo(48).quantizerStep, 170);
  }

  void mirrorPairsSides() {
    int pairs = 0;
    for (const FapInfo& info : fapTable()) {
      const int other = mirroredFap(info.number);
      QVERIFY(isValidFap(other));
      QCOMPARE(mirroredFap(other), info.number);
      const std::string swapped = swapSide(std::string(info.name));
      QCOMPARE(std::string(fapInfo(other).name), swapped);
      if (other != info.number) {
        ++pairs;
        // QCOMPARE would pick lacrima::toString(FapUnit) by ADL and not compile.
        QVERIFY(fapInfo(other).unit == info.unit);
        QVERIFY(fapInfo(other).group == info.group);
        QCOMPARE(fapInfo(other).motion, info.motion);
      }
    }
    QCOMPARE(pairs, 48);
    QCOMPARE(mirroredFap(3), 3);
    QCOMPARE(mirroredFap(69), 70);
  }

  void mirroredMotionsAreMirrorImages() {
    for (const FapInfo& info : fapTable()) {
      const FapInfo& other = fapInfo(mirroredFap(info.number));
      if (!isSpatial(info)) {
        QVERIFY2(!mirrorNegates(info.number), std::string(info.name).c_str());
        continue;
      }
      const float sign = mirrorNegates(info.number) ? -1.0f : 1.0f;
      QVERIFY2(other.positiveMotion == sign * mirrored(info), std::string(info.name).c_str());
      QCOMPARE(mirrorNegates(other.number), mirrorNegates(info.number));
    }
    std::set<int> negated;
    for (const FapInfo& info : fapTable())
      if (mirrorNegates(info.number)) negated.insert(info.number);
    QCOMPARE(negated, (std::set<int>{15, 23, 24, 43, 49, 50, 64}));
  }

  void rotationsTurnTheWayTheStandardSays() {
    const Eigen::Vector3f gaze(0, 0, 1), top(0, 1, 0);
    const float a = 0.1f;
    QVERIFY(rotate(fapInfo(23), a, gaze).x() > 0);  // yaw left eye: toward the face's left
    QVERIFY(rotate(fapInfo(24), a, gaze).x() > 0);
    QVERIFY(rotate(fapInfo(49), a, gaze).x() > 0);  // head yaw: face turns to its left
    QVERIFY(rotate(fapInfo(25), a, gaze).y() < 0);  // pitch: looks down
    QVERIFY(rotate(fapInfo(26), a, gaze).y() < 0);
    QVERIFY(rotate(fapInfo(48), a, gaze).y() < 0);  // head nods down
    QVERIFY(rotate(fapInfo(50), a, top).x() < 0);   // roll: top of head toward face's right
  }

  void invalidChannelsAreRejected() {
    for (int fap : {0, -1, 71}) {
      QVERIFY_THROWS_EXCEPTION(std::out_of_range, fapInfo(fap));
      QVERIFY_THROWS_EXCEPTION(std::out_of_range, mirroredFap(fap));
      QVERIFY_THROWS_EXCEPTION(std::out_of_range, mirrorNegates(fap));
    }
  }

  void unitAndGroupNames() {
    QCOMPARE(toString(FapUnit::IRISD), std::string_view("IRISD"));
    QCOMPARE(toString(FapUnit::ES), std::string_view("ES"));
    QCOMPARE(toString(FapUnit::ENS), std::string_view("ENS"));
    QCOMPARE(toString(FapUnit::MNS), std::string_view("MNS"));
    QCOMPARE(toString(FapUnit::MW), std::string_view("MW"));
    QCOMPARE(toString(FapUnit::AU), std::string_view("AU"));
    QCOMPARE(toString(FapUnit::Particles), std::string_view("particles"));
    QCOMPARE(toString(FapUnit::None), std::string_view("none"));
    QCOMPARE(toString(FapGroup::JawChinInnerLips), std::string_view("jaw, chin and inner lips"));
    QCOMPARE(toString(FapGroup::Tears), std::string_view("tears"));
    std::set<std::string_view> groupNames;
    for (int g = 1; g <= 11; ++g) {
      const std::string_view n = toString(FapGroup(g));
      QVERIFY(!n.empty() && n != "unknown");
      groupNames.insert(n);
    }
    QCOMPARE(int(groupNames.size()), 11);
  }
};

QTEST_GUILESS_MAIN(FapTableTest)
#include "FapTableTest.moc"
