#pragma once
// The dope sheet's sheet: channel names on the left, a row per channel along time on the
// right, a mark where the channel is keyed (DopeSheetRows.h says which rows there are).
//
// Marks: a diamond for a linear key, a circle for a smooth one, a square for a constant one, a
// diamond with a handle line for a Bézier one (the channel's own shape at that key); group and
// summary rows draw plain diamonds. Between two keys of a channel that holds (equal values, a
// constant segment, or a viseme/expression code) a bar is drawn, as Blender does; the hold
// before a channel's first key and after its last is drawn faintly with the value held, so a
// tear count keyed 60 at 2 s shows that it reads 60 from 0 s.
//
// Mouse: the ruler scrubs; a click on a mark selects its channel keys (Ctrl/Shift adds or
// removes), dragging selected marks moves them by whole frames, dragging on empty space selects
// the marks it spans; a click on a name selects the row's keys and its channels (the graph
// editor shows those); the arrow of a group row folds it. The wheel zooms about the pointer,
// Shift+wheel pans, a middle drag pans; over the names (or with Ctrl) the wheel scrolls rows.
// Keys (while the sheet has focus): A all, Alt+A none, Delete/X/Backspace delete, Ctrl+C copy,
// Ctrl+V paste at the playhead, Shift+D duplicate to the playhead, F frame all.
//
// Every edit is planned by ChannelKeyEdits.h and is one undo step; the selection follows the
// moved or pasted channel keys.
#include <lacrima/editing/ChannelKeyEdits.h>
#include <lacrima/editor/DopeSheetRows.h>
#include <lacrima/editor/TimeAxis.h>

#include <QWidget>

#include <utility>
#include <vector>

class QPainter;
class QScrollBar;

namespace lacrima::editor {

class DopeSheetView : public QWidget {
  Q_OBJECT
 public:
  static constexpr double kRulerHeight = 22.0;
  static constexpr double kRowHeight = 20.0;
  static constexpr double kNamesWidth = 200.0;
  static constexpr double kMarkRadius = 5.0;

  explicit DopeSheetView(editing::EditorModel& model, QWidget* parent = nullptr);

  // --- rows ---------------------------------------------------------------------------------
  void setFilterText(const QString& text);  // ChannelFilter syntax, as the slider panel's
  void setOnlyAnimated(bool on);
  bool onlyAnimated() const { return options_.onlyAnimated; }
  void setGroupFolded(FapGroup group, bool folded);
  bool isGroupFolded(FapGroup group) const;
  const std::vector<DopeSheetRow>& rows();  // rebuilt first if keys changed while hidden
  int channelRow(int fap);                  // -1 when not shown
  int groupRow(FapGroup group);             // -1 when not shown

  // --- view ---------------------------------------------------------------------------------
  const TimeAxis& axis() const { return axis_; }
  void setView(double startSeconds, double pixelsPerSecond);
  void fitAll();
  double xOfTime(double seconds) const { return kNamesWidth + axis_.xOf(seconds); }
  double timeAtX(double x) const { return axis_.timeAt(x - kNamesWidth); }
  QRectF rowRect(int row) const;  // the whole row, names included
  // Centre of row `row`'s mark at `seconds`, and a point on the row's name (tests drive the
  // mouse with them).
  QPointF markPosition(int row, double seconds) const;
  QPointF namePosition(int row) const;
  QScrollBar* verticalScrollBar() const { return scroll_; }

  // --- edits (the selection is the model's selectedChannelKeys) ----------------------------
  void selectAll();  // every shown channel's keys
  void clearSelection();
  void deleteSelected();
  void copySelected();
  void pasteAtPlayhead();
  void duplicateToPlayhead();
  const editing::ChannelKeyClip& clip() const { return clip_; }

  QSize sizeHint() const override { return {900, 260}; }
  QSize minimumSizeHint() const override { return {360, 110}; }

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
  enum class Drag { None, Scrub, PendingMove, Move, PendingBand, Band, Pan };
  struct Hit {
    enum class Area { None, Ruler, Names, Keys } area = Area::None;
    int row = -1;
    int key = -1;  // index into the sequence, for a mark
  };

  void rebuildRows();
  void updateScrollRange();
  double keysWidth() const;
  int rowAtY(double y) const;
  Hit hitAt(QPointF position) const;
  int markAt(int row, double x) const;
  std::vector<editing::ChannelKey> markKeys(int row, int key) const;
  bool isMarkSelected(int row, int key) const;
  const std::vector<std::pair<double, ChannelMask>>& selectedByTime() const;
  void selectRow(int row, bool additive);
  std::vector<editing::ChannelKey> keysInBand(const QRectF& band) const;
  int dragFrames(double x) const;
  void apply(const editing::ChannelKeyEdit& edit, const QString& text);
  bool handlesKey(const QKeyEvent& event) const;

  void paintNames(QPainter& p, int firstRow, int lastRow);
  void paintRow(QPainter& p, int row);
  void paintHolds(QPainter& p, const DopeSheetRow& row, double cy);
  void paintMark(QPainter& p, QPointF centre, const DopeSheetRow& row, const Keyframe& key,
                 bool selected);

  editing::EditorModel& model_;
  DopeSheetRowOptions options_;
  std::vector<DopeSheetRow> rows_;
  bool rowsValid_ = false;
  TimeAxis axis_;
  QScrollBar* scroll_;
  editing::ChannelKeyClip clip_;
  Drag drag_ = Drag::None;
  QPointF pressPos_;
  double panStart_ = 0;
  int panScrollStart_ = 0;
  int ghostFrames_ = 0;
  QRectF band_;
  std::vector<editing::ChannelKey> bandBase_;  // the selection a Ctrl/Shift band adds to
  std::vector<editing::ChannelKey> narrowTo_;  // a click without a drag selects only these
  bool fitPending_ = true;
  // The channel-key selection as (time, channels) sorted by time, so that whether a group or
  // summary mark is selected is one lookup; rebuilt on the first paint after a change.
  mutable std::vector<std::pair<double, ChannelMask>> selectedByTime_;
  mutable bool selectedByTimeValid_ = false;
};

}  // namespace lacrima::editor
