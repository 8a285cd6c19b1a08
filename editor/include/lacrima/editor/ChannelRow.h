#pragma once
// One channel in the slider list: key toggle, FAP number, name, slider, value field, reset.
// The tooltip carries the channel's description, unit, direction and range. The row edits
// through the model (a slider drag is one undo step) and is refreshed by the slider panel,
// which computes the key states for all rows at once. The value field takes whole numbers in the
// channel's edit limits (ChannelLimits.h) exactly as typed, or refuses them (NumberField.h).
#include <lacrima/editor/KeyToggle.h>

#include <QWidget>

class QLabel;
class QToolButton;

namespace lacrima::editing {
class EditorModel;
}  // namespace lacrima::editing

namespace lacrima::editor {

class NumberField;
class ZeroSlider;

class ChannelRow : public QWidget {
  Q_OBJECT
 public:
  ChannelRow(editing::EditorModel& model, int fap, QWidget* parent = nullptr);

  int fap() const { return fap_; }
  // Shows a value and key state; does nothing when both are already shown.
  void show(float value, KeyToggle::State state);
  void setHighlighted(bool on);

  ZeroSlider* slider() const { return slider_; }
  NumberField* valueField() const { return field_; }
  QToolButton* resetButton() const { return reset_; }
  KeyToggle* keyToggle() const { return key_; }

 protected:
  void paintEvent(QPaintEvent* event) override;
  void mousePressEvent(QMouseEvent* event) override;

 private:
  void edit(int value);

  editing::EditorModel& model_;
  int fap_;
  KeyToggle* key_;
  QLabel* number_;
  QLabel* name_;
  ZeroSlider* slider_;
  NumberField* field_;
  QToolButton* reset_;
  int session_ = 0;
  int shownValue_ = 0;
  bool highlighted_ = false;
};

// Keeps wheel events away from a spin box or combo box that does not have focus, so scrolling
// the slider list never changes a value.
class WheelGuard : public QObject {
 public:
  using QObject::QObject;
  static WheelGuard* instance();
  bool eventFilter(QObject* watched, QEvent* event) override;
};

}  // namespace lacrima::editor
