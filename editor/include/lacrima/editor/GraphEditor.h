#pragma once
// The graph editor (as Blender's and Maya's): the curves of the chosen channels over time,
// their keys as points and the Bézier handles, edited with the mouse.
//
// Shown channels: EditorModel::selectedChannels(), else the focus channel. Each curve has its
// own colour and its name in the legend; holds before the first and after the last key are
// dashed. The value axis is labelled in channel units, or in -1..1 when the view is
// normalised (each curve mapped by its own min/max, as Blender's Normalize).
//
// Mouse: the ruler scrubs. Click a key or handle to select (Shift adds or removes); drag keys
// to move them (time in whole frames, value free; Ctrl: whole values); drag a handle to shape
// its segment (Auto handles become Aligned; see CurveEdits.h); drag on empty space to box
// select. Wheel zooms time about the pointer, Ctrl+wheel zooms values, Shift+wheel pans; a
// middle drag pans. Keys: T interpolation, V handle type, Home frame all, F or numpad .
// frame selected. Right-click: the same commands. Each drag is one undo step, pushed on
// release; while dragging, the curves show the edit as it would be.
//
// The Moods button swaps the channels for the project's mood curves (MoodGraph.h), edited the
// same way, on the same time view.
//
// Drawing cost does not grow with the animation: curves are sampled once per edit (only the
// dragged channels during a drag), drawn with one point per pixel column, and only keys in
// view are visited.
#include <lacrima/common/Keyframes.h>
#include <lacrima/editing/CurveEdits.h>

#include <QWidget>

#include <optional>
#include <vector>

class QMenu;
class QPainter;
class QToolButton;

namespace lacrima::editing {
class EditorModel;
}  // namespace lacrima::editing

namespace lacrima::editor {

struct GraphCurve;
class MoodGraph;

class GraphEditor : public QWidget {
  Q_OBJECT
 public:
  explicit GraphEditor(editing::EditorModel& model, QWidget* parent = nullptr);
  ~GraphEditor() override;

  // The channels drawn, ascending.
  std::vector<int> shownChannels() const;

  void setNormalized(bool on);
  // The Moods view (MoodGraph) in place of the channels.
  void setMoodsShown(bool on);
  bool moodsShown() const;
  MoodGraph* moodGraph() const { return moodGraph_; }

  // The view: time at the left edge of the plot, pixels per second; value at the top edge of
  // the plot, pixels per unit (per normalised unit in the normalised view).
  void setView(double startSeconds, double pixelsPerSecond, double topValue, double pixelsPerUnit);
  void frameAll();
  void frameSelected();

  // Pixel mapping, for tests and the painting. Values are channel units of `fap`.
  double xOfTime(double seconds) const;
  double timeAtX(double x) const;
  double yOfValue(int fap, double value) const;
  double valueAtY(int fap, double y) const;
  // Where channel `fap`'s key keys()[keyIndex] and its handles are drawn.
  QPointF keyPosition(int fap, int keyIndex) const;
  QPointF handlePosition(int fap, int keyIndex, editing::HandleSide side) const;
  // Curve points drawn by the last paint (the drawing cost; tests check it is bounded).
  int lastPaintPoints() const { return lastPaintPoints_; }

  QSize sizeHint() const override { return {900, 260}; }
  QSize minimumSizeHint() const override { return {240, 140}; }

 protected:
  bool event(QEvent* event) override;
  void paintEvent(QPaintEvent* event) override;
  void mousePressEvent(QMouseEvent* event) override;
  void mouseMoveEvent(QMouseEvent* event) override;
  void mouseReleaseEvent(QMouseEvent* event) override;
  void wheelEvent(QWheelEvent* event) override;
  void keyPressEvent(QKeyEvent* event) override;
  void contextMenuEvent(QContextMenuEvent* event) override;
  void resizeEvent(QResizeEvent* event) override;
  void showEvent(QShowEvent* event) override;

 private:
  enum class Drag { None, Scrub, PendingKey, MoveKeys, Handle, PendingBand, Band, Pan };
  enum class HitKind { None, Key, InHandle, OutHandle };
  struct Hit {
    HitKind kind = HitKind::None;
    int fap = 0;
    int keyIndex = -1;
  };

  // The keys drawn: the document's, or the edit being dragged.
  const KeyframeSequence& shownKeys() const;
  const GraphCurve* curveOf(int fap) const;
  void ensureCurves() const;
  void invalidateCurves(ChannelMask channels);
  void invalidateAllCurves();
  void shownChannelsChanged();
  void setPreview(const editing::KeyChange& change, ChannelMask channels);
  void clearPreview();
  // Display value (normalised or not) of a channel value, and back.
  double displayOf(int fap, double value) const;
  double valueOfDisplay(int fap, double display) const;
  // Whether the curve's key at keys[position] shows handles: a Bézier segment touches it.
  bool showsHandles(const GraphCurve& curve, std::size_t position) const;
  bool isShownSelected(int fap, double time) const;
  Hit hitAt(QPointF position) const;
  void selectFromHit(const Hit& hit, bool additive);
  void updateKeyDrag(QPointF position, Qt::KeyboardModifiers modifiers);
  void updateHandleDrag(QPointF position);
  void updateBand(QPointF position);
  void finishDrag();
  void frameRange(double t0, double t1, double v0, double v1);
  void popupMenu(void (*fill)(QMenu&, editing::EditorModel&));
  QRectF plotArea() const;

  void paintRuler(QPainter& p) const;
  void paintValueAxis(QPainter& p) const;
  void paintCurve(QPainter& p, const GraphCurve& curve, const QColor& colour);
  void paintKeys(QPainter& p, const GraphCurve& curve, const QColor& colour) const;
  void paintLegend(QPainter& p) const;

  editing::EditorModel& model_;
  QToolButton* normalizeButton_ = nullptr;
  QToolButton* moodsButton_ = nullptr;
  MoodGraph* moodGraph_ = nullptr;
  bool normalized_ = false;
  double start_ = -0.25;      // seconds at the plot's left edge
  double scale_ = 200.0;      // pixels per second
  double top_ = 100.0;        // display value at the plot's top edge
  double vScale_ = 1.0;       // pixels per display unit
  bool framePending_ = true;  // frame once the widget has its real size
  bool viewTouched_ = false;  // the user zoomed or panned since the last framing

  mutable std::vector<GraphCurve> curves_;  // of shownChannels(), in that order
  mutable ChannelMask dirty_;
  mutable bool curvesValid_ = false;
  std::optional<KeyframeSequence> preview_;
  std::optional<editing::KeyChange> previewChange_;
  QString previewText_;
  std::vector<editing::ChannelKey> previewSelection_;

  Drag drag_ = Drag::None;
  QPointF pressPos_;
  Hit pressed_;
  std::vector<editing::ChannelKey> selectionAtPress_;
  double panStart_ = 0.0, panTop_ = 0.0;
  QRectF band_;
  bool bandAdds_ = false;  // Shift at the press: the box adds to the selection
  int lastPaintPoints_ = 0;
};

}  // namespace lacrima::editor
