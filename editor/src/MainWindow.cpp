#include <lacrima/editor/MainWindow.h>

#include <lacrima/common/FapTable.h>
#include <lacrima/editing/EditorModel.h>
#include <lacrima/editing/FrameStepClock.h>
#include <lacrima/editing/KeyClipboard.h>
#include <lacrima/editing/RecoveryStore.h>
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
#include <lacrima/editor/head/HeadWorkspace.h>
#include <lacrima/viewport/EffectsPanel.h>

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
#include <QMenuBar>
#include <QMessageBox>
#include <QSettings>
#include <QStackedWidget>
#include <QStatusBar>
#include <QTabBar>
#include <QTabWidget>
#include <QTimer>
#include <QToolBar>
#include <QUndoGroup>
#include <QUndoView>
#include <QVBoxLayout>

namespace lacrima::editor {

MainWindow::MainWindow(EditorOptions options, QWidget* parent)
    : QMainWindow(parent),
      options_(std::move(options)),
      model_(std::make_unique<editing::EditorModel>()),
      clock_(std::make_unique<editing::FrameStepClock>(*model_)),
      recovery_(std::make_unique<editing::RecoveryStore>(
          options_.recoveryDirectory.isEmpty() ? editing::RecoveryStore::defaultDirectory()
                                               : options_.recoveryDirectory)) {
  setObjectName(QStringLiteral("lacrimaEditor"));
  setAcceptDrops(true);
  setDockNestingEnabled(true);
  createDocks();
  // One history per workspace, the one shown active (setWorkspace).
  undoGroup_ = new QUndoGroup(this);
  undoGroup_->addStack(model_->undoStack());
  undoGroup_->addStack(headWorkspace_->setup().undoStack());
  undoGroup_->setActiveStack(model_->undoStack());
  createMenus();

  figures_ = new QLabel(this);
  statusBar()->addPermanentWidget(figures_);

  autosaveSoon_ = new QTimer(this);
  autosaveSoon_->setSingleShot(true);
  autosaveSoon_->setInterval(options_.autosaveDelayMs);
  connect(autosaveSoon_, &QTimer::timeout, this, &MainWindow::autosaveNow);
  autosavePeriodic_ = new QTimer(this);
  autosavePeriodic_->setInterval(options_.autosaveIntervalMs);
  connect(autosavePeriodic_, &QTimer::timeout, this, [this] {
    if (autosaveDirty_) autosaveNow();
  });
  autosavePeriodic_->start();

  connect(model_->undoStack(), &QUndoStack::indexChanged, this, &MainWindow::onDocumentChanged);
  connect(model_->undoStack(), &QUndoStack::cleanChanged, this, &MainWindow::updateTitle);
  connect(model_.get(), &editing::EditorModel::documentReset, this, &MainWindow::updateTitle);
  connect(model_.get(), &editing::EditorModel::settingsChanged, this, &MainWindow::updateTitle);
  connect(model_.get(), &editing::EditorModel::keysChanged, this, &MainWindow::updateStatusFigures);
  connect(model_.get(), &editing::EditorModel::settingsChanged, this,
          &MainWindow::updateStatusFigures);
  connect(model_.get(), &editing::EditorModel::message, this,
          [this](const QString& text) { statusBar()->showMessage(text, 5000); });
  connect(clock_.get(), &editing::FrameStepClock::playingChanged, this,
          &MainWindow::updateStatusFigures);

  QSettings settings;
  resize(1440, 900);
  restoreGeometry(settings.value(QStringLiteral("window/geometry")).toByteArray());
  restoreState(settings.value(QStringLiteral("window/state")).toByteArray());

  newDocument();
  if (options_.offerRecovery) checkForRecovery();
  if (options_.preview) QTimer::singleShot(0, preview_, &PreviewPanel::followDocumentHead);
  statusBar()->showMessage(
      tr("Move a slider to key it at the playhead · K keys the whole pose · Space plays"), 8000);
}

MainWindow::~MainWindow() {
  // The widgets and this window's slots refer to the model and the clock, which are members
  // and so die before the widgets would: cut the window's connections, then let the widgets go.
  clock_->pause();
  disconnect(model_.get(), nullptr, this, nullptr);
  disconnect(model_->undoStack(), nullptr, this, nullptr);
  disconnect(clock_.get(), nullptr, this, nullptr);
  delete takeCentralWidget();
  const auto docks = findChildren<QDockWidget*>();
  for (QDockWidget* dock : docks) delete dock;
}

void MainWindow::setWorkspace(Workspace workspace) {
  workspaceStack_->setCurrentIndex(static_cast<int>(workspace));
  const QSignalBlocker block(workspaces_);
  workspaces_->setCurrentIndex(static_cast<int>(workspace));
  // Edit ▸ Undo and Redo (and their shortcuts) act on the history of the workspace shown.
  undoGroup_->setActiveStack(workspace == Workspace::Head ? headWorkspace_->setup().undoStack()
                                                          : model_->undoStack());
}

MainWindow::Workspace MainWindow::workspace() const {
  return static_cast<Workspace>(workspaceStack_->currentIndex());
}

QAction* MainWindow::action(const QString& name) const { return findChild<QAction*>(name); }

bool MainWindow::showAnimationView(const QString& name) {
  QWidget* view = name == QLatin1String("keys")    ? static_cast<QWidget*>(timeline_)
                  : name == QLatin1String("dope")  ? static_cast<QWidget*>(dopeSheet_)
                  : name == QLatin1String("graph") ? static_cast<QWidget*>(graphEditor_)
                                                   : nullptr;
  if (!view) return false;
  animationViews_->setCurrentWidget(view);
  return true;
}

void MainWindow::createDocks() {
  editing::PresetLibrary library;
  QString presetsSource = QString::fromUtf8(editing::PresetLibrary::kBuiltInPath.data());
  try {
    if (!options_.presetsPath.isEmpty()) {
      library = editing::PresetLibrary::load(options_.presetsPath.toStdString());
      presetsSource = options_.presetsPath;
    }
  } catch (const FileError& e) {
    lastError_ = QString::fromUtf8(e.what());  // reported by the caller; the built-in set is used
  }
  if (presetsSource.startsWith(QLatin1Char(':'))) library = editing::PresetLibrary::builtIn();

  // Centre: the recovery offer above the preview.
  auto* centre = new QWidget(this);
  auto* centreLayout = new QVBoxLayout(centre);
  centreLayout->setContentsMargins(0, 0, 0, 0);
  centreLayout->setSpacing(0);
  banner_ = new RecoveryBanner(centre);
  banner_->hide();
  preview_ = new PreviewPanel(*model_, *clock_, centre);
  preview_->setSimulationThreads(options_.simulationThreads);
  centreLayout->addWidget(banner_);
  centreLayout->addWidget(preview_, 1);
  // Over the centre: Animate (the preview) | Head (import and rig your own head, issue 13).
  auto* workspaces = new QWidget(this);
  auto* workspacesLayout = new QVBoxLayout(workspaces);
  workspacesLayout->setContentsMargins(0, 0, 0, 0);
  workspacesLayout->setSpacing(0);
  workspaces_ = new QTabBar(workspaces);
  workspaces_->setObjectName(QStringLiteral("workspaces"));
  workspaces_->addTab(tr("Animate"));
  workspaces_->addTab(tr("Head"));
  workspaceStack_ = new QStackedWidget(workspaces);
  workspaceStack_->addWidget(centre);
  headWorkspace_ = new head::HeadWorkspace(*model_, workspaceStack_);
  headWorkspace_->setInteractive(options_.interactive);
  workspaceStack_->addWidget(headWorkspace_);
  workspacesLayout->addWidget(workspaces_);
  workspacesLayout->addWidget(workspaceStack_, 1);
  setCentralWidget(workspaces);
  connect(workspaces_, &QTabBar::currentChanged, this,
          [this](int index) { setWorkspace(static_cast<Workspace>(index)); });
  connect(headWorkspace_, &head::HeadWorkspace::useInProjectRequested, this,
          [this](const QString& mesh, const QString& fdp) {
            if (!setHead(mesh, fdp)) return;
            setWorkspace(Workspace::Animate);
            statusBar()->showMessage(tr("The project now uses %1").arg(QFileInfo(mesh).fileName()),
                                     5000);
          });
  connect(banner_, &RecoveryBanner::restoreRequested, this, &MainWindow::restoreRecovery);
  connect(banner_, &RecoveryBanner::discardRequested, this, &MainWindow::discardRecovery);

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

  sliders_ = new SliderPanel(*model_, this);
  QDockWidget* channels =
      dock(tr("Channels"), QStringLiteral("dock.channels"), sliders_, Qt::LeftDockWidgetArea);
  sliders_->setMinimumWidth(430);

  presets_ = new PresetPanel(*model_, std::move(library), this);
  presets_->setLibrary(presets_->library(), presetsSource);
  QDockWidget* presetDock =
      dock(tr("Presets"), QStringLiteral("dock.presets"), presets_, Qt::RightDockWidgetArea);
  keyList_ = new KeyListPanel(*model_, this);
  QDockWidget* keysDock =
      dock(tr("Keys"), QStringLiteral("dock.keys"), keyList_, Qt::RightDockWidgetArea);
  layers_ = new LayerPanel(*model_, this);
  QDockWidget* layersDock =
      dock(tr("Layers"), QStringLiteral("dock.layers"), layers_, Qt::RightDockWidgetArea);
  history_ = new QUndoView(model_->undoStack(), this);
  history_->setEmptyLabel(tr("<opened>"));
  QDockWidget* historyDock =
      dock(tr("History"), QStringLiteral("dock.history"), history_, Qt::RightDockWidgetArea);
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
  transport_ = new TransportBar(*model_, *clock_, timelineBox);
  // The animation views share the space under the transport: the key rows (the timeline), and
  // per-channel views beside it.
  animationViews_ = new QTabWidget(timelineBox);
  animationViews_->setDocumentMode(true);
  timeline_ = new TimelineWidget(*model_, animationViews_);
  animationViews_->addTab(timeline_, tr("Keys"));
  dopeSheet_ = new DopeSheet(*model_, animationViews_);
  animationViews_->addTab(dopeSheet_, tr("Dope sheet"));
  graphEditor_ = new GraphEditor(*model_, animationViews_);
  animationViews_->addTab(graphEditor_, tr("Graph"));
  timelineLayout->addWidget(transport_);
  timelineLayout->addWidget(animationViews_, 1);
  QDockWidget* timelineDock =
      dock(tr("Timeline"), QStringLiteral("dock.timeline"), timelineBox, Qt::BottomDockWidgetArea);
  // The timeline spans the whole width, under the channel list too.
  setCorner(Qt::BottomLeftCorner, Qt::BottomDockWidgetArea);
  setCorner(Qt::BottomRightCorner, Qt::BottomDockWidgetArea);
  resizeDocks({timelineDock}, {300}, Qt::Vertical);  // room for the dope sheet and graph
  resizeDocks({channels, presetDock}, {470, 330}, Qt::Horizontal);

  connect(timeline_, &TimelineWidget::copyRequested, this, &MainWindow::copyKeys);
  connect(timeline_, &TimelineWidget::pasteRequested, this, [this](double at) { pasteKeys(at); });
  connect(timeline_, &TimelineWidget::mirrorRequested, model_.get(), &editing::EditorModel::mirror);
  connect(presets_, &PresetPanel::loadRequested, this, &MainWindow::loadPresetsDialog);
  connect(sliders_, &SliderPanel::expressionPresetRequested, this, [this](int code) {
    if (const editing::Preset* preset = presets_->library().forExpression(code)) {
      model_->applyPreset(*preset, presets_->intensity(), presets_->replacesPose());
    } else {
      statusBar()->showMessage(tr("The presets file has no pose for expression %1").arg(code),
                               5000);
    }
  });
  connect(preview_, &PreviewPanel::statusChanged, this, &MainWindow::updateStatusFigures);
}

QAction* MainWindow::addAction(QMenu* menu, const QString& name, const QString& text,
                               const QKeySequence& shortcut, const QString& tip) {
  auto* a = new QAction(text, this);
  a->setObjectName(name);
  if (!shortcut.isEmpty()) a->setShortcut(shortcut);
  a->setShortcutContext(Qt::WindowShortcut);
  if (!tip.isEmpty()) a->setStatusTip(tip);
  if (menu) menu->addAction(a);
  QMainWindow::addAction(a);  // shortcuts work even when the menu bar is hidden
  return a;
}

void MainWindow::createMenus() {
  editing::EditorModel& m = *model_;
  QMenu* file = menuBar()->addMenu(tr("&File"));
  connect(addAction(file, QStringLiteral("file.new"), tr("&New"), QKeySequence::New),
          &QAction::triggered, this, [this] {
            if (maybeSave()) newDocument();
          });
  connect(addAction(file, QStringLiteral("file.open"), tr("&Open…"), QKeySequence::Open),
          &QAction::triggered, this, &MainWindow::openDialog);
  recentMenu_ = file->addMenu(tr("Open &Recent"));
  file->addSeparator();
  connect(addAction(file, QStringLiteral("file.save"), tr("&Save"), QKeySequence::Save),
          &QAction::triggered, this, [this] {
            if (filePath_.isEmpty())
              saveDialog();
            else
              saveTo(filePath_);
          });
  connect(addAction(file, QStringLiteral("file.saveAs"), tr("Save &As…"),
                    QKeySequence(QStringLiteral("Ctrl+Shift+S"))),
          &QAction::triggered, this, &MainWindow::saveDialog);
  file->addSeparator();
  connect(addAction(file, QStringLiteral("file.import"), tr("&Import FAP…"),
                    QKeySequence(QStringLiteral("Ctrl+I")),
                    tr("Read a .fap file: its frames become keys, optionally reduced")),
          &QAction::triggered, this, &MainWindow::importDialog);
  connect(
      addAction(file, QStringLiteral("file.export"), tr("&Export FAP…"),
                QKeySequence(QStringLiteral("Ctrl+E")),
                tr("Bake the keys to a .fap file (22 fps; with tear channels, or strict 68 FAPs)")),
      &QAction::triggered, this, &MainWindow::exportDialog);
  connect(addAction(file, QStringLiteral("file.chooseHead"), tr("Choose &head…"), {},
                    tr("The mesh and feature-point file this project is animated on")),
          &QAction::triggered, this, &MainWindow::chooseHeadDialog);
  file->addSeparator();
  connect(addAction(file, QStringLiteral("file.quit"), tr("&Quit"), QKeySequence::Quit),
          &QAction::triggered, this, &QWidget::close);
  rebuildRecentMenu();

  QMenu* edit = menuBar()->addMenu(tr("&Edit"));
  QAction* undo = undoGroup_->createUndoAction(this, tr("&Undo"));
  undo->setObjectName(QStringLiteral("edit.undo"));
  undo->setShortcut(QKeySequence::Undo);
  QAction* redo = undoGroup_->createRedoAction(this, tr("&Redo"));
  redo->setObjectName(QStringLiteral("edit.redo"));
  redo->setShortcuts(
      {QKeySequence(QStringLiteral("Ctrl+Shift+Z")), QKeySequence(QStringLiteral("Ctrl+Y"))});
  edit->addAction(undo);
  edit->addAction(redo);
  QMainWindow::addAction(undo);
  QMainWindow::addAction(redo);
  edit->addSeparator();
  connect(addAction(edit, QStringLiteral("edit.copy"), tr("&Copy keys"), QKeySequence::Copy),
          &QAction::triggered, this, &MainWindow::copyKeys);
  connect(addAction(edit, QStringLiteral("edit.paste"), tr("&Paste keys at playhead"),
                    QKeySequence::Paste),
          &QAction::triggered, this, [this] { pasteKeys(); });
  QAction* del =
      addAction(edit, QStringLiteral("edit.delete"), tr("&Delete keys"), QKeySequence::Delete);
  del->setShortcuts({QKeySequence::Delete, QKeySequence(Qt::Key_Backspace)});
  connect(del, &QAction::triggered, this, [this] {
    if (!model_->selectedTimes().empty())
      model_->deleteSelectedKeys();
    else if (model_->currentKeyIndex() >= 0)
      model_->deleteKeys({model_->currentTime()});
  });
  connect(addAction(edit, QStringLiteral("edit.selectAll"), tr("Select &all keys"),
                    QKeySequence::SelectAll),
          &QAction::triggered, &m, &editing::EditorModel::selectAll);
  edit->addSeparator();
  connect(addAction(edit, QStringLiteral("edit.mirror"), tr("&Mirror left ↔ right"),
                    QKeySequence(QStringLiteral("Ctrl+M")),
                    tr("Mirror the selected keys, or the pose at the playhead")),
          &QAction::triggered, &m, &editing::EditorModel::mirror);
  QAction* symmetric = addAction(edit, QStringLiteral("edit.symmetric"), tr("S&ymmetric editing"),
                                 QKeySequence(QStringLiteral("Ctrl+Shift+M")),
                                 tr("Moving a left or right channel moves its mirror channel too"));
  symmetric->setCheckable(true);
  connect(symmetric, &QAction::toggled, &m, &editing::EditorModel::setSymmetricEdit);
  connect(&m, &editing::EditorModel::symmetricEditChanged, symmetric, &QAction::setChecked);
  edit->addSeparator();
  connect(addAction(edit, QStringLiteral("edit.settings"), tr("Project &settings…"),
                    QKeySequence(QStringLiteral("Ctrl+,"))),
          &QAction::triggered, this, &MainWindow::settingsDialog);

  QMenu* key = menuBar()->addMenu(tr("&Key"));
  connect(addAction(key, QStringLiteral("key.add"), tr("&Add key (whole pose)"),
                    QKeySequence(Qt::Key_K), tr("Key every animated channel at the playhead")),
          &QAction::triggered, &m, &editing::EditorModel::addKey);
  const auto targets = [this] {
    std::vector<double> t = model_->selectedTimes();
    if (t.empty() && model_->currentKeyIndex() >= 0) t.push_back(model_->currentTime());
    return t;
  };
  connect(addAction(key, QStringLiteral("key.linear"), tr("Make &linear"), QKeySequence(Qt::Key_L)),
          &QAction::triggered, this,
          [this, targets] { model_->setInterpolation(targets(), Interpolation::Linear); });
  connect(addAction(key, QStringLiteral("key.smooth"), tr("Make s&mooth"), QKeySequence(Qt::Key_S)),
          &QAction::triggered, this,
          [this, targets] { model_->setInterpolation(targets(), Interpolation::Smooth); });
  key->addSeparator();
  connect(addAction(key, QStringLiteral("key.previous"), tr("&Previous key"),
                    QKeySequence(Qt::Key_Comma)),
          &QAction::triggered, this, [this] { model_->setCurrentTime(previousKeyTime(*model_)); });
  connect(addAction(key, QStringLiteral("key.next"), tr("&Next key"), QKeySequence(Qt::Key_Period)),
          &QAction::triggered, this, [this] { model_->setCurrentTime(nextKeyTime(*model_)); });

  QMenu* play = menuBar()->addMenu(tr("&Playback"));
  connect(addAction(play, QStringLiteral("play.toggle"), tr("&Play / pause"),
                    QKeySequence(Qt::Key_Space)),
          &QAction::triggered, clock_.get(), &editing::FrameStepClock::toggle);
  connect(
      addAction(play, QStringLiteral("play.start"), tr("Go to &start"), QKeySequence(Qt::Key_Home)),
      &QAction::triggered, this,
      [this] { model_->setCurrentTime(model_->document().keys.startTime()); });
  connect(addAction(play, QStringLiteral("play.end"), tr("Go to &end"), QKeySequence(Qt::Key_End)),
          &QAction::triggered, this, [this] { model_->setCurrentTime(model_->endTime()); });
  connect(addAction(play, QStringLiteral("play.previousFrame"), tr("Previous &frame"),
                    QKeySequence(Qt::Key_Left)),
          &QAction::triggered, this,
          [this] { model_->setCurrentTime(model_->currentTime() - model_->frameDuration()); });
  connect(addAction(play, QStringLiteral("play.nextFrame"), tr("&Next frame"),
                    QKeySequence(Qt::Key_Right)),
          &QAction::triggered, this,
          [this] { model_->setCurrentTime(model_->currentTime() + model_->frameDuration()); });
  // Blender's and Maya's "go to frame": type a time or frame into the transport's time field.
  connect(addAction(play, QStringLiteral("play.goToTime"), tr("&Go to time…"),
                    QKeySequence(QStringLiteral("Ctrl+G"))),
          &QAction::triggered, transport_, &TransportBar::editTime);

  viewMenu_ = menuBar()->addMenu(tr("&View"));
  QAction* tears = addAction(viewMenu_, QStringLiteral("view.tearPreview"), tr("&Tear preview"),
                             QKeySequence(Qt::Key_T), tr("Simulate the tears while paused"));
  tears->setCheckable(true);
  tears->setChecked(preview_->tearPreview());
  connect(tears, &QAction::toggled, preview_, &PreviewPanel::setTearPreview);
  connect(addAction(viewMenu_, QStringLiteral("view.frameAll"), tr("&Frame all keys"),
                    QKeySequence(Qt::Key_F)),
          &QAction::triggered, timeline_, &TimelineWidget::fitAll);
  connect(
      addAction(viewMenu_, QStringLiteral("view.filter"), tr("Find &channel"), QKeySequence::Find),
      &QAction::triggered, this, [this] {
        sliders_->filterBox()->setFocus();
        sliders_->filterBox()->selectAll();
      });
  viewMenu_->addSeparator();
  connect(addAction(viewMenu_, QStringLiteral("view.animate"), tr("&Animate workspace"),
                    QKeySequence(QStringLiteral("Ctrl+1"))),
          &QAction::triggered, this, [this] { setWorkspace(Workspace::Animate); });
  connect(addAction(viewMenu_, QStringLiteral("view.head"), tr("&Head workspace"),
                    QKeySequence(QStringLiteral("Ctrl+2")),
                    tr("Import your own head, place its feature points and rig it")),
          &QAction::triggered, this, [this] { setWorkspace(Workspace::Head); });
  viewMenu_->addSeparator();
  for (QDockWidget* d : findChildren<QDockWidget*>()) viewMenu_->addAction(d->toggleViewAction());

  QMenu* help = menuBar()->addMenu(tr("&Help"));
  connect(addAction(help, QStringLiteral("help.shortcuts"), tr("&Keyboard shortcuts"),
                    QKeySequence::HelpContents),
          &QAction::triggered, this, &MainWindow::showShortcuts);

  auto* bar = addToolBar(tr("Main"));
  bar->setObjectName(QStringLiteral("toolbar.main"));
  bar->setMovable(false);
  bar->setToolButtonStyle(Qt::ToolButtonTextOnly);
  for (const char* name :
       {"file.new", "file.open", "file.save", "", "edit.undo", "edit.redo", "", "key.add",
        "edit.delete", "edit.mirror", "edit.symmetric", "", "file.import", "file.export"}) {
    if (!*name) {
      bar->addSeparator();
      continue;
    }
    bar->addAction(action(QString::fromLatin1(name)));
  }
  action(QStringLiteral("key.add"))->setIconText(tr("Key"));
  action(QStringLiteral("edit.delete"))->setIconText(tr("Delete"));
  action(QStringLiteral("edit.mirror"))->setIconText(tr("Mirror"));
  action(QStringLiteral("edit.symmetric"))->setIconText(tr("Symmetric"));
  action(QStringLiteral("file.import"))->setIconText(tr("Import FAP"));
  action(QStringLiteral("file.export"))->setIconText(tr("Export FAP"));
  undo->setIconText(tr("Undo"));
  redo->setIconText(tr("Redo"));
}

void MainWindow::updateTitle() {
  const QString name = filePath_.isEmpty() ? QString::fromStdString(model_->document().name)
                                           : QFileInfo(filePath_).fileName();
  setWindowTitle(QStringLiteral("%1[*] — Lacrima Editor").arg(name));
  setWindowModified(model_->isModified());
}

void MainWindow::updateStatusFigures() {
  const ProjectDocument& doc = model_->document();
  QString text = tr("%1 fps · %n keys · %2 s", nullptr, static_cast<int>(doc.keys.keys().size()))
                     .arg(doc.fps)
                     .arg(doc.keys.endTime(), 0, 'f', 2);
  if (clock_->isPlaying()) text += tr(" · playing at %1 fps").arg(clock_->rate());
  if (preview_ && !preview_->statusText().isEmpty())
    text += QStringLiteral(" · ") + preview_->statusText();
  figures_->setText(text);
}

void MainWindow::onDocumentChanged() {
  updateTitle();
  autosaveDirty_ = true;
  autosaveSoon_->start();
}

void MainWindow::copyKeys() {
  std::vector<double> times = model_->selectedTimes();
  if (times.empty() && model_->currentKeyIndex() >= 0) times.push_back(model_->currentTime());
  if (times.empty()) {
    statusBar()->showMessage(tr("Select keys to copy (click them in the timeline)"), 4000);
    return;
  }
  QApplication::clipboard()->setMimeData(
      editing::keysToMimeData(editing::copyKeys(model_->document().keys, times)));
  statusBar()->showMessage(tr("Copied %n key(s)", nullptr, static_cast<int>(times.size())), 3000);
}

void MainWindow::pasteKeys(std::optional<double> at) {
  const auto clip = editing::keysFromMimeData(QApplication::clipboard()->mimeData());
  if (!clip) {
    statusBar()->showMessage(tr("The clipboard holds no keys"), 4000);
    return;
  }
  model_->pasteKeys(*clip, at.value_or(model_->currentTime()));
}

void MainWindow::settingsDialog() {
  if (!options_.interactive) return;
  const ProjectDocument& doc = model_->document();
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
  if (preview_)
    connect(preview_, &PreviewPanel::tearsStepped, effects, &viewport::EffectsPanel::addFrameCost);
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
  model_->setSettings(settings, tr("Project settings"));
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
  if (!options_.interactive) return;
  QMessageBox box(this);
  box.setWindowTitle(tr("Keyboard shortcuts"));
  box.setTextFormat(Qt::RichText);
  box.setText(QStringLiteral("<table>%1</table>%2").arg(rows, extra));
  box.exec();
}

}  // namespace lacrima::editor
