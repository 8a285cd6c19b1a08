#include <lacrima/editor/TimeField.h>

#include <lacrima/editing/EditorModel.h>
#include <lacrima/editor/NumberField.h>

#include <QCoreApplication>

namespace lacrima::editor {

void setUpTimeField(NumberField& field, const editing::EditorModel& model,
                    std::function<editing::TimeUnit()> unit) {
  field.setRange({0.0, editing::kMaxEditTime, false, {}});
  field.setSubject(QCoreApplication::translate("TimeField", "the time"),
                   QCoreApplication::translate("TimeField", "0 … %1 s, or whole frames such as 55f")
                       .arg(editing::kMaxEditTime));
  field.setSingleStep(1.0 / model.document().fps);
  field.setReader([&model, unit](const QString& text) {
    const editing::TimeParse time = editing::parseTime(text, model.document().fps, unit());
    return editing::NumberParse{time.seconds, time.reason};
  });
  field.setWriter([&model, unit](double seconds) {
    if (unit() == editing::TimeUnit::Frames)
      return QCoreApplication::translate("TimeField", "%1 f").arg(model.frameAt(seconds));
    return QCoreApplication::translate("TimeField", "%1 s").arg(editing::formatNumber(seconds, 3));
  });
}

TimeFieldDelegate::TimeFieldDelegate(const editing::EditorModel& model, QObject* parent)
    : QStyledItemDelegate(parent), model_(model) {}

QWidget* TimeFieldDelegate::createEditor(QWidget* parent, const QStyleOptionViewItem&,
                                         const QModelIndex&) const {
  auto* field = new NumberField(parent);
  setUpTimeField(*field, model_, [] { return editing::TimeUnit::Seconds; });
  field->setButtonSymbols(QAbstractSpinBox::NoButtons);
  field->setFrame(false);
  return field;
}

void TimeFieldDelegate::setEditorData(QWidget* editor, const QModelIndex& index) const {
  static_cast<NumberField*>(editor)->setValue(index.data(Qt::EditRole).toDouble());
}

void TimeFieldDelegate::setModelData(QWidget* editor, QAbstractItemModel* model,
                                     const QModelIndex& index) const {
  auto* field = static_cast<NumberField*>(editor);
  if (!field->commit()) return;  // refused: the cell stays as it was
  if (field->value() == index.data(Qt::EditRole).toDouble()) return;  // nothing to move
  model->setData(index, field->value(), Qt::EditRole);
}

}  // namespace lacrima::editor
