#include <lacrima/editor/ChannelKeyMenus.h>

#include <lacrima/editing/ChannelKeyEdits.h>
#include <lacrima/editing/CurveEdits.h>
#include <lacrima/editing/EditorModel.h>

#include <QMenu>

#include <utility>

namespace lacrima::editor {
namespace {

QString interpolationName(Interpolation mode) {
  switch (mode) {
    case Interpolation::Constant:
      return ChannelKeyMenus::tr("&Constant");
    case Interpolation::Linear:
      return ChannelKeyMenus::tr("&Linear");
    case Interpolation::Smooth:
      return ChannelKeyMenus::tr("&Smooth");
    case Interpolation::Bezier:
      return ChannelKeyMenus::tr("&Bézier");
  }
  return {};
}

QString handleTypeName(HandleType type) {
  switch (type) {
    case HandleType::Auto:
      return ChannelKeyMenus::tr("&Auto");
    case HandleType::Aligned:
      return ChannelKeyMenus::tr("A&ligned");
    case HandleType::Free:
      return ChannelKeyMenus::tr("&Free");
  }
  return {};
}

// Undo text without the menu's accelerator marks.
QString plain(QString text) { return text.remove(QLatin1Char('&')); }

template <typename Shape>
void setShapes(editing::EditorModel& model, Shape shape, const QString& text) {
  const std::vector<editing::ChannelKey> selection = model.channelKeySelection().keys();
  const editing::KeyChange change =
      editing::setChannelKeyShapes(model.document().keys, selection, shape);
  if (change.isNoOp()) return;
  model.editKeys(change, text, std::nullopt, selection);
}

}  // namespace

void ChannelKeyMenus::fillInterpolationMenu(QMenu& menu, editing::EditorModel& model) {
  for (Interpolation mode : {Interpolation::Constant, Interpolation::Linear, Interpolation::Smooth,
                             Interpolation::Bezier}) {
    QObject::connect(
        menu.addAction(interpolationName(mode)), &QAction::triggered, &menu, [&model, mode] {
          setShapes(model, mode, tr("Interpolation: %1").arg(plain(interpolationName(mode))));
        });
  }
  menu.setEnabled(!model.channelKeySelection().empty());
}

void ChannelKeyMenus::fillHandleTypeMenu(QMenu& menu, editing::EditorModel& model) {
  for (HandleType type : {HandleType::Auto, HandleType::Aligned, HandleType::Free}) {
    QObject::connect(menu.addAction(handleTypeName(type)), &QAction::triggered, &menu,
                     [&model, type] {
                       setShapes(model, type, tr("Handles: %1").arg(plain(handleTypeName(type))));
                     });
  }
  menu.setEnabled(!model.channelKeySelection().empty());
}

void ChannelKeyMenus::deleteSelected(editing::EditorModel& model) {
  const std::vector<editing::ChannelKey> selected = model.channelKeySelection().keys();
  if (selected.empty()) {
    emit model.message(tr("Select channel keys to delete first"));
    return;
  }
  const editing::ChannelKeyEdit edit = editing::deleteChannelKeys(model.document().keys, selected);
  if (edit.change.isNoOp()) return;
  const QString text = selected.size() == 1 ? tr("Delete channel key")
                                            : tr("Delete %1 channel keys").arg(selected.size());
  model.editKeys(edit.change, text, std::nullopt, edit.selection);
}

}  // namespace lacrima::editor
