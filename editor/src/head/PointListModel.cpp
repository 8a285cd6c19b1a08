#include <lacrima/editor/head/PointListModel.h>

#include <lacrima/editing/HeadSetup.h>
#include <lacrima/rigging/FeaturePointProposal.h>

#include <QBrush>
#include <QFont>

#include <algorithm>
#include <set>

namespace lacrima::editor::head {

PointListModel::PointListModel(editing::HeadSetup& setup, Describe describe, QObject* parent)
    : QAbstractTableModel(parent), setup_(setup), describe_(std::move(describe)) {
  rebuild();
  connect(&setup_, &editing::HeadSetup::pointsChanged, this, [this] {
    const std::size_t before = ids_.size();
    rebuild();
    if (ids_.size() != before) return;  // rebuild reset the model
    if (!ids_.empty()) emit dataChanged(index(0, 0), index(rowCount() - 1, ColumnCount - 1));
  });
}

const std::vector<std::string>& PointListModel::anchorOrder() {
  // From the top of the face down, the eyes first: they and the chin give the face's frame.
  static const std::vector<std::string> order = {"3.7", "3.8", "3.11", "3.12",
                                                 "9.3", "8.3", "8.4",  "2.10"};
  return order;
}

void PointListModel::rebuild() {
  // The anchors in the order they are placed, then every point the rig knows, then any other
  // point the document has (a file may carry more), by FDP id.
  std::vector<std::string> ids = anchorOrder();
  std::set<std::string, rigging::FdpIdLess> rest;
  for (const auto& id : rigging::fapuFeaturePoints()) rest.insert(id);
  for (const auto& id : rigging::animatedFeaturePoints()) rest.insert(id);
  for (const auto& [id, p] : setup_.points()) rest.insert(id);
  for (const auto& id : rest)
    if (std::find(ids.begin(), ids.end(), id) == ids.end()) ids.push_back(id);
  if (ids == ids_) return;
  beginResetModel();
  ids_ = std::move(ids);
  endResetModel();
}

int PointListModel::rowOf(const std::string& id) const {
  const auto it = std::find(ids_.begin(), ids_.end(), id);
  return it == ids_.end() ? -1 : static_cast<int>(it - ids_.begin());
}

int PointListModel::rowCount(const QModelIndex& parent) const {
  return parent.isValid() ? 0 : static_cast<int>(ids_.size());
}

int PointListModel::columnCount(const QModelIndex& parent) const {
  return parent.isValid() ? 0 : ColumnCount;
}

QVariant PointListModel::data(const QModelIndex& index, int role) const {
  if (!index.isValid() || index.row() >= rowCount()) return {};
  const std::string& id = ids_[static_cast<std::size_t>(index.row())];
  const editing::PlacedPoint* point = setup_.point(id);
  const bool anchor = index.row() < static_cast<int>(rigging::proposalAnchors().size());
  if (role == IdRole) return QString::fromStdString(id);
  if (role == Qt::DisplayRole) {
    switch (index.column()) {
      case Id:
        return QString::fromStdString(id);
      case Description:
        return describe_ ? describe_(id) : QString();
      case State:
        if (!point) return anchor ? tr("place by hand") : tr("missing");
        return point->byHand() ? tr("hand") : tr("proposed");
      default:
        return {};
    }
  }
  if (role == Qt::ForegroundRole && index.column() == State)
    return QBrush(!point            ? PointColours::missing()
                  : point->byHand() ? PointColours::hand()
                                    : PointColours::proposed());
  if (role == Qt::ToolTipRole) return describe_ ? describe_(id) : QString();
  if (role == Qt::FontRole && anchor && index.column() == Id) {
    QFont bold;
    bold.setBold(true);
    return bold;
  }
  return {};
}

QVariant PointListModel::headerData(int section, Qt::Orientation orientation, int role) const {
  if (orientation != Qt::Horizontal || role != Qt::DisplayRole) return {};
  switch (section) {
    case Id:
      return tr("Point");
    case Description:
      return tr("Where");
    case State:
      return tr("Placed");
    default:
      return {};
  }
}

}  // namespace lacrima::editor::head
