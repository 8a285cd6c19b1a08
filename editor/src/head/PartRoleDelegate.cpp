#include <lacrima/editor/head/PartRoleDelegate.h>

#include <lacrima/editing/HeadSetupRoles.h>
#include <lacrima/editor/head/PartsTableModel.h>

#include <QComboBox>

namespace lacrima::editor::head {

QWidget* PartRoleDelegate::createEditor(QWidget* parent, const QStyleOptionViewItem& option,
                                        const QModelIndex& index) const {
  if (index.column() != PartsTableModel::Role)
    return QStyledItemDelegate::createEditor(parent, option, index);
  auto* combo = new QComboBox(parent);
  for (editing::PartRole role : editing::kPartRoles)
    combo->addItem(PartsTableModel::roleLabel(static_cast<int>(role)), static_cast<int>(role));
  // Commit as soon as a role is picked: one undo step per choice. (Qt declares createEditor
  // const but its commit signals not: the delegate itself is not changed by emitting them.)
  connect(combo, &QComboBox::activated, this, [this, combo] {
    auto* self = const_cast<PartRoleDelegate*>(this);
    emit self->commitData(combo);
    emit self->closeEditor(combo);
  });
  return combo;
}

void PartRoleDelegate::setEditorData(QWidget* editor, const QModelIndex& index) const {
  if (auto* combo = qobject_cast<QComboBox*>(editor))
    combo->setCurrentIndex(combo->findData(index.data(Qt::EditRole)));
  else
    QStyledItemDelegate::setEditorData(editor, index);
}

void PartRoleDelegate::setModelData(QWidget* editor, QAbstractItemModel* model,
                                    const QModelIndex& index) const {
  if (auto* combo = qobject_cast<QComboBox*>(editor))
    model->setData(index, combo->currentData(), Qt::EditRole);
  else
    QStyledItemDelegate::setModelData(editor, model, index);
}

}  // namespace lacrima::editor::head
