#pragma once
// The editor's menu bar and main toolbar, laid out from the window's actions. It decides where
// each action is offered and how the toolbar labels it; what an action does is the window's
// (MainWindow::createActions).
#include <QString>

#include <functional>

class QAction;
class QMainWindow;
class QMenu;

namespace lacrima::editor {

// `action` finds an action by object name ("file.save"); every name laid out must exist. The
// View menu also lists the window's docks. Returns File ▸ Open Recent, which the window fills.
QMenu* buildMainMenus(QMainWindow& window, const std::function<QAction*(const QString&)>& action);

}  // namespace lacrima::editor
