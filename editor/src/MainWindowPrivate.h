#pragma once
// What MainWindow owns, shared by its source files (MainWindow.cpp: layout and workspaces,
// MainWindowActions.cpp: actions, MainWindowFiles.cpp: files and recovery). The widgets are
// Qt children of the window; the pointers here only name them.
#include <lacrima/editing/EditorModel.h>
#include <lacrima/editing/FrameStepClock.h>
#include <lacrima/editing/RecoveryStore.h>
#include <lacrima/editor/MainWindow.h>

#include <QString>

#include <memory>

class QLabel;
class QMenu;
class QStackedWidget;
class QTabBar;
class QTimer;
class QUndoGroup;
class QUndoView;

namespace lacrima::editor {

struct MainWindow::Private {
  explicit Private(EditorOptions o)
      : options(std::move(o)),
        model(std::make_unique<editing::EditorModel>()),
        clock(std::make_unique<editing::FrameStepClock>(*model)),
        recovery(std::make_unique<editing::RecoveryStore>(
            options.recoveryDirectory.isEmpty() ? editing::RecoveryStore::defaultDirectory()
                                                : options.recoveryDirectory)) {}

  EditorOptions options;
  std::unique_ptr<editing::EditorModel> model;
  std::unique_ptr<editing::FrameStepClock> clock;
  std::unique_ptr<editing::RecoveryStore> recovery;
  SliderPanel* sliders = nullptr;
  QTabWidget* animationViews = nullptr;
  LayerPanel* layers = nullptr;
  TimelineWidget* timeline = nullptr;
  DopeSheet* dopeSheet = nullptr;
  GraphEditor* graphEditor = nullptr;
  TransportBar* transport = nullptr;
  PresetPanel* presets = nullptr;
  PreviewPanel* preview = nullptr;
  KeyListPanel* keyList = nullptr;
  RecoveryBanner* banner = nullptr;
  head::HeadWorkspace* headWorkspace = nullptr;
  QTabBar* workspaces = nullptr;
  QStackedWidget* workspaceStack = nullptr;
  QUndoGroup* undoGroup = nullptr;  // the animation's and the head's undo stacks
  QUndoView* history = nullptr;
  QMenu* recentMenu = nullptr;
  QLabel* figures = nullptr;
  QTimer* autosaveSoon = nullptr;
  QTimer* autosavePeriodic = nullptr;
  bool autosaveDirty = false;
  QString filePath;
  QString lastError;
  QString pendingRecovery;
};

}  // namespace lacrima::editor
