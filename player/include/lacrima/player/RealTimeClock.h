#pragma once
// The player's wall clock: animation time advances with real time while playing, from wherever
// the timeline was left. QElapsedTimer is monotonic, so system clock changes do not jump it.
#include <QElapsedTimer>

namespace lacrima::player {

class RealTimeClock {
 public:
  void play();                   // runs on from time()
  void pause();                  // holds time()
  void setTime(double seconds);  // keeps running or paused
  double time() const;
  bool running() const { return running_; }

 private:
  QElapsedTimer elapsed_;
  double origin_ = 0;  // animation time when elapsed_ was (re)started
  bool running_ = false;
};

}  // namespace lacrima::player
