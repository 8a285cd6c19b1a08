#pragma once
// When a live display renders. A stream frame that arrives while a render is running waits for
// it, on average half a render, before its own render can start. The tears change at every
// display tick, so without pacing the renders run back to back and every frame pays that wait.
//
// The pacer watches when stream frames arrive and how long a render takes (from the tick that
// asks for it to the end of the render), and answers at each tick: render now, or wait. A frame
// that came during a render is read only after it, with the others that came meanwhile, so read
// times are late by up to a render: the stream's interval is the slope of a line fitted to the
// last read times (unbiased by a delay that does not grow), and its phase the line through the
// least delayed read, so a frame's arrival is when the line says it came. While frames arrive
// regularly:
//  - with no stream frame waiting (only the tears or the moods moved), a render starts only if
//    it ends before the next frame is due; otherwise the display waits for that frame. The tears
//    are then drawn at the stream's rate, and at the display's when the stream is slow enough
//    for a render to fit between two frames;
//  - with a frame waiting, it is rendered at once, unless the next frame is due within a render
//    and sooner than the waiting one came: waiting for it shows a fresher face. The waiting frame
//    is then replaced (dropped) by the next, as any frame the display cannot keep up with.
// A frame later than its due time and a tolerance ends the waiting: the stream may have stopped,
// and the display goes on at its own pace. With no stream (moods, or before the third frame) the
// pacer always says render.
//
// Times are seconds of one clock (live::liveClockSeconds() in the player). Engine-free, so the
// player's window and lacrima-bench live share it.
#include <array>
#include <optional>

namespace lacrima::playback {

class LivePacer {
 public:
  // Frame arrivals the stream's line is fitted to, and render durations whose median is the
  // estimate of a render.
  static constexpr int kArrivals = 32;
  static constexpr int kRenders = 9;
  // Margin a render is given to end before a frame is due.
  static constexpr double kMargin = 0.001;

  struct Decision {
    bool render = true;
    double wakeAt = 0;  // when not rendering: the latest time to ask again
  };

  // A stream frame was read at `seconds`.
  void frameArrived(double seconds);
  // A render asked for at a tick took `seconds`, tick to end.
  void rendered(double seconds);
  // `frameWaiting`: a stream frame arrived that no render has shown yet.
  Decision decide(double now, bool frameWaiting) const;

  // The stream's interval while frames arrive regularly enough to pace by.
  std::optional<double> streamInterval() const;
  // When the newest frame came, by the stream's line; negative without a regular stream.
  double newestArrival() const;
  double renderSeconds() const;  // 0 before the first render
  // How late a frame may be before the display stops waiting for it.
  static double tolerance(double interval);
  void reset();

 private:
  void fitStream();

  std::array<double, kArrivals> reads_{};  // by frame number modulo kArrivals
  long long frames_ = 0;                   // frames read since the stream (re)started
  std::optional<double> interval_;
  double newest_ = -1;  // the newest frame's arrival on the stream's line
  std::array<double, kRenders> renders_{};
  int renderCount_ = 0, nextRender_ = 0;
};

}  // namespace lacrima::playback
