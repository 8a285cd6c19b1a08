#include <lacrima/editor/head/PartsTableModel.h>

#include <lacrima/editing/HeadSetup.h>

namespace lacrima::editor::head {

using editing::PartRole;

PartsTableModel::PartsTableModel(editing::HeadSetup& setup, QObject* parent)
    : QAbstractTableModel(parent), setup_(setup) {
  connect(&setup_, &editing::HeadSetup::meshChanged, this, [this] {
    beginResetModel();
    endResetModel();
  });
  connect(&setup_, &editing::HeadSetup::rolesChanged, this, [this] {
    if (rowCount() > 0) emit dataChanged(index(0, Role), index(rowCount() - 1, Role));
  });
}

QString PartsTableModel::roleLabel(int partRole) {
  switch (static_cast<PartRole>(partRole)) {
    case PartRole::Skin:
      return tr("Skin");
    case PartRole::EyeLeft:
      return tr("Eye (left)");
    case PartRole::EyeRight:
      return tr("Eye (right)");
    case PartRole::CorneaLeft:
      return tr("Cornea (left)");
    case PartRole::CorneaRight:
      return tr("Cornea (right)");
    case PartRole::TeethUpper:
      return tr("Upper teeth");
    case PartRole::TeethLower:
      return tr("Lower teeth (jaw)");
    case PartRole::Tongue:
      return tr("Tongue");
    case PartRole::Attached:
      return tr("Attached to skin");
    case PartRole::Rigid:
      return tr("Rigid");
    case PartRole::Ignored:
      return tr("Ignored");
  }
  return {};
}

int PartsTableModel::rowCount(const QModelIndex& parent) const {
  if (parent.isValid() || !setup_.hasMesh()) return 0;
  return static_cast<int>(setup_.mesh().submeshes.size());
}

int PartsTableModel::columnCount(const QModelIndex& parent) const {
  return parent.isValid() ? 0 : ColumnCount;
}

QVariant PartsTableModel::data(const QModelIndex& index, int role) const {
  if (!index.isValid() || index.row() >= rowCount()) return {};
  const HeadMesh& mesh = setup_.mesh();
  const HeadSubmesh& part = mesh.submeshes[static_cast<std::size_t>(index.row())];
  if (role == Qt::DisplayRole) {
    switch (index.column()) {
      case Name:
        return QString::fromStdString(part.name);
      case Material:
        return part.material >= 0 && part.material < static_cast<int>(mesh.materials.size())
                   ? QString::fromStdString(
                         mesh.materials[static_cast<std::size_t>(part.material)].name)
                   : QString();
      case Triangles:
        return static_cast<qlonglong>(part.triangles.size());
      case Role:
        return roleLabel(static_cast<int>(setup_.role(index.row())));
      default:
        return {};
    }
  }
  if (role == Qt::EditRole && index.column() == Role)
    return static_cast<int>(setup_.role(index.row()));
  if (role == Qt::ToolTipRole && index.column() == Role)
    return tr("What this part does in the rig; double-click to change");
  return {};
}

QVariant PartsTableModel::headerData(int section, Qt::Orientation orientation, int role) const {
  if (orientation != Qt::Horizontal || role != Qt::DisplayRole) return {};
  switch (section) {
    case Name:
      return tr("Part");
    case Material:
      return tr("Material");
    case Triangles:
      return tr("Triangles");
    case Role:
      return tr("Role");
    default:
      return {};
  }
}

Qt::ItemFlags PartsTableModel::flags(const QModelIndex& index) const {
  Qt::ItemFlags f = QAbstractTableModel::flags(index);
  if (index.column() == Role) f |= Qt::ItemIsEditable;
  return f;
}

bool PartsTableModel::setData(const QModelIndex& index, const QVariant& value, int role) {
  if (role != Qt::EditRole || index.column() != Role || index.row() >= rowCount()) return false;
  bool ok = false;
  const int r = value.toInt(&ok);
  if (!ok || r < 0 || r >= static_cast<int>(editing::kPartRoles.size())) return false;
  setup_.setRole(index.row(), static_cast<PartRole>(r));  // rolesChanged updates the view
  return true;
}

}  // namespace lacrima::editor::head
