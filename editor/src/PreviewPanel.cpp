#include <lacrima/editor/PreviewPanel.h>

#include <lacrima/common/FapTable.h>
#include <lacrima/editing/EditorModel.h>
#include <lacrima/editing/FrameStepClock.h>
#include <lacrima/editor/EditorTheme.h>

#include <lacrima/playback/FrameProducer.h>
#include <lacrima/playback/HeadRig.h>
#include <lacrima/viewport/FaceViewport.h>

#include <QElapsedTimer>
#include <QHBoxLayout>
#include <QImage>
#include <QLabel>
#include <QTimer>
#include <QToolButton>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace lacrima::editor {

struct PreviewPanel::State {
  std::unique_ptr<playback::HeadRig> rig;
  std::unique_ptr<playback::FrameProducer> producer;
  viewport::FaceViewport* viewport = nullptr;
  bool attempted = false;
};

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
  status_ = new QLabel(bar);
  status_->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
  QPalette dim = status_->palette();
  dim.setColor(QPalette::WindowText, dim.color(QPalette::WindowText).darker(125));
  status_->setPalette(dim);
  barLayout->addWidget(tearToggle_);
  barLayout->addWidget(resetTears);
  barLayout->addStretch(1);
  barLayout->addWidget(status_);
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
  message_->setText(tr("Loading the head…"));
  message_->setMinimumSize(320, 240);
  layout->addWidget(message_, 1);

  idle_ = new QTimer(this);
  connect(idle_, &QTimer::timeout, this, [this] { step(model_.frameDuration()); });
  connect(tearToggle_, &QToolButton::toggled, this, &PreviewPanel::setTearPreview);
  connect(resetTears, &QToolButton::clicked, this, [this] {
    if (state_->producer) {
      state_->producer->reset();
      pose();
    }
  });
  connect(&model_, &editing::EditorModel::valuesChanged, this, &PreviewPanel::onValuesChanged);
  connect(&clock_, &editing::FrameStepClock::ticked, this, &PreviewPanel::step);
  connect(&clock_, &editing::FrameStepClock::playingChanged, this, &PreviewPanel::updateIdleTimer);
  connect(&model_, &editing::EditorModel::documentReset, this, [this] {
    if (state_->producer) state_->producer->reset();
    onValuesChanged();
  });
  connect(&model_, &editing::EditorModel::settingsChanged, this, [this] {
    if (!state_->producer) return;
    if (!(state_->producer->scene() == model_.document().scene))
      state_->producer->setScene(model_.document().scene);
    state_->producer->setTearSources(model_.document().tearSources);
  });
}

PreviewPanel::~PreviewPanel() = default;

bool PreviewPanel::hasHead() const { return state_->producer != nullptr; }

QString PreviewPanel::statusText() const { return statusText_; }

void PreviewPanel::setStatus(const QString& text) {
  if (text == statusText_) return;
  statusText_ = text;
  status_->setText(text);
  emit statusChanged(text);
}

bool PreviewPanel::loadHead() {
  if (state_->attempted) return hasHead();
  state_->attempted = true;
  try {
    QElapsedTimer timer;
    timer.start();
    state_->rig = playback::loadDefaultHeadRig();
    state_->producer =
        std::make_unique<playback::FrameProducer>(*state_->rig, model_.document().scene);
    state_->producer->setTearSources(model_.document().tearSources);
    state_->viewport = new viewport::FaceViewport(this);
    state_->viewport->setObjectName(QStringLiteral("faceViewport"));
    state_->viewport->setHead(state_->rig->head);
    layout()->replaceWidget(message_, state_->viewport);
    message_->hide();
    state_->viewport->show();  // a child added to a visible parent stays hidden until shown
    layout()->activate();
    if (!state_->viewport->usesOgre()) {
      // Nothing can be drawn here (no X display): say why, and spend no time simulating.
      setStatus(state_->viewport->message());
      state_->producer.reset();
      return false;
    }
    setStatus(tr("head ready in %1 ms").arg(timer.elapsed()));
    onValuesChanged();
    return true;
  } catch (const std::exception& e) {
    state_->producer.reset();
    state_->rig.reset();
    message_->setText(
        tr("No preview: %1\n\nThe editor works without it; the tear channels still export.")
            .arg(QString::fromUtf8(e.what())));
    setStatus(tr("no head"));
    return false;
  }
}

void PreviewPanel::setTearPreview(bool on) {
  if (on == tearPreview_) return;
  tearPreview_ = on;
  const QSignalBlocker block(tearToggle_);
  tearToggle_->setChecked(on);
  onValuesChanged();
}

int PreviewPanel::particleCount() const {
  return state_->producer ? state_->producer->particleCount() : 0;
}

QWidget* PreviewPanel::viewportWidget() const { return state_->viewport; }

QImage PreviewPanel::grabFrame() {
  if (state_->viewport) return state_->viewport->grabFrame();
  return {};
}

void PreviewPanel::pose() {
  if (!state_->producer) return;
  QElapsedTimer timer;
  timer.start();
  const auto& view = state_->producer->pose(model_.currentValues());
  lastProduceMs_ = timer.nsecsElapsed() / 1e6;
  state_->viewport->showFrame(view);
}

void PreviewPanel::step(double dt) {
  if (!state_->producer) return;
  const double duration = model_.endTime();
  const double progress =
      duration > 0 ? std::clamp(model_.currentTime() / duration, 0.0, 1.0) : 0.0;
  QElapsedTimer timer;
  timer.start();
  const auto& view = state_->producer->produce(model_.currentValues(), dt, progress);
  lastProduceMs_ = timer.nsecsElapsed() / 1e6;
  state_->viewport->showFrame(view);
  setStatus(tr("%1 particles · %2 ms")
                .arg(state_->producer->particleCount())
                .arg(lastProduceMs_, 0, 'f', 1));
}

void PreviewPanel::onValuesChanged() {
  updateIdleTimer();
  // While playing, the clock's tick advances the tears; here only a paused face is re-posed.
  if (!clock_.isPlaying() && !idle_->isActive()) pose();
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
}

}  // namespace lacrima::editor
