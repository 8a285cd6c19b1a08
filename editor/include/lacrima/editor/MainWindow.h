#pragma once
// The editor window: channels on the left, the preview in the middle, presets / keys / history
// on the right, transport and timeline at the bottom; menus and shortcuts for everything.
//
// Files: projects are the foundation's JSON documents (saved atomically); FAP files are
// imported (frames become keys, optionally reduced) and exported (extended or strict 68).
// Comfort: the title carries the unsaved mark, closing or replacing unsaved work asks first,
// recent files are remembered (QSettings), and unsaved work is autosaved to a recovery file
// two seconds after each change and every 30 s, removed on a clean exit; the next editor to
// start offers to restore it (RecoveryStore.h).
//
// Every path-taking operation exists without dialogs (openFile, saveTo, importFap, exportFap),
// for the command line and tests; with `interactive` off, nothing ever opens a modal dialog
// (errors go to lastError() and the status bar, and unsaved changes are discarded).
#include <lacrima/editing/FapTransfer.h>

#include <QByteArray>
#include <QMainWindow>

#include <memory>
#include <optional>

class QTabWidget;

namespace lacrima::editing {
class EditorModel;
class FrameStepClock;
class RecoveryStore;
struct MoodGenerationRequest;
}  // namespace lacrima::editing

namespace lacrima::appsupport {
class ExportDialog;
}

namespace lacrima::editor {

namespace head {
class HeadWorkspace;
}
class DopeSheet;
class GraphEditor;
class KeyListPanel;
class LayerPanel;
class PresetPanel;
class LiveRecording;
class MoodGenerationDialog;
class PreviewPanel;
class RecoveryBanner;
class SliderPanel;
class TimelineWidget;
class TransportBar;

struct EditorOptions {
  bool preview = true;         // load the head and show the viewport
  bool interactive = true;     // dialogs and prompts (off: tests, batch screenshots)
  bool offerRecovery = true;   // look for crashed sessions at start
  QString recoveryDirectory;   // empty: RecoveryStore::defaultDirectory()
  QString presetsPath;         // empty: the built-in presets
  int autosaveDelayMs = 2000;  // after a change
  int autosaveIntervalMs = 30000;
  int simulationThreads = 0;  // the preview's tears (PreviewPanel::setSimulationThreads)
};

class MainWindow : public QMainWindow {
  Q_OBJECT
 public:
  explicit MainWindow(EditorOptions options = {}, QWidget* parent = nullptr);
  ~MainWindow() override;

  editing::EditorModel& model();
  editing::FrameStepClock& clock();
  SliderPanel* sliders() const;
  TimelineWidget* timeline() const;
  LayerPanel* layers() const;
  GraphEditor* graphEditor() const;
  // The tabs under the transport: Keys (the timeline) and the per-channel views.
  QTabWidget* animationViews() const;
  // Brings the view named "keys", "dope", "graph" or "moods" (the graph editor's Moods view) to
  // the front; false for any other name.
  bool showAnimationView(const QString& name);
  DopeSheet* dopeSheet() const;  // the Dope sheet tab
  TransportBar* transport() const;
  PresetPanel* presets() const;
  PreviewPanel* preview() const;
  KeyListPanel* keyList() const;
  RecoveryBanner* recoveryBanner() const;
  // The workspaces over the central area: Animate (the preview) and Head (bring your own head).
  // Each has its own undo history; Edit ▸ Undo and Redo act on the one shown. The Head workspace
  // hides the animation's docks (presets, keys, layers, history, timeline) for room, and its
  // sliders pose the head without keying (EditorModel::setPosingOnly).
  enum class Workspace { Animate, Head };
  head::HeadWorkspace* headWorkspace() const;
  void setWorkspace(Workspace workspace);
  Workspace workspace() const;
  editing::RecoveryStore& recovery();
  // Actions by object name ("file.save", "key.add", ...), for tests and the shortcut list.
  QAction* action(const QString& name) const;
  // Playback > Record live...: a stream turned into keys from the playhead (LiveRecording.h).
  LiveRecording& liveRecording();
  // Animation > Generate crying...: opens a dialog (MoodGenerationDialog.h) whose Generate writes
  // the take with generateCrying(). Its range starts as the span of the selected keys, else the
  // whole take (10 s when there are no keys). Returns it (it closes itself), for tests.
  MoodGenerationDialog* openGenerateCrying();
  // A take of the crying generator as keys over the request's range, or `asLayer` as a
  // procedural layer (EditorModel::addMoodLayer), in one undo step; false (the reason in
  // lastError() and the status bar) when the request is refused.
  bool generateCrying(const editing::MoodGenerationRequest& request, bool asLayer = false);

  // --- files (false on failure; the reason is in lastError()) ---------------------------
  void newDocument();
  bool openFile(const QString& path);  // a project, or a .fap to import
  bool saveTo(const QString& path);
  bool importFap(const QString& path, std::optional<double> reductionTolerance);
  bool exportFap(const QString& path, const editing::FapExportOptions& options);
  QString filePath() const;
  // File > Export Animation…: the shared export dialog (appsupport/ExportDialog.h, the player's)
  // on the document as it is now, unsaved edits included, non-modal; returned for tests. The
  // export reads the project file when it is saved and unchanged; otherwise a temporary copy
  // saved for it (owned by the dialog, removed with it), never the user's file. Outputs go
  // beside the project by default. Nullptr, the reason in lastError(), when the document
  // cannot be baked or copied.
  appsupport::ExportDialog* exportAnimationDialog();
  // The project's head: a mesh and its feature-point file (File > Choose head…), as one undoable
  // edit; the preview rigs it in the background. False (reason in lastError()) when either file
  // does not exist.
  bool setHead(const QString& meshPath, const QString& fdpPath);
  QString lastError() const;

  // --- autosave and recovery --------------------------------------------------------------
  void autosaveNow();
  void checkForRecovery();  // shows the banner when a crashed session left work
  bool restoreRecovery();   // the newest orphan
  void discardRecovery();

  // --- clipboard --------------------------------------------------------------------------
  void copyKeys();
  void pasteKeys(std::optional<double> at = std::nullopt);

 protected:
  void closeEvent(QCloseEvent* event) override;
  void showEvent(QShowEvent* event) override;
  void dragEnterEvent(QDragEnterEvent* event) override;
  void dropEvent(QDropEvent* event) override;

 private:
  // The widgets, models and timers the window owns (MainWindowPrivate.h), so that this header
  // names no widget it does not hand out.
  struct Private;

  void createDocks();
  void arrangeDocks(Workspace workspace);
  // The docks to save: the Animate workspace's, also while the Head workspace is shown.
  QByteArray animateLayout() const;
  void createActions();  // every action and what it does; MainMenus.h lays them out
  QAction* makeAction(const QString& name, const QString& text, const QKeySequence& shortcut,
                      const QString& tip = {});
  bool maybeSave();
  void updateTitle();
  void updateStatusFigures();
  void addRecentFile(const QString& path);
  void rebuildRecentMenu();
  void reportError(const QString& title, const QString& message);
  void onDocumentChanged();
  void openDialog();
  bool saveDialog();
  void importDialog();
  void exportDialog();
  void chooseHeadDialog();
  void settingsDialog();
  void loadPresetsDialog();
  void showShortcuts();

  std::unique_ptr<Private> d_;
};

}  // namespace lacrima::editor
