#pragma once
// The key table view (KeyTableModel), its selection kept in step with the timeline's.
#include <QWidget>

class QTableView;

namespace lacrima::editing {
class EditorModel;
}  // namespace lacrima::editing

namespace lacrima::editor {

class KeyTableModel;

class KeyListPanel : public QWidget {
  Q_OBJECT
 public:
  explicit KeyListPanel(editing::EditorModel& model, QWidget* parent = nullptr);
  QTableView* view() const { return view_; }

 private:
  void pullSelection();  // model -> view
  void pushSelection();  // view -> model

  editing::EditorModel& model_;
  KeyTableModel* table_;
  QTableView* view_;
  bool syncing_ = false;
};

}  // namespace lacrima::editor
