#pragma once
// Record (Playback > Record live...): a live stream (an agent, lacrima-send, a phone; the
// player's URLs, docs/live.md) turned into keys. After a count-in the stream is recorded from
// the playhead on; the preview shows it all the while (the model poses without keys). Stop
// writes the take as keys on the chosen channels, reduced by the import's key reduction
// (editing::planLiveTakeKeys), as one undoable step.
#include <lacrima/common/FapChannels.h>
#include <lacrima/live/LiveSession.h>

#include <QObject>
#include <QTimer>

#include <memory>

namespace lacrima::editing {
class EditorModel;
}

namespace lacrima::editor {

class LiveRecording : public QObject {
  Q_OBJECT
 public:
  enum class State { Idle, CountIn, Recording };

  explicit LiveRecording(editing::EditorModel& model, QObject* parent = nullptr);
  ~LiveRecording() override;

  // Listens at `url` and counts in for `countIn` seconds before recording. `channels`: those to
  // key; empty keys every channel the stream sets. Throws std::runtime_error when the input
  // cannot be opened.
  void start(const live::ListenUrl& url, ChannelMask channels, double countIn);
  // Writes the take as keys (one undo step); false when nothing was recorded. Stops listening.
  bool stop();
  void cancel();  // stops without writing anything

  State state() const { return state_; }
  live::LiveSession& session() { return *session_; }
  double tolerance() const { return tolerance_; }
  void setTolerance(double tolerance) { tolerance_ = tolerance; }

 signals:
  // "Recording in 3...", "Recording: 120 frames", "Recorded 8 keys from 240 frames".
  void message(const QString& text);
  void stateChanged(State state);

 private:
  void frame(const live::LiveFrame& frame);
  void tick();

  editing::EditorModel& model_;
  std::unique_ptr<live::LiveSession> session_;
  ChannelMask channels_;
  State state_ = State::Idle;
  double countInEnds_ = 0;
  double start_ = 0;  // the playhead when recording began
  double tolerance_ = 1;
  QTimer ticker_;
};

}  // namespace lacrima::editor
