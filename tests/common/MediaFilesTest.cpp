// findMediaFile: an installed program reads the share/lacrima beside its own bin/, under any
// prefix, and only a program in this build's bin/ may fall back on the source tree's media/.
#include <lacrima/common/Diagnostics.h>
#include <lacrima/common/MediaFiles.h>

#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <QtTest>

#include <filesystem>

using namespace lacrima;

namespace {

const std::string kSourceMedia = LACRIMA_SOURCE_DIR "/media";

std::string clean(const QString& path) { return QDir::cleanPath(path).toStdString(); }

}  // namespace

class MediaFilesTest : public QObject {
  Q_OBJECT
 private slots:
  void anInstalledProgramLooksOnlyBesideItsOwnPrefix_data() {
    QTest::addColumn<QString>("bin");
    QTest::addColumn<QString>("share");
    QTest::newRow("/usr") << "/usr/bin"
                          << "/usr/share/lacrima";
    QTest::newRow("/usr/local") << "/usr/local/bin"
                                << "/usr/local/share/lacrima";
    QTest::newRow("~/opt/lacrima") << "/home/someone/opt/lacrima/bin"
                                   << "/home/someone/opt/lacrima/share/lacrima";
  }
  void anInstalledProgramLooksOnlyBesideItsOwnPrefix() {
    QFETCH(QString, bin);
    QFETCH(QString, share);
    const std::vector<std::string> places =
        mediaCandidatesFor(bin.toStdString(), "demo/crying.fap");
    QCOMPARE(places, std::vector<std::string>{clean(share + "/demo/crying.fap")});
  }

  void aProgramOfThisBuildFallsBackOnTheSources() {
    const std::vector<std::string> places =
        mediaCandidatesFor(LACRIMA_BIN_DIR, "default-head.fdp.json");
    QCOMPARE(places.size(), std::size_t(2));
    QCOMPARE(places[0], clean(LACRIMA_BIN_DIR "/../share/lacrima/default-head.fdp.json"));
    QCOMPARE(places[1], clean(QString::fromStdString(kSourceMedia + "/default-head.fdp.json")));
  }

  // Equivalence, not spelling: a build reached through a symbolic link is still this build.
  void thisBuildThroughALinkIsStillThisBuild() {
    QTemporaryDir tmp;
    const QString link = tmp.filePath("bin-link");
    QVERIFY(QFile::link(QStringLiteral(LACRIMA_BIN_DIR), link));
    QCOMPARE(mediaCandidatesFor(link.toStdString(), "x").size(), std::size_t(2));
  }

  void theRunningTestIsInThisBuildsBin() {
    std::error_code error;
    QVERIFY(std::filesystem::equivalent(executableDir(), LACRIMA_BIN_DIR, error));
    QCOMPARE(findMediaFile("demo/crying.fap"), kSourceMedia + "/demo/crying.fap");
  }

  void aMissingFileNamesEveryPlaceLooked() {
    try {
      findMediaFile("no/such/file.json");
      QFAIL("no exception");
    } catch (const FileError& e) {
      const QString message = QString::fromUtf8(e.what());
      QVERIFY2(message.contains("no/such/file.json"), e.what());
      QVERIFY2(message.contains(QString::fromStdString(kSourceMedia + "/no/such/file.json")),
               e.what());
      QVERIFY2(message.contains("share/lacrima/no/such/file.json"), e.what());
    }
  }

  void noExecutableFolderMeansNowhereToLook() {
    QVERIFY(mediaCandidatesFor("", "demo/crying.fap").empty());
  }
};

QTEST_GUILESS_MAIN(MediaFilesTest)
#include "MediaFilesTest.moc"
