// Faults that must lose nothing: Save, Save As, export and autosave when the disk
// fills mid-write, when the folder is read-only and when the target path is a folder. Every
// case checks the same three promises: the old file is intact byte for byte (and no temporary
// file is left beside it), the document stays marked unsaved, and the window says why, naming
// the file. The faults are real ones (tests/support/FileFaults.h), not injected errors.
#include "../support/FileFaults.h"

#include <lacrima/editing/EditorModel.h>
#include <lacrima/editing/FapTransfer.h>
#include <lacrima/editing/RecoveryStore.h>
#include <lacrima/editor/MainWindow.h>

#include <QDir>
#include <QFile>
#include <QSettings>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QtTest>

#include <memory>

using namespace lacrima;
using namespace lacrima::editor;

namespace {

enum class Operation { Save, SaveAs, Export, Autosave };
enum class Fault { DiskFull, ReadOnlyFolder, TargetIsFolder };

QByteArray contents(const QString& path) {
  QFile file(path);
  return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

// A few keys on many channels: several KiB of project and of FAP file, so that the disk-full
// limit below falls in the middle of the write.
void animate(editing::EditorModel& model, double offset) {
  for (int key = 0; key < 4; ++key) {
    model.setCurrentTime(key * 0.5);
    std::vector<editing::ChannelValue> values;
    for (int fap = 3; fap <= 68; ++fap)
      values.emplace_back(fap, static_cast<float>(offset + key * 10.0 + fap));
    model.setChannels(std::move(values), QStringLiteral("pose"));
  }
}

}  // namespace

class EditorFaultsTest : public QObject {
  Q_OBJECT

  QTemporaryDir work_;
  std::unique_ptr<MainWindow> window_;

  // Where the operation writes, and what the window said about it.
  QString folder() const { return work_.filePath(QStringLiteral("files")); }
  QString recoveryFolder() const { return work_.filePath(QStringLiteral("recovery")); }

  QString targetOf(Operation operation) const {
    switch (operation) {
      case Operation::Save:
        return folder() + QStringLiteral("/scene.lacrima");
      case Operation::SaveAs:
        return folder() + QStringLiteral("/other.lacrima");
      case Operation::Export:
        return folder() + QStringLiteral("/scene.fap");
      case Operation::Autosave:
        return window_->recovery().filePath();
    }
    return {};
  }

  // What the target's folder holds besides the session's autosave lock, which an autosave makes
  // before it writes, and keeps.
  QStringList entriesBeside(const QString& target) const {
    QStringList entries = QFileInfo(target).dir().entryList(QDir::AllEntries | QDir::Hidden);
    entries.removeAll(QFileInfo(target).completeBaseName() + QStringLiteral(".lock"));
    return entries;
  }

  QString messageAfter(Operation operation) const {
    return operation == Operation::Autosave ? window_->statusBar()->currentMessage()
                                            : window_->lastError();
  }

  bool run(Operation operation) {
    switch (operation) {
      case Operation::Save:
      case Operation::SaveAs:
        return window_->saveTo(targetOf(operation));
      case Operation::Export:
        return window_->exportFap(targetOf(operation), {});
      case Operation::Autosave:
        window_->statusBar()->clearMessage();
        window_->autosaveNow();
        return !window_->statusBar()->currentMessage().startsWith(
            QStringLiteral("Autosave failed"));
    }
    return false;
  }

 private slots:
  void initTestCase() {
    QStandardPaths::setTestModeEnabled(true);
    QCoreApplication::setOrganizationName(QStringLiteral("lacrima-test"));
    QCoreApplication::setApplicationName(QStringLiteral("editor-faults-test"));
    QSettings().clear();
    QVERIFY(work_.isValid());
  }

  void init() {
    QDir(folder()).removeRecursively();
    QDir(recoveryFolder()).removeRecursively();
    QVERIFY(QDir().mkpath(folder()) && QDir().mkpath(recoveryFolder()));
    EditorOptions options;
    options.preview = false;
    options.interactive = false;
    options.offerRecovery = false;
    options.recoveryDirectory = recoveryFolder();
    window_ = std::make_unique<MainWindow>(options);
  }

  void cleanup() {
    window_->model().markSaved();
    window_.reset();
  }

  void faultLosesNothing_data() {
    QTest::addColumn<Operation>("operation");
    QTest::addColumn<Fault>("fault");
    const std::pair<Operation, const char*> operations[] = {{Operation::Save, "save"},
                                                            {Operation::SaveAs, "save as"},
                                                            {Operation::Export, "export"},
                                                            {Operation::Autosave, "autosave"}};
    const std::pair<Fault, const char*> faults[] = {{Fault::DiskFull, "disk full"},
                                                    {Fault::ReadOnlyFolder, "read-only folder"},
                                                    {Fault::TargetIsFolder, "target is a folder"}};
    for (const auto& [operation, operationName] : operations)
      for (const auto& [fault, faultName] : faults)
        QTest::addRow("%s, %s", operationName, faultName) << operation << fault;
  }

  void faultLosesNothing() {
    QFETCH(Operation, operation);
    QFETCH(Fault, fault);
    editing::EditorModel& model = window_->model();

    // The old file: the same operation once, with nothing in the way. A folder in the target's
    // place is the old "file" of the last fault, and it must stay a folder with its content.
    animate(model, 0);
    const QString target = targetOf(operation);
    if (fault == Fault::TargetIsFolder) {
      QVERIFY(QDir().mkpath(target));
      QFile inside(target + QStringLiteral("/keep.txt"));
      QVERIFY(inside.open(QIODevice::WriteOnly) && inside.write("kept") == 4);
    } else {
      QVERIFY(run(operation));
      QVERIFY(QFileInfo(target).isFile());
    }
    const QByteArray before = contents(target);
    const QString targetFolder = QFileInfo(target).absolutePath();
    const QStringList entriesBefore = entriesBeside(target);

    // An edit the fault must not lose; the document is unsaved from here on.
    animate(model, 100);
    QVERIFY(model.isModified());
    if (operation == Operation::Save && fault != Fault::TargetIsFolder)
      QCOMPARE(window_->filePath(), target);

    bool succeeded = true;
    if (fault == Fault::DiskFull) {
      const test::FileSizeLimit full(1024);
      QVERIFY(full.active());
      succeeded = run(operation);
    } else if (fault == Fault::ReadOnlyFolder) {
      const test::ReadOnlyFolder readOnly(targetFolder);
      QVERIFY2(readOnly.refusesWrites(), "the folder still takes new files");
      succeeded = run(operation);
    } else {
      succeeded = run(operation);
    }

    QVERIFY2(!succeeded, "the operation reported success under the fault");
    if (fault == Fault::TargetIsFolder) {
      QVERIFY(QFileInfo(target).isDir());
      QCOMPARE(contents(target + QStringLiteral("/keep.txt")), QByteArray("kept"));
    } else {
      QCOMPARE(contents(target), before);
    }
    QCOMPARE(entriesBeside(target), entriesBefore);
    QVERIFY(model.isModified());
    const QString message = messageAfter(operation);
    QVERIFY2(message.contains(target), qPrintable(message));
    QVERIFY2(message.contains(QStringLiteral("cannot save")), qPrintable(message));

    // Without the fault the same operation goes through, with the edit in it.
    if (fault != Fault::TargetIsFolder) {
      QVERIFY(run(operation));
      QVERIFY(contents(target) != before);
      if (operation == Operation::Save || operation == Operation::SaveAs)
        QVERIFY(!model.isModified());
    }
  }
};

QTEST_MAIN(EditorFaultsTest)
#include "EditorFaultsTest.moc"
