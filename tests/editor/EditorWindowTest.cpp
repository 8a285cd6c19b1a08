// The editor as people use it: real widgets on the offscreen platform, driven by mouse and
// keyboard events and by the window's actions.
#include "../support/MissingData.h"
#include "../support/WeepingClip.h"

#include <lacrima/appsupport/ExportDialog.h>
#include <lacrima/common/FapReader.h>
#include <lacrima/common/FapTable.h>
#include <lacrima/common/FapWriter.h>
#include <lacrima/editing/EditorModel.h>
#include <lacrima/editing/FrameStepClock.h>
#include <lacrima/editing/HeadSetup.h>
#include <lacrima/editing/RecoveryStore.h>
#include <lacrima/editor/ChannelRow.h>
#include <lacrima/editor/DopeSheet.h>
#include <lacrima/editor/DopeSheetView.h>
#include <lacrima/editor/KeyListPanel.h>
#include <lacrima/editor/MainWindow.h>
#include <lacrima/editor/NumberField.h>
#include <lacrima/editor/PresetPanel.h>
#include <lacrima/editor/RecoveryBanner.h>
#include <lacrima/editor/SliderPanel.h>
#include <lacrima/editor/TimelineWidget.h>
#include <lacrima/editor/WindowFit.h>
#include <lacrima/editor/ZeroSlider.h>
#include <lacrima/editor/head/HeadWorkspace.h>
#include <lacrima/rigging/DefaultHead.h>
#include <lacrima/viewport/ElidedLabel.h>
#include <lacrima/viewport/FaceViewport.h>

#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QDir>
#include <QDockWidget>
#include <QElapsedTimer>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QScreen>
#include <QSettings>
#include <QTabBar>
#include <QTableView>
#include <QTemporaryDir>
#include <QToolButton>
#include <QUndoCommand>
#include <QUndoStack>
#include <QUndoView>
#include <QtTest>

#include <memory>

using namespace lacrima;
using namespace lacrima::editor;

namespace {

EditorOptions testOptions(const QString& recoveryDir) {
  EditorOptions options;
  options.preview = false;
  options.interactive = false;
  options.offerRecovery = true;
  options.recoveryDirectory = recoveryDir;
  return options;
}

// Drags a slider at 0 by `fraction` of its range: presses on its zero mark (the handle) and
// moves fraction x ZeroSlider::kPixelsPerRange pixels to the right.
void dragSlider(ZeroSlider* slider, double fraction) {
  const int y = slider->height() / 2;
  const int zero =
      static_cast<int>(6 + (0.0 - slider->minimum()) / (slider->maximum() - slider->minimum()) *
                               (slider->width() - 12));
  const int target = zero + static_cast<int>(fraction * ZeroSlider::kPixelsPerRange);
  QTest::mousePress(slider, Qt::LeftButton, {}, QPoint(zero, y));
  for (int step = 1; step <= 8; ++step) {
    QMouseEvent move(QEvent::MouseMove, QPointF(zero + (target - zero) * step / 8.0, y),
                     slider->mapToGlobal(QPointF(0, 0)), Qt::NoButton, Qt::LeftButton,
                     Qt::NoModifier);
    QCoreApplication::sendEvent(slider, &move);
  }
  QTest::mouseRelease(slider, Qt::LeftButton, {}, QPoint(target, y));
}

// A head edit that needs no head: counts how many times it is done.
class CountedEdit : public QUndoCommand {
 public:
  explicit CountedEdit(int& done) : QUndoCommand(QStringLiteral("Place point")), done_(done) {}
  void redo() override { ++done_; }
  void undo() override { --done_; }

 private:
  int& done_;
};

void setSpin(NumberField* spin, int value) {
  spin->setFocus();
  spin->selectAll();
  QTest::keyClicks(spin, QString::number(value));
  QTest::keyClick(spin, Qt::Key_Return);
  spin->clearFocus();  // window shortcuts (K, Space, Delete) act again, as after a click elsewhere
}

}  // namespace

class EditorWindowTest : public QObject {
  Q_OBJECT

 private:
  QTemporaryDir recoveryDir_;
  std::unique_ptr<MainWindow> window_;

  MainWindow& window() { return *window_; }
  editing::EditorModel& model() { return window_->model(); }

 private slots:
  void initTestCase() {
    QStandardPaths::setTestModeEnabled(true);
    QCoreApplication::setOrganizationName(QStringLiteral("lacrima-test"));
    QCoreApplication::setApplicationName(QStringLiteral("editor-window-test"));
    QSettings().clear();
  }

