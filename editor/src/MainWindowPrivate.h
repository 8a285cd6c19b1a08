#pragma once
// What MainWindow owns, shared by its source files (MainWindow.cpp: layout and workspaces,
// MainWindowActions.cpp: actions, MainWindowFiles.cpp: files and recovery). The widgets are
// Qt children of the window; the pointers here only name them.
#include <lacrima/editing/EditorModel.h>
#include <lacrima/editing/FrameStepClock.h>
#include <lacrima/editing/RecoveryStore.h>
#include <lacrima/editor/MainWindow.h>
#include <lacrima/editor/RecordLiveDialog.h>

#include <QByteArray>
#include <QString>

#include <memory>

class QLabel;
class QMenu;
class QStackedWidget;
class QTabBar;
class QTimer;
class QUndoGroup;
class QUndoView;

namespace lacrima::viewport {
class ElidedLabel;
}

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
  LiveRecording* liveRecording = nullptr;
  RecordLiveSettings recordSettings;  // as last confirmed in the Record live dialog
  KeyListPanel* keyList = nullptr;
  RecoveryBanner* banner = nullptr;
  head::HeadWorkspace* headWorkspace = nullptr;
  QTabBar* workspaces = nullptr;
  QStackedWidget* workspaceStack = nullptr;
  QUndoGroup* undoGroup = nullptr;  // the animation's and the head's undo stacks
  QUndoView* history = nullptr;
  QMenu* recentMenu = nullptr;
  viewport::ElidedLabel* figures = nullptr;
  QTimer* autosaveSoon = nullptr;
  QTimer* autosavePeriodic = nullptr;
  bool autosaveDirty = false;
  QString filePath;
  QString lastError;
  QString pendingRecovery;
  // The Animate workspace's docks as they were when the Head workspace was shown (which hides
  // every dock but the channels), to put back on return and to save on closing.
  QByteArray animateLayout;
  // The docks' sizes are set once the window has its size (on the first show), unless a saved
  // layout was restored: set before, the window's first, smaller size squeezes the timeline.
  bool docksSized = false;
};

}  // namespace lacrima::editor
