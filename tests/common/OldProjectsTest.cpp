// Projects of schema version 1 read and export exactly as they did before keys had shapes.
// The .fap beside each fixture in tests/fixtures/projects-v1 was written by the Lacrima that
// wrote version 1 (lacrima-fap convert); media/demo/crying.fap is the demo project's export.
#include <lacrima/common/FapReader.h>
#include <lacrima/common/FapWriter.h>
#include <lacrima/common/ProjectDocument.h>

#include <QDir>
#include <QFile>
#include <QtTest>

using namespace lacrima;

namespace {

const QString kFixtures = QStringLiteral(LACRIMA_SOURCE_DIR "/tests/fixtures/projects-v1");
const QString kDemo = QStringLiteral(LACRIMA_SOURCE_DIR "/media/demo/crying");

QByteArray readBytes(const QString& path) {
  QFile file(path);
  if (!file.open(QIODevice::ReadOnly)) return {};
  return file.readAll();
}

QByteArray exported(const ProjectDocument& document) {
  return QByteArray::fromStdString(FapWriter::toText(document.bake()));
}

}  // namespace

class OldProjectsTest : public QObject {
  Q_OBJECT

 private slots:
  void exportsAreByteIdentical_data() {
    QTest::addColumn<QString>("project");
    QTest::addColumn<QString>("expectedFap");
    QTest::newRow("demo") << kDemo + ".json" << kDemo + ".fap";
    const QStringList fixtures = QDir(kFixtures).entryList({"*.json"}, QDir::Files, QDir::Name);
    QVERIFY(fixtures.size() >= 3);
    for (const QString& name : fixtures) {
      const QString base = kFixtures + '/' + QFileInfo(name).completeBaseName();
      QTest::newRow(qPrintable(name)) << base + ".json" << base + ".fap";
    }
  }

  void exportsAreByteIdentical() {
    QFETCH(QString, project);
    QFETCH(QString, expectedFap);
    const QByteArray expected = readBytes(expectedFap);
    QVERIFY2(!expected.isEmpty(), qPrintable(expectedFap));
    const ProjectDocument document = ProjectDocument::load(project.toStdString());
    QVERIFY(document.moods.empty());  // they predate mood curves, which stay optional
    QVERIFY(exported(document) == expected);
  }

  // Saved again (as version 2), the document reads back equal, names no shape it did not have
  // and exports the same bytes.
  void resavedAsVersion2TheyStayTheSame_data() { exportsAreByteIdentical_data(); }
  void resavedAsVersion2TheyStayTheSame() {
    QFETCH(QString, project);
    QFETCH(QString, expectedFap);
    const ProjectDocument document = ProjectDocument::load(project.toStdString());
    const std::string json = document.toJson();
    QVERIFY(json.find("\"version\": 2") != std::string::npos);
    QVERIFY(json.find("\"shapes\"") == std::string::npos);
    QVERIFY(json.find("\"moods\"") == std::string::npos);
    const ProjectDocument again = ProjectDocument::fromJson(json, "resaved.json");
    QVERIFY(again == document);
    QVERIFY(exported(again) == readBytes(expectedFap));
  }

  // The demo as a .fap, taken in as a key per frame and exported again, is the same file.
  void fapImportExportsTheSameFile() {
    const QByteArray original = readBytes(kDemo + ".fap");
    const FapReadResult read = FapReader::readFile((kDemo + ".fap").toStdString());
    const ProjectDocument document = ProjectDocument::fromAnimation(read.animation);
    QVERIFY(exported(document) == original);
    const ProjectDocument again = ProjectDocument::fromJson(document.toJson(), "demo.json");
    QVERIFY(exported(again) == original);
  }
};

QTEST_GUILESS_MAIN(OldProjectsTest)
#include "OldProjectsTest.moc"
