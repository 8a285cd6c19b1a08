#include <lacrima/editor/KeyTableModel.h>

#include <lacrima/common/FapTable.h>
#include <lacrima/editing/EditorModel.h>
#include <lacrima/editor/EditorTheme.h>

#include <QColor>

#include <cmath>

namespace lacrima::editor {

KeyTableModel::KeyTableModel(editing::EditorModel& model, QObject* parent)
    : QAbstractTableModel(parent), model_(model) {
  // Any key change may add, remove or reorder rows; the table is small enough to reset.
  connect(&model_, &editing::EditorModel::keysChanged, this, [this] {
    beginResetModel();
    endResetModel();
  });
  connect(&model_, &editing::EditorModel::settingsChanged, this, [this] {
    if (rowCount() > 0) emit dataChanged(index(0, FrameColumn), index(rowCount() - 1, FrameColumn));
  });
  connect(&model_, &editing::EditorModel::timeChanged, this, [this] {
    if (rowCount() > 0)
      emit dataChanged(index(0, 0), index(rowCount() - 1, ColumnCount - 1), {Qt::ForegroundRole});
  });
}

int KeyTableModel::rowCount(const QModelIndex& parent) const {
  return parent.isValid() ? 0 : static_cast<int>(model_.document().keys.keys().size());
}

int KeyTableModel::columnCount(const QModelIndex& parent) const {
  return parent.isValid() ? 0 : ColumnCount;
}

QVariant KeyTableModel::data(const QModelIndex& index, int role) const {
  const auto& keys = model_.document().keys.keys();
  if (!index.isValid() || index.row() >= static_cast<int>(keys.size())) return {};
  const Keyframe& key = keys[static_cast<std::size_t>(index.row())];
  if (role == Qt::ForegroundRole) {
    if (std::abs(key.time - model_.currentTime()) < 1e-9) return theme::keyAccent();
    return {};
  }
  if (role == Qt::TextAlignmentRole && index.column() <= FrameColumn)
    return QVariant::fromValue(Qt::AlignRight | Qt::AlignVCenter);
  if (role != Qt::DisplayRole && role != Qt::EditRole && role != Qt::ToolTipRole) return {};
  switch (index.column()) {
    case TimeColumn:
      return role == Qt::EditRole ? QVariant(key.time)
                                  : QVariant(QString::number(key.time, 'f', 3));
    case FrameColumn:
      return key.time * model_.document().fps;
    case InterpolationColumn:
      return QString::fromUtf8(toString(key.interpolation).data());
    case ChannelsColumn: {
      QStringList names;
      for (int fap = 1; fap <= kChannelCount; ++fap)
        if (key.has(fap))
          names << QString::fromUtf8(fapInfo(fap).name.data(),
                                     static_cast<qsizetype>(fapInfo(fap).name.size()));
      if (role == Qt::ToolTipRole) return names.join(QStringLiteral(", "));
      const int count = static_cast<int>(names.size());
      if (names.size() > 3) names = names.mid(0, 3) << QStringLiteral("…");
      return QStringLiteral("%1: %2").arg(count).arg(names.join(QStringLiteral(", ")));
    }
    default:
      return {};
  }
}

QVariant KeyTableModel::headerData(int section, Qt::Orientation orientation, int role) const {
  if (orientation != Qt::Horizontal || role != Qt::DisplayRole) return {};
  switch (section) {
    case TimeColumn:
      return tr("Time (s)");
    case FrameColumn:
      return tr("Frame");
    case InterpolationColumn:
      return tr("Interpolation");
    case ChannelsColumn:
      return tr("Channels");
    default:
      return {};
  }
}

Qt::ItemFlags KeyTableModel::flags(const QModelIndex& index) const {
  Qt::ItemFlags f = QAbstractTableModel::flags(index);
  if (index.column() == TimeColumn || index.column() == InterpolationColumn)
    f |= Qt::ItemIsEditable;
  return f;
}

bool KeyTableModel::setData(const QModelIndex& index, const QVariant& value, int role) {
  if (role != Qt::EditRole || !index.isValid()) return false;
  const auto& keys = model_.document().keys.keys();
  if (index.row() >= static_cast<int>(keys.size())) return false;
  const double time = keys[static_cast<std::size_t>(index.row())].time;
  if (index.column() == TimeColumn) {
    bool ok = false;
    const double target = value.toDouble(&ok);
    if (!ok || !std::isfinite(target) || target < 0) return false;
    const int frames = static_cast<int>(std::lround((target - time) * model_.document().fps));
    model_.moveKeys({time}, frames);
    return true;
  }
  if (index.column() == InterpolationColumn) {
    const auto mode = interpolationFromString(value.toString().toStdString());
    if (!mode) return false;
    model_.setInterpolation({time}, *mode);
    return true;
  }
  return false;
}

}  // namespace lacrima::editor
