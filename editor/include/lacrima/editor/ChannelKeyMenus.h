#pragma once
// The per-channel key actions the dope sheet and the graph editor share, as Blender's T and V
// menus: the interpolation (Constant, Linear, Smooth, Bézier) and the handle type (Auto,
// Aligned, Free) of the selected channel keys (EditorModel::selectedChannelKeys), and deleting
// them. Each action is one undo step that also restores the channel-key selection.
#include <QCoreApplication>

class QMenu;

namespace lacrima::editing {
class EditorModel;
}  // namespace lacrima::editing

namespace lacrima::editor {

class ChannelKeyMenus {
  Q_DECLARE_TR_FUNCTIONS(ChannelKeyMenus)

 public:
  // Fill `menu` with the actions; disabled while nothing is selected.
  static void fillInterpolationMenu(QMenu& menu, editing::EditorModel& model);
  static void fillHandleTypeMenu(QMenu& menu, editing::EditorModel& model);
  // Removes the selected channel keys (a key left with no channel goes); says so when nothing
  // is selected.
  static void deleteSelected(editing::EditorModel& model);
};

}  // namespace lacrima::editor
