#pragma once
// A compact, painted slider for one FAP: the track spans the channel's slider range, a tick
// marks 0, and the fill runs from 0 to the value, so the sign and size of a bidirectional
// value read at a glance. Values beyond the range (from files or the spin box) pin the handle
// to the end and show an arrow there.
//
// Mouse: press jumps to the pointer and drags; Shift drags ten times finer; the value sticks
// to 0 within 1.5 % of the range so returning to neutral is easy; double-click resets to 0.
// Keys (when focused): arrows step by the channel's quantiser step, Page Up/Down by a tenth of
// the range. The wheel only acts on a focused slider, so scrolling the list never edits.
// Painting is one rounded track and one handle: 70 of these update in well under a millisecond.
#include <QColor>
#include <QWidget>

namespace lacrima::editor {

class ZeroSlider : public QWidget {
  Q_OBJECT
 public:
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
  void edit(int value);

  int min_, max_, step_;
  int value_ = 0;
  QColor colour_;
  bool emphasis_ = false;
  bool dragging_ = false;
  double grabX_ = 0;  // fine drags move relative to where they started
  int grabValue_ = 0;
};

}  // namespace lacrima::editor
