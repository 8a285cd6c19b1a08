#pragma once
// A compact, painted slider for one FAP: the track spans the channel's slider range, a tick
// marks 0, and the fill runs from 0 to the value, so the sign and size of a bidirectional
// value read at a glance. Values beyond the range (from files or the spin box) pin the handle
// to the end and show an arrow there.
//
// Mouse: a press on the track away from the handle jumps there; a drag then moves the value
// relative to the pointer at a rate set by the channel's range, not by the slider's width:
//
//   dvalue = dx * (max - min) / kPixelsPerRange * gain,   gain = 1, Shift 1/10, Ctrl 5
//
// so 600 px cross the whole range at any width (a 60-px drag moves a tenth of it: 372 of
// raise_b_midlip's 3,720, not 1,410 as when the value followed a 158-px-wide track). Changing
// the modifier mid-drag re-anchors there, so the value never jumps. Unless fine, the value
// sticks to 0 within 1.5 % of the range so returning to neutral is easy; double-click resets.
// Keys (when focused): arrows step by the channel's quantiser step, Page Up/Down by a tenth of
// the range. The wheel only acts on a focused slider, so scrolling the list never edits.
// Painting is one rounded track and one handle: 70 of these update in well under a millisecond.
#include <QColor>
#include <QWidget>

namespace lacrima::editor {

class ZeroSlider : public QWidget {
  Q_OBJECT
 public:
  static constexpr double kPixelsPerRange = 600.0;  // drag distance across the whole range
  static constexpr double kFineGain = 0.1;          // Shift
  static constexpr double kCoarseGain = 5.0;        // Ctrl

  ZeroSlider(int minimum, int maximum, int step, QColor colour, QWidget* parent = nullptr);

  int value() const { return value_; }
  void setValue(int value);  // shows a value; emits nothing
  int minimum() const { return min_; }
  int maximum() const { return max_; }
  // Highlights the fill (the channel is keyed at the current time).
  void setEmphasis(bool on);
  bool isDragging() const { return dragging_; }

  QSize sizeHint() const override { return {140, 20}; }
  QSize minimumSizeHint() const override { return {60, 20}; }

 signals:
  void dragStarted();
  void valueEdited(int value);  // by the user, while dragging or by keys
  void dragFinished();
  void resetRequested();

 protected:
  void paintEvent(QPaintEvent* event) override;
  void mousePressEvent(QMouseEvent* event) override;
  void mouseMoveEvent(QMouseEvent* event) override;
  void mouseReleaseEvent(QMouseEvent* event) override;
  void mouseDoubleClickEvent(QMouseEvent* event) override;
  void keyPressEvent(QKeyEvent* event) override;
  void wheelEvent(QWheelEvent* event) override;
  bool event(QEvent* event) override;  // keeps its keys from window shortcuts while focused

 private:
  double xOf(double value) const;
  int valueAt(double x) const;
  int magnetised(double value, double gain) const;
  void edit(int value);

  int min_, max_, step_;
  int value_ = 0;
  QColor colour_;
  bool emphasis_ = false;
  bool dragging_ = false;
  // A drag moves relative to its anchor: the pointer's x and the (unrounded) value there.
  double grabX_ = 0;
  double grabValue_ = 0;
  double dragValue_ = 0;
  double gain_ = 1;
};

}  // namespace lacrima::editor
