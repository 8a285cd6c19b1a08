#pragma once
// The Dope sheet tab: a filter field (the slider panel's syntax: name, number or group), an
// "Only animated" toggle, and the sheet itself (DopeSheetView.h: rows, marks, mouse and keys).
#include <QWidget>

class QLineEdit;
class QToolButton;

namespace lacrima::editing {
class EditorModel;
}  // namespace lacrima::editing

namespace lacrima::editor {

class DopeSheetView;

class DopeSheet : public QWidget {
  Q_OBJECT
 public:
  explicit DopeSheet(editing::EditorModel& model, QWidget* parent = nullptr);

  DopeSheetView* view() const { return view_; }
  QLineEdit* filterBox() const { return filter_; }
  QToolButton* onlyAnimatedButton() const { return onlyAnimated_; }

 private:
  DopeSheetView* view_;
  QLineEdit* filter_;
  QToolButton* onlyAnimated_;
};

}  // namespace lacrima::editor
