#pragma once
// Plays the animation in the editor: a QTimer ticking at the playback rate (22 fps unless set
// otherwise) advances the model's time by exactly one playback frame per tick, so the preview's
// tear simulation steps by the same dt as the player's and a slow frame slows playback rather
// than skipping simulation steps. Plays from the current time to the last key, then stops or
// loops back to the first key.
#include <QObject>
#include <QTimer>

namespace lacrima::editing {

class EditorModel;

class FrameStepClock : public QObject {
  Q_OBJECT
 public:
  explicit FrameStepClock(EditorModel& model, QObject* parent = nullptr);

  bool isPlaying() const { return timer_.isActive(); }
  double rate() const { return rate_; }  // frames per second
  bool loops() const { return loop_; }

 public slots:
  void play();
  void pause();
  void toggle();
  void setRate(double framesPerSecond);  // clamped to [1, 120]
  void setLoop(bool on);
  void advance();  // one playback frame (the timer calls it; tests may too)

 signals:
  void playingChanged(bool playing);
  // Emitted after each advance with the step in seconds (the preview simulates by it).
  void ticked(double dt);

 private:
  EditorModel& model_;
  QTimer timer_;
  double rate_ = 22.0;
  bool loop_ = true;
};

}  // namespace lacrima::editing
