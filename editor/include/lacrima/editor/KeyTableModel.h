#pragma once
// The keys as a table (Qt model/view): time, frame, interpolation and the channels each key
// sets. Time and interpolation are editable; edits go through the editor model, so they are
// undoable like every other edit (a time edit moves the key by whole frames).
#include <QAbstractTableModel>

namespace lacrima::editing {
class EditorModel;
}  // namespace lacrima::editing

namespace lacrima::editor {

class KeyTableModel : public QAbstractTableModel {
  Q_OBJECT
 public:
  enum Column { TimeColumn, FrameColumn, InterpolationColumn, ChannelsColumn, ColumnCount };

  explicit KeyTableModel(editing::EditorModel& model, QObject* parent = nullptr);

  int rowCount(const QModelIndex& parent = {}) const override;
  int columnCount(const QModelIndex& parent = {}) const override;
  QVariant data(const QModelIndex& index, int role) const override;
  QVariant headerData(int section, Qt::Orientation orientation, int role) const override;
  Qt::ItemFlags flags(const QModelIndex& index) const override;
  bool setData(const QModelIndex& index, const QVariant& value, int role) override;

 private:
  editing::EditorModel& model_;
};

}  // namespace lacrima::editor
