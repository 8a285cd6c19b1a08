#pragma once
// A NumberField for times: shows seconds ("2.5 s") or frames ("55 f") of the project's rate and
// reads "2.5", "2.5s" or "55f" (a bare number in the unit shown) with editing::parseTime, so a
// time is typed the same way in the transport bar and in the Keys table. Up/Down step a frame.
#include <lacrima/editing/NumberInput.h>

#include <QStyledItemDelegate>

#include <functional>

namespace lacrima::editing {
class EditorModel;
}  // namespace lacrima::editing

namespace lacrima::editor {

class NumberField;

// Makes `field` a time field; `unit` says which unit it shows (asked at every read and write).
void setUpTimeField(NumberField& field, const editing::EditorModel& model,
                    std::function<editing::TimeUnit()> unit);

// Edits a table's time cells (EditRole: seconds as a double) in a time field: a typed time is
// written to the model only when the field takes it; a refusal leaves the cell as it was and
// says why in the status bar.
class TimeFieldDelegate : public QStyledItemDelegate {
 public:
  TimeFieldDelegate(const editing::EditorModel& model, QObject* parent);

  QWidget* createEditor(QWidget* parent, const QStyleOptionViewItem& option,
                        const QModelIndex& index) const override;
  void setEditorData(QWidget* editor, const QModelIndex& index) const override;
  void setModelData(QWidget* editor, QAbstractItemModel* model,
                    const QModelIndex& index) const override;

 private:
  const editing::EditorModel& model_;
};

}  // namespace lacrima::editor
