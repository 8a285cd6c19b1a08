// Every malformed fixture opened in the editor as a user would: through File ▸ Open
// (the file dialog and the warning it leads to) and by drag and drop. Each is refused with a
// message naming the file, and the project that was open stays as it was, file name included.
#include "../support/MalformedFiles.h"

#include <lacrima/editing/EditorModel.h>
#include <lacrima/editor/MainWindow.h>

#include <QAction>
#include <QMimeData>
#include <QSettings>
#include <QTemporaryDir>
#include <QtTest>

#include <memory>

using namespace lacrima;
using namespace lacrima::editor;

class EditorMalformedFilesTest : public QObject {
  Q_OBJECT

  QTemporaryDir work_;
  std::unique_ptr<MainWindow> window_;
  QString project_;
  std::string projectJson_;

  // The window's state a refused file must not touch.
  void verifyUnchanged() {
    QCOMPARE(window_->filePath(), project_);
    QCOMPARE(window_->model().document().toJson(), projectJson_);
    QVERIFY(!window_->model().isModified());
  }

  void verifyNamed(const QString& message, const QString& file) {
    QVERIFY2(message.contains(QFileInfo(file).fileName()), qPrintable(message));
  }

 private slots:
  void initTestCase() {
    QStandardPaths::setTestModeEnabled(true);
    QCoreApplication::setOrganizationName(QStringLiteral("lacrima-test"));
    QCoreApplication::setApplicationName(QStringLiteral("editor-malformed-test"));
    QCoreApplication::setAttribute(Qt::AA_DontUseNativeDialogs);
    QSettings().clear();
    QVERIFY(test::malformedFiles().size() >= 10);

    EditorOptions options;
    options.preview = false;
    options.interactive = true;  // File ▸ Open shows its dialogs
    options.offerRecovery = false;
    options.recoveryDirectory = work_.filePath(QStringLiteral("recovery"));
    window_ = std::make_unique<MainWindow>(options);
    window_->show();
    project_ = QStringLiteral(LACRIMA_SOURCE_DIR "/media/demo/crying.json");
    QVERIFY(window_->openFile(project_));
    projectJson_ = window_->model().document().toJson();
  }

  void refusedThroughFileOpen_data() {
    QTest::addColumn<QString>("file");
    for (const QString& file : test::malformedFiles())
      QTest::newRow(qPrintable(QFileInfo(file).fileName())) << file;
  }

  void refusedThroughFileOpen() {
    QFETCH(QString, file);
    auto* open = window_->findChild<QAction*>(QStringLiteral("file.open"));
    QVERIFY(open);
    QStringList messages;
    test::answeringDialogs(file, messages, [&] { open->trigger(); });
    QCOMPARE(messages.size(), 1);
    verifyNamed(messages.front(), file);
    verifyUnchanged();
  }

  void refusedWhenDropped_data() {
    QTest::addColumn<QString>("file");
    for (const QString& file : test::malformedFiles())
      QTest::newRow(qPrintable(QFileInfo(file).fileName())) << file;
    // What no file dialog would hand over, but a drop can.
    const QString folder = work_.filePath(QStringLiteral("folder.fap"));
    QDir().mkpath(folder);
    QTest::newRow("a folder") << folder;
    QTest::newRow("a file that is gone") << work_.filePath(QStringLiteral("gone.lacrima"));
  }

  void refusedWhenDropped() {
    QFETCH(QString, file);
    QMimeData mime;
    mime.setUrls({QUrl::fromLocalFile(file)});
    QDragEnterEvent enter(QPoint(40, 40), Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
    QApplication::sendEvent(window_.get(), &enter);
    QVERIFY(enter.isAccepted());
    QDropEvent drop(QPointF(40, 40), Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
    QStringList messages;
    test::answeringDialogs(file, messages, [&] { QApplication::sendEvent(window_.get(), &drop); });
    QCOMPARE(messages.size(), 1);
    verifyNamed(messages.front(), file);
    verifyNamed(window_->lastError(), file);
    verifyUnchanged();
  }
};

QTEST_MAIN(EditorMalformedFilesTest)
#include "EditorMalformedFilesTest.moc"
