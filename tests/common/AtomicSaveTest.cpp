// saveAtomically, the one way Lacrima writes a user's file: on a disk that fills mid-write, the
// old file stays as it was and the error says what happened. Qt 6.4's QSaveFile alone reports
// such a short write as success and renames the truncated file into place.
#include "../support/FileFaults.h"

#include <lacrima/common/AtomicSave.h>
#include <lacrima/common/Diagnostics.h>

#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <QtTest>

#include <string>

using namespace lacrima;

namespace {

QByteArray contents(const QString& path) {
  QFile file(path);
  return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

}  // namespace

class AtomicSaveTest : public QObject {
  Q_OBJECT

  QTemporaryDir dir_;

 private slots:
  void replacesTheFile() {
    const QString path = dir_.filePath("replace.txt");
    saveAtomically(path.toStdString(), "first");
    saveAtomically(path.toStdString(), "second, longer");
    QCOMPARE(contents(path), QByteArray("second, longer"));
  }

  void aFullDiskKeepsTheOldFile() {
    const QString path = dir_.filePath("full.txt");
    const std::string old(300, 'o');
    saveAtomically(path.toStdString(), old);
    const std::string large(8000, 'n');
    try {
      const test::FileSizeLimit full(4096);
      QVERIFY(full.active());
      saveAtomically(path.toStdString(), large);
      QFAIL("a save that did not fit reported success");
    } catch (const FileError& e) {
      const QString message = QString::fromStdString(e.what());
      QVERIFY2(message.startsWith(path) && message.contains("4096 of 8000 bytes"),
               qPrintable(message));
    }
    QCOMPARE(contents(path), QByteArray::fromStdString(old));
    QCOMPARE(QDir(dir_.path()).entryList({"full.txt*"}, QDir::Files | QDir::Hidden),
             QStringList{"full.txt"});
  }

  void aFolderInTheWayIsLeftAlone() {
    const QString path = dir_.filePath("folder");
    QVERIFY(QDir().mkpath(path));
    QVERIFY_THROWS_EXCEPTION(FileError, saveAtomically(path.toStdString(), "text"));
    QVERIFY(QFileInfo(path).isDir());
  }
};

QTEST_GUILESS_MAIN(AtomicSaveTest)
#include "AtomicSaveTest.moc"
