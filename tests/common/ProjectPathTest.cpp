// isProjectPath: the one rule by which the editor, the player and lacrima-fap tell projects
// (.lacrima, and .json as before it) from FAP files.
#include <lacrima/common/ProjectPath.h>

#include <QtTest>

using namespace lacrima;

class ProjectPathTest : public QObject {
  Q_OBJECT
 private slots:
  void projects_data() {
    QTest::addColumn<QString>("path");
    for (const char* path :
         {"crying.lacrima", "/usr/share/lacrima/demo/crying.lacrima", "CRYING.LACRIMA", "old.json",
          "Old.JSON", "dir.fap/p.lacrima", ".lacrima"})
      QTest::newRow(path) << QString::fromLatin1(path);
  }
  void projects() {
    QFETCH(QString, path);
    QVERIFY(isProjectPath(path.toStdString()));
  }

  void fapFiles_data() {
    QTest::addColumn<QString>("path");
    for (const char* path : {"crying.fap", "crying", "crying.lacrima.fap", "crying.lacrimas",
                             "lacrima", "crying.json.bak", "", "x.jso"})
      QTest::newRow(path) << QString::fromLatin1(path);
  }
  void fapFiles() {
    QFETCH(QString, path);
    QVERIFY(!isProjectPath(path.toStdString()));
  }

  void newProjectsGetTheirOwnExtension() { QCOMPARE(kProjectExtension, ".lacrima"); }
};

QTEST_GUILESS_MAIN(ProjectPathTest)
#include "ProjectPathTest.moc"
