#pragma once
// The Head workspace: bring your own head. Import a mesh, say what each part is,
// click the 8 anchors on it, let the rest be proposed, drag what is off, and watch the rigged
// head follow the editor's FAP sliders; then save the feature points and use the head in the
// project.
//
// Layout: a tool bar (Import..., Open points..., Propose, Save..., Use in project, the rig's
// progress and status), the face viewport in the middle, and on the right the parts table, the
// point list, the reference picture of the current point and the rig checks.
//
// Mouse on the viewport (FaceViewport's pointer signals): a click places the current point
// where it hits the head, then selects the next anchor still missing; pressing on a marker
// claims the drag and moves that point (snapped to its part's surface when released, one undo
// step; released in place it only selects the point); every other drag orbits, pans or zooms
// as in the preview. Markers: hand points green, proposed ones blue, the current point yellow
// and ringed. Clicks go through attached and ignored parts (lashes, tear films). Once the eye
// corners and the chin are placed the view turns to the face's own frame (a Z-up head stands
// up; FaceFrame.h).
//
// Nothing blocks the window: the import (assimp), the proposal and the rig run on worker
// threads; an edit restarts the rig after a short pause (rigDelay), with progress, and a newer
// edit supersedes a rig still running (RigJob.h). Once rigged, the viewport shows the head posed
// by the editor model's current FAP values, so the slider panel deforms it at once; while the
// workspace is shown the sliders pose without keying (EditorModel::setPosingOnly), and the bar
// over the viewport says so.
//
// Every action exists without dialogs (importHead, proposePoints, saveTo, openPoints) for
// tests; failures go to lastError() and the status line and leave the workspace as it was.
#include <lacrima/common/HeadMesh.h>
#include <lacrima/rigging/RigChecks.h>

#include <Eigen/Core>
#include <QImage>
#include <QPointF>
#include <QString>
#include <QStringList>
#include <QWidget>

#include <atomic>
#include <map>
#include <memory>
#include <string>
#include <vector>

class QLabel;
class QProgressBar;
class QTableView;
class QListWidget;
class QTimer;
class QToolButton;

namespace lacrima::editing {
enum class PartRole;
class EditorModel;
class HeadSetup;
struct ProposalReference;
}  // namespace lacrima::editing
namespace lacrima::playback {
struct HeadRig;
class FrameProducer;
}  // namespace lacrima::playback
namespace lacrima::viewport {
class FaceViewport;
}
namespace lacrima::exporters {
struct ReferenceHead;
}

namespace lacrima::editor {
class RigJob;
}

namespace lacrima::editor::head {

class PartsTableModel;
class PointListModel;

class HeadWorkspace : public QWidget {
  Q_OBJECT
 public:
  explicit HeadWorkspace(editing::EditorModel& model, QWidget* parent = nullptr);
  ~HeadWorkspace() override;

  editing::HeadSetup& setup() { return *setup_; }
  viewport::FaceViewport* viewport() const { return viewport_; }
  QTableView* partsView() const { return partsView_; }
  QListWidget* checksView() const { return checksView_; }

  // --- actions (no dialogs) ---------------------------------------------------------------
  // Reads the mesh on a worker thread, through the importer process (a file that crashes or
  // hangs assimp costs that process only); importFinished(ok) tells how it went. On failure or
  // cancel the workspace keeps the head it had.
  void importHead(const QString& path);
  // Stops a running import at once (its process is killed); importFinished(false) follows.
  void cancelImport();
  bool importing() const { return importing_; }
  // How long an import may take; 0 (the default) lets the file's size decide (ImportProcess.h).
  void setImportTimeLimit(double seconds) { importSeconds_ = seconds; }
  // Proposes every point not placed by hand, on a worker thread; proposalFinished(ok).
  void proposePoints();
  bool saveTo(const QString& path);
  bool openPoints(const QString& path);
  // Saves when needed (asks for a path when interactive) and asks the window to use the head.
  void useInProject();

  std::string currentPoint() const { return current_; }
  void setCurrentPoint(const std::string& id);

  // The reference picture shown for the current point (null while it renders, or without the
  // default head).
  QImage referencePicture() const;

  // The rig of the newest finished job and its checks: null before the first rig of a head; an
  // edit the rig fails on keeps the last one shown (the status line says why).
  const playback::HeadRig* rig() const { return rig_.get(); }
  const std::vector<rigging::RigCheck>& checks() const { return checks_; }
  bool rigging() const;  // a rig is waiting for the edits to pause, or running
  // How long the workspace waits after an edit before rigging again.
  void setRigDelay(int milliseconds);

