#pragma once
// The live inputs a player listens to, as one: every input's frames go to one handler (the
// newest wins downstream) and, while recording, to the recorder. It counts what arrives and says
// so in one line for the window or stderr, and knows how long it has been idle
// (--exit-when-idle). Used by the player's window and by its headless mode alike.
#include <lacrima/live/LiveInput.h>
#include <lacrima/live/LiveRecorder.h>

#include <QObject>

#include <functional>
#include <memory>
#include <vector>

namespace lacrima::live {

class LiveSession : public QObject {
  Q_OBJECT
 public:
  explicit LiveSession(QObject* parent = nullptr);
  ~LiveSession() override;

  // Starts an input; throws std::runtime_error when it cannot bind. Returns it (its url() has
  // the port the system chose for port 0).
  LiveInput& listen(const ListenUrl& url);
  void stopListening();
  const std::vector<std::unique_ptr<LiveInput>>& inputs() const { return inputs_; }
  bool listening() const { return !inputs_.empty(); }

  // Every frame, in arrival order.
  void setFrameHandler(LiveInput::FrameHandler handler) { handler_ = std::move(handler); }
  // Every mood line (docs/live.md), in arrival order. Not recorded: a recording holds frames.
  void setMoodHandler(LiveInput::MoodHandler handler) { moodHandler_ = std::move(handler); }
  // The Live Link mapping of every Live Link input, now and later.
  void setMapping(const LiveLinkMapping& mapping);
  const LiveLinkMapping& mapping() const { return mapping_; }

  void startRecording(const std::string& path, std::optional<double> rate);
  // Writes the recording (atomically); false when nothing was recorded. Throws FileError.
  bool stopRecording();
  const LiveRecorder* recorder() const { return recorder_.get(); }
  // The crying generator's face at `arrival` (liveClockSeconds()), made here, not received (the
  // window's LiveSource, LiveMoodFeed): recorded like a received frame that sets the channels
  // it moves, but neither counted nor activity (--exit-when-idle waits for the stream).
  void recordGenerated(const FapValues& values, double arrival);

  long long framesReceived() const { return frames_; }
  InputCounters totals() const;
  // Seconds since the last frame arrived, or since listening began when none has.
  double idleSeconds() const;
  // "fap+tcp://127.0.0.1:5555: 1 client; 1520 frames, 3 malformed (last: ...)" per input.
  QString statusText() const;

 signals:
  void frameArrived();
  void countersChanged();

 private:
  std::vector<std::unique_ptr<LiveInput>> inputs_;
  LiveInput::FrameHandler handler_;
  LiveInput::MoodHandler moodHandler_;
  LiveLinkMapping mapping_;
  bool mappingSet_ = false;
  std::unique_ptr<LiveRecorder> recorder_;
  long long frames_ = 0;
  double lastActivity_ = 0;
};

}  // namespace lacrima::live
