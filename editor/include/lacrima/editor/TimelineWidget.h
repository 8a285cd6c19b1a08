#pragma once
// The timeline: a ruler in seconds and frames, the keys as marks along time (diamonds are
// linear keys, circles smooth ones), the curve of the channel touched last, the tear counts as
// a blue band, and the playhead.
//
// Mouse: the ruler scrubs; clicking a key selects it and moves the playhead to it (Ctrl adds
// to the selection); dragging selected keys moves them by whole frames (a key dropped on
// another merges into it); dragging on empty space selects the keys it spans; double-click on
// empty space adds a key there; the wheel zooms about the pointer, Shift+wheel or a middle
// drag pans. Right-click: interpolation, copy, paste, delete, mirror, add key, frame all.
//
// Drawing cost does not grow with the view: keys outside it are skipped, keys falling on the
// same pixel are drawn once, and the curves are baked once per edit (a single-channel bake at
// >= 60 samples per second) and reused for every repaint while scrubbing or playing.
#include <lacrima/common/FapChannels.h>
#include <lacrima/editor/TimeAxis.h>

#include <QWidget>

#include <vector>

class QPainter;

namespace lacrima::editing {
class EditorModel;
}  // namespace lacrima::editing

namespace lacrima::editor {

class TimelineWidget : public QWidget {
  Q_OBJECT
 public:
  explicit TimelineWidget(editing::EditorModel& model, QWidget* parent = nullptr);

  // What the empty timeline suggests: only what works on an empty project (K keys channels
  // already animated, so it has nothing to key yet).
  static QString emptyHint();

  double viewStart() const { return axis_.start(); }
  double pixelsPerSecond() const { return axis_.scale(); }
  void setView(double startSeconds, double pixelsPerSecond);
  void fitAll();

  double xOfTime(double seconds) const { return axis_.xOf(seconds); }
  double timeAtX(double x) const { return axis_.timeAt(x); }
  // Centre of key `index`'s mark (tests drive the mouse with it).
  QPointF keyPosition(int index) const;
  int keyAt(QPointF position) const;  // -1 when no key is there

  QSize sizeHint() const override { return {900, 170}; }
  QSize minimumSizeHint() const override { return {200, 110}; }

 signals:
  void copyRequested();
  void pasteRequested(double atSeconds);
  void mirrorRequested();

 protected:
  void paintEvent(QPaintEvent* event) override;
  void mousePressEvent(QMouseEvent* event) override;
  void mouseMoveEvent(QMouseEvent* event) override;
  void mouseReleaseEvent(QMouseEvent* event) override;
  void mouseDoubleClickEvent(QMouseEvent* event) override;
  void wheelEvent(QWheelEvent* event) override;
  void contextMenuEvent(QContextMenuEvent* event) override;
  void resizeEvent(QResizeEvent* event) override;
  void showEvent(QShowEvent* event) override;

 private:
  enum class Drag { None, Scrub, PendingKey, MoveKeys, PendingBand, Band, Pan };
  struct Curve {
    double start = 0, rate = 1;  // sample i is at start + i / rate
    std::vector<float> samples;
  };

  void followPlayhead();
  void invalidateCurves();
  void ensureCurves();
  Curve bakeChannel(int fap) const;
  int dragFrames(double x) const;
  void paintCurves(QPainter& p, const QRectF& area);
  void paintKeys(QPainter& p);
  double frameStepSeconds() const;

  editing::EditorModel& model_;
  TimeAxis axis_;
  Drag drag_ = Drag::None;
  QPointF pressPos_;
  double panStart_ = 0;
  int pressedKey_ = -1;
  int ghostFrames_ = 0;
  QRectF band_;
  bool fitPending_ = true;  // fit once the widget has its real width
  bool curvesValid_ = false;
  Curve focusCurve_, tearLeft_, tearRight_;
  float tearMax_ = 0;
};

}  // namespace lacrima::editor