  QString lastError() const { return lastError_; }
  QString statusText() const;
  void setInteractive(bool on) { interactive_ = on; }

  // Re-poses the rigged head with the model's current values (the sliders call this).
  void pose();

 signals:
  void importFinished(bool ok);
  void proposalFinished(bool ok);
  void rigFinished();
  void rigFailed(const QString& message);
  void referenceShown(const QString& id);  // the current point's picture is up
  void statusChanged(const QString& text);
  // The saved head, for MainWindow::setHead.
  void useInProjectRequested(const QString& meshPath, const QString& fdpPath);

 private:
  QWidget* createToolBar();
  void showImportRunning(bool running);
  QWidget* createSidePanel();
  QWidget* createPoseBar(QWidget* parent);
  void onMeshChanged();
  void onDocumentEdited();
  void startRig();
  void onRigFinished(std::shared_ptr<playback::HeadRig> rig);
  void updateMarkers();
  void updateReference();
  void updateChecks();
  static QStringList fdpIdsIn(const QString& text);
  static std::shared_ptr<const HeadMesh> withRigRoles(const HeadMesh& mesh,
                                                      const std::vector<editing::PartRole>& roles);
  void updatePickable();
  void onRolesChanged();
  void setStatus(const QString& text);
  void fail(const QString& what, const QString& message);
  void selectNextMissingAnchor();
  // Mouse on the viewport (its pointer signals): place the current point, drag a marker.
  void connectViewport();
  void orientView();  // the view frame from the placed eyes and mouth
  bool clickPlaces(QPointF pixel);
  void dragMarker(QPointF pixel);
  void dropMarker(QPointF pixel);
  std::string markerAt(QPointF pixel) const;
  Eigen::Vector3d shownPosition(const std::string& id) const;

  editing::EditorModel& model_;
  std::unique_ptr<editing::HeadSetup> setup_;
  std::shared_ptr<const editing::ProposalReference> reference_;
  std::shared_ptr<const HeadMesh> shownMesh_;  // what the viewport's setHead was given
  std::shared_ptr<playback::HeadRig> rig_;
  std::unique_ptr<playback::FrameProducer> producer_;
  const Eigen::Matrix3Xf* shownPositions_ = nullptr;  // the posed head shown, or null
  Eigen::Matrix3Xf posedPositions_, posedNormals_;    // a rotated rig's pose, in mesh axes
  std::vector<rigging::RigCheck> checks_;
  QStringList proposalWarnings_;  // the last proposal's, until the head changes
  // The default head drawn with the current point highlighted, loaded and rendered off the GUI
  // thread; pictures are kept per point.
  std::shared_ptr<const exporters::ReferenceHead> referenceHead_;
  std::map<std::string, QImage> referencePictures_;
  bool referenceRendering_ = false;
  QString referenceProblem_;  // why there is no picture (the default head not fetched)
  std::shared_ptr<std::vector<rigging::RigCheck>> pendingChecks_;  // the newest job's checks
  std::shared_ptr<const HeadMesh> pendingMesh_;                    // and the head it rigs

  viewport::FaceViewport* viewport_ = nullptr;
  PartsTableModel* parts_ = nullptr;
  PointListModel* pointList_ = nullptr;
  QTableView* partsView_ = nullptr;
  QTableView* pointsView_ = nullptr;
  QListWidget* checksView_ = nullptr;
  QLabel* referencePicture_ = nullptr;
  QLabel* referenceText_ = nullptr;
  QLabel* status_ = nullptr;
  QProgressBar* progress_ = nullptr;
  QToolButton* proposeButton_ = nullptr;
  QToolButton* saveButton_ = nullptr;
  QToolButton* useButton_ = nullptr;
  QToolButton* importButton_ = nullptr;
  QToolButton* openPointsButton_ = nullptr;
  QToolButton* cancelImportButton_ = nullptr;
  QTimer* rigDelay_ = nullptr;
  RigJob* rigJob_ = nullptr;

  std::string current_;
  std::string dragged_;  // the point whose marker is being dragged
  QPointF pressAt_;      // where the marker drag started
  bool importing_ = false;
  std::shared_ptr<std::atomic<bool>> importCancelled_;  // the running import's cancel flag
  double importSeconds_ = 0;
  bool proposing_ = false;
  bool interactive_ = true;
  QString lastError_;
  QString statusText_;
};

}  // namespace lacrima::editor::head
