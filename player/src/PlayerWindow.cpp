#include <lacrima/player/PlayerWindow.h>

#include <lacrima/player/ErrorReport.h>
#include <lacrima/player/HeadViews.h>
#include <lacrima/player/LiveMappingDialog.h>
#include <lacrima/player/LivePanel.h>
#include <lacrima/player/MoodPanel.h>
#include <lacrima/player/ProjectHead.h>
#include <lacrima/player/TearParametersPanel.h>

#include <lacrima/appsupport/ExportDialog.h>
#include <lacrima/common/MediaFiles.h>
#include <lacrima/common/ProjectPath.h>
#include <lacrima/live/ListenUrl.h>
#include <lacrima/live/LiveSession.h>
#include <lacrima/playback/AnimationFile.h>
#include <lacrima/viewport/EffectsPanel.h>
#include <lacrima/viewport/FaceViewport.h>
#include <lacrima/viewport/WarningsButton.h>

#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QDockWidget>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QInputDialog>
#include <QLabel>
#include <QLineEdit>
#include <QMenuBar>
#include <QMessageBox>
#include <QMimeData>
#include <QScrollArea>
#include <QSignalBlocker>
#include <QSlider>
#include <QStatusBar>
#include <QStyle>
#include <QTimer>
#include <QToolButton>
#include <QVBoxLayout>

#include <cmath>
#include <cstdio>

