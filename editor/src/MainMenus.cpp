#include "MainMenus.h"

#include <QAction>
#include <QDockWidget>
#include <QMainWindow>
#include <QMenuBar>
#include <QToolBar>

#include <initializer_list>

namespace lacrima::editor {
namespace {

// In a layout, "" is a separator.
using Layout = std::initializer_list<const char*>;

void addActions(QWidget& to, const Layout& names,
                const std::function<QAction*(const QString&)>& action) {
  for (const char* name : names) {
    if (!*name) {
      auto* separator = new QAction(&to);
      separator->setSeparator(true);
      to.addAction(separator);
      continue;
    }
    to.addAction(action(QString::fromLatin1(name)));
  }
}

}  // namespace

QMenu* buildMainMenus(QMainWindow& window, const std::function<QAction*(const QString&)>& action) {
  QMenuBar* bar = window.menuBar();
  QMenu* file = bar->addMenu(QMainWindow::tr("&File"));
  addActions(*file, {"file.new", "file.open"}, action);
  QMenu* recent = file->addMenu(QMainWindow::tr("Open &Recent"));
  addActions(*file,
             {"", "file.save", "file.saveAs", "", "file.import", "file.export",
              "file.exportAnimation", "file.chooseHead", "", "file.quit"},
             action);

  addActions(*bar->addMenu(QMainWindow::tr("&Edit")),
             {"edit.undo", "edit.redo", "", "edit.copy", "edit.paste", "edit.delete",
              "edit.selectAll", "", "edit.mirror", "edit.symmetric", "", "edit.settings"},
             action);
  addActions(*bar->addMenu(QMainWindow::tr("&Key")),
             {"key.add", "key.linear", "key.smooth", "", "key.previous", "key.next"}, action);
  addActions(*bar->addMenu(QMainWindow::tr("&Animation")), {"anim.generateCrying"}, action);
  addActions(*bar->addMenu(QMainWindow::tr("&Playback")),
             {"play.toggle", "play.start", "play.end", "play.previousFrame", "play.nextFrame",
              "play.goToTime", "", "play.recordLive"},
             action);
  QMenu* view = bar->addMenu(QMainWindow::tr("&View"));
  addActions(
      *view,
      {"view.tearPreview", "view.frameAll", "view.filter", "", "view.animate", "view.head", ""},
      action);
  for (QDockWidget* dock : window.findChildren<QDockWidget*>())
    view->addAction(dock->toggleViewAction());
  addActions(*bar->addMenu(QMainWindow::tr("&Help")), {"help.shortcuts"}, action);

  QToolBar* tools = window.addToolBar(QMainWindow::tr("Main"));
  tools->setObjectName(QStringLiteral("toolbar.main"));
  tools->setMovable(false);
  tools->setToolButtonStyle(Qt::ToolButtonTextOnly);
  addActions(*tools,
             {"file.new", "file.open", "file.save", "", "edit.undo", "edit.redo", "", "key.add",
              "edit.delete", "edit.mirror", "edit.symmetric", "", "file.import", "file.export"},
             action);
  // Short labels on the toolbar; the menus keep the full texts.
  for (const auto& [name, label] : {std::pair{"edit.undo", QMainWindow::tr("Undo")},
                                    std::pair{"edit.redo", QMainWindow::tr("Redo")},
                                    std::pair{"key.add", QMainWindow::tr("Key")},
                                    std::pair{"edit.delete", QMainWindow::tr("Delete")},
                                    std::pair{"edit.mirror", QMainWindow::tr("Mirror")},
                                    std::pair{"edit.symmetric", QMainWindow::tr("Symmetric")},
                                    std::pair{"file.import", QMainWindow::tr("Import FAP")},
                                    std::pair{"file.export", QMainWindow::tr("Export FAP")}})
    action(QString::fromLatin1(name))->setIconText(label);
  return recent;
}

}  // namespace lacrima::editor
