#pragma once
// Without a window (lacrima-player --no-window), what the window's LiveSource does with a
// stream's mood lines (docs/live.md): the crying generator (MoodGenerator) makes the face, a
// frame every 1/rate s of the live clock, and each goes to the session's recording
// (LiveSession::recordGenerated). The newest message wins, as in the window: a frame from the
// stream takes the face back (the generator waits, keeping its take and its clock), the next mood
// line gives it to the generator again. The generator's clock runs only while it drives, at the
// live clock's pace; the face colours have no place in a FAP file and are not recorded.
#include <lacrima/common/mood/MoodGenerator.h>
#include <lacrima/live/LiveSession.h>

#include <QObject>

#include <cstdint>
#include <memory>

class QTimer;

namespace lacrima::live {

class LiveMoodFeed : public QObject {
  Q_OBJECT
 public:
  // Takes over the session's frame and mood handlers. `rate`: generated frames per second (the
  // recording's); `seed`: the take (the Mood panel's default is 1).
  LiveMoodFeed(LiveSession& session, double rate, std::uint64_t seed = 1,
               QObject* parent = nullptr);
  ~LiveMoodFeed() override;

  bool driving() const { return driving_; }
  long long framesGenerated() const { return generated_; }
  const MoodLevels& moods() const { return moods_; }

 private:
  void setMoods(const MoodLevels& levels);
  void step();

  LiveSession& session_;
  MoodGenerator generator_;
  QTimer* timer_;
  MoodLevels moods_;
  bool driving_ = false;
  double takeSeconds_ = 0;  // the generator's clock
  double lastStep_ = 0;     // liveClockSeconds() of the last step
  long long generated_ = 0;
};

}  // namespace lacrima::live