  void init() {
    window_ = std::make_unique<MainWindow>(testOptions(recoveryDir_.path()));
    window_->resize(1400, 900);
    window_->show();
    window_->activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(window_.get()));
  }

  void cleanup() {
    window_->model().markSaved();  // nothing to recover from a finished test
    window_->close();
    window_.reset();
  }

  void buildsSeventyChannelsGroupedAsTheStandard() {
    SliderPanel* panel = window().sliders();
    QCOMPARE(panel->visibleChannels().size(), std::size_t{70});
    for (int fap = 3; fap <= 70; ++fap) {
      ChannelRow* row = panel->row(fap);
      QVERIFY(row);
      QCOMPARE(row->slider()->minimum(), fapInfo(fap).sliderMin);
      QCOMPARE(row->slider()->maximum(), fapInfo(fap).sliderMax);
      QVERIFY(row->slider()->toolTip().contains(
          QString::fromUtf8(fapInfo(fap).description.data(),
                            static_cast<qsizetype>(fapInfo(fap).description.size()))));
    }
    QVERIFY(panel->visemePicker());
    QCOMPARE(panel->visemePicker()->count(), 15);
    QCOMPARE(panel->expressionPicker()->count(), 7);
    // Groups in the standard's order: their first channels appear in number order.
    const std::vector<int> order = panel->visibleChannels();
    QVERIFY(std::is_sorted(order.begin(), order.end()));
  }

  void movingASliderChangesTheProject() {
    ChannelRow* row = window().sliders()->row(3);  // open_jaw, 0..1080
    QVERIFY(model().document().keys.empty());
    dragSlider(row->slider(), 0.5);
    QCOMPARE(model().document().keys.keys().size(), std::size_t{1});
    const Keyframe& key = model().document().keys.keys().front();
    QCOMPARE(key.time, 0.0);
    QVERIFY(key.has(3));
    QVERIFY(std::abs(key.value(3) - 540.0f) <= 12.0f);
    QCOMPARE(row->valueField()->value(), static_cast<double>(key.value(3)));
    QCOMPARE(model().undoStack()->count(), 1);  // the whole drag is one step
    QVERIFY(window().isWindowModified());
    QVERIFY(window().windowTitle().contains(QStringLiteral("[*]")));
    // The spin box edits the same key.
    setSpin(row->valueField(), 123);
    QCOMPARE(model().document().keys.keys().front().value(3), 123.0f);
    QCOMPARE(row->slider()->value(), 123);
  }

  void keysAtZeroAndOneSecondExport23FramesAtTwentyTwoFps() {
    ChannelRow* jaw = window().sliders()->row(3);
    ChannelRow* tears = window().sliders()->row(69);
    setSpin(jaw->valueField(), 220);
    setSpin(jaw->valueField(), 0);                          // keyed at 0 s with 0
    QTest::mouseClick(tears->keyToggle(), Qt::LeftButton);  // keys tears_l_eye = 0 at 0 s
    QVERIFY(model().keyedAtCurrentTime().test(channelIndex(69)));
    QTest::keyClick(window().timeline(), Qt::Key_Right);  // next frame...
    model().setCurrentTime(1.0);                          // ...and to 1 s
    setSpin(jaw->valueField(), 440);
    setSpin(tears->valueField(), 44);
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("jaw.fap"));
    QVERIFY2(window().exportFap(path, editing::FapExportOptions{}),
             qPrintable(window().lastError()));
    const FapAnimation animation = FapReader::readFile(path.toStdString()).animation;
    QCOMPARE(animation.frameCount(), 23);
    QCOMPARE(animation.fps, 22.0);
    for (int i = 0; i < 23; ++i) {
      QCOMPARE(animation.frames[i][channelIndex(3)], 20.0f * i);
      QCOMPARE(animation.frames[i][channelIndex(69)], 2.0f * i);
    }
  }

  void undoAndRedoThroughTheMenuRestoreExactly() {
    std::vector<ProjectDocument> states{model().document()};
    dragSlider(window().sliders()->row(31)->slider(), 0.8);
    states.push_back(model().document());
    model().setCurrentTime(0.5);
    window().action(QStringLiteral("key.add"))->trigger();
    states.push_back(model().document());
    window().presets()->apply(QStringLiteral("sad-crying"));
    states.push_back(model().document());
    window().action(QStringLiteral("edit.mirror"))->trigger();
    states.push_back(model().document());
    window().action(QStringLiteral("key.smooth"))->trigger();
    states.push_back(model().document());
    QCOMPARE(model().undoStack()->count(), 5);
    QAction* undo = window().action(QStringLiteral("edit.undo"));
    QAction* redo = window().action(QStringLiteral("edit.redo"));
    for (int i = 4; i >= 0; --i) {
      undo->trigger();
      QVERIFY(model().document() == states[static_cast<std::size_t>(i)]);
    }
    QVERIFY(!undo->isEnabled());
    QVERIFY(!window().isWindowModified());
    for (std::size_t i = 1; i < states.size(); ++i) {
      redo->trigger();
      QVERIFY(model().document() == states[i]);
    }
    // Keyboard shortcuts reach the same actions.
    QTest::keySequence(&window(), QKeySequence(QStringLiteral("Ctrl+Z")));
    QVERIFY(model().document() == states[4]);
    QTest::keySequence(&window(), QKeySequence(QStringLiteral("Ctrl+Shift+Z")));
    QVERIFY(model().document() == states[5]);
  }

  void mirrorActionMapsStretchLeftToRight() {
    setSpin(window().sliders()->row(6)->valueField(), 150);
    window().action(QStringLiteral("edit.mirror"))->trigger();
    QCOMPARE(window().sliders()->row(7)->valueField()->value(), 150.0);
    QCOMPARE(window().sliders()->row(6)->valueField()->value(), 0.0);
    QVERIFY(!model().document().keys.keys().front().has(6));
  }

  void symmetricToggleMovesBothSliders() {
    window().action(QStringLiteral("edit.symmetric"))->trigger();
    QVERIFY(model().symmetricEdit());
    dragSlider(window().sliders()->row(19)->slider(), 0.75);  // close_t_l_eyelid
    QCOMPARE(window().sliders()->row(20)->valueField()->value(),
             window().sliders()->row(19)->valueField()->value());
    QVERIFY(window().sliders()->row(19)->valueField()->value() > 400);
    QCOMPARE(model().undoStack()->count(), 1);
  }

  void theFilterFindsSliders() {
    QLineEdit* filter = window().sliders()->filterBox();
    filter->setFocus();
    QTest::keyClicks(filter, QStringLiteral("jaw"));
    QCOMPARE(window().sliders()->visibleChannels(), (std::vector<int>{3, 14, 15}));
    QVERIFY(window().sliders()->row(3)->isVisible());
    QVERIFY(!window().sliders()->row(31)->isVisible());
    filter->clear();
    QTest::keyClicks(filter, QStringLiteral("31"));
    QCOMPARE(window().sliders()->visibleChannels(), (std::vector<int>{31}));
    filter->clear();
    QTest::keyClicks(filter, QStringLiteral("tears"));
    QCOMPARE(window().sliders()->visibleChannels(), (std::vector<int>{69, 70}));
    filter->clear();
    QTest::keyClicks(filter, QStringLiteral("expression"));
    QCOMPARE(window().sliders()->visibleChannels(), (std::vector<int>{2}));
    filter->clear();
    QCOMPARE(window().sliders()->visibleChannels().size(), std::size_t{70});
    // Typing K in the filter types a K; it does not add a key.
    QTest::keyClicks(filter, QStringLiteral("k"));
    QCOMPARE(filter->text(), QStringLiteral("k"));
    QVERIFY(model().document().keys.empty());
  }

  void resetsPerSliderAndPerGroup() {
    for (int fap : {31, 32, 33}) setSpin(window().sliders()->row(fap)->valueField(), 200);
    QTest::mouseClick(window().sliders()->row(31)->resetButton(), Qt::LeftButton);
    QCOMPARE(model().currentValue(31), 0.0f);
    QCOMPARE(model().currentValue(32), 200.0f);
    QTest::mouseClick(window().sliders()->groupResetButton(static_cast<int>(FapGroup::Eyebrows)),
                      Qt::LeftButton);
    QCOMPARE(model().currentValue(32), 0.0f);
    QCOMPARE(model().currentValue(33), 0.0f);
    QCOMPARE(model().undoStack()->count(), 5);  // three sets, one reset, one group reset
  }

  void highLevelPickersSetTheirCodes() {
    QComboBox* expression = window().sliders()->expressionPicker();
    expression->setCurrentIndex(3);
    emit expression->activated(3);            // what a user's pick sends
    QCOMPARE(model().currentValue(2), 3.0f);  // anger
    QComboBox* viseme = window().sliders()->visemePicker();
    viseme->setCurrentIndex(10);
    emit viseme->activated(10);
    QCOMPARE(model().currentValue(1), 10.0f);  // aa
    model().setCurrentTime(1.0);
    QCOMPARE(expression->currentIndex(), 3);  // codes hold
  }

  void timelineAddsMovesCopiesPastesAndDeletesKeys() {
    TimelineWidget* timeline = window().timeline();
    // The empty timeline's hint offers only what works now: K has nothing to key yet.
    QVERIFY(model().document().keys.keys().empty());
    QSignalSpy said(&model(), &editing::EditorModel::message);
    QTest::keyClick(&window(), Qt::Key_K);
    QVERIFY(model().document().keys.keys().empty());
    QCOMPARE(said.size(), 1);
    QVERIFY(!TimelineWidget::emptyHint().contains(QLatin1String("K")));
    QVERIFY(TimelineWidget::emptyHint().contains(QLatin1String("slider")));
    timeline->setView(-0.1, 200.0);  // 200 px per second
    setSpin(window().sliders()->row(3)->valueField(), 300);
    model().setCurrentTime(1.0);
    setSpin(window().sliders()->row(3)->valueField(), 600);
    QTest::keyClick(&window(), Qt::Key_Home);
    QCOMPARE(model().currentTime(), 0.0);
    // K adds a whole-pose key at the playhead.
    model().setCurrentTime(0.5);
    QTest::keyClick(&window(), Qt::Key_K);
    QCOMPARE(model().document().keys.keys().size(), std::size_t{3});
    QCOMPARE(model().document().keys.keys()[1].value(3), 450.0f);
    // Drag the 0.5 s key right by 0.3 s (6.6 frames at 200 px/s; keys move by whole frames).
    const QPoint from = timeline->keyPosition(1).toPoint();
    QTest::mousePress(timeline, Qt::LeftButton, {}, from);
    for (int dx = 10; dx <= 60; dx += 10) {
      QMouseEvent move(QEvent::MouseMove, QPointF(from.x() + dx, from.y()),
                       timeline->mapToGlobal(QPointF(from.x() + dx, from.y())), Qt::NoButton,
                       Qt::LeftButton, Qt::NoModifier);
      QCoreApplication::sendEvent(timeline, &move);
    }
    QTest::mouseRelease(timeline, Qt::LeftButton, {}, QPoint(from.x() + 60, from.y()));
    const double moved = model().document().keys.keys()[1].time;
    QCOMPARE(moved, 18.0 / 22.0);  // frame 11 -> 18
    QVERIFY(model().isSelected(moved));
    // Copy the selected key and paste it at 2 s.
    QTest::keySequence(&window(), QKeySequence::Copy);
    model().setCurrentTime(2.0);
    QTest::keySequence(&window(), QKeySequence::Paste);
    QCOMPARE(model().document().keys.keys().size(), std::size_t{4});
    QCOMPARE(model().document().keys.keys().back().time, 2.0);
    QCOMPARE(model().document().keys.keys().back().value(3), 450.0f);
    // Smooth, then delete it.
    QTest::keyClick(&window(), Qt::Key_S);
    QVERIFY(model().document().keys.keys().back().interpolation == Interpolation::Smooth);
    QTest::keyClick(&window(), Qt::Key_Delete);
    QCOMPARE(model().document().keys.keys().size(), std::size_t{3});
    // The key table shows the same keys.
    QCOMPARE(window().keyList()->view()->model()->rowCount(), 3);
  }

  void presetPanelAppliesAtThePlayhead() {
    PresetPanel* presets = window().presets();
    model().setCurrentTime(1.0);
    QVERIFY(presets->apply(QStringLiteral("surprise")));
    QCOMPARE(model().currentTime(), 1.0);
    QCOMPARE(model().currentValue(3), 450.0f);
    QCOMPARE(window().sliders()->row(3)->valueField()->value(), 450.0);
    QVERIFY(!presets->apply(QStringLiteral("no-such-preset")));
  }

  void savingClearsTheMarkAndRemembersTheFile() {
    QTemporaryDir dir;
    setSpin(window().sliders()->row(3)->valueField(), 100);
    QVERIFY(window().isWindowModified());
    const QString path = dir.filePath(QStringLiteral("take.json"));
    QVERIFY(window().saveTo(path));
    QVERIFY(!window().isWindowModified());
    QCOMPARE(model().document().name, std::string("take"));
    QVERIFY(QSettings()
                .value(QStringLiteral("files/recent"))
                .toStringList()
                .contains(QFileInfo(path).absoluteFilePath()));
    QVERIFY(ProjectDocument::load(path.toStdString()) == model().document());
    // Open it in a fresh document: identical, clean.
    window().newDocument();
    QVERIFY(window().openFile(path));
    QVERIFY(ProjectDocument::load(path.toStdString()) == model().document());
    QVERIFY(!window().isWindowModified());
    QVERIFY(!window().openFile(dir.filePath(QStringLiteral("missing.json"))));
    QVERIFY(window().lastError().contains(QStringLiteral("missing.json")));
  }

  // File > Export Animation: the player's dialog on the document as it is, unsaved edits
  // included, run through lacrima-player, without touching the user's project file.
  void exportAnimationExportsTheDocumentAsItIs() {
    QTemporaryDir dir;
    const QString fap = dir.filePath(QStringLiteral("weep.fap"));
    FapWriter::save(testsupport::weepingClip(12, 20, 25), fap.toStdString());
    QVERIFY(window().importFap(fap, std::nullopt));
    const QString project = dir.filePath(QStringLiteral("weep.lacrima"));
    QVERIFY(window().saveTo(project));
    auto openDialog = [this] {
      window().action(QStringLiteral("file.exportAnimation"))->trigger();
      return window().findChild<appsupport::ExportDialog*>();
    };
    // Saved and unchanged: the project file itself, outputs beside it.
    appsupport::ExportDialog* dialog = openDialog();
    QVERIFY(dialog && dialog->isVisible());
    QCOMPARE(dialog->arguments().back(), QFileInfo(project).absoluteFilePath());
    QCOMPARE(dialog->output(), dir.filePath(QStringLiteral("weep.glb")));
    QVERIFY(dialog->arguments().contains(QStringLiteral("0-11")));
    dialog->setFormat(appsupport::ExportFormat::Images);
    QCOMPARE(dialog->output(), dir.filePath(QStringLiteral("weep_frames")));
    dialog->close();  // deletes itself
    QTRY_VERIFY(!window().findChild<appsupport::ExportDialog*>());

    // An unsaved edit: a copy of the document as it is now, never the user's file.
    QFile file(project);
    QVERIFY(file.open(QIODevice::ReadOnly));
    const QByteArray saved = file.readAll();
    file.close();
    setSpin(window().sliders()->row(3)->valueField(), 100);
    QVERIFY(window().isWindowModified());
    dialog = openDialog();
    QVERIFY(dialog);
    const QString copy = dialog->arguments().back();
    QVERIFY2(copy != project && QFileInfo::exists(copy), qPrintable(copy));
    QVERIFY(ProjectDocument::load(copy.toStdString()).bake().frames ==
            model().document().bake().frames);
    QCOMPARE(dialog->output(), dir.filePath(QStringLiteral("weep.glb")));
    if (rigging::defaultHeadAvailable()) {
      dialog->setFrameRange(0, 3);
      QSignalSpy finished(dialog, &appsupport::ExportDialog::exportFinished);
      dialog->start();
      QVERIFY(finished.wait(120000));
      QVERIFY2(finished.at(0).at(0).toBool(), qPrintable(finished.at(0).at(1).toString()));
      QFile glb(dir.filePath(QStringLiteral("weep.glb")));
      QVERIFY(glb.open(QIODevice::ReadOnly));
      const QByteArray bytes = glb.readAll();
      QVERIFY(bytes.startsWith("glTF"));  // a binary glTF, its morph targets named by FAP
      QVERIFY(bytes.contains("\"targetNames\"") && bytes.contains("\"open_jaw\""));
      QVERIFY(bytes.contains("\"lacrima\""));  // its animation
    }
    QVERIFY(file.open(QIODevice::ReadOnly));
    QCOMPARE(file.readAll(), saved);
    dialog->close();
    QTRY_VERIFY(!QFileInfo::exists(copy));  // the copy goes with the dialog
    if (!rigging::defaultHeadAvailable()) LACRIMA_SKIP_WITHOUT_DEFAULT_HEAD();
  }

  void importThenExportRoundTrip() {
    QTemporaryDir dir;
    FapAnimation original;
    original.fps = 22;
    original.frames.assign(120, FapValues{});
    for (int i = 0; i < 120; ++i) {
      original.frames[i][channelIndex(3)] =
          static_cast<float>(std::lround(300 * std::sin(i * 0.1)) + 300);
      original.frames[i][channelIndex(70)] = static_cast<float>(i / 3);
    }
    original.animated.set(channelIndex(3));
    original.animated.set(channelIndex(70));
    const QString in = dir.filePath(QStringLiteral("in.fap"));
    FapWriter::save(original, in.toStdString());
    QVERIFY(window().importFap(in, std::nullopt));
    QCOMPARE(model().document().keys.keys().size(), std::size_t{120});
    QVERIFY(window().isWindowModified());  // an import is unsaved work
    const QString out = dir.filePath(QStringLiteral("out.fap"));
    QVERIFY(window().exportFap(out, editing::FapExportOptions{}));
    QVERIFY(FapReader::readFile(in.toStdString()).animation.frames ==
            FapReader::readFile(out.toStdString()).animation.frames);
    // With reduction: fewer keys, same file within a unit.
    QVERIFY(window().importFap(in, 0.5));
    QVERIFY(model().document().keys.keys().size() < 120);
    QVERIFY(window().exportFap(out, editing::FapExportOptions{}));
    const FapAnimation back = FapReader::readFile(out.toStdString()).animation;
    for (int i = 0; i < 120; ++i)
      for (int c = 0; c < kChannelCount; ++c)
        QVERIFY(std::abs(back.frames[i][c] - original.frames[i][c]) <= 1.0f);
  }

  void autosaveIsRecoveredAfterACrash() {
    QTemporaryDir dir;
    auto first = std::make_unique<MainWindow>(testOptions(dir.path()));
    first->show();
    first->model().setChannel(3, 250);
    first->model().setCurrentTime(2.0);
    first->presets()->apply(QStringLiteral("sad-crying"));
    first->autosaveNow();
    QVERIFY(first->recovery().hasFile());
    const ProjectDocument unsaved = first->model().document();
    // While the first editor runs, a second one offers nothing.
    {
      MainWindow second(testOptions(dir.path()));
      QVERIFY(second.recoveryBanner()->isHidden());
    }
    // Crash: the first editor goes away without closing (no clean exit).
    first.reset();
    MainWindow next(testOptions(dir.path()));
    next.show();
    QVERIFY(next.recoveryBanner()->isVisible());
    QTest::mouseClick(next.recoveryBanner()->restoreButton(), Qt::LeftButton);
    QVERIFY(next.model().document() == unsaved);
    QVERIFY(next.isWindowModified());
    QVERIFY(next.recoveryBanner()->isHidden());
    // Closing cleanly removes the recovery file.
    next.model().markSaved();
    next.close();
    QVERIFY(QDir(dir.path()).entryList({QStringLiteral("*.json")}, QDir::Files).isEmpty());
  }

  void autosaveRunsSoonAfterAChange() {
    QTemporaryDir dir;
    EditorOptions options = testOptions(dir.path());
    options.autosaveDelayMs = 50;
    MainWindow editor(options);
    editor.show();
    editor.model().setChannel(31, 100);
    QTRY_VERIFY(editor.recovery().hasFile());
    QVERIFY(editing::RecoveryStore::read(editor.recovery().filePath()) ==
            editor.model().document());
    // Undoing back to the saved state leaves nothing to recover.
    editor.model().undoStack()->undo();
    QTRY_VERIFY(!editor.recovery().hasFile());
    editor.close();
  }

  void discardingAnOfferRemovesIt() {
    QTemporaryDir dir;
    {
      editing::RecoveryStore crashed(dir.path());
      ProjectDocument doc;
      Keyframe key;
      key.set(3, 10);
      doc.keys.insert(key);
      crashed.save(doc, {});
    }
    MainWindow editor(testOptions(dir.path()));
    editor.show();
    QVERIFY(editor.recoveryBanner()->isVisible());
    QTest::mouseClick(editor.recoveryBanner()->discardButton(), Qt::LeftButton);
    QVERIFY(editor.recoveryBanner()->isHidden());
    QVERIFY(editor.model().document().keys.empty());
    QVERIFY(QDir(dir.path()).entryList({QStringLiteral("*.json")}, QDir::Files).isEmpty());
    editor.close();
  }

  // Ctrl+Z undoes the history of the workspace shown: the head's in Head, the animation's in
  // Animate, switched through the workspace tabs as a user does.
  void ctrlZFollowsTheWorkspaceShown() {
    setSpin(window().sliders()->row(3)->valueField(), 10);
    QUndoStack* animation = model().undoStack();
    QUndoStack* head = window().headWorkspace()->setup().undoStack();
    int headEdits = 0;
    head->push(new CountedEdit(headEdits));  // the stack owns its commands
    QCOMPARE(animation->index(), 1);
    QCOMPARE(headEdits, 1);
    auto* tabs = window().findChild<QTabBar*>(QStringLiteral("workspaces"));
    QVERIFY(tabs);

    // The History dock lists the steps of the workspace shown.
    auto* history = window().findChild<QUndoView*>();
    QVERIFY(history);
    QCOMPARE(history->stack(), animation);

    tabs->setCurrentIndex(static_cast<int>(MainWindow::Workspace::Head));
    QCOMPARE(window().workspace(), MainWindow::Workspace::Head);
    QCOMPARE(history->stack(), head);
    QTest::keySequence(&window(), QKeySequence::Undo);
    QCOMPARE(headEdits, 0);
    QCOMPARE(animation->index(), 1);

    tabs->setCurrentIndex(static_cast<int>(MainWindow::Workspace::Animate));
    QCOMPARE(history->stack(), animation);
    QTest::keySequence(&window(), QKeySequence::Undo);
    QCOMPARE(animation->index(), 0);
    QCOMPARE(headEdits, 0);
    QTest::keySequence(&window(), QKeySequence(QStringLiteral("Ctrl+Shift+Z")));
    QCOMPARE(animation->index(), 1);
    QCOMPARE(headEdits, 0);

    tabs->setCurrentIndex(static_cast<int>(MainWindow::Workspace::Head));
    QTest::keySequence(&window(), QKeySequence(QStringLiteral("Ctrl+Shift+Z")));
    QCOMPARE(headEdits, 1);
    QCOMPARE(animation->index(), 1);
  }

  // No text widens the window: a status as long as a rig warning with its path is cut to fit.
  void longStatusTextDoesNotWidenTheWindow() {
    window_->resize(1440, 900);
    auto* figures = window().findChild<viewport::ElidedLabel*>(QStringLiteral("statusFigures"));
    QVERIFY(figures);
    const QString warning = QStringLiteral(
        "ict.obj ready in 111 ms · 28716 vertices · 10 warning(s): /a/long/path/to/the/heads/"
        "ict.fdp.json:30:3: points: no feature point 6.1; FAP 43, 44, 45 will have no pose");
    figures->setText(warning + QLatin1Char(' ') + warning);
    QVERIFY(figures->fontMetrics().horizontalAdvance(figures->text()) > 1440);
    QVERIFY2(window().minimumSizeHint().width() <= 1440,
             qPrintable(QString::number(window().minimumSizeHint().width())));
    QCoreApplication::processEvents();
    QCOMPARE(window().width(), 1440);
    QVERIFY(figures->shownText().endsWith(QChar(0x2026)));  // cut, "…"
    QCOMPARE(figures->toolTip(), figures->text());          // and whole in the tooltip
  }

  // The default layout gives the dope sheet room for about ten channels, and its bar shows
  // its "Keys…" help whole.
  void theDopeSheetHasRoomInTheDefaultLayout() {
    QVERIFY(window().showAnimationView(QStringLiteral("dope")));
    QCoreApplication::processEvents();
    auto* view = window().dopeSheet()->findChild<DopeSheetView*>();
    QVERIFY(view);
    const double rows = (view->height() - DopeSheetView::kRulerHeight) / DopeSheetView::kRowHeight;
    QVERIFY2(rows >= 9, qPrintable(QString::number(rows)));
    QLabel* help = nullptr;
    for (QLabel* label : window().dopeSheet()->findChildren<QLabel*>())
      if (label->text() == QStringLiteral("Keys…")) help = label;
    QVERIFY(help);
    QVERIFY(help->width() >= help->sizeHint().width());
    QVERIFY(help->geometry().right() < window().dopeSheet()->width());
  }

  // A geometry saved wider and taller than the screen (a window once widened by its status)
  // opens fitted to the screen it opens on.
  void savedGeometryIsFittedToTheScreen() {
    const QRect screen = QGuiApplication::primaryScreen()->availableGeometry();
    QWidget huge;
    huge.setGeometry(screen.x() + 40, screen.y() + 40, screen.width() * 3, screen.height() * 2);
    QSettings().setValue(QStringLiteral("window/geometry"), huge.saveGeometry());
    MainWindow next(testOptions(recoveryDir_.path()));
    const QSize least = next.minimumSizeHint();
    QVERIFY(next.width() <= std::max(screen.width(), least.width()));
    QVERIFY(next.height() <= std::max(screen.height(), least.height()));
    QVERIFY(next.width() < screen.width() * 3);
    QSettings().remove(QStringLiteral("window/geometry"));
    // The rule itself: shrunk to the room, then moved inside it.
    QCOMPARE(fitRect(QRect(300, 50, 2124, 900), QRect(0, 0, 1600, 1000)), QRect(0, 50, 1600, 900));
    QCOMPARE(fitRect(QRect(900, 800, 1000, 600), QRect(0, 0, 1600, 1000), QSize(10, 30)),
             QRect(590, 370, 1000, 600));
    QCOMPARE(fitRect(QRect(-50, -20, 400, 300), QRect(0, 0, 1600, 1000)), QRect(0, 0, 400, 300));
  }

  // The Head workspace has the room (the animation's docks step aside), lists the anchors in the
  // manual's order, and its sliders pose without keying; Animate gets its docks and values back.
  void headWorkspaceHasRoomAndPosesWithoutKeys() {
    window_->resize(1440, 900);
    QCoreApplication::processEvents();
    auto* presets = window().findChild<QDockWidget*>(QStringLiteral("dock.presets"));
    auto* timeline = window().findChild<QDockWidget*>(QStringLiteral("dock.timeline"));
    QVERIFY(presets && timeline && presets->isVisible() && timeline->isVisible());
    window().setWorkspace(MainWindow::Workspace::Head);
    QCoreApplication::processEvents();
    QVERIFY(!presets->isVisible() && !timeline->isVisible());
    QVERIFY(window().sliders()->isVisible());
    head::HeadWorkspace* ws = window().headWorkspace();
    QVERIFY2(ws->viewport()->width() >= 480, qPrintable(QString::number(ws->viewport()->width())));
    auto* points = ws->findChild<QTableView*>(QStringLiteral("head.points"));
    QVERIFY(points);
    const int rowsShown = points->viewport()->height() / points->rowHeight(0);
    QVERIFY2(rowsShown >= 10, qPrintable(QString::number(rowsShown)));
    QCOMPARE(points->model()->index(0, 0).data().toString(), QStringLiteral("3.7"));
    QCOMPARE(points->model()->index(7, 0).data().toString(), QStringLiteral("2.10"));

    const int steps = model().undoStack()->count();
    setSpin(window().sliders()->row(3)->valueField(), 500);
    QCOMPARE(model().currentValue(3), 500.0f);
    QVERIFY(model().document().keys.keys().empty());
    QCOMPARE(model().undoStack()->count(), steps);
    QTest::keyClick(&window(), Qt::Key_K);  // K keys nothing here either
    QVERIFY(model().document().keys.keys().empty());
    ws->findChild<QToolButton*>(QStringLiteral("head.neutral"))->click();
    QCOMPARE(model().currentValue(3), 0.0f);
    setSpin(window().sliders()->row(3)->valueField(), 300);

    window().setWorkspace(MainWindow::Workspace::Animate);
    QCoreApplication::processEvents();
    QVERIFY(presets->isVisible() && timeline->isVisible());
    QCOMPARE(model().currentValue(3), 0.0f);  // the pose is gone, the animation is as it was
    QCOMPARE(window().sliders()->row(3)->valueField()->value(), 0.0);
    setSpin(window().sliders()->row(3)->valueField(), 200);  // Animate keys again
    QCOMPARE(model().document().keys.keys().size(), std::size_t{1});
  }

  void spaceTogglesPlayback() {
    setSpin(window().sliders()->row(3)->valueField(), 10);
    model().setCurrentTime(1.0);
    setSpin(window().sliders()->row(3)->valueField(), 220);
    model().setCurrentTime(0.0);
    QTest::keyClick(&window(), Qt::Key_Space);
    QVERIFY(window().clock().isPlaying());
    QTRY_VERIFY(model().currentTime() > 0.1);
    QTest::keyClick(&window(), Qt::Key_Space);
    QVERIFY(!window().clock().isPlaying());
    // Stopping lands on a frame.
    const double frames = model().currentTime() * 22.0;
    QCOMPARE(frames, std::round(frames));
  }
};

QTEST_MAIN(EditorWindowTest)
#include "EditorWindowTest.moc"
