#pragma once
// The Head workspace's feature points: the anchors to place by hand first (proposalAnchors(),
// in anchorOrder()), then every other point a rig uses, by FDP id. Columns: id, description,
// state (hand, proposed or missing, coloured as the markers are).
#include <QAbstractTableModel>
#include <QColor>

#include <functional>
#include <string>
#include <vector>

namespace lacrima::editing {
class HeadSetup;
}

namespace lacrima::editor::head {

// The markers' and the list's colours.
struct PointColours {
  static QColor hand() { return {70, 200, 120}; }      // placed by the user
  static QColor proposed() { return {90, 160, 255}; }  // carried over by the proposal
  static QColor current() { return {255, 196, 40}; }   // the point being placed
  static QColor missing() { return {200, 90, 90}; }
};

class PointListModel : public QAbstractTableModel {
  Q_OBJECT
 public:
  enum Column { Id, Description, State, ColumnCount };
  static constexpr int IdRole = Qt::UserRole + 1;  // the FDP id as a QString

  // `describe` gives a point's description from the FDP table (empty: none).
  using Describe = std::function<QString(const std::string& id)>;
  PointListModel(editing::HeadSetup& setup, Describe describe, QObject* parent = nullptr);

  // The 8 anchors in the order they are asked for, as the manual lists them: the eye corners,
  // the nose tip, the mouth corners, the chin.
  static const std::vector<std::string>& anchorOrder();

  const std::vector<std::string>& ids() const { return ids_; }
  int rowOf(const std::string& id) const;  // -1 when absent

  int rowCount(const QModelIndex& parent = {}) const override;
  int columnCount(const QModelIndex& parent = {}) const override;
  QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
  QVariant headerData(int section, Qt::Orientation orientation, int role) const override;

 private:
  void rebuild();

  editing::HeadSetup& setup_;
  Describe describe_;
  std::vector<std::string> ids_;
};

}  // namespace lacrima::editor::head
