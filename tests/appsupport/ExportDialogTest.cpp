// File > Export (ExportDialog, shared by the player and the editor) driven as a user would: a
// glTF export runs in its own lacrima-player process while the dialog stays responsive (Export
// disabled, no progress shown before it starts), reports progress and ends with the written
// file; a video export stopped half way (Escape) leaves neither the video nor its temporary;
// the output starts beside the animation and follows the format until the user types one; bad
// choices are refused with a reason before anything runs; the player's File > Export opens it
// on the file shown. The editor's File > Export Animation: test_editor_window.
#include "../support/MissingData.h"
#include "../support/WeepingClip.h"

#include <lacrima/appsupport/ExportDialog.h>
#include <lacrima/common/FapWriter.h>
#include <lacrima/player/PlayerWindow.h>
#include <lacrima/rigging/DefaultHead.h>

#include <QDir>
#include <QElapsedTimer>
#include <QLineEdit>
#include <QProgressBar>
#include <QPushButton>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QtTest>

using namespace lacrima;
using appsupport::ExportDialog;
using appsupport::ExportFormat;

namespace {

const QString kPlayer = QStringLiteral(LACRIMA_BIN_DIR "/lacrima-player");

}  // namespace

class ExportDialogTest : public QObject {
  Q_OBJECT

  QTemporaryDir dir_;
  QString clip_;

  appsupport::ExportSource source(int frames) const { return {clip_, {}, {}, frames, {}}; }

 private slots:
  void initTestCase() {
    QVERIFY(dir_.isValid());
    clip_ = dir_.filePath("weeping.fap");
    FapWriter::save(testsupport::weepingClip(120, 5, 25), clip_.toStdString());
  }

  void refusesBadChoicesWithAReason() {
    ExportDialog dialog(source(120), nullptr, kPlayer);
    // Beside the animation, named after it, with the format's extension or folder suffix...
    QCOMPARE(dialog.output(), dir_.filePath("weeping.glb"));
    dialog.setFormat(ExportFormat::Video);
    QCOMPARE(dialog.output(), dir_.filePath("weeping.mp4"));
    dialog.setFormat(ExportFormat::TearMeshes);
    QCOMPARE(dialog.output(), dir_.filePath("weeping_tears"));
    // ... until the user types one, which then stays whatever the format.
    auto* output = dialog.findChild<QLineEdit*>("output");
    QVERIFY(output);
    QTest::keyClick(output, Qt::Key_End);
    QTest::keyClicks(output, "2");
    dialog.setFormat(ExportFormat::Gltf);
    QCOMPARE(dialog.output(), dir_.filePath("weeping_tears2"));
    QString why;
    dialog.setOutput(QString());
    QVERIFY(dialog.arguments(&why).isEmpty());  // no output chosen
    QVERIFY(why.contains("where"));
    dialog.setOutput(dir_.filePath("x.mp4"));
    dialog.setFormat(ExportFormat::Video);
    dialog.setImageSize("321x240");
    QVERIFY(dialog.arguments(&why).isEmpty());
    QVERIFY2(why.contains("even"), qPrintable(why));
    dialog.setImageSize("big");
    QVERIFY(dialog.arguments(&why).isEmpty());
    QVERIFY2(why.contains("Size"), qPrintable(why));
    dialog.setImageSize("320x240");
    dialog.setFrameRange(9, 3);
    QVERIFY(dialog.arguments(&why).isEmpty());
    dialog.setFrameRange(3, 9);
    QCOMPARE(dialog.arguments(),
             QStringList({"--video", dir_.filePath("x.mp4"), "--size", "320x240", "--view",
                          "framing", "--frames", "3-9", clip_}));
    dialog.setFormat(ExportFormat::Images);
    dialog.setLayers(true, true);
    QVERIFY(dialog.arguments().contains("--alpha") && dialog.arguments().contains("--masks"));
    dialog.setFormat(ExportFormat::Gltf);  // no size, view or layers for a glTF file
    QVERIFY(!dialog.arguments().contains("--size") && !dialog.arguments().contains("--alpha"));
  }

