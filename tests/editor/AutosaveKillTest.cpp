// The editor killed (SIGKILL) during an autosave: the next start offers the last
// complete recovery file, never a truncated one.
//
// The killed editor is this test's own executable started again as a child that autosaves a
// large project over and over (LACRIMA_AUTOSAVE_CHILD names its recovery folder), announcing
// "start N" before each save and "saved N" after it. The test kills it at moments spread over a
// whole save (building the text, writing it, flushing it to disk, renaming it), then starts a
// window on the same folder as the next editor would, and checks what the banner offers and
// what Restore brings back.
#include <lacrima/common/ProjectDocument.h>
#include <lacrima/editing/EditorModel.h>
#include <lacrima/editing/RecoveryStore.h>
#include <lacrima/editor/MainWindow.h>
#include <lacrima/editor/RecoveryBanner.h>

#include <QApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QLabel>
#include <QProcess>
#include <QPushButton>
#include <QSettings>
#include <QTemporaryDir>
#include <QThread>
#include <QtTest>

#include <algorithm>
#include <csignal>
#include <cstdio>

using namespace lacrima;

namespace {

constexpr const char* kChildVariable = "LACRIMA_AUTOSAVE_CHILD";

// About 2 MB of project: long enough that a kill lands inside the write, not only around it.
ProjectDocument largeProject() {
  ProjectDocument document;
  std::vector<Keyframe> keys;
  for (int k = 0; k < 2000; ++k) {
    Keyframe key;
    key.time = k * 0.05;
    for (int fap = 3; fap <= 68; ++fap) key.set(fap, static_cast<float>((k * 7 + fap) % 200));
    keys.push_back(key);
  }
  document.keys = KeyframeSequence(std::move(keys));
  return document;
}

QString generationName(long long generation) {
  return QStringLiteral("generation %1").arg(generation);
}

// The child: autosaves forever until it is killed.
int autosaveForever(const QString& folder) {
  editing::RecoveryStore store(folder);
  ProjectDocument document = largeProject();
  for (long long generation = 1;; ++generation) {
    document.name = generationName(generation).toStdString();
    std::printf("start %lld\n", generation);
    std::fflush(stdout);
    store.save(document, QString());
    std::printf("saved %lld\n", generation);
    std::fflush(stdout);
  }
}

// Reads the child's announcements as they come.
struct ChildLog {
  long long started = 0;
  long long saved = 0;

  void read(QProcess& child) {
    while (child.canReadLine()) {
      const QByteArray line = child.readLine().trimmed();
      const long long n = line.mid(line.indexOf(' ') + 1).toLongLong();
      if (line.startsWith("start")) started = n;
      if (line.startsWith("saved")) saved = n;
    }
  }
};

}  // namespace

class AutosaveKillTest : public QObject {
  Q_OBJECT

  QTemporaryDir recovery_;

  // The killed session's recovery file (there is one session at a time).
  QString recoveryFile() const {
    const QStringList files =
        QDir(recovery_.path()).entryList({QStringLiteral("session-*.json")}, QDir::Files);
    return files.size() == 1 ? recovery_.filePath(files.front()) : QString();
  }

  // Bytes the process has passed to write(2) so far (wchar in /proc/PID/io), -1 if unknown.
  static qint64 bytesWritten(pid_t pid) {
    QFile io(QStringLiteral("/proc/%1/io").arg(pid));
    if (!io.open(QIODevice::ReadOnly)) return -1;
    for (const QByteArray& line : io.readAll().split('\n'))
      if (line.startsWith("wchar:")) return line.mid(6).trimmed().toLongLong();
    return -1;
  }

 private slots:
  void initTestCase() {
    QStandardPaths::setTestModeEnabled(true);
    QCoreApplication::setOrganizationName(QStringLiteral("lacrima-test"));
    QCoreApplication::setApplicationName(QStringLiteral("autosave-kill-test"));
    QSettings().clear();
    QVERIFY(recovery_.isValid());
  }

