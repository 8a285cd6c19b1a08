// MainWindow: its layout, workspaces, status figures, clipboard and project settings.
#include "MainMenus.h"
#include "MainWindowPrivate.h"

#include <lacrima/common/FapTable.h>
#include <lacrima/editing/HeadSetup.h>
#include <lacrima/editing/KeyClipboard.h>
#include <lacrima/editor/DopeSheet.h>
#include <lacrima/editor/GraphEditor.h>
#include <lacrima/editor/KeyListPanel.h>
#include <lacrima/editor/LayerPanel.h>
#include <lacrima/editor/NumberField.h>
#include <lacrima/editor/PresetPanel.h>
#include <lacrima/editor/PreviewPanel.h>
#include <lacrima/editor/RecoveryBanner.h>
#include <lacrima/editor/SliderPanel.h>
#include <lacrima/editor/TimelineWidget.h>
#include <lacrima/editor/TransportBar.h>
#include <lacrima/editor/WindowFit.h>
#include <lacrima/editor/head/HeadWorkspace.h>
#include <lacrima/viewport/EffectsPanel.h>
#include <lacrima/viewport/ElidedLabel.h>

#include <QApplication>
#include <QClipboard>
#include <QComboBox>
#include <QDialog>
#include <QDialogButtonBox>
#include <QDockWidget>
#include <QFileInfo>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QSettings>
#include <QStackedWidget>
#include <QStatusBar>
#include <QTabBar>
#include <QTabWidget>
#include <QTimer>
#include <QUndoGroup>
#include <QUndoView>
#include <QVBoxLayout>

#include <algorithm>

