#include <lacrima/editor/LiveRecording.h>

#include <lacrima/editing/EditorModel.h>
#include <lacrima/editing/LiveTake.h>

#include <cmath>

namespace lacrima::editor {

namespace {

// The take is kept in memory only: written as keys, never as a file.
constexpr const char* kNoFile = "";

}  // namespace

LiveRecording::LiveRecording(editing::EditorModel& model, QObject* parent)
    : QObject(parent), model_(model) {
  ticker_.setInterval(100);
  connect(&ticker_, &QTimer::timeout, this, &LiveRecording::tick);
}

LiveRecording::~LiveRecording() { cancel(); }

void LiveRecording::start(const live::ListenUrl& url, ChannelMask channels, double countIn) {
  cancel();
  auto session = std::make_unique<live::LiveSession>();
  session->listen(url);  // throws before anything changes
  session_ = std::move(session);
  session_->setFrameHandler([this](const live::LiveFrame& f) { frame(f); });
  channels_ = channels;
  countInEnds_ = live::liveClockSeconds() + std::max(0.0, countIn);
  start_ = model_.currentTime();
  // The preview shows the stream: the model poses without writing keys until Stop.
  model_.setPosingOnly(true);
  state_ = State::CountIn;
  emit stateChanged(state_);
  ticker_.start();
  tick();
}

void LiveRecording::frame(const live::LiveFrame& f) {
  if (state_ == State::Idle) return;
  ChannelMask shown = f.mask;
  if (channels_.any()) shown &= channels_;
  std::vector<editing::ChannelValue> values;
  for (int c = 2; c < kChannelCount; ++c)  // codes (FAP 1, 2) are not posed
    if (shown.test(static_cast<std::size_t>(c)))
      values.push_back({fapNumber(c), f.values[static_cast<std::size_t>(c)]});
  if (!values.empty()) model_.setChannels(std::move(values), QString());
}

void LiveRecording::tick() {
  if (state_ == State::CountIn) {
    const double left = countInEnds_ - live::liveClockSeconds();
    if (left > 0) {
      emit message(tr("Recording in %1…").arg(static_cast<int>(std::ceil(left))));
      return;
    }
    session_->startRecording(kNoFile, std::nullopt);
    state_ = State::Recording;
    emit stateChanged(state_);
  }
  if (state_ == State::Recording) {
    const live::LiveRecorder* recorder = session_->recorder();
    emit message(tr("Recording from %1 s: %2 frames received (Stop writes the keys)")
                     .arg(start_, 0, 'f', 2)
                     .arg(recorder ? recorder->frameCount() : 0));
  }
}

bool LiveRecording::stop() {
  if (state_ == State::Idle) return false;
  FapAnimation take;
  if (state_ == State::Recording && session_->recorder()) take = session_->recorder()->animation();
  cancel();
  ChannelMask channels = channels_.any() ? channels_ : take.animated;
  const editing::LiveTakeKeys keys =
      editing::planLiveTakeKeys(model_.document().keys, take, start_, channels, tolerance_,
                                model_.document().defaultInterpolation);
  if (keys.keysWritten == 0) {
    emit message(tr("Nothing recorded: no frame arrived on the chosen channels"));
    return false;
  }
  model_.editKeys(keys.change, tr("Record live take"));
  emit message(tr("Recorded %1 keys from %2 frames (within %3 of every frame)")
                   .arg(keys.keysWritten)
                   .arg(keys.framesRecorded)
                   .arg(keys.maxError, 0, 'g', 3));
  return true;
}

void LiveRecording::cancel() {
  ticker_.stop();
  if (session_) {
    session_->stopListening();
    session_.reset();
  }
  if (state_ != State::Idle) {
    model_.setPosingOnly(false);
    state_ = State::Idle;
    emit stateChanged(state_);
  }
}

}  // namespace lacrima::editor
