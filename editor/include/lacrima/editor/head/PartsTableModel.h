#pragma once
// The Head workspace's parts table: one row per sub-mesh of the imported head (name, material,
// triangles, role). The role column is editable (PartRoleDelegate shows a combo box); an edit
// is the document's undoable setRole.
#include <QAbstractTableModel>

namespace lacrima::editing {
class HeadSetup;
}

namespace lacrima::editor::head {

class PartsTableModel : public QAbstractTableModel {
  Q_OBJECT
 public:
  enum Column { Name, Material, Triangles, Role, ColumnCount };
  // Qt::EditRole of the role column: the PartRole as an int.
  explicit PartsTableModel(editing::HeadSetup& setup, QObject* parent = nullptr);

  int rowCount(const QModelIndex& parent = {}) const override;
  int columnCount(const QModelIndex& parent = {}) const override;
  QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
  QVariant headerData(int section, Qt::Orientation orientation, int role) const override;
  Qt::ItemFlags flags(const QModelIndex& index) const override;
  bool setData(const QModelIndex& index, const QVariant& value, int role = Qt::EditRole) override;

  // "Skin", "Eye (left)", ... for the table and the combo box.
  static QString roleLabel(int partRole);

 private:
  editing::HeadSetup& setup_;
};

}  // namespace lacrima::editor::head