namespace lacrima::editor {

MainWindow::MainWindow(EditorOptions options, QWidget* parent)
    : QMainWindow(parent), d_(std::make_unique<Private>(std::move(options))) {
  setObjectName(QStringLiteral("lacrimaEditor"));
  setAcceptDrops(true);
  setDockNestingEnabled(true);
  createDocks();
  // One history per workspace, the one shown active (setWorkspace).
  d_->undoGroup = new QUndoGroup(this);
  d_->undoGroup->addStack(d_->model->undoStack());
  d_->undoGroup->addStack(d_->headWorkspace->setup().undoStack());
  d_->undoGroup->setActiveStack(d_->model->undoStack());
  d_->history->setGroup(d_->undoGroup);  // the History dock shows the active workspace's steps
  createActions();
  d_->recentMenu = buildMainMenus(*this, [this](const QString& name) { return action(name); });
  rebuildRecentMenu();

  // The figures repeat the preview's status, which can be long: cut to fit, never wider.
  d_->figures = new viewport::ElidedLabel(this);
  d_->figures->setObjectName(QStringLiteral("statusFigures"));
  d_->figures->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
  d_->figures->setSizePolicy(QSizePolicy::Preferred, QSizePolicy::Preferred);
  d_->figures->setMaximumWidth(720);  // the status bar's messages keep the rest
  statusBar()->addPermanentWidget(d_->figures);

  d_->autosaveSoon = new QTimer(this);
  d_->autosaveSoon->setSingleShot(true);
  d_->autosaveSoon->setInterval(d_->options.autosaveDelayMs);
  connect(d_->autosaveSoon, &QTimer::timeout, this, &MainWindow::autosaveNow);
  d_->autosavePeriodic = new QTimer(this);
  d_->autosavePeriodic->setInterval(d_->options.autosaveIntervalMs);
  connect(d_->autosavePeriodic, &QTimer::timeout, this, [this] {
    if (d_->autosaveDirty) autosaveNow();
  });
  d_->autosavePeriodic->start();

  connect(d_->model->undoStack(), &QUndoStack::indexChanged, this, &MainWindow::onDocumentChanged);
  connect(d_->model->undoStack(), &QUndoStack::cleanChanged, this, &MainWindow::updateTitle);
  connect(d_->model.get(), &editing::EditorModel::documentReset, this, &MainWindow::updateTitle);
  connect(d_->model.get(), &editing::EditorModel::settingsChanged, this, &MainWindow::updateTitle);
  connect(d_->model.get(), &editing::EditorModel::keysChanged, this,
          &MainWindow::updateStatusFigures);
  connect(d_->model.get(), &editing::EditorModel::settingsChanged, this,
          &MainWindow::updateStatusFigures);
  connect(d_->model.get(), &editing::EditorModel::message, this,
          [this](const QString& text) { statusBar()->showMessage(text, 5000); });
  connect(d_->clock.get(), &editing::FrameStepClock::playingChanged, this,
          &MainWindow::updateStatusFigures);

  QSettings settings;
  resize(1440, 900);
  restoreGeometry(settings.value(QStringLiteral("window/geometry")).toByteArray());
  d_->docksSized = restoreState(settings.value(QStringLiteral("window/state")).toByteArray());
  // The default size, or one saved on a larger screen, fitted to the screen it opens on.
  fitToScreen(*this);

  newDocument();
  if (d_->options.offerRecovery) checkForRecovery();
  if (d_->options.preview) QTimer::singleShot(0, d_->preview, &PreviewPanel::followDocumentHead);
  statusBar()->showMessage(
      tr("Move a slider to key it at the playhead · K keys the whole pose · Space plays"), 8000);
}

MainWindow::~MainWindow() {
  // The widgets and this window's slots refer to the model and the clock, which are members
  // and so die before the widgets would: cut the window's connections, then let the widgets go.
  d_->clock->pause();
  disconnect(d_->model.get(), nullptr, this, nullptr);
  disconnect(d_->model->undoStack(), nullptr, this, nullptr);
  disconnect(d_->clock.get(), nullptr, this, nullptr);
  delete takeCentralWidget();
  const auto docks = findChildren<QDockWidget*>();
  for (QDockWidget* dock : docks) delete dock;
}

void MainWindow::setWorkspace(Workspace workspace) {
  const Workspace before = this->workspace();
  d_->workspaceStack->setCurrentIndex(static_cast<int>(workspace));
  if (workspace != before) arrangeDocks(workspace);
  // Checking a rig is not animating: in the Head workspace the sliders pose without keys.
  d_->model->setPosingOnly(workspace == Workspace::Head);
  const QSignalBlocker block(d_->workspaces);
  d_->workspaces->setCurrentIndex(static_cast<int>(workspace));
  // Edit ▸ Undo and Redo (and their shortcuts) act on the history of the workspace shown.
  d_->undoGroup->setActiveStack(workspace == Workspace::Head
                                    ? d_->headWorkspace->setup().undoStack()
                                    : d_->model->undoStack());
}

// The Head workspace needs the room: its viewport, parts, points, reference picture and checks
// beside the channels. The presets, keys, layers, history and timeline act on the animation, so
// they step aside there and come back as they were.
void MainWindow::arrangeDocks(Workspace workspace) {
  if (workspace == Workspace::Head) {
    d_->animateLayout = saveState();
    for (QDockWidget* dock : findChildren<QDockWidget*>())
      if (dock->objectName() != QLatin1String("dock.channels")) dock->hide();
  } else if (!d_->animateLayout.isEmpty()) {
    restoreState(d_->animateLayout);
    d_->animateLayout.clear();
  }
}

QByteArray MainWindow::animateLayout() const {
  return d_->animateLayout.isEmpty() ? saveState() : d_->animateLayout;
}

MainWindow::Workspace MainWindow::workspace() const {
  return static_cast<Workspace>(d_->workspaceStack->currentIndex());
}

QAction* MainWindow::action(const QString& name) const { return findChild<QAction*>(name); }

editing::EditorModel& MainWindow::model() { return *d_->model; }
editing::FrameStepClock& MainWindow::clock() { return *d_->clock; }
editing::RecoveryStore& MainWindow::recovery() { return *d_->recovery; }
SliderPanel* MainWindow::sliders() const { return d_->sliders; }
TimelineWidget* MainWindow::timeline() const { return d_->timeline; }
LayerPanel* MainWindow::layers() const { return d_->layers; }
GraphEditor* MainWindow::graphEditor() const { return d_->graphEditor; }
QTabWidget* MainWindow::animationViews() const { return d_->animationViews; }
DopeSheet* MainWindow::dopeSheet() const { return d_->dopeSheet; }
TransportBar* MainWindow::transport() const { return d_->transport; }
PresetPanel* MainWindow::presets() const { return d_->presets; }
PreviewPanel* MainWindow::preview() const { return d_->preview; }
KeyListPanel* MainWindow::keyList() const { return d_->keyList; }
RecoveryBanner* MainWindow::recoveryBanner() const { return d_->banner; }
head::HeadWorkspace* MainWindow::headWorkspace() const { return d_->headWorkspace; }
QString MainWindow::filePath() const { return d_->filePath; }
QString MainWindow::lastError() const { return d_->lastError; }

bool MainWindow::showAnimationView(const QString& name) {
  const bool moods = name == QLatin1String("moods");
  QWidget* view = name == QLatin1String("keys")             ? static_cast<QWidget*>(d_->timeline)
                  : name == QLatin1String("dope")           ? static_cast<QWidget*>(d_->dopeSheet)
                  : name == QLatin1String("graph") || moods ? static_cast<QWidget*>(d_->graphEditor)
                                                            : nullptr;
  if (!view) return false;
  d_->animationViews->setCurrentWidget(view);
  d_->graphEditor->setMoodsShown(moods);
  return true;
}

void MainWindow::createDocks() {
  editing::PresetLibrary library;
  QString presetsSource = QString::fromUtf8(editing::PresetLibrary::kBuiltInPath.data());
  try {
    if (!d_->options.presetsPath.isEmpty()) {
      library = editing::PresetLibrary::load(d_->options.presetsPath.toStdString());
      presetsSource = d_->options.presetsPath;
    }
  } catch (const FileError& e) {
    // Reported by the caller (lastError()); the built-in set is used.
    d_->lastError = QString::fromUtf8(e.what());
  }
  if (presetsSource.startsWith(QLatin1Char(':'))) library = editing::PresetLibrary::builtIn();

  // Centre: the recovery offer above the preview.
  auto* centre = new QWidget(this);
  auto* centreLayout = new QVBoxLayout(centre);
  centreLayout->setContentsMargins(0, 0, 0, 0);
  centreLayout->setSpacing(0);
  d_->banner = new RecoveryBanner(centre);
  d_->banner->hide();
  d_->preview = new PreviewPanel(*d_->model, *d_->clock, centre);
  d_->preview->setSimulationThreads(d_->options.simulationThreads);
  centreLayout->addWidget(d_->banner);
  centreLayout->addWidget(d_->preview, 1);
  // Over the centre: Animate (the preview) | Head (import and rig your own head).
  auto* workspaces = new QWidget(this);
  auto* workspacesLayout = new QVBoxLayout(workspaces);
  workspacesLayout->setContentsMargins(0, 0, 0, 0);
  workspacesLayout->setSpacing(0);
  d_->workspaces = new QTabBar(workspaces);
  d_->workspaces->setObjectName(QStringLiteral("workspaces"));
  d_->workspaces->addTab(tr("Animate"));
  d_->workspaces->addTab(tr("Head"));
  d_->workspaceStack = new QStackedWidget(workspaces);
  d_->workspaceStack->addWidget(centre);
  d_->headWorkspace = new head::HeadWorkspace(*d_->model, d_->workspaceStack);
  d_->headWorkspace->setInteractive(d_->options.interactive);
  d_->workspaceStack->addWidget(d_->headWorkspace);
  workspacesLayout->addWidget(d_->workspaces);
  workspacesLayout->addWidget(d_->workspaceStack, 1);
  setCentralWidget(workspaces);
  connect(d_->workspaces, &QTabBar::currentChanged, this,
          [this](int index) { setWorkspace(static_cast<Workspace>(index)); });
  connect(d_->headWorkspace, &head::HeadWorkspace::useInProjectRequested, this,
          [this](const QString& mesh, const QString& fdp) {
            if (!setHead(mesh, fdp)) return;
            setWorkspace(Workspace::Animate);
            statusBar()->showMessage(tr("The project now uses %1").arg(QFileInfo(mesh).fileName()),
                                     5000);
          });
  connect(d_->banner, &RecoveryBanner::restoreRequested, this, &MainWindow::restoreRecovery);
  connect(d_->banner, &RecoveryBanner::discardRequested, this, &MainWindow::discardRecovery);

  const auto dock = [this](const QString& title, const QString& name, QWidget* content,
                           Qt::DockWidgetArea area) {
    auto* d = new QDockWidget(title, this);
    d->setObjectName(name);
    d->setWidget(content);
    d->setFeatures(QDockWidget::DockWidgetMovable | QDockWidget::DockWidgetFloatable |
                   QDockWidget::DockWidgetClosable);
    addDockWidget(area, d);
    return d;
  };

  d_->sliders = new SliderPanel(*d_->model, this);
  QDockWidget* channels =
      dock(tr("Channels"), QStringLiteral("dock.channels"), d_->sliders, Qt::LeftDockWidgetArea);
  d_->sliders->setMinimumWidth(430);

  d_->presets = new PresetPanel(*d_->model, std::move(library), this);
  d_->presets->setLibrary(d_->presets->library(), presetsSource);
  QDockWidget* presetDock =
      dock(tr("Presets"), QStringLiteral("dock.presets"), d_->presets, Qt::RightDockWidgetArea);
  d_->keyList = new KeyListPanel(*d_->model, this);
  QDockWidget* keysDock =
      dock(tr("Keys"), QStringLiteral("dock.keys"), d_->keyList, Qt::RightDockWidgetArea);
  d_->layers = new LayerPanel(*d_->model, this);
  QDockWidget* layersDock =
      dock(tr("Layers"), QStringLiteral("dock.layers"), d_->layers, Qt::RightDockWidgetArea);
  d_->history = new QUndoView(d_->model->undoStack(), this);
  d_->history->setEmptyLabel(tr("<opened>"));
  QDockWidget* historyDock =
      dock(tr("History"), QStringLiteral("dock.history"), d_->history, Qt::RightDockWidgetArea);
  // Presets above, the key table and the history tabbed below them.
  splitDockWidget(presetDock, keysDock, Qt::Vertical);
  tabifyDockWidget(keysDock, layersDock);
  tabifyDockWidget(keysDock, historyDock);
  keysDock->raise();
  resizeDocks({presetDock, keysDock}, {470, 200}, Qt::Vertical);
  presetDock->setMinimumWidth(280);

  auto* timelineBox = new QWidget(this);
  auto* timelineLayout = new QVBoxLayout(timelineBox);
  timelineLayout->setContentsMargins(0, 0, 0, 0);
  timelineLayout->setSpacing(0);
  d_->transport = new TransportBar(*d_->model, *d_->clock, timelineBox);
  // The animation views share the space under the transport: the key rows (the timeline), and
  // per-channel views beside it.
  d_->animationViews = new QTabWidget(timelineBox);
  d_->animationViews->setDocumentMode(true);
  d_->timeline = new TimelineWidget(*d_->model, d_->animationViews);
  d_->animationViews->addTab(d_->timeline, tr("Keys"));
  d_->dopeSheet = new DopeSheet(*d_->model, d_->animationViews);
  d_->animationViews->addTab(d_->dopeSheet, tr("Dope sheet"));
  d_->graphEditor = new GraphEditor(*d_->model, d_->animationViews);
  d_->animationViews->addTab(d_->graphEditor, tr("Graph"));
  timelineLayout->addWidget(d_->transport);
  timelineLayout->addWidget(d_->animationViews, 1);
  QDockWidget* timelineDock =
      dock(tr("Timeline"), QStringLiteral("dock.timeline"), timelineBox, Qt::BottomDockWidgetArea);
  // The timeline spans the whole width, under the channel list too.
  setCorner(Qt::BottomLeftCorner, Qt::BottomDockWidgetArea);
  setCorner(Qt::BottomRightCorner, Qt::BottomDockWidgetArea);
  resizeDocks({timelineDock}, {300}, Qt::Vertical);  // room for the dope sheet and graph
  resizeDocks({channels, presetDock}, {470, 330}, Qt::Horizontal);

  // A time typed and entered (Ctrl+G, "2.5", Enter) hands the keys back to the animation view,
  // so K keys there instead of typing "k" into the field.
  connect(d_->transport->timeField(), &NumberField::entered, this,
          [this] { d_->animationViews->currentWidget()->setFocus(Qt::OtherFocusReason); });
  connect(d_->timeline, &TimelineWidget::copyRequested, this, &MainWindow::copyKeys);
  connect(d_->timeline, &TimelineWidget::pasteRequested, this,
          [this](double at) { pasteKeys(at); });
  connect(d_->timeline, &TimelineWidget::mirrorRequested, d_->model.get(),
          &editing::EditorModel::mirror);
  connect(d_->presets, &PresetPanel::loadRequested, this, &MainWindow::loadPresetsDialog);
  connect(d_->sliders, &SliderPanel::expressionPresetRequested, this, [this](int code) {
    if (const editing::Preset* preset = d_->presets->library().forExpression(code)) {
      d_->model->applyPreset(*preset, d_->presets->intensity(), d_->presets->replacesPose());
    } else {
      statusBar()->showMessage(tr("The presets file has no pose for expression %1").arg(code),
                               5000);
    }
  });
  connect(d_->preview, &PreviewPanel::statusChanged, this, &MainWindow::updateStatusFigures);
}

void MainWindow::showEvent(QShowEvent* event) {
  QMainWindow::showEvent(event);
  if (d_->docksSized) return;
  d_->docksSized = true;
  // The timeline under the transport gets over a third of the height, so the dope sheet shows
  // about ten channels at 1440x900.
  if (auto* timeline = findChild<QDockWidget*>(QStringLiteral("dock.timeline")))
    resizeDocks({timeline}, {std::max(300, height() * 2 / 5)}, Qt::Vertical);
  // Of the column beside the face, the presets keep what their list needs first.
  auto* presets = findChild<QDockWidget*>(QStringLiteral("dock.presets"));
  auto* keys = findChild<QDockWidget*>(QStringLiteral("dock.keys"));
  if (presets && keys) resizeDocks({presets, keys}, {330, 110}, Qt::Vertical);
}

void MainWindow::updateTitle() {
  const QString name = d_->filePath.isEmpty() ? QString::fromStdString(d_->model->document().name)
                                              : QFileInfo(d_->filePath).fileName();
  setWindowTitle(QStringLiteral("%1[*] — Lacrima Editor").arg(name));
  setWindowModified(d_->model->isModified());
}

void MainWindow::updateStatusFigures() {
  const ProjectDocument& doc = d_->model->document();
  QString text = tr("%1 fps · %n keys · %2 s", nullptr, static_cast<int>(doc.keys.keys().size()))
                     .arg(doc.fps)
                     .arg(doc.keys.endTime(), 0, 'f', 2);
  if (d_->clock->isPlaying()) text += tr(" · playing at %1 fps").arg(d_->clock->rate());
  if (d_->preview && !d_->preview->statusText().isEmpty())
    text += QStringLiteral(" · ") + d_->preview->statusText();
  d_->figures->setText(text);
}

void MainWindow::onDocumentChanged() {
  updateTitle();
  d_->autosaveDirty = true;
  d_->autosaveSoon->start();
}

void MainWindow::copyKeys() {
  std::vector<double> times = d_->model->selectedTimes();
  if (times.empty() && d_->model->currentKeyIndex() >= 0) times.push_back(d_->model->currentTime());
  if (times.empty()) {
    statusBar()->showMessage(tr("Select keys to copy (click them in the timeline)"), 4000);
    return;
  }
  QApplication::clipboard()->setMimeData(
      editing::keysToMimeData(editing::copyKeys(d_->model->document().keys, times)));
  statusBar()->showMessage(tr("Copied %n key(s)", nullptr, static_cast<int>(times.size())), 3000);
}

void MainWindow::pasteKeys(std::optional<double> at) {
  const auto clip = editing::keysFromMimeData(QApplication::clipboard()->mimeData());
  if (!clip) {
    statusBar()->showMessage(tr("The clipboard holds no keys"), 4000);
    return;
  }
  d_->model->pasteKeys(*clip, at.value_or(d_->model->currentTime()));
}

void MainWindow::settingsDialog() {
  if (!d_->options.interactive) return;
  const ProjectDocument& doc = d_->model->document();
  QDialog dialog(this);
  dialog.setWindowTitle(tr("Project settings"));
  auto* form = new QFormLayout(&dialog);
  auto* name = new QLineEdit(QString::fromStdString(doc.name), &dialog);
  auto* fps = new NumberField(&dialog);
  fps->setRange({1, 240, false, tr("fps")});
  fps->setSubject(tr("the frame rate"));
  fps->setDecimals(3);
  fps->setValue(doc.fps);
  fps->setKeepsRefusedText(true);
  auto* mode = new QComboBox(&dialog);
  mode->addItems({tr("linear"), tr("smooth")});
  mode->setCurrentIndex(doc.defaultInterpolation == Interpolation::Smooth ? 1 : 0);
  auto* effects = new viewport::EffectsPanel(&dialog);
  effects->display(doc.scene);
  // The preview keeps running behind the dialog: its cost shows beside the quality it has now.
  if (d_->preview)
    connect(d_->preview, &PreviewPanel::tearsStepped, effects,
            &viewport::EffectsPanel::addFrameCost);
  form->addRow(tr("Name"), name);
  form->addRow(tr("Frame rate (export)"), fps);
  form->addRow(tr("New keys"), mode);
  form->addRow(tr("Effects"), effects);
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, &dialog);
  form->addRow(buttons);
  connect(buttons, &QDialogButtonBox::accepted, &dialog, [&dialog, fps] {
    if (commitFields({fps})) dialog.accept();
  });
  connect(buttons, &QDialogButtonBox::rejected, &dialog, &QDialog::reject);
  if (dialog.exec() != QDialog::Accepted) return;
  ProjectDocument settings = doc;
  settings.name =
      name->text().trimmed().isEmpty() ? "untitled" : name->text().trimmed().toStdString();
  settings.fps = fps->value();
  settings.defaultInterpolation =
      mode->currentIndex() == 1 ? Interpolation::Smooth : Interpolation::Linear;
  effects->applyTo(settings.scene);
  d_->model->setSettings(settings, tr("Project settings"));
}