namespace lacrima::player {

namespace {

// Most file frames the tears may advance per tick before the clock is held back.
constexpr int kMaxFramesPerTick = 4;
// A checkpoint every 22 frames (a second at the usual rate): scrubbing back replays at most
// 21 frames, about 0.1 s on the demo, for some hundred kilobytes per checkpoint.
constexpr int kCheckpointInterval = 22;
// A live stream is shown at the display's pace: about 60 pictures a second.
constexpr int kLiveTickMilliseconds = 16;
constexpr int kFileTickMilliseconds = 8;

QString clockText(double seconds) {
  const int tenths = static_cast<int>(std::lround(seconds * 100));
  return QStringLiteral("%1:%2.%3")
      .arg(tenths / 6000)
      .arg(tenths / 100 % 60, 2, 10, QLatin1Char('0'))
      .arg(tenths % 100, 2, 10, QLatin1Char('0'));
}

}  // namespace

PlayerWindow::PlayerWindow(std::unique_ptr<playback::HeadRig> rig, QWidget* parent)
    : QMainWindow(parent),
      rig_(std::move(rig)),
      playback_(std::make_unique<playback::Playback>(*rig_, kCheckpointInterval)),
      source_(playback_.get()) {
  setWindowTitle(tr("Lacrima Player"));
  setAcceptDrops(true);
  sinceStart_.start();
  ticker_ = new QTimer(this);
  ticker_->setTimerType(Qt::PreciseTimer);
  ticker_->setInterval(kFileTickMilliseconds);
  session_ = new live::LiveSession(this);
  session_->setFrameHandler([this](const live::LiveFrame& frame) {
    if (!live_) return;
    live_->push(frame.values, frame.mask, frame.arrival);
    pacer_.frameArrived(frame.arrival);
    if (frame.frameRate) live_->setFrameRate(*frame.frameRate);
  });
  session_->setMoodHandler([this](const live::LiveMood& mood) {
    if (!live_) return;
    live_->setMoods(mood.levels);
    moodPanel_->display(live_->moods(), live_->moodSeed());
  });
  connect(session_, &live::LiveSession::countersChanged, this, &PlayerWindow::liveFrameArrived);
  // A new frame is shown at once, not at the next tick: the next turn of the event loop ticks.
  connect(session_, &live::LiveSession::frameArrived, this, [this] {
    if (isLive() && playing() && ticker_->interval() != 0) ticker_->setInterval(0);
  });
  connect(ticker_, &QTimer::timeout, this, &PlayerWindow::tick);
  buildActions();
  buildLayout();
  viewport_->setHead(rig_->head);
  showRigWarnings();
  display(playback_->view());
  updateTransport();
  statusBar()->showMessage(tr("Open a FAP file or a project (Ctrl+O), or drop one here"));
}

PlayerWindow::~PlayerWindow() = default;

void PlayerWindow::buildActions() {
  QStyle* s = style();
  open_ = new QAction(s->standardIcon(QStyle::SP_DialogOpenButton), tr("&Open..."), this);
  open_->setObjectName(QStringLiteral("file.open"));
  open_->setShortcut(QKeySequence::Open);
  open_->setToolTip(tr("Open a FAP file or a Lacrima project (Ctrl+O)"));
  connect(open_, &QAction::triggered, this, &PlayerWindow::chooseFile);
  openDemo_ = new QAction(tr("Open the &demo"), this);
  openDemo_->setShortcut(Qt::CTRL | Qt::Key_D);
  connect(openDemo_, &QAction::triggered, this, &PlayerWindow::openDemo);
  export_ = new QAction(tr("&Export..."), this);
  export_->setObjectName(QStringLiteral("file.export"));
  export_->setShortcut(Qt::CTRL | Qt::SHIFT | Qt::Key_E);  // as the editor's Export Animation
  export_->setToolTip(tr("Export the animation with its tears: glTF, video, images, tear meshes"));
  connect(export_, &QAction::triggered, this, &PlayerWindow::exportDialog);
  quit_ = new QAction(tr("&Quit"), this);
  quit_->setShortcut(QKeySequence::Quit);
  connect(quit_, &QAction::triggered, this, &QWidget::close);

  play_ = new QAction(this);
  play_->setShortcut(Qt::Key_Space);
  connect(play_, &QAction::triggered, this, &PlayerWindow::togglePlay);
  reset_ = new QAction(s->standardIcon(QStyle::SP_MediaSkipBackward), tr("&Reset"), this);
  reset_->setShortcut(Qt::Key_Home);
  reset_->setToolTip(tr("Neutral face, all tears gone, back to the start (Home)"));
  connect(reset_, &QAction::triggered, this, &PlayerWindow::resetPlayback);
  stepBack_ = new QAction(tr("Previous frame"), this);
  stepBack_->setShortcut(Qt::Key_Left);
  connect(stepBack_, &QAction::triggered, this, [this] {
    if (isLive()) return;
    pause();
    seek((playback_->currentFrame() - 1) / playback_->frameRate());
  });
  stepForward_ = new QAction(tr("Next frame"), this);
  stepForward_->setShortcut(Qt::Key_Right);
  connect(stepForward_, &QAction::triggered, this, [this] {
    if (isLive()) return;
    pause();
    seek((playback_->currentFrame() + 1) / playback_->frameRate());
  });
  loop_ = new QAction(tr("&Loop"), this);
  loop_->setObjectName(QStringLiteral("playback.loop"));
  loop_->setCheckable(true);
  loop_->setShortcut(Qt::Key_L);
  loop_->setToolTip(tr("Play again from the start at the end (L)"));
  resetView_ = new QAction(tr("Reset &view"), this);
  resetView_->setShortcut(Qt::Key_V);
  resetView_->setToolTip(tr("Frame the face again (V, or double-click the face)"));
  connect(resetView_, &QAction::triggered, this, [this] {
    viewport_->resetView();
    cameraPreset_ = scene::CameraPreset::Framing;
    cameraActions_.front()->setChecked(true);
  });
  updatePlayIcon();

  QMenu* file = menuBar()->addMenu(tr("&File"));
  file->addAction(open_);
  file->addAction(openDemo_);
  file->addAction(export_);
  file->addSeparator();
  file->addAction(quit_);
  QMenu* playMenu = menuBar()->addMenu(tr("&Playback"));
  for (QAction* a : {play_, reset_, stepBack_, stepForward_, loop_}) playMenu->addAction(a);
  listen_ = new QAction(tr("&Listen..."), this);
  listen_->setObjectName(QStringLiteral("live.listen"));
  listen_->setToolTip(tr("Play a live stream: FAP frames over TCP or UDP, or Live Link Face"));
  connect(listen_, &QAction::triggered, this, &PlayerWindow::chooseStream);
  stopListening_ = new QAction(tr("&Stop listening"), this);
  stopListening_->setObjectName(QStringLiteral("live.stop"));
  stopListening_->setEnabled(false);
  connect(stopListening_, &QAction::triggered, this, &PlayerWindow::stopListening);
  QAction* mapping = new QAction(tr("Live Link &mapping..."), this);
  mapping->setObjectName(QStringLiteral("live.mapping"));
  mapping->setToolTip(tr("The gains from Live Link Face's blendshapes and angles to FAPs"));
  connect(mapping, &QAction::triggered, this, &PlayerWindow::editMapping);
  QMenu* liveMenu = menuBar()->addMenu(tr("&Live"));
  liveMenu->addAction(listen_);
  liveMenu->addAction(stopListening_);
  liveMenu->addSeparator();
  liveMenu->addAction(mapping);
  viewMenu_ = menuBar()->addMenu(tr("&View"));
  viewMenu_->addAction(resetView_);
  // The named cameras of --view, also here: one checked, the camera shown.
  viewMenu_->addSection(tr("Camera"));
  auto* cameras = new QActionGroup(this);
  const std::pair<scene::CameraPreset, QString> kCameras[] = {
      {scene::CameraPreset::Framing, tr("&Framing")},
      {scene::CameraPreset::Front, tr("F&ront")},
      {scene::CameraPreset::ThreeQuarter, tr("&Three-quarter")},
      {scene::CameraPreset::Profile, tr("&Profile")},
      {scene::CameraPreset::CloseLeft, tr("Close-up, &left cheek")},
      {scene::CameraPreset::CloseRight, tr("Close-up, ri&ght cheek")}};
  for (const auto& [preset, label] : kCameras) {
    QAction* a = viewMenu_->addAction(label);
    a->setObjectName(QStringLiteral("view.") + QString::fromUtf8(scene::toString(preset).data()));
    a->setCheckable(true);
    a->setChecked(preset == cameraPreset_);
    cameras->addAction(a);
    connect(a, &QAction::triggered, this, [this, p = preset] { setCameraPreset(p); });
    cameraActions_.push_back(a);
  }
  viewMenu_->addSeparator();
  // Application-wide, so the keys also work while the floating Scene panel has the focus;
  // modal dialogs still block them, and text fields keep Space and the arrows for typing.
  for (QAction* a : {play_, reset_, stepBack_, stepForward_, loop_, resetView_})
    a->setShortcutContext(Qt::ApplicationShortcut);
  addActions({play_, reset_, stepBack_, stepForward_, loop_, resetView_});
}

void PlayerWindow::buildLayout() {
  viewport_ = new viewport::FaceViewport(this);
  viewport_->setMinimumSize(320, 240);
  viewport_->setAcceptDrops(false);  // drops go to the window
  connect(viewport_, &viewport::FaceViewport::rendered, this, &PlayerWindow::countRender);
  connect(viewport_, &viewport::FaceViewport::rendered, this, [this] {
    if (liveTickAt_ < 0) return;
    pacer_.rendered(live::liveClockSeconds() - liveTickAt_);
    liveTickAt_ = -1;
  });

  auto* transport = new QWidget(this);
  auto* bar = new QHBoxLayout(transport);
  bar->setContentsMargins(6, 2, 6, 2);
  for (QAction* a : {open_, play_, reset_}) {
    auto* button = new QToolButton(transport);
    button->setDefaultAction(a);
    button->setFocusPolicy(Qt::NoFocus);
    button->setIconSize(QSize(22, 22));
    button->setObjectName(a == play_ ? "playButton" : a == reset_ ? "resetButton" : "openButton");
    bar->addWidget(button);
  }
  timeline_ = new QSlider(Qt::Horizontal, transport);
  timeline_->setFocusPolicy(Qt::NoFocus);
  timeline_->setToolTip(
      tr("Drag to scrub; going back replays the tears from the nearest checkpoint"));
  bar->addWidget(timeline_, 1);
  timeLabel_ = new QLabel(transport);
  timeLabel_->setMinimumWidth(timeLabel_->fontMetrics().horizontalAdvance("00:00.00 / 00:00.00") +
                              8);
  bar->addWidget(timeLabel_);
  connect(timeline_, &QSlider::sliderPressed, this, [this] {
    playAfterScrub_ = playing();
    pause();
  });
  connect(timeline_, &QSlider::sliderReleased, this, [this] {
    if (playAfterScrub_) play();
  });
  connect(timeline_, &QSlider::valueChanged, this, &PlayerWindow::timelineMoved);

  auto* centre = new QWidget(this);
  auto* column = new QVBoxLayout(centre);
  column->setContentsMargins(0, 0, 0, 0);
  column->setSpacing(0);
  column->addWidget(viewport_, 1);
  column->addWidget(transport);
  setCentralWidget(centre);

  effects_ = new viewport::EffectsPanel(this);
  parameters_ = new TearParametersPanel(this);
  auto* side = new QWidget(this);
  auto* sideLayout = new QVBoxLayout(side);
  auto* effectsBox = new QGroupBox(tr("Effects"), side);
  (new QVBoxLayout(effectsBox))->addWidget(effects_);
  auto* parametersBox = new QGroupBox(tr("Tear parameters"), side);
  (new QVBoxLayout(parametersBox))->addWidget(parameters_);
  parametersBox->setToolTip(tr("Changing a parameter restarts the tears"));
  livePanel_ = new LivePanel(side);
  auto* liveBox = new QGroupBox(tr("Live"), side);
  liveBox->setObjectName("liveBox");
  (new QVBoxLayout(liveBox))->addWidget(livePanel_);
  liveBox->setVisible(false);
  connect(livePanel_, &LivePanel::tearsEdited, this, [this](int left, int right) {
    if (live_) live_->setTears(static_cast<float>(left), static_cast<float>(right));
  });
  moodPanel_ = new MoodPanel(side);
  auto* moodBox = new QGroupBox(tr("Mood"), side);
  moodBox->setObjectName("moodBox");
  moodBox->setToolTip(
      tr("The crying generator: moving a slider makes the face cry live, with no file"));
  (new QVBoxLayout(moodBox))->addWidget(moodPanel_);
  connect(moodPanel_, &MoodPanel::moodsEdited, this, &PlayerWindow::playMoods);
  connect(moodPanel_, &MoodPanel::seedEdited, this, &PlayerWindow::setMoodSeed);
  sideLayout->addWidget(liveBox);
  sideLayout->addWidget(moodBox);
  sideLayout->addWidget(effectsBox);
  sideLayout->addWidget(parametersBox);
  sideLayout->addStretch(1);
  auto* scroll = new QScrollArea(this);
  scroll->setWidget(side);
  scroll->setWidgetResizable(true);
  scroll->setFrameShape(QFrame::NoFrame);
  scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
  auto* dock = new QDockWidget(tr("Scene"), this);
  dock->setObjectName("sceneDock");
  dock->setWidget(scroll);
  dock->setFeatures(QDockWidget::DockWidgetMovable | QDockWidget::DockWidgetFloatable);
  addDockWidget(Qt::RightDockWidgetArea, dock);
  viewMenu_->addAction(dock->toggleViewAction());
  effects_->display(playback_->scene());
  parameters_->display({}, {});
  connect(effects_, &viewport::EffectsPanel::edited, this, &PlayerWindow::applyScene);
  connect(parameters_, &TearParametersPanel::edited, this, &PlayerWindow::applyScene);

  frameLabel_ = new QLabel(this);
  fpsLabel_ = new QLabel(this);
  tearsLabel_ = new QLabel(this);
  fpsLabel_->setMinimumWidth(fpsLabel_->fontMetrics().horizontalAdvance("000 fps") + 8);
  // The rig's warnings are read in the window (stderr has them too).
  rigWarnings_ = new viewport::WarningsButton(this);
  statusBar()->addPermanentWidget(rigWarnings_);
  for (QLabel* label : {tearsLabel_, frameLabel_, fpsLabel_}) {
    label->setContentsMargins(10, 0, 10, 0);
    statusBar()->addPermanentWidget(label);
  }
  try {
    findMediaFile("demo/crying.fap");
  } catch (const FileError&) {
    openDemo_->setEnabled(false);
  }
}

void PlayerWindow::setHeadSource(std::optional<HeadFiles> head, bool fixed) {
  head_ = std::move(head);
  headFixed_ = fixed;
}

bool PlayerWindow::openFile(const QString& path) {
  pause();
  QApplication::setOverrideCursor(Qt::WaitCursor);
  const TearQualitySettings qualityBefore = playback_->scene().quality;
  // A project on another head: rig it and open the file on it before anything is replaced, so
  // a failure leaves the previous head and animation playing.
  std::unique_ptr<playback::HeadRig> newRig;
  std::unique_ptr<playback::Playback> newPlayback;
  std::optional<HeadFiles> newHead;
  try {
    const std::string file = path.toStdString();
    if (!headFixed_ && isProjectPath(file)) {
      newHead = headOfFile(file);
      if (newHead != head_) {
        newRig = loadHeadFor(newHead, file);
        newPlayback = std::make_unique<playback::Playback>(*newRig, kCheckpointInterval);
        newPlayback->setSimulationThreads(simulationThreads_);
        newPlayback->open(file);
      }
    }
    if (!newRig) playback_->open(file);
  } catch (const std::exception& e) {
    QApplication::restoreOverrideCursor();
    reportError(e, path);
    return false;
  }
  QApplication::restoreOverrideCursor();
  stopListening();  // the file takes the transport (and a new head outlives no live source)
  if (newRig) {
    for (const std::string& w : newRig->warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());
    viewport_->setHead(newRig->head);
    playback_ = std::move(newPlayback);  // the old playback goes before the rig it refers to
    rig_ = std::move(newRig);
    head_ = std::move(newHead);
    showRigWarnings();
    viewport_->resetView();
    if (cameraPreset_ != scene::CameraPreset::Framing)
      viewport_->setView(presetView(*rig_, cameraPreset_));
  }
  source_ = playback_.get();
  clock_.setTime(0);
  applyTearQuality();
  const bool qualityChanged = playback_->scene().quality != qualityBefore;
  fileParameters_ = playback_->scene().simulation;
  effects_->display(playback_->scene());
  parameters_->display(playback_->scene().simulation, fileParameters_);
  {
    const QSignalBlocker block(timeline_);
    timeline_->setRange(0, static_cast<int>(std::lround(playback_->duration() * 1000)));
    timeline_->setPageStep(std::max(1, timeline_->maximum() / 20));
    timeline_->setSingleStep(static_cast<int>(std::lround(1000 / playback_->frameRate())));
  }
  const QFileInfo info(path);
  setWindowTitle(tr("%1 - Lacrima Player").arg(info.fileName()));
  QString summary =
      tr("%1: %2 frames at %3 fps, %4 s%5")
          .arg(info.fileName())
          .arg(playback_->frameCount())
          .arg(playback_->frameRate())
          .arg(playback_->duration(), 0, 'f', 2)
          .arg(playback_->hasTears() ? tr(", with tears") : tr(", no tears (nothing simulated)"));
  if (!playback_->warnings().empty())
    summary += tr("; %n warning(s), the first: %1", nullptr,
                  static_cast<int>(playback_->warnings().size()))
                   .arg(QString::fromStdString(playback_->warnings().front().toString()));
  // A project brings its own tear quality: say so when it replaces the one shown.
  if (qualityChanged)
    summary += tr("; tear quality %1 (the file's)")
                   .arg(QString::fromUtf8(toString(playback_->scene().quality.level).data()));
  statusBar()->showMessage(summary);
  for (const Diagnostic& d : playback_->warnings())
    std::fprintf(stderr, "warning: %s\n", d.toString().c_str());
  display(playback_->view());
  updateTransport();
  emit fileOpened(path);
  return true;
}

void PlayerWindow::reportError(const std::exception& error, const QString& path) {
  const ErrorReport report = describeError(error, path);
  std::fprintf(stderr, "lacrima-player: %s\n", report.oneLine.toLocal8Bit().constData());
  // Only an animation that is there can be said to stay.
  const QString name = QFileInfo(path).fileName();
  const QString loaded = QFileInfo(QString::fromStdString(playback_->path())).fileName();
  statusBar()->showMessage(
      playback_->frameCount() == 0 ? tr("Could not open %1").arg(name)
      : loaded.isEmpty()
          ? tr("Could not open %1 (the previous animation is still loaded)").arg(name)
          : tr("Could not open %1 (%2 is still loaded)").arg(name, loaded));
  emit openFailed(report.oneLine);
  if (!errorDialogs_) return;
  auto* box =
      new QMessageBox(QMessageBox::Critical, tr("Cannot open %1").arg(QFileInfo(path).fileName()),
                      report.html(), QMessageBox::Ok, this);
  box->setObjectName("openErrorDialog");
  box->setDetailedText(report.oneLine);
  box->setAttribute(Qt::WA_DeleteOnClose);
  box->open();
}

appsupport::ExportDialog* PlayerWindow::exportDialog() {
  appsupport::ExportSource source;
  source.file = QString::fromStdString(playback_->path());
  if (source.file.isEmpty()) return nullptr;
  // The head shown, named explicitly: a FAP file opened after a project plays on that head.
  if (head_)
    source.headArguments = {"--mesh", QString::fromStdString(head_->mesh), "--fdp",
                            QString::fromStdString(head_->fdp)};
  source.frameCount = playback_->frameCount();
  auto* dialog = new appsupport::ExportDialog(source, this);
  dialog->setAttribute(Qt::WA_DeleteOnClose);
  dialog->show();
  return dialog;
}

void PlayerWindow::chooseFile() {
  const QString dir = playback_->path().empty()
                          ? QString()
                          : QFileInfo(QString::fromStdString(playback_->path())).absolutePath();
  const QString path = QFileDialog::getOpenFileName(
      this, tr("Open an animation"), dir,
      tr("Animations (*.fap *.json *.lacrima);;FAP files (*.fap);;Lacrima projects (*.json "
         "*.lacrima);;All files (*)"));
  if (!path.isEmpty()) openFile(path);
}

void PlayerWindow::openDemo() {
  try {
    openFile(QString::fromStdString(findMediaFile("demo/crying.fap")));
  } catch (const std::exception& e) {
    reportError(e, "demo/crying.fap");
  }
}

void PlayerWindow::play() {
  if (playing()) return;
  if (isLive()) {
    clock_.play();
    ticker_->setInterval(kLiveTickMilliseconds);
    ticker_->start();
    updatePlayIcon();
    return;
  }
  if (playback_->frameCount() == 0) return;
  ticker_->setInterval(kFileTickMilliseconds);
  // At the end, Play starts over (the tears replay from the first checkpoint).
  if (playback_->currentTime() >= playback_->duration()) seek(0);
  clock_.setTime(playback_->currentTime());
  clock_.play();
  ticker_->start();
  updatePlayIcon();
}

void PlayerWindow::pause() {
  clock_.pause();
  ticker_->stop();
  updatePlayIcon();
  fpsLabel_->setText(tr("paused"));
}

void PlayerWindow::togglePlay() { playing() ? pause() : play(); }

void PlayerWindow::resetPlayback() {
  const bool live = isLive() && playing();
  pause();
  source_->reset();
  clock_.setTime(0);
  display(source_->view());
  if (live) play();  // a stream goes on: Reset clears the tears
  updateTransport();
}

void PlayerWindow::seek(double seconds) {
  if (isLive() || playback_->frameCount() == 0) return;
  display(playback_->seek(seconds));
  clock_.setTime(playback_->currentTime());
  updateTransport();
}

void PlayerWindow::tick() {
  if (isLive()) {
    const double now = live::liveClockSeconds();
    // While a stream arrives regularly, a render starts only when it will not keep the next
    // frame waiting (LivePacer.h); a frame that arrives meanwhile ticks at once.
    if (const playback::LivePacer::Decision d = pacer_.decide(now, live_->frameWaiting());
        !d.render) {
      const auto wait = static_cast<int>(std::ceil((d.wakeAt - now) * 1000));
      ticker_->setInterval(std::clamp(wait, 1, kLiveTickMilliseconds));
      return;
    }
    if (ticker_->interval() != kLiveTickMilliseconds) ticker_->setInterval(kLiveTickMilliseconds);
    liveTickAt_ = now;
    display(live_->seek(now));
    // Nothing new to draw (the viewport renders nothing): no render to time.
    if (!viewport_->renderPending()) liveTickAt_ = -1;
    // --record keeps what the face shows: the generator's face too while moods drive it.
    if (live_->moodDriven()) session_->recordGenerated(live_->shownValues(), now);
    // Each tear step once, when it is first shown (the steps run on the source's worker).
    if (const auto tears = live_->tearFrame(); tears && tears->request != liveTearsCosted_) {
      liveTearsCosted_ = tears->request;
      const playback::ProducerTimes& t = tears->times;
      effects_->addFrameCost(t.simulation + t.surface + t.trails, t.substeps);
    }
    updateTransport();
    liveFrameArrived();
    return;
  }
  double t = clock_.time();
  const double end = playback_->duration();
  const double reachable = (playback_->currentFrame() + kMaxFramesPerTick) / playback_->frameRate();
  if (t > reachable) {
    t = reachable;
    clock_.setTime(t);
  }
  const long long framesBefore = playback_->producer().counters().frames;
  display(playback_->seek(std::min(t, end)));
  recordTearCost(framesBefore);
  if (t >= end && loop_->isChecked()) {
    // From the first checkpoint, as Play at the end does: every pass shows the same tears.
    display(playback_->seek(0));
    clock_.setTime(0);
  } else if (t >= end) {
    pause();
  }
  updateTransport();
}

// Only frames produced by a tick of playing: seeking replays from a checkpoint, which says
// nothing about the cost of a frame as it plays. Of a tick's frames the last is measured.
void PlayerWindow::recordTearCost(long long framesBefore) {
  const playback::FrameProducer& producer = source_->producer();
  if (producer.counters().frames == framesBefore) return;  // the tick stayed on its frame
  const playback::ProducerTimes& t = producer.lastTimes();
  effects_->addFrameCost(t.simulation + t.surface + t.trails, t.substeps);
}

void PlayerWindow::setTearQuality(TearQuality level) {
  tearQuality_ = level;
  applyTearQuality();
  effects_->display(source_->scene());
  display(source_->view());
  updateTransport();
}

void PlayerWindow::setSimulationThreads(int threads) {
  simulationThreads_ = threads;
  playback_->setSimulationThreads(threads);
  if (live_) live_->setSimulationThreads(threads);
}

void PlayerWindow::applyTearQuality() {
  if (!tearQuality_ || source_->scene().quality.level == *tearQuality_) return;
  SceneSettings scene = source_->scene();
  scene.quality.level = *tearQuality_;
  source_->setScene(scene);
}

void PlayerWindow::display(const playback::FrameView& view) { viewport_->showFrame(view); }

void PlayerWindow::applyScene() {
  SceneSettings scene = source_->scene();
  effects_->applyTo(scene);
  scene.simulation = parameters_->values();
  const bool restart = playback::restartsTears(source_->scene(), scene);
  if (restart) QApplication::setOverrideCursor(Qt::WaitCursor);
  try {
    source_->setScene(scene);
  } catch (const std::exception& e) {
    statusBar()->showMessage(tr("Parameters refused: %1").arg(QString::fromUtf8(e.what())));
  }
  if (restart) {
    QApplication::restoreOverrideCursor();
    statusBar()->showMessage(tr("Tear parameters or quality changed: the tears restarted"), 4000);
  }
  clock_.setTime(source_->currentTime());
  display(source_->view());
  updateTransport();
}

// Dragging (paused meanwhile), a click on the groove or a key: the clock follows, so playing
// goes on from there.
void PlayerWindow::timelineMoved(int milliseconds) { seek(milliseconds / 1000.0); }

void PlayerWindow::updateTransport() {
  if (isLive()) {
    const QSignalBlocker block(timeline_);
    timeline_->setEnabled(false);
    play_->setEnabled(true);
    // No position in a stream: the indicator says it is live, and since when.
    timeLabel_->setText(tr("\u25CF LIVE %1").arg(clockText(live_->currentTime())));
    if (live_->moodDriven())
      frameLabel_->setText(tr("moods %1, seed %2: %3 frames generated")
                               .arg(QString::fromStdString(toString(live_->moods())))
                               .arg(live_->moodSeed())
                               .arg(live_->currentFrame()));
    else
      frameLabel_->setText(tr("%1 frames received, %2 shown, %3 dropped")
                               .arg(live_->framesReceived())
                               .arg(live_->currentFrame())
                               .arg(live_->framesDropped()));
    const auto tears = live_->tearFrame();
    const int particles = tears ? tears->particleCount : 0;
    const playback::ProducerTimes t = tears ? tears->times : playback::ProducerTimes{};
    tearsLabel_->setText(particles > 0 ? tr("%1 tear particles (%2 ms)")
                                             .arg(particles)
                                             .arg(t.simulation + t.surface + t.trails, 0, 'f', 1)
                                       : QString());
    return;
  }
  timeLabel_->setStyleSheet(QString());
  const bool loaded = playback_->frameCount() > 0;
  {
    const QSignalBlocker block(timeline_);
    timeline_->setEnabled(loaded);
    timeline_->setValue(static_cast<int>(std::lround(playback_->currentTime() * 1000)));
  }
  play_->setEnabled(loaded);
  timeLabel_->setText(clockText(playback_->currentTime()) + " / " +
                      clockText(playback_->duration()));
  frameLabel_->setText(
      loaded ? tr("frame %1 / %2").arg(playback_->currentFrame()).arg(playback_->frameCount() - 1)
             : tr("no animation"));
  const playback::ProducerTimes& t = playback_->producer().lastTimes();
  const int particles = playback_->producer().particleCount();
  tearsLabel_->setText(particles > 0 ? tr("%1 tear particles (%2 ms)")
                                           .arg(particles)
                                           .arg(t.simulation + t.surface + t.trails, 0, 'f', 1)
                                     : (playback_->hasTears() ? tr("no tears now") : QString()));
}

void PlayerWindow::updatePlayIcon() {
  const bool on = playing();
  play_->setIcon(style()->standardIcon(on ? QStyle::SP_MediaPause : QStyle::SP_MediaPlay));
  play_->setText(on ? tr("&Pause") : tr("&Play"));
  play_->setToolTip(on ? tr("Pause (Space)") : tr("Play (Space)"));
}

void PlayerWindow::countRender() {
  const qint64 now = sinceStart_.elapsed();
  renderTimes_.push_back(now);
  while (!renderTimes_.empty() && renderTimes_.front() < now - 1000) renderTimes_.pop_front();
  // Over the last second, or since the first render of a burst when that is shorter.
  const double span =
      renderTimes_.size() > 1 ? static_cast<double>(renderTimes_.back() - renderTimes_.front()) : 0;
  fps_ = span > 0 ? (static_cast<double>(renderTimes_.size()) - 1) * 1000.0 / span : 0;
  fpsLabel_->setText(playing() ? tr("%1 fps").arg(fps_, 0, 'f', 0) : tr("paused"));
}

void PlayerWindow::setCameraPreset(scene::CameraPreset preset) {
  cameraPreset_ = preset;
  viewport_->setView(presetView(*rig_, preset));
  if (QAction* a = cameraAction(preset)) a->setChecked(true);
}

QAction* PlayerWindow::cameraAction(scene::CameraPreset preset) const {
  const auto index = static_cast<std::size_t>(preset);
  return index < cameraActions_.size() ? cameraActions_[index] : nullptr;
}

void PlayerWindow::showRigWarnings() {
  QStringList warnings;
  for (const std::string& w : rig_->warnings) warnings << QString::fromStdString(w);
  rigWarnings_->setWarnings(warnings, tr("the head's rig"));
}

void PlayerWindow::dragEnterEvent(QDragEnterEvent* event) {
  const QList<QUrl> urls = event->mimeData()->urls();
  if (urls.size() == 1 && urls.front().isLocalFile()) event->acceptProposedAction();
}

void PlayerWindow::dropEvent(QDropEvent* event) {
  const QList<QUrl> urls = event->mimeData()->urls();
  if (urls.size() != 1 || !urls.front().isLocalFile()) return;
  event->acceptProposedAction();
  // Open after the drop returns, so the drag source is not kept waiting by a dialog.
  const QString path = urls.front().toLocalFile();
  QTimer::singleShot(0, this, [this, path] { openFile(path); });
}

void PlayerWindow::listen(const live::ListenUrl& url) {
  session_->listen(url);  // throws before anything changes
  startLiveSource();
  if (QWidget* box = findChild<QWidget*>(QStringLiteral("liveBox"))) box->setVisible(true);
  stopListening_->setEnabled(true);
  setWindowTitle(tr("Live - Lacrima Player"));
  QStringList urls;
  for (const auto& input : session_->inputs()) urls << input->url().toString();
  statusBar()->showMessage(tr("Listening on %1").arg(urls.join(QStringLiteral(", "))));
  liveStatusShown_ = -1000;
  liveFrameArrived();
}

// The source of streams and moods, when there is none yet: the scene as the panels show it,
// the eye redness following the tears shed (neither has progress to follow), playing.
void PlayerWindow::startLiveSource() {
  if (live_) return;
  pause();
  live_ = std::make_unique<playback::LiveSource>(*rig_);
  liveTearsCosted_ = 0;
  pacer_.reset();
  liveTickAt_ = -1;
  live_->setSimulationThreads(simulationThreads_);
  SceneSettings scene = live_->scene();
  scene.simulation = parameters_->values();
  effects_->applyTo(scene);
  scene.redness = SceneSettings::Redness::Tears;
  if (tearQuality_) scene.quality.level = *tearQuality_;
  live_->setScene(scene);
  live_->setTears(static_cast<float>(livePanel_->tearsLeft()),
                  static_cast<float>(livePanel_->tearsRight()));
  live_->setMoodSeed(moodPanel_->seed());
  source_ = live_.get();
  effects_->display(live_->scene());
  timeLabel_->setStyleSheet(QStringLiteral("color: #e04040; font-weight: bold"));
  play();
}

void PlayerWindow::stopLiveSource() {
  if (!live_) return;
  pause();
  source_ = playback_.get();
  live_.reset();
  effects_->display(playback_->scene());
  display(playback_->view());
  updateTransport();
}

void PlayerWindow::stopListening() {
  if (!live_) return;
  const bool wasListening = session_->listening();
  session_->stopListening();
  stopLiveSource();
  stopListening_->setEnabled(false);
  if (QWidget* box = findChild<QWidget*>(QStringLiteral("liveBox"))) box->setVisible(false);
  if (wasListening) statusBar()->showMessage(tr("Stopped listening"), 4000);
}

void PlayerWindow::playMoods(const MoodLevels& levels) {
  const bool starting = !live_;
  startLiveSource();
  if (!live_->moodDriven()) {
    // The generator's blush is a colour of its own: show it (the Effects box can hide it).
    SceneSettings scene = live_->scene();
    scene.blush = true;
    live_->setScene(scene);
    effects_->display(scene);
  }
  live_->setMoods(levels);
  moodPanel_->display(live_->moods(), live_->moodSeed());
  if (starting) setWindowTitle(tr("Moods - Lacrima Player"));
  statusBar()->showMessage(tr("Crying generator: %1, seed %2")
                               .arg(QString::fromStdString(toString(live_->moods())))
                               .arg(live_->moodSeed()),
                           4000);
  if (!playing()) play();
  updateTransport();
}

void PlayerWindow::setMoodSeed(std::uint64_t seed) {
  if (live_) live_->setMoodSeed(seed);
  moodPanel_->display(live_ ? live_->moods() : moodPanel_->levels(), seed);
}

void PlayerWindow::chooseStream() {
  bool ok = false;
  const QString text = QInputDialog::getText(
      this, tr("Listen to a live stream"),
      tr("fap+tcp://HOST:PORT (FAP text, e.g. from an agent or lacrima-send)\n"
         "fap+udp://HOST:PORT (one frame per datagram)\n"
         "livelink+udp://HOST:PORT (Live Link Face, port 11111)\n"
         "Without HOST only this machine can send (127.0.0.1); 0.0.0.0 listens on every "
         "network."),
      QLineEdit::Normal, QStringLiteral("fap+tcp://127.0.0.1:5555"), &ok);
  if (!ok || text.isEmpty()) return;
  QString error;
  const std::optional<live::ListenUrl> url = live::parseListenUrl(text, error);
  try {
    if (!url) throw std::runtime_error(error.toStdString());
    listen(*url);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "lacrima-player: %s\n", e.what());
    statusBar()->showMessage(tr("Cannot listen: %1").arg(QString::fromStdString(e.what())));
    if (errorDialogs_)
      QMessageBox::warning(this, tr("Cannot listen"), QString::fromStdString(e.what()));
  }
}

// At most a few times a second: a flood of datagrams must not become a flood of repaints.
void PlayerWindow::liveFrameArrived() {
  if (!live_) return;
  const qint64 now = sinceStart_.elapsed();
  if (now - liveStatusShown_ < 250) return;
  liveStatusShown_ = now;
  livePanel_->showStatus(session_->statusText());
}

LiveMappingDialog& PlayerWindow::mappingDialog() {
  if (!mappingDialog_) {
    LiveLinkMapping mapping = session_->mapping();
    if (mapping.rows.empty()) {
      try {
        mapping = live::defaultLiveLinkMapping();
      } catch (const std::exception& e) {
        std::fprintf(stderr, "lacrima-player: %s\n", e.what());
      }
    }
    mappingDialog_ = new LiveMappingDialog(mapping, this);
    connect(mappingDialog_, &LiveMappingDialog::applied, this, [this](const LiveLinkMapping& m) {
      session_->setMapping(m);
      statusBar()->showMessage(tr("Live Link mapping applied"), 4000);
    });
  }
  return *mappingDialog_;
}

void PlayerWindow::editMapping() {
  LiveMappingDialog& dialog = mappingDialog();
  dialog.show();
  dialog.raise();
}

}  // namespace lacrima::player