  void gltfExportRunsBesideTheWindow() {
    if (!rigging::defaultHeadAvailable()) LACRIMA_SKIP_WITHOUT_DEFAULT_HEAD();
    ExportDialog dialog(source(120), nullptr, kPlayer);
    const QString out = dir_.filePath("clip.glb");
    dialog.setFormat(ExportFormat::Gltf);
    dialog.setOutput(out);
    dialog.setFrameRange(0, 59);
    QSignalSpy finished(&dialog, &ExportDialog::exportFinished);
    auto* progress = dialog.findChild<QProgressBar*>();
    auto* exportButton = dialog.findChild<QPushButton*>("export");
    QVERIFY(progress && exportButton);
    QVERIFY(progress->isHidden());  // no "0%" before anything ran
    QElapsedTimer returned;
    returned.start();
    dialog.start();
    // start() returns at once: the export runs in its own process, the event loop goes on.
    QVERIFY(dialog.running());
    QVERIFY(returned.elapsed() < 5000);
    QVERIFY(!progress->isHidden());
    QVERIFY(!exportButton->isEnabled());  // one export at a time
    QVERIFY(finished.wait(300000));
    QVERIFY(exportButton->isEnabled());
    QVERIFY2(finished.at(0).at(0).toBool(), qPrintable(finished.at(0).at(1).toString()));
    QVERIFY(finished.at(0).at(1).toString().contains("clip.glb"));
    QVERIFY(QFileInfo(out).size() > 1000);
    QCOMPARE(dialog.findChild<QProgressBar*>()->value(), 100);
  }

  void stoppedVideoLeavesNothing() {
    if (!rigging::defaultHeadAvailable()) LACRIMA_SKIP_WITHOUT_DEFAULT_HEAD();
    ExportDialog dialog(source(120), nullptr, kPlayer);
    const QString out = dir_.filePath("stopped.mp4");
    dialog.setFormat(ExportFormat::Video);
    dialog.setOutput(out);
    dialog.setImageSize("640x480");
    QSignalSpy finished(&dialog, &ExportDialog::exportFinished);
    dialog.start();
    QVERIFY(dialog.running());
    // Stop once it has made some progress (its first progress line), well before the end.
    QProgressBar* progress = dialog.findChild<QProgressBar*>();
    QTRY_VERIFY_WITH_TIMEOUT(progress->value() > 0 || !dialog.running(), 300000);
    QVERIFY2(dialog.running(), "the export ended before it could be stopped");
    QTest::keyClick(&dialog, Qt::Key_Escape);  // stops it, rather than hiding it running
    QVERIFY(finished.wait(60000));
    QCOMPARE(finished.at(0).at(0).toBool(), false);
    QVERIFY(finished.at(0).at(1).toString().contains("stopped"));
    QVERIFY(!QFile::exists(out));
    for (const QString& name : QDir(dir_.path()).entryList(QDir::Files | QDir::Hidden))
      QVERIFY2(!name.contains(".part"), qPrintable(name));
  }

  void playerFileMenuExportsTheFileShown() {
    if (!rigging::defaultHeadAvailable()) LACRIMA_SKIP_WITHOUT_DEFAULT_HEAD();
    player::PlayerWindow window(playback::loadDefaultHeadRig());
    QVERIFY(window.exportDialog() == nullptr);  // nothing open yet
    QVERIFY(window.openFile(clip_));
    ExportDialog* dialog = window.exportDialog();
    QVERIFY(dialog);
    QCOMPARE(dialog->output(), dir_.filePath("weeping.glb"));
    dialog->setOutput(dir_.filePath("menu.glb"));
    QCOMPARE(dialog->arguments().back(), clip_);
    QCOMPARE(dialog->arguments().front(), QStringLiteral("--export-gltf"));
    QVERIFY(dialog->arguments().contains("0-119"));
    dialog->close();
  }
};

QTEST_MAIN(ExportDialogTest)
#include "ExportDialogTest.moc"
