#include <lacrima/editor/KeyListPanel.h>

#include <lacrima/editing/EditorModel.h>
#include <lacrima/editor/KeyTableModel.h>
#include <lacrima/editor/TimeField.h>

#include <QComboBox>
#include <QHeaderView>
#include <QItemSelectionModel>
#include <QStyledItemDelegate>
#include <QTableView>
#include <QVBoxLayout>

namespace lacrima::editor {
namespace {

// A choice between the two modes instead of free text.
class InterpolationDelegate : public QStyledItemDelegate {
 public:
  using QStyledItemDelegate::QStyledItemDelegate;
  QWidget* createEditor(QWidget* parent, const QStyleOptionViewItem&,
                        const QModelIndex&) const override {
    auto* combo = new QComboBox(parent);
    combo->addItems({QStringLiteral("linear"), QStringLiteral("smooth")});
    return combo;
  }
  void setEditorData(QWidget* editor, const QModelIndex& index) const override {
    static_cast<QComboBox*>(editor)->setCurrentText(index.data(Qt::EditRole).toString());
  }
  void setModelData(QWidget* editor, QAbstractItemModel* model,
                    const QModelIndex& index) const override {
    model->setData(index, static_cast<QComboBox*>(editor)->currentText(), Qt::EditRole);
  }
};

}  // namespace

KeyListPanel::KeyListPanel(editing::EditorModel& model, QWidget* parent)
    : QWidget(parent), model_(model) {
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  table_ = new KeyTableModel(model_, this);
  view_ = new QTableView(this);
  view_->setModel(table_);
  view_->setSelectionBehavior(QAbstractItemView::SelectRows);
  view_->setSelectionMode(QAbstractItemView::ExtendedSelection);
  view_->setEditTriggers(QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed);
  view_->setItemDelegateForColumn(KeyTableModel::InterpolationColumn,
                                  new InterpolationDelegate(view_));
  // Times are typed as in the transport's time field ("2.5", "55f"), refused when out of range.
  view_->setItemDelegateForColumn(KeyTableModel::TimeColumn, new TimeFieldDelegate(model_, view_));
  view_->verticalHeader()->hide();
  view_->verticalHeader()->setSectionResizeMode(QHeaderView::Fixed);
  view_->verticalHeader()->setDefaultSectionSize(fontMetrics().height() + 6);
  view_->horizontalHeader()->setStretchLastSection(true);
  view_->setColumnWidth(KeyTableModel::TimeColumn, 70);
  view_->setColumnWidth(KeyTableModel::FrameColumn, 52);
  view_->setColumnWidth(KeyTableModel::InterpolationColumn, 86);
  view_->setAlternatingRowColors(true);
  view_->setShowGrid(false);
  view_->setWordWrap(false);
  layout->addWidget(view_);

  connect(view_->selectionModel(), &QItemSelectionModel::selectionChanged, this,
          &KeyListPanel::pushSelection);
  connect(&model_, &editing::EditorModel::selectionChanged, this, &KeyListPanel::pullSelection);
  connect(table_, &QAbstractItemModel::modelReset, this, &KeyListPanel::pullSelection);
  connect(view_, &QTableView::clicked, this, [this](const QModelIndex& index) {
    const auto& keys = model_.document().keys.keys();
    if (index.row() < static_cast<int>(keys.size()))
      model_.setCurrentTime(keys[static_cast<std::size_t>(index.row())].time);
  });
}

void KeyListPanel::pullSelection() {
  if (syncing_) return;
  syncing_ = true;
  QItemSelection selection;
  const auto& keys = model_.document().keys.keys();
  for (std::size_t i = 0; i < keys.size(); ++i) {
    if (model_.isSelected(keys[i].time)) {
      const int row = static_cast<int>(i);
      selection.select(table_->index(row, 0), table_->index(row, KeyTableModel::ColumnCount - 1));
    }
  }
  view_->selectionModel()->select(selection, QItemSelectionModel::ClearAndSelect);
  syncing_ = false;
}

void KeyListPanel::pushSelection() {
  if (syncing_) return;
  syncing_ = true;
  std::vector<double> times;
  const auto& keys = model_.document().keys.keys();
  for (const QModelIndex& index : view_->selectionModel()->selectedRows())
    if (index.row() < static_cast<int>(keys.size()))
      times.push_back(keys[static_cast<std::size_t>(index.row())].time);
  model_.setSelectedTimes(times);
  syncing_ = false;
}

}  // namespace lacrima::editor
