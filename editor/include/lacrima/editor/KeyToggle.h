#pragma once
// The small diamond in front of each slider, as in other animation tools: filled when the
// channel is keyed at the current time, outlined when it is animated elsewhere, faint when no
// key sets it. Clicking it keys the channel at its current value, or removes it from the key
// at the current time when it is keyed there.
#include <QWidget>

namespace lacrima::editor {

class KeyToggle : public QWidget {
  Q_OBJECT
 public:
  enum class State { Unanimated, Animated, Keyed };
  explicit KeyToggle(QWidget* parent = nullptr);

  State state() const { return state_; }
  void setState(State state);
  QSize sizeHint() const override { return {14, 18}; }

 signals:
  void clicked();

 protected:
  void paintEvent(QPaintEvent* event) override;
  void mousePressEvent(QMouseEvent* event) override;

 private:
  State state_ = State::Unanimated;
};

}  // namespace lacrima::editor
