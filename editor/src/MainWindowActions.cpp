// MainWindow: its actions, each with its name ("file.save"), text, shortcut and what it does.
// Where they are offered (menus, toolbar) is MainMenus.cpp's business.
#include "MainWindowPrivate.h"

#include <lacrima/editor/PreviewPanel.h>
#include <lacrima/editor/SliderPanel.h>
#include <lacrima/editor/TimelineWidget.h>
#include <lacrima/editor/TransportBar.h>

#include <lacrima/editor/LiveRecording.h>
#include <lacrima/editor/MoodGenerationDialog.h>
#include <lacrima/editor/RecordLiveDialog.h>
#include <lacrima/live/ListenUrl.h>

#include <QAction>
#include <QLineEdit>
#include <QMessageBox>
#include <QSignalBlocker>
#include <QStatusBar>
#include <QUndoGroup>

#include <algorithm>
#include <tuple>
#include <utility>

namespace lacrima::editor {

QAction* MainWindow::makeAction(const QString& name, const QString& text,
                                const QKeySequence& shortcut, const QString& tip) {
  auto* a = new QAction(text, this);
  a->setObjectName(name);
  if (!shortcut.isEmpty()) a->setShortcut(shortcut);
  a->setShortcutContext(Qt::WindowShortcut);
  if (!tip.isEmpty()) a->setStatusTip(tip);
  addAction(a);  // shortcuts work even when the menu bar is hidden
  return a;
}

void MainWindow::createActions() {
  editing::EditorModel& m = *d_->model;
  connect(makeAction(QStringLiteral("file.new"), tr("&New"), QKeySequence::New),
          &QAction::triggered, this, [this] {
            if (maybeSave()) newDocument();
          });
  connect(makeAction(QStringLiteral("file.open"), tr("&Open…"), QKeySequence::Open),
          &QAction::triggered, this, &MainWindow::openDialog);
  connect(makeAction(QStringLiteral("file.save"), tr("&Save"), QKeySequence::Save),
          &QAction::triggered, this, [this] {
            if (d_->filePath.isEmpty())
              saveDialog();
            else
              saveTo(d_->filePath);
          });
  connect(makeAction(QStringLiteral("file.saveAs"), tr("Save &As…"),
                     QKeySequence(QStringLiteral("Ctrl+Shift+S"))),
          &QAction::triggered, this, &MainWindow::saveDialog);
  connect(makeAction(QStringLiteral("file.import"), tr("&Import FAP…"),
                     QKeySequence(QStringLiteral("Ctrl+I")),
                     tr("Read a .fap file: its frames become keys, optionally reduced")),
          &QAction::triggered, this, &MainWindow::importDialog);
  connect(
      makeAction(
          QStringLiteral("file.export"), tr("&Export FAP…"), QKeySequence(QStringLiteral("Ctrl+E")),
          tr("Bake the keys to a .fap file (22 fps; with tear channels, or strict 68 FAPs)")),
      &QAction::triggered, this, &MainWindow::exportDialog);
  connect(makeAction(QStringLiteral("file.exportAnimation"), tr("Export &Animation…"),
                     QKeySequence(QStringLiteral("Ctrl+Shift+E")),
                     tr("The animation with its tears as glTF, H.264 video, PNG images or PLY tear "
                        "meshes, as the player exports it")),
          &QAction::triggered, this, &MainWindow::exportAnimationDialog);
  connect(makeAction(QStringLiteral("file.chooseHead"), tr("Choose &head…"), {},
                     tr("The mesh and feature-point file this project is animated on")),
          &QAction::triggered, this, &MainWindow::chooseHeadDialog);
  connect(makeAction(QStringLiteral("file.quit"), tr("&Quit"), QKeySequence::Quit),
          &QAction::triggered, this, &QWidget::close);

  QAction* undo = d_->undoGroup->createUndoAction(this, tr("&Undo"));
  undo->setObjectName(QStringLiteral("edit.undo"));
  undo->setShortcut(QKeySequence::Undo);
  QAction* redo = d_->undoGroup->createRedoAction(this, tr("&Redo"));
  redo->setObjectName(QStringLiteral("edit.redo"));
  redo->setShortcuts(
      {QKeySequence(QStringLiteral("Ctrl+Shift+Z")), QKeySequence(QStringLiteral("Ctrl+Y"))});
  addAction(undo);
  addAction(redo);
  connect(makeAction(QStringLiteral("edit.copy"), tr("&Copy keys"), QKeySequence::Copy),
          &QAction::triggered, this, &MainWindow::copyKeys);
  connect(
      makeAction(QStringLiteral("edit.paste"), tr("&Paste keys at playhead"), QKeySequence::Paste),
      &QAction::triggered, this, [this] { pasteKeys(); });
  QAction* del =
      makeAction(QStringLiteral("edit.delete"), tr("&Delete keys"), QKeySequence::Delete);
  del->setShortcuts({QKeySequence::Delete, QKeySequence(Qt::Key_Backspace)});
  connect(del, &QAction::triggered, this, [this] {
    if (!d_->model->selectedTimes().empty())
      d_->model->deleteSelectedKeys();
    else if (d_->model->currentKeyIndex() >= 0)
      d_->model->deleteKeys({d_->model->currentTime()});
  });
  connect(
      makeAction(QStringLiteral("edit.selectAll"), tr("Select &all keys"), QKeySequence::SelectAll),
      &QAction::triggered, &m, &editing::EditorModel::selectAll);
  connect(makeAction(QStringLiteral("edit.mirror"), tr("&Mirror left ↔ right"),
                     QKeySequence(QStringLiteral("Ctrl+M")),
                     tr("Mirror the selected keys, or the pose at the playhead")),
          &QAction::triggered, &m, &editing::EditorModel::mirror);
  QAction* symmetric =
      makeAction(QStringLiteral("edit.symmetric"), tr("S&ymmetric editing"),
                 QKeySequence(QStringLiteral("Ctrl+Shift+M")),
                 tr("Moving a left or right channel moves its mirror channel too"));
  symmetric->setCheckable(true);
  connect(symmetric, &QAction::toggled, &m, &editing::EditorModel::setSymmetricEdit);
  connect(&m, &editing::EditorModel::symmetricEditChanged, symmetric, &QAction::setChecked);
  connect(makeAction(QStringLiteral("edit.settings"), tr("Project &settings…"),
                     QKeySequence(QStringLiteral("Ctrl+,"))),
          &QAction::triggered, this, &MainWindow::settingsDialog);

  connect(makeAction(QStringLiteral("key.add"), tr("&Add key (whole pose)"),
                     QKeySequence(Qt::Key_K), tr("Key every animated channel at the playhead")),
          &QAction::triggered, &m, &editing::EditorModel::addKey);
  const auto targets = [this] {
    std::vector<double> t = d_->model->selectedTimes();
    if (t.empty() && d_->model->currentKeyIndex() >= 0) t.push_back(d_->model->currentTime());
    return t;
  };
  connect(makeAction(QStringLiteral("key.linear"), tr("Make &linear"), QKeySequence(Qt::Key_L)),
          &QAction::triggered, this,
          [this, targets] { d_->model->setInterpolation(targets(), Interpolation::Linear); });
  connect(makeAction(QStringLiteral("key.smooth"), tr("Make s&mooth"), QKeySequence(Qt::Key_S)),
          &QAction::triggered, this,
          [this, targets] { d_->model->setInterpolation(targets(), Interpolation::Smooth); });
  connect(
      makeAction(QStringLiteral("key.previous"), tr("&Previous key"), QKeySequence(Qt::Key_Comma)),
      &QAction::triggered, this,
      [this] { d_->model->setCurrentTime(previousKeyTime(*d_->model)); });
  connect(makeAction(QStringLiteral("key.next"), tr("&Next key"), QKeySequence(Qt::Key_Period)),
          &QAction::triggered, this,
          [this] { d_->model->setCurrentTime(nextKeyTime(*d_->model)); });

  connect(
      makeAction(QStringLiteral("play.toggle"), tr("&Play / pause"), QKeySequence(Qt::Key_Space)),
      &QAction::triggered, d_->clock.get(), &editing::FrameStepClock::toggle);
  connect(makeAction(QStringLiteral("play.start"), tr("Go to &start"), QKeySequence(Qt::Key_Home)),
          &QAction::triggered, this,
          [this] { d_->model->setCurrentTime(d_->model->document().keys.startTime()); });
  connect(makeAction(QStringLiteral("play.end"), tr("Go to &end"), QKeySequence(Qt::Key_End)),
          &QAction::triggered, this, [this] { d_->model->setCurrentTime(d_->model->endTime()); });
  connect(makeAction(QStringLiteral("play.previousFrame"), tr("Previous &frame"),
                     QKeySequence(Qt::Key_Left)),
          &QAction::triggered, this, [this] {
            d_->model->setCurrentTime(d_->model->currentTime() - d_->model->frameDuration());
          });
  connect(
      makeAction(QStringLiteral("play.nextFrame"), tr("&Next frame"), QKeySequence(Qt::Key_Right)),
      &QAction::triggered, this,
      [this] { d_->model->setCurrentTime(d_->model->currentTime() + d_->model->frameDuration()); });
  // Blender's and Maya's "go to frame": type a time or frame into the transport's time field.
  connect(makeAction(QStringLiteral("play.goToTime"), tr("&Go to time…"),
                     QKeySequence(QStringLiteral("Ctrl+G"))),
          &QAction::triggered, d_->transport, &TransportBar::editTime);

  // Generate crying: the crying generator's take as keys over a range (docs/mood.md).
  connect(makeAction(QStringLiteral("anim.generateCrying"), tr("&Generate crying…"), QKeySequence(),
                     tr("Keys from the crying generator over a range: moods, intensities, seed")),
          &QAction::triggered, this, &MainWindow::openGenerateCrying);

  // Record live: asks where to listen, counts in, records; the same action stops and keys.
  d_->liveRecording = new LiveRecording(m, this);
  QAction* record = makeAction(QStringLiteral("play.recordLive"), tr("&Record live…"),
                               QKeySequence(QStringLiteral("Ctrl+R")),
                               tr("Turn a live stream into keys from the playhead, after a "
                                  "count-in; the selected channels, or all the stream sets"));
  record->setCheckable(true);
  connect(d_->liveRecording, &LiveRecording::message, this,
          [this](const QString& text) { statusBar()->showMessage(text, 8000); });
  connect(d_->liveRecording, &LiveRecording::stateChanged, this,
          [record](LiveRecording::State state) {
            const QSignalBlocker block(record);
            record->setChecked(state != LiveRecording::State::Idle);
          });
  connect(record, &QAction::triggered, this, [this, record] {
    if (d_->liveRecording->state() != LiveRecording::State::Idle) {
      d_->liveRecording->stop();
      return;
    }
    record->setChecked(false);
    if (!d_->options.interactive) return;
    const ChannelMask selected = d_->model->selectedChannels();
    RecordLiveDialog dialog(d_->recordSettings, selected, this);
    if (dialog.exec() != QDialog::Accepted) return;
    d_->recordSettings = dialog.settings();
    QString error;
    const std::optional<live::ListenUrl> url = live::parseListenUrl(d_->recordSettings.url, error);
    const std::optional<ChannelMask> channels = recordedChannels(d_->recordSettings, selected);
    try {
      if (!url) throw std::runtime_error(error.toStdString());
      if (!channels) throw std::runtime_error(tr("no channel to key").toStdString());
      d_->liveRecording->start(*url, *channels, d_->recordSettings.countIn);
    } catch (const std::exception& e) {
      reportError(tr("Cannot record"), QString::fromStdString(e.what()));
    }
  });

  QAction* tears = makeAction(QStringLiteral("view.tearPreview"), tr("&Tear preview"),
                              QKeySequence(Qt::Key_T), tr("Simulate the tears while paused"));
  tears->setCheckable(true);
  tears->setChecked(d_->preview->tearPreview());
  connect(tears, &QAction::toggled, d_->preview, &PreviewPanel::setTearPreview);
  connect(
      makeAction(QStringLiteral("view.frameAll"), tr("&Frame all keys"), QKeySequence(Qt::Key_F)),
      &QAction::triggered, d_->timeline, &TimelineWidget::fitAll);
  connect(makeAction(QStringLiteral("view.filter"), tr("Find &channel"), QKeySequence::Find),
          &QAction::triggered, this, [this] {
            d_->sliders->filterBox()->setFocus();
            d_->sliders->filterBox()->selectAll();
          });
  connect(makeAction(QStringLiteral("view.animate"), tr("&Animate workspace"),
                     QKeySequence(QStringLiteral("Ctrl+1"))),
          &QAction::triggered, this, [this] { setWorkspace(Workspace::Animate); });
  connect(makeAction(QStringLiteral("view.head"), tr("&Head workspace"),
                     QKeySequence(QStringLiteral("Ctrl+2")),
                     tr("Import your own head, place its feature points and rig it")),
          &QAction::triggered, this, [this] { setWorkspace(Workspace::Head); });

  connect(makeAction(QStringLiteral("help.shortcuts"), tr("&Keyboard shortcuts"),
                     QKeySequence::HelpContents),
          &QAction::triggered, this, &MainWindow::showShortcuts);
}

LiveRecording& MainWindow::liveRecording() { return *d_->liveRecording; }

MoodGenerationDialog* MainWindow::openGenerateCrying() {
  const editing::EditorModel& m = *d_->model;
  const std::vector<double>& selected = m.selectedTimes();
  // The whole take, as far as its keys or its mood curves reach.
  const double last = std::max(m.endTime(), m.document().moods.endTime());
  double start = 0, end = last > 0 ? last : 10;
  if (selected.size() >= 2) {
    const auto [low, high] = std::minmax_element(selected.begin(), selected.end());
    if (*high > *low) std::tie(start, end) = std::pair{*low, *high};
  }
  auto* dialog = new MoodGenerationDialog(start, end, m.document().fps, &m.document().moods, this);
  dialog->setAttribute(Qt::WA_DeleteOnClose);
  connect(dialog, &QDialog::accepted, this, [this, dialog] {
    if (!generateCrying(dialog->request(), dialog->asLayer()) && d_->options.interactive)
      QMessageBox::warning(this, tr("Generate crying"), d_->lastError);
  });
  dialog->open();
  return dialog;
}

bool MainWindow::generateCrying(const editing::MoodGenerationRequest& request, bool asLayer) {
  try {
    if (asLayer) {
      d_->model->addMoodLayer(request);
      statusBar()->showMessage(tr("Added a crying layer from %1 s to %2 s, seed %3: it follows "
                                  "the mood curves (graph editor, Moods)")
                                   .arg(request.start)
                                   .arg(request.end)
                                   .arg(request.seed),
                               8000);
      return true;
    }
    const editing::MoodGenerationPlan plan =
        editing::planMoodGeneration(d_->model->document().keys, request);
    d_->model->editKeys(plan.change, tr("Generate crying"));
    statusBar()->showMessage(tr("Generated crying from %1 s to %2 s: %3 frames kept as %4 keys")
                                 .arg(request.start)
                                 .arg(request.end)
                                 .arg(plan.frames)
                                 .arg(plan.keys),
                             8000);
    return true;
  } catch (const std::exception& e) {
    d_->lastError =
        (asLayer ? tr("Cannot add the crying layer: %1") : tr("Cannot generate crying: %1"))
            .arg(QString::fromUtf8(e.what()));
    statusBar()->showMessage(d_->lastError, 8000);
    return false;
  }
}

}  // namespace lacrima::editor
