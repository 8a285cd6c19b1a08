#include <lacrima/editor/PreviewPanel.h>

#include <lacrima/common/FapTable.h>
#include <lacrima/editing/EditorModel.h>
#include <lacrima/editing/FrameStepClock.h>
#include <lacrima/editor/EditorTheme.h>
#include <lacrima/editor/HeadRigWork.h>
#include <lacrima/editor/RigJob.h>

#include <lacrima/playback/FrameProducer.h>
#include <lacrima/playback/HeadRig.h>
#include <lacrima/playback/PreviewWorker.h>
#include <lacrima/viewport/ElidedLabel.h>
#include <lacrima/viewport/FaceViewport.h>
#include <lacrima/viewport/WarningsButton.h>

#include <QElapsedTimer>
#include <QEventLoop>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QImage>
#include <QLabel>
#include <QTimer>
#include <QToolButton>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

namespace lacrima::editor {

struct PreviewPanel::State {
  std::shared_ptr<playback::HeadRig> rig;  // the head shown (kept while a failure is shown)
  // The face, posed on this thread at once (pose() only: it never simulates).
  std::unique_ptr<playback::FrameProducer> producer;
  // The tears, on their own thread. Workers of a former head finish their last step in
  // `retiring` (they share that head's rig) and are let go once their threads have ended.
  std::unique_ptr<playback::PreviewWorker> worker;
  std::vector<std::unique_ptr<playback::PreviewWorker>> retiring;
  // What the viewport shows: the face's revision and the tear frame drawn over it.
  long long faceRevision = -1;
  std::shared_ptr<const playback::PreviewFrame> tears;
  long long revision = 0;
  viewport::FaceViewport* viewport = nullptr;
  RigJob job;
  bool following = false;  // followDocumentHead() was called: rig the document's head
  bool failed = false;     // the target's rig failed (a file missing, a bad file)
  // The head the panel shows or is rigging (nullopt inside: the default head); unset before
  // the first request, so the first sync always starts a job.
  std::optional<std::optional<HeadFiles>> target;
  QElapsedTimer rigTimer;
};

namespace {

QString headName(const std::optional<HeadFiles>& head) {
  return head ? QFileInfo(QString::fromStdString(head->mesh)).fileName()
              : PreviewPanel::tr("the default head");
}

}  // namespace

PreviewPanel::PreviewPanel(editing::EditorModel& model, editing::FrameStepClock& clock,
                           QWidget* parent)
    : QWidget(parent), state_(std::make_unique<State>()), model_(model), clock_(clock) {
  setObjectName(QStringLiteral("preview"));
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->setSpacing(0);

  auto* bar = new QWidget(this);
  auto* barLayout = new QHBoxLayout(bar);
  barLayout->setContentsMargins(6, 3, 6, 3);
  tearToggle_ = new QToolButton(bar);
  tearToggle_->setText(tr("Tear preview"));
  tearToggle_->setCheckable(true);
  tearToggle_->setChecked(tearPreview_);
  tearToggle_->setToolTip(tr("Simulate the tears while paused when a tear channel is above 0 (T)"));
  auto* resetTears = new QToolButton(bar);
  resetTears->setText(tr("Clear tears"));
  resetTears->setToolTip(
      tr("Remove every tear particle and trail; they build up again from the tear channels"));
  // The status can name a file and a warning: cut to the room there is, whole in the tooltip;
  // the warnings themselves are read in full through the button beside it.
  status_ = new viewport::ElidedLabel(bar);
  status_->setObjectName(QStringLiteral("previewStatus"));
  status_->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
  warnings_ = new viewport::WarningsButton(bar);
  // While paused the tears run on from whatever they were, to show the pose's tears as you
  // work: what the player shows at this time may differ (it has wept since 0 s). Say so.
  approximate_ = new viewport::ElidedLabel(bar);
  approximate_->setText(tr("live tears, not the animation's"));
  approximate_->setObjectName(QStringLiteral("approximateTears"));
  approximate_->setToolTip(
      tr("Paused, the tears keep running from where they were, for the pose at the playhead. "
         "The animation's own tears at this time (what lacrima-player shows) are the ones "
         "played from 0 s: play from the start to see them."));
  QPalette amber = approximate_->palette();
  amber.setColor(QPalette::WindowText, QColor(0xe6, 0xb4, 0x3c));
  approximate_->setPalette(amber);
  approximate_->hide();
  QPalette dim = status_->palette();
  dim.setColor(QPalette::WindowText, dim.color(QPalette::WindowText).darker(125));
  status_->setPalette(dim);
  barLayout->addWidget(tearToggle_);
  barLayout->addWidget(resetTears);
  // The note first: the status is in the status bar too.
  barLayout->addWidget(approximate_, 3);
  barLayout->addWidget(status_, 2);
  barLayout->addWidget(warnings_);
  layout->addWidget(bar);

  message_ = new QLabel(this);
  message_->setAlignment(Qt::AlignCenter);
  message_->setWordWrap(true);
  message_->setMargin(24);
  message_->setAutoFillBackground(true);
  QPalette dark = message_->palette();
  dark.setColor(QPalette::Window, QColor(0x17, 0x18, 0x1b));
  dark.setColor(QPalette::WindowText, QColor(0x9a, 0x9e, 0xa6));
  message_->setPalette(dark);
  message_->setText(tr("The head loads once the window is up…"));
  message_->setMinimumSize(320, 240);
  layout->addWidget(message_, 1);

  tearToggle_->setObjectName(QStringLiteral("tearPreviewToggle"));
  // Fusion draws a checked tool button barely darker on this dark palette: fill it with the
  // tear colour so "on" reads at a glance.
  const QColor tear = theme::tearBlue();
  tearToggle_->setStyleSheet(
      QStringLiteral("QToolButton { padding: 2px 8px; border: 1px solid #50545b; border-radius: "
                     "3px; background: #36393e; }"
                     "QToolButton:hover { border-color: %1; }"
                     "QToolButton:checked { background: %2; border-color: %1; color: #ffffff; }")
          .arg(tear.name(), tear.darker(170).name()));

  idle_ = new QTimer(this);
  connect(idle_, &QTimer::timeout, this, [this] { step(model_.frameDuration()); });
  connect(tearToggle_, &QToolButton::toggled, this, &PreviewPanel::setTearPreview);
  connect(resetTears, &QToolButton::clicked, this, [this] {
    if (!state_->worker) return;
    state_->worker->clearTears();
    draw();
    if (figuresShown_) showFigures();
  });
  connect(&model_, &editing::EditorModel::valuesChanged, this, &PreviewPanel::onValuesChanged);
  connect(&clock_, &editing::FrameStepClock::ticked, this, &PreviewPanel::step);
  connect(&clock_, &editing::FrameStepClock::playingChanged, this, &PreviewPanel::updateIdleTimer);
  connect(&model_, &editing::EditorModel::documentReset, this, [this] {
    syncHead(true);  // a project naming another head, or the same one whose file is back
    if (state_->producer) state_->producer->reset();
    if (state_->worker) state_->worker->clearTears();
    onValuesChanged();
  });
  connect(&state_->job, &RigJob::progress, this, [this](double fraction, const QString& stage) {
    const QString text = tr("rigging %1: %2 (%3%)")
                             .arg(headName(*state_->target), stage)
                             .arg(std::lround(100 * fraction));
    setStatus(text);
    if (!hasHead()) message_->setText(text);
  });
  connect(&state_->job, &RigJob::finished, this, &PreviewPanel::installRig);
  connect(&state_->job, &RigJob::failed, this, &PreviewPanel::showRigFailure);
  connect(&model_, &editing::EditorModel::settingsChanged, this, [this] {
    syncHead(false);  // File > Choose head…, or its undo
    if (!state_->producer) return;
    if (!(state_->producer->scene() == model_.document().scene))
      state_->producer->setScene(model_.document().scene);
    state_->worker->setScene(model_.document().scene);
    state_->worker->setTearSources(model_.document().tearSources);
    draw();
  });
}

PreviewPanel::~PreviewPanel() {
  // Workers first, while the panel is whole: each waits for its running step, and their
  // frame-ready callbacks (which post to this panel) are over once they are gone.
  state_->worker.reset();
  state_->retiring.clear();
}

bool PreviewPanel::hasHead() const { return state_->producer != nullptr; }

int PreviewPanel::headVertexCount() const {
  return hasHead() ? state_->rig->head.vertexCount() : 0;
}

QStringList PreviewPanel::headWarnings() const {
  QStringList lines;
  if (state_->rig)
    for (const std::string& w : state_->rig->warnings) lines << QString::fromStdString(w);
  return lines;
}

QString PreviewPanel::statusText() const { return statusText_; }

QString PreviewPanel::messageText() const {
  return message_->isHidden() ? QString() : message_->text();
}

void PreviewPanel::setStatus(const QString& text) {
  if (text == statusText_) return;
  statusText_ = text;
  status_->setText(text);
  emit statusChanged(text);
}

void PreviewPanel::showMessage(const QString& text) {
  message_->setText(text);
  if (state_->viewport) state_->viewport->hide();
  message_->show();
}

void PreviewPanel::followDocumentHead() {
  state_->following = true;
  syncHead(false);
}

bool PreviewPanel::loadHead() {
  followDocumentHead();
  if (state_->job.running()) {
    QEventLoop loop;
    connect(this, &PreviewPanel::headReady, &loop, &QEventLoop::quit);
    connect(this, &PreviewPanel::headFailed, &loop, &QEventLoop::quit);
    loop.exec();
  }
  return hasHead();
}

// Starts rigging the document's head unless it is the one shown or being rigged already (or,
// without `retryFailed`, the one that just failed: other settings edits do not rig it again).
void PreviewPanel::syncHead(bool retryFailed) {
  if (!state_->following) return;
  const std::optional<HeadFiles>& wanted = model_.document().head;
  if (state_->target && *state_->target == wanted && !(retryFailed && state_->failed)) return;
  state_->target = wanted;
  state_->failed = false;
  state_->rigTimer.start();
  const QString name = headName(wanted);
  setStatus(tr("rigging %1…").arg(name));
  if (!hasHead()) showMessage(tr("Rigging %1…").arg(name));
  if (!wanted) {
    state_->job.start(defaultHeadWork());
    return;
  }
  // Checked here, not left to the mesh reader, so the message names the project's field.
  ProjectDocument probe;
  probe.head = wanted;
  if (auto missing = probe.missingHeadFile(model_.document().name)) {
    state_->job.start(failingWork(std::move(*missing)));
    return;
  }
  state_->job.start(headFilesWork(wanted->mesh, wanted->fdp));
}

void PreviewPanel::installRig(std::shared_ptr<playback::HeadRig> rig) {
  // The producer and the viewport refer to the old rig's head: replace them first, then let
  // the old rig go (at the end of this function).
  std::shared_ptr<playback::HeadRig> old = std::move(state_->rig);
  retireWorker();
  state_->producer.reset();
  state_->rig = std::move(rig);
  if (!state_->viewport) {
    state_->viewport = new viewport::FaceViewport(this);
    state_->viewport->setObjectName(QStringLiteral("faceViewport"));
    static_cast<QVBoxLayout*>(layout())->addWidget(state_->viewport, 1);
  }
  state_->viewport->setHead(state_->rig->head);
  message_->hide();
  state_->viewport->show();  // a child added to a visible parent stays hidden until shown
  layout()->activate();
  if (!state_->viewport->usesOgre()) {
    // Nothing can be drawn here (no X display): say why, and spend no time simulating.
    setStatus(state_->viewport->message());
    emit headReady();
    return;
  }
  state_->producer =
      std::make_unique<playback::FrameProducer>(*state_->rig, model_.document().scene);
  state_->worker = std::make_unique<playback::PreviewWorker>(
      state_->rig, model_.document().scene, model_.document().tearSources, simulationThreads_);
  // On the worker thread: only post. A post to a panel being destroyed is dropped with it,
  // and the destructor ends the workers before that anyway.
  state_->worker->setFrameReady([this] {
    QMetaObject::invokeMethod(this, &PreviewPanel::onTearsReady, Qt::QueuedConnection);
  });
  figuresShown_ = false;
  QString text = tr("%1 ready in %2 ms · %3 vertices")
                     .arg(headName(*state_->target))
                     .arg(state_->rigTimer.elapsed())
                     .arg(state_->rig->head.vertexCount());
  const QStringList warnings = headWarnings();
  if (!warnings.isEmpty()) {
    // The first warning in the line (a head without eyes: "tears disabled"), all in the list.
    text += tr(" · %n warning(s): %1", nullptr, static_cast<int>(warnings.size()))
                .arg(warnings.front());
  }
  warnings_->setWarnings(warnings, tr("%1's rig").arg(headName(*state_->target)));
  setStatus(text);
  onValuesChanged();
  emit headReady();
}

void PreviewPanel::showRigFailure(const QString& error) {
  state_->failed = true;
  retireWorker();
  state_->producer.reset();  // keeps the rig: the hidden viewport still points at its head
  idle_->stop();
  warnings_->setWarnings({}, {});
  if (*state_->target) {
    showMessage(tr("No preview: the project's head could not be loaded.\n\n%1\n\nUse File > "
                   "Choose head… to point the project at the mesh and feature-point files. Until "
                   "then the editor works without a preview, and saving keeps the project's head "
                   "entry as it is.")
                    .arg(error));
    setStatus(tr("head missing"));
  } else {
    showMessage(tr("No preview: %1\n\nThe editor works without it; the tear channels still export.")
                    .arg(error));
    setStatus(tr("no head"));
  }
  emit headFailed(error);
}

void PreviewPanel::setTearPreview(bool on) {
  if (on == tearPreview_) return;
  tearPreview_ = on;
  const QSignalBlocker block(tearToggle_);
  tearToggle_->setChecked(on);
  onValuesChanged();
}

int PreviewPanel::particleCount() const {
  if (!state_->worker) return 0;
  const auto frame = state_->worker->currentFrame();
  return frame ? frame->particleCount : 0;
}

double PreviewPanel::lastProduceMilliseconds() const {
  const auto frame = state_->worker ? state_->worker->currentFrame() : nullptr;
  return frame ? frame->times.total() : 0.0;
}

// A former head's worker: it may be in a step of seconds; let it end on its own thread.
void PreviewPanel::retireWorker() {
  auto& retiring = state_->retiring;
  retiring.erase(
      std::remove_if(retiring.begin(), retiring.end(), [](const auto& w) { return w->stopped(); }),
      retiring.end());
  if (!state_->worker) return;
  state_->worker->stop();
  retiring.push_back(std::move(state_->worker));
  state_->tears.reset();
  state_->faceRevision = -1;
}

QWidget* PreviewPanel::viewportWidget() const {
  return state_->viewport && !state_->viewport->isHidden() ? state_->viewport : nullptr;
}

QImage PreviewPanel::grabFrame() {
  if (viewportWidget()) return state_->viewport->grabFrame();
  return {};
}

namespace {

double progressAt(const editing::EditorModel& model) {
  const double duration = model.endTime();
  return duration > 0 ? std::clamp(model.currentTime() / duration, 0.0, 1.0) : 0.0;
}

}  // namespace

// The face posed now with the worker's newest tears over it; the viewport draws it when the
// revision moved (a new face or another tear frame).
void PreviewPanel::draw() {
  State& s = *state_;
  if (!s.producer) return;
  const playback::FrameView& face = s.producer->view();
  auto tears = s.worker ? s.worker->currentFrame() : nullptr;
  if (face.revision == s.faceRevision && tears == s.tears) return;
  s.faceRevision = face.revision;
  s.tears = std::move(tears);
  playback::FrameView view = s.tears ? s.tears->over(face) : face;
  view.revision = ++s.revision;
  s.viewport->showFrame(view);
}

void PreviewPanel::pose() {
  if (!state_->producer) return;
  const FapValues& values = model_.currentValues();
  state_->producer->pose(values, progressAt(model_));
  // Tears only while a channel asks for them: set to 0, they go now, not after a step.
  if (!playback::tearsCommanded(*state_->rig, values)) state_->worker->clearTears();
  draw();
  if (figuresShown_) showFigures();
}

void PreviewPanel::step(double dt) {
  if (!state_->producer) return;
  const double progress = progressAt(model_);
  const FapValues& values = model_.currentValues();
  state_->producer->pose(values, progress);
  state_->worker->request({values, dt, progress});
  draw();
  if (figuresShown_ || particleCount() > 0) showFigures();
}

void PreviewPanel::waitForTears() {
  if (!state_->worker) return;
  state_->worker->waitIdle();
  onTearsReady();
}

void PreviewPanel::onTearsReady() {
  if (!state_->worker) return;
  draw();
  showFigures();
  const auto frame = state_->worker->currentFrame();
  if (frame && frame->request != steppedRequest_ && frame->times.substeps > 0) {
    steppedRequest_ = frame->request;
    const playback::ProducerTimes& t = frame->times;
    emit tearsStepped(t.simulation + t.surface + t.trails, t.substeps);
  }
}

void PreviewPanel::showFigures() {
  figuresShown_ = true;
  QString text = tr("%1 particles").arg(particleCount());
  if (particleCount() > 0) text += tr(" · step %1 ms").arg(lastProduceMilliseconds(), 0, 'f', 1);
  // The rig's warnings stay in view (listed by the button) once the figures take the line.
  if (const auto count = static_cast<int>(state_->rig->warnings.size()); count > 0)
    text += tr(" · %n rig warning(s)", nullptr, count);
  setStatus(text);
}

void PreviewPanel::onValuesChanged() {
  updateIdleTimer();
  // The face follows at once, playing or not; the tears follow on the next request.
  pose();
}

void PreviewPanel::updateIdleTimer() {
  const FapValues& v = model_.currentValues();
  const bool tears = v[static_cast<std::size_t>(channelIndex(kTearLeftFap))] >= 1.0f ||
                     v[static_cast<std::size_t>(channelIndex(kTearRightFap))] >= 1.0f;
  const bool run = hasHead() && tearPreview_ && tears && !clock_.isPlaying();
  if (run && !idle_->isActive()) {
    idle_->start(static_cast<int>(std::lround(1000.0 * model_.frameDuration())));
  } else if (!run && idle_->isActive()) {
    idle_->stop();
  }
  approximate_->setVisible(run);
}

bool PreviewPanel::showsLiveTears() const { return approximate_->isVisibleTo(this); }

}  // namespace lacrima::editor
