// The feature-point table (FdpTable.h): complete, ordered, consistent with itself (groups, sides,
// mirrors), with the FAP table and with the default head's feature-point file, and (when
// ../shared is there) with the reference list of ids and sides.
#include "../support/MissingData.h"

#include <lacrima/common/FapTable.h>
#include <lacrima/common/FdpTable.h>

#include <QtTest>

#include <set>
#include <string>

using namespace lacrima;

class FdpTableTest : public QObject {
  Q_OBJECT

 private slots:
  void every84PointsOnceInOrder() {
    const auto table = fdpTable();
    QCOMPARE(int(table.size()), 84);
    std::set<std::string_view> ids;
    std::pair<int, int> previous{0, 0};
    for (const FdpInfo& p : table) {
      QVERIFY2(ids.insert(p.id).second, p.id.data());
      const std::string id(p.id);
      const auto dot = id.find('.');
      QVERIFY(dot != std::string::npos);
      const std::pair<int, int> key{std::stoi(id.substr(0, dot)), std::stoi(id.substr(dot + 1))};
      QCOMPARE(key.first, p.group);
      QVERIFY(key > previous);
      previous = key;
      QVERIFY(p.description.size() > 8);
      QVERIFY(!fdpGroupName(p.group).empty());
      QCOMPARE(fdpDescription(p.id), p.description);
    }
    QVERIFY(!fdpInfo("2.15"));
    QVERIFY(!fdpInfo(""));
    QVERIFY(fdpDescription("12.1").empty());
  }

  void mirrorsPairLeftWithRight() {
    for (const FdpInfo& p : fdpTable()) {
      const auto mirror = mirroredFdp(p.id);
      QVERIFY(mirror);
      QCOMPARE(*mirroredFdp(*mirror), p.id);
      const FdpInfo other = *fdpInfo(*mirror);
      QCOMPARE(other.group, p.group);
      if (p.side == FdpSide::Centre) QCOMPARE(*mirror, p.id);
      if (p.side == FdpSide::Left) QVERIFY(other.side == FdpSide::Right);
      if (p.side == FdpSide::Right) QVERIFY(other.side == FdpSide::Left);
    }
    QCOMPARE(*mirroredFdp("3.7"), std::string_view("3.12"));
    QCOMPARE(*mirroredFdp("3.11"), std::string_view("3.8"));
    QVERIFY(!mirroredFdp("1.1"));
  }

  void everyPointAFapMovesIsDescribed() {
    for (const FapInfo& fap : fapTable()) {
      QString points = QString::fromUtf8(fap.featurePoint.data(), int(fap.featurePoint.size()));
      for (const QString& id : points.split(';', Qt::SkipEmptyParts))
        QVERIFY2(fdpInfo(id.toStdString()), qPrintable(id));
    }
  }

  void everyPointOfTheDefaultHeadIsDescribed() {
    QFile file(LACRIMA_SOURCE_DIR "/media/default-head.fdp.json");
    QVERIFY(file.open(QIODevice::ReadOnly));
    const QJsonObject points =
        QJsonDocument::fromJson(file.readAll()).object()["points"].toObject();
    QVERIFY(points.size() > 40);
    for (const QString& id : points.keys())
      QVERIFY2(!fdpDescription(id.toStdString()).empty(), qPrintable(id));
  }

  void idsAndSidesMatchTheReferenceList() {
    const QString csv = testsupport::sharedPath(QStringLiteral("mpeg4/fdps.csv"));
    LACRIMA_REQUIRE_SHARED(csv);
    QFile file(csv);
    QVERIFY2(file.open(QIODevice::ReadOnly), qPrintable(csv));
    file.readLine();  // header
    int rows = 0;
    while (!file.atEnd()) {
      const QString line = QString::fromUtf8(file.readLine()).trimmed();
      if (line.isEmpty()) continue;
      // id, group, region, description, side, ...; quoted fields may hold commas.
      QStringList fields{QString()};
      bool quoted = false;
      for (const QChar c : line) {
        if (c == '"')
          quoted = !quoted;
        else if (c == ',' && !quoted)
          fields.append(QString());
        else
          fields.last() += c;
      }
      QVERIFY(fields.size() > 4);
      const QString id = fields[0];
      const auto info = fdpInfo(id.toStdString());
      QVERIFY2(info, qPrintable(id));
      ++rows;
      const QString side = fields[4];
      QVERIFY2(side == "L" || side == "R" || side == "C", qPrintable(line));
      if (side == "L") QVERIFY2(info->side == FdpSide::Left, qPrintable(id));
      if (side == "R") QVERIFY2(info->side == FdpSide::Right, qPrintable(id));
      if (side == "C") QVERIFY2(info->side == FdpSide::Centre, qPrintable(id));
    }
    QCOMPARE(rows, 84);
  }
};

QTEST_GUILESS_MAIN(FdpTableTest)
#include "FdpTableTest.moc"