  void nextStartOffersTheLastCompleteFile() {
    // Half the kills are spread over a whole save's time, most of which goes into building the
    // text; the other half aim at the write itself: they watch the bytes the child has written
    // (/proc/PID/io, wchar) and strike once a given fraction of the file has gone out, from
    // the first byte to the last (and so also between the write and the rename).
    constexpr int kTimedRounds = 6;
    constexpr int kWriteRounds = 10;
    qint64 saveMs = 0;
    for (int round = 0; round < kTimedRounds + kWriteRounds; ++round) {
      QProcess child;
      QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
      environment.insert(QString::fromLatin1(kChildVariable), recovery_.path());
      child.setProcessEnvironment(environment);
      child.start(QCoreApplication::applicationFilePath(), {});
      QVERIFY(child.waitForStarted());
      const auto pid = static_cast<pid_t>(child.processId());

      // Two whole saves first (the second one timed), then a kill some way into a later one.
      ChildLog log;
      QElapsedTimer clock;
      while (log.saved < 2) {
        QVERIFY2(child.waitForReadyRead(30000), "the child stopped announcing saves");
        const long long before = log.started;
        log.read(child);
        if (log.started == 2 && before < 2) clock.start();
      }
      if (round == 0) saveMs = std::max<qint64>(1, clock.elapsed());
      const qint64 fileBytes = QFileInfo(recoveryFile()).size();
      QVERIFY(fileBytes > 1000000);
      while (log.started <= log.saved) {
        QVERIFY(child.waitForReadyRead(30000));
        log.read(child);
      }
      QString when;
      if (round < kTimedRounds) {
        const qint64 delay = saveMs * round / kTimedRounds;
        QThread::msleep(static_cast<unsigned long>(delay));
        when = QStringLiteral("%1 ms into the save").arg(delay);
      } else {
        const qint64 start = bytesWritten(pid);
        QVERIFY2(start >= 0, "/proc/PID/io is not readable here");
        const qint64 goal = fileBytes * (round - kTimedRounds) / (kWriteRounds - 1);
        QElapsedTimer patience;
        patience.start();
        while (bytesWritten(pid) - start < std::max<qint64>(goal, 1) &&
               patience.elapsed() < 10000) {
        }
        when = QStringLiteral("after %1 of %2 bytes").arg(bytesWritten(pid) - start).arg(fileBytes);
      }
      ::kill(pid, SIGKILL);
      QVERIFY(child.waitForFinished(30000));
      log.read(child);

      // The next editor's view of the folder: exactly the killed session's file, complete, and
      // no older than the last save the child finished.
      editing::RecoveryStore next(recovery_.path());
      const auto orphans = next.orphans();
      QCOMPARE(orphans.size(), std::size_t{1});
      const editing::RecoveryStore::Orphan& orphan = orphans.front();
      const long long offered = orphan.name.section(QLatin1Char(' '), 1).toLongLong();
      QVERIFY2(offered >= log.saved && offered <= log.saved + 1,
               qPrintable(QStringLiteral("offered %1, last finished save %2, killed %3 of save %4")
                              .arg(offered)
                              .arg(log.saved)
                              .arg(when)
                              .arg(log.started)));
      QCOMPARE(orphan.keys, 2000);

      // Every file left in the folder is complete, or it is not a recovery file at all.
      for (const QString& name : QDir(recovery_.path()).entryList(QDir::Files)) {
        if (!name.endsWith(QStringLiteral(".json"))) continue;
        QVERIFY2(editing::RecoveryStore::read(recovery_.filePath(name)).keys.keys().size() == 2000,
                 qPrintable(name));
      }

      if (round == kTimedRounds + kWriteRounds - 1) {
        // The window itself: the banner offers it, and Restore brings back that generation.
        editor::EditorOptions options;
        options.preview = false;
        options.interactive = false;
        options.recoveryDirectory = recovery_.path();
        editor::MainWindow window(options);
        window.checkForRecovery();
        QVERIFY(window.recoveryBanner()->isVisibleTo(&window));
        const auto* offer = window.recoveryBanner()->findChild<QLabel*>();
        QVERIFY(offer && offer->text().contains(generationName(offered)));
        window.recoveryBanner()->restoreButton()->click();
        QCOMPARE(QString::fromStdString(window.model().document().name), generationName(offered));
        QCOMPARE(window.model().document().keys.keys().size(), std::size_t{2000});
        window.model().markSaved();
        window.recovery().discard();
      }
      editing::RecoveryStore::remove(orphan.file);
    }
    qInfo("one save of the 2,000-key project took %lld ms", static_cast<long long>(saveMs));
  }
};

int main(int argc, char** argv) {
  if (qEnvironmentVariableIsSet(kChildVariable)) {
    QCoreApplication app(argc, argv);
    return autosaveForever(qEnvironmentVariable(kChildVariable));
  }
  QApplication app(argc, argv);
  AutosaveKillTest test;
  return QTest::qExec(&test, argc, argv);
}

#include "AutosaveKillTest.moc"
