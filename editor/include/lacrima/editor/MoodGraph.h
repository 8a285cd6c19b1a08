#pragma once
// The graph editor's Moods view (GraphEditor's "Moods" button; docs/editor.md): the project's
// mood curves (sadness, anger, joy, shame; MoodCurves.h) over time on a 0..1 axis, edited with
// the mouse. Each edit is one undo step (EditorModel::editMoods).
//
// Mouse: the ruler scrubs. Click a key to select it; drag it to move it (time in whole frames,
// value clamped to 0..1); double-click empty space to key the chosen mood there (click a name in
// the legend to choose it). Delete or Backspace removes the selected key (not the window's
// keys), Home frames all. Wheel zooms time about the pointer, Shift+wheel pans. The moods are what
// Animation > Generate crying... can follow and what a crying layer follows (its range shaded
// behind the curves); they are not baked into the animation.
#include <lacrima/common/mood/MoodCurves.h>
#include <lacrima/editor/TimeAxis.h>

#include <QWidget>

#include <optional>

namespace lacrima::editing {
class EditorModel;
}  // namespace lacrima::editing

namespace lacrima::editor {

class MoodGraph : public QWidget {
  Q_OBJECT
 public:
  explicit MoodGraph(editing::EditorModel& model, QWidget* parent = nullptr);

  // The time view: `startSeconds` at the plot's left edge, `pixelsPerSecond`.
  void setTimeView(double startSeconds, double pixelsPerSecond);
  // Shows every mood key (or the document's keys, or two seconds); once the widget is shown at
  // its size when it is not yet, and again as it resizes until the user zooms or pans.
  void frameAll();

  // The mood new keys go to (double-click); chosen in the legend.
  Mood activeMood() const { return active_; }
  void setActiveMood(Mood mood);

  // Pixel mapping, for tests and the painting.
  double xOfTime(double seconds) const;
  double timeAtX(double x) const;
  double yOfValue(double value) const;
  double valueAtY(double y) const;
  // Where `mood`'s key keys()[index] is drawn (a null point for no such key).
  QPointF keyPosition(Mood mood, int index) const;
  // The selected key: its mood and time.
  struct KeyRef {
    Mood mood = Mood::Sadness;
    double time = 0;
  };
  std::optional<KeyRef> selectedKey() const { return selected_; }

  QSize sizeHint() const override { return {900, 260}; }

 protected:
  void paintEvent(QPaintEvent* event) override;
  void mousePressEvent(QMouseEvent* event) override;
  void mouseMoveEvent(QMouseEvent* event) override;
  void mouseReleaseEvent(QMouseEvent* event) override;
  void mouseDoubleClickEvent(QMouseEvent* event) override;
  void wheelEvent(QWheelEvent* event) override;
  void keyPressEvent(QKeyEvent* event) override;
  bool event(QEvent* event) override;
  void resizeEvent(QResizeEvent* event) override;
  void showEvent(QShowEvent* event) override;
  void contextMenuEvent(QContextMenuEvent* event) override;

 private:
  enum class Drag { None, Scrub, Key };
  const MoodCurves& shownMoods() const { return preview_ ? *preview_ : documentMoods(); }
  const MoodCurves& documentMoods() const;
  std::optional<KeyRef> keyAt(QPointF position) const;
  std::optional<Mood> legendAt(QPointF position) const;
  QRectF legendBox(int row) const;
  QRectF plotArea() const;
  // The moods with the selected key moved to `position` (the dragged key wins a time it lands
  // on).
  MoodCurves moved(QPointF position) const;
  void paintCurves(QPainter& p) const;
  void paintMoodLayer(QPainter& p) const;
  void paintValueAxis(QPainter& p) const;
  void paintLegend(QPainter& p) const;

  editing::EditorModel& model_;
  TimeAxis axis_;
  Mood active_ = Mood::Sadness;
  std::optional<KeyRef> selected_;
  std::optional<MoodCurves> preview_;  // the drag as it would be
  Drag drag_ = Drag::None;
  bool framePending_ = true;
  bool viewTouched_ = false;  // zoomed, panned or given a view since the last framing
};

// The colour each mood is drawn in, in the Moods view and its legend.
QColor moodColour(Mood mood);

}  // namespace lacrima::editor