void MainWindow::showShortcuts() {
  QString rows;
  for (QAction* a : findChildren<QAction*>()) {
    if (a->objectName().isEmpty() || a->shortcut().isEmpty()) continue;
    QString text = a->text();
    text.remove(QLatin1Char('&'));
    rows += QStringLiteral("<tr><td style='padding-right:18px'><b>%1</b></td><td>%2</td></tr>")
                .arg(a->shortcut().toString(QKeySequence::NativeText).toHtmlEscaped(),
                     text.toHtmlEscaped());
  }
  const QString extra = tr(
      "<p>Timeline: click a key to select it and jump to it, drag to move (whole frames), "
      "drag on empty space to select, double-click to add a key, right-click for interpolation, "
      "wheel to zoom, Shift+wheel or middle-drag to pan.<br>Sliders: a drag crosses the range in "
      "600 px, Shift-drag 10x finer, Ctrl-drag 5x coarser; double-click resets, the diamond "
      "keys or unkeys the channel.<br>Number fields: Enter takes the typed number or refuses "
      "it (red, with the range in the status bar), Esc puts the value back, Up/Down step; "
      "Space plays unless you are typing in one.</p>");
  if (!d_->options.interactive) return;
  QMessageBox box(this);
  box.setWindowTitle(tr("Keyboard shortcuts"));
  box.setTextFormat(Qt::RichText);
  box.setText(QStringLiteral("<table>%1</table>%2").arg(rows, extra));
  box.exec();
}

}  // namespace lacrima::editor
