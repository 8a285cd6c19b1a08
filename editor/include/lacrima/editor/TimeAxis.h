#pragma once
// The horizontal time axis the timeline and the dope sheet share: which second is at which
// pixel, zooming and panning, and the ruler and playhead drawn along it.
//
//   x(t) = (t - start) * scale,   t(x) = start + x / scale      (scale in pixels per second)
//
// The scale stays within [0.5, 4000] px/s (30 minutes across 900 px .. a frame at 22 fps is
// 180 px wide) and the view never starts more than 40 px before 0 s.
#include <QRectF>
#include <QString>

class QFont;
class QPainter;
class QPalette;
class QPoint;

namespace lacrima::editor {

class TimeAxis {
 public:
  static constexpr double kMinScale = 0.5;
  static constexpr double kMaxScale = 4000.0;

  double start() const { return start_; }  // seconds at x = 0
  double scale() const { return scale_; }  // pixels per second
  void set(double startSeconds, double pixelsPerSecond);

  double xOf(double seconds) const { return (seconds - start_) * scale_; }
  double timeAt(double x) const { return start_ + x / scale_; }

  // 0 s to max(end, 2 s) across `width` pixels, with a margin of 20 px on either side.
  void fit(double endSeconds, double width);
  // Keeps `seconds` in [0, width - 10]: when it leaves the view, the view jumps to show it a
  // tenth of the way in. Returns whether the view moved.
  bool follow(double seconds, double width);
  // The wheel: zooms by 1.15 per notch about x (the time under the pointer stays put), or pans
  // 60 px per notch when `pan` is set or the wheel turns sideways.
  void wheel(const QPoint& angleDelta, bool pan, double x);

 private:
  double start_ = -0.25;
  double scale_ = 120.0;
};

// A ruler's label for `seconds` on labels `step` apart: m:ss from a minute on at whole-second
// steps, else seconds with as many decimals as the step needs (0.25 s steps: 0.25, 0.50, 0.75).
QString rulerLabel(double seconds, double step);

// The ruler over `area` (x measured from area.left()): labels at the smallest "nice" step
// that leaves >= 70 px between them, half-step ticks, frame ticks when frames are >= 6 px
// apart, and grid lines from the ruler down to `gridBottom`.
void paintTimeRuler(QPainter& p, const TimeAxis& axis, const QRectF& area, double gridBottom,
                    double frameSeconds, const QPalette& palette, const QFont& font);

// The playhead: a line from the top of the ruler to `bottom`, with the frame number in a tag
// on the ruler (`rulerHeight` high). x measured as in paintTimeRuler, from `left`.
void paintPlayhead(QPainter& p, const TimeAxis& axis, double seconds, int frame, double left,
                   double rulerHeight, double bottom, const QFont& font);

}  // namespace lacrima::editor
