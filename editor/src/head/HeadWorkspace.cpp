#include <lacrima/editor/head/HeadWorkspace.h>

#include <lacrima/common/FdpTable.h>
#include <lacrima/editing/EditorModel.h>
#include <lacrima/editing/HeadSetup.h>
#include <lacrima/editor/RigJob.h>
#include <lacrima/editor/head/PartRoleDelegate.h>
#include <lacrima/editor/head/PartsTableModel.h>
#include <lacrima/editor/head/PointListModel.h>
#include <lacrima/exporters/FeaturePointReference.h>
#include <lacrima/playback/FrameProducer.h>
#include <lacrima/playback/HeadRig.h>
#include <lacrima/rigging/FaceFrame.h>
#include <lacrima/rigging/FeaturePointProposal.h>
#include <lacrima/viewport/FaceViewport.h>

#include <QAction>
#include <QElapsedTimer>
#include <QFileDialog>
#include <QFileInfo>
#include <QFutureWatcher>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QListWidget>
#include <QMessageBox>
#include <QMouseEvent>
#include <QPixmap>
#include <QProgressBar>
#include <QSplitter>
#include <QTableView>
#include <QTimer>
#include <QToolButton>
#include <QVBoxLayout>
#include <QtConcurrent/QtConcurrentRun>

#include <algorithm>

namespace lacrima::editor::head {
namespace {

// A press and release closer than this (pixels, Manhattan) is a click, not a drag.
constexpr double kClickSlop = 4.0;
// A press this close to a marker's centre grabs it (pixels).
constexpr double kGrabRadius = 9.0;

QString text(const std::exception& e) { return QString::fromUtf8(e.what()); }

struct ImportResult {
  HeadMesh mesh;
  QString error;
  double milliseconds = 0;
};

struct ProposalResult {
  editing::PlacedPoints points;
  std::shared_ptr<const editing::ProposalReference> reference;
  Warnings warnings;
  QString error;
  double milliseconds = 0;
};

// The local triangle index of a global one (HeadMesh order over the sub-meshes).
int localTriangle(const HeadMesh& mesh, int submesh, int global) {
  for (int s = 0; s < submesh; ++s)
    global -= static_cast<int>(mesh.submeshes[static_cast<std::size_t>(s)].triangles.size());
  return global;
}

}  // namespace

HeadWorkspace::HeadWorkspace(editing::EditorModel& model, QWidget* parent)
    : QWidget(parent), model_(model), setup_(std::make_unique<editing::HeadSetup>()) {
  setObjectName(QStringLiteral("headWorkspace"));
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->setSpacing(0);
  layout->addWidget(createToolBar());

  auto* split = new QSplitter(Qt::Horizontal, this);
  viewport_ = new viewport::FaceViewport(split);
  viewport_->setObjectName(QStringLiteral("headViewport"));
  viewport_->setMinimumSize(320, 240);
  viewport_->installEventFilter(this);
  split->addWidget(viewport_);
  split->addWidget(createSidePanel());
  split->setStretchFactor(0, 3);
  split->setStretchFactor(1, 2);
  layout->addWidget(split, 1);

  rigDelay_ = new QTimer(this);
  rigDelay_->setSingleShot(true);
  rigDelay_->setInterval(250);
  connect(rigDelay_, &QTimer::timeout, this, &HeadWorkspace::startRig);

  rigJob_ = new RigJob(this);
  connect(rigJob_, &RigJob::progress, this, [this](double fraction, const QString& stage) {
    progress_->setValue(static_cast<int>(fraction * 100));
    progress_->setFormat(tr("Rigging: %1").arg(stage));
  });
  connect(rigJob_, &RigJob::finished, this, &HeadWorkspace::onRigFinished);
  connect(rigJob_, &RigJob::failed, this, [this](const QString& message) {
    progress_->hide();
    lastError_ = message;
    setStatus(tr("Not rigged: %1").arg(message));
    emit rigFailed(message);
  });

  connect(setup_.get(), &editing::HeadSetup::meshChanged, this, &HeadWorkspace::onMeshChanged);
  connect(setup_.get(), &editing::HeadSetup::changed, this, &HeadWorkspace::onDocumentEdited);
  connect(setup_.get(), &editing::HeadSetup::pointsChanged, this, &HeadWorkspace::updateMarkers);
  connect(setup_.get(), &editing::HeadSetup::rolesChanged, this, &HeadWorkspace::updatePickable);
  connect(&model_, &editing::EditorModel::valuesChanged, this, &HeadWorkspace::pose);

  setStatus(tr("Import a head (OBJ, FBX, glTF, ...) to start"));
}

HeadWorkspace::~HeadWorkspace() {
  // The producer refers to the rig; the viewport to neither (it shows shownMesh_).
  producer_.reset();
  rig_.reset();
}

QWidget* HeadWorkspace::createToolBar() {
  auto* bar = new QWidget(this);
  auto* row = new QHBoxLayout(bar);
  row->setContentsMargins(6, 3, 6, 3);
  const auto button = [&](const QString& label, const QString& tip, const QString& name) {
    auto* b = new QToolButton(bar);
    b->setText(label);
    b->setToolTip(tip);
    b->setObjectName(name);
    row->addWidget(b);
    return b;
  };
  connect(button(tr("Import…"), tr("Read a head mesh (any format assimp reads)"),
                 QStringLiteral("head.import")),
          &QToolButton::clicked, this, [this] {
            const QString path = QFileDialog::getOpenFileName(
                this, tr("Import a head"), {},
                tr("Meshes (*.obj *.fbx *.glb *.gltf *.dae *.ply *.stl *.3ds *.blend);;"
                   "All files (*)"));
            if (!path.isEmpty()) importHead(path);
          });
  connect(button(tr("Open points…"), tr("Open a feature-point file (.fdp.json) for this head"),
                 QStringLiteral("head.open")),
          &QToolButton::clicked, this, [this] {
            const QString path = QFileDialog::getOpenFileName(
                this, tr("Open feature points"), QFileInfo(setup_->meshPath()).absolutePath(),
                tr("Feature points (*.fdp.json *.json)"));
            if (!path.isEmpty()) openPoints(path);
          });
  proposeButton_ =
      button(tr("Propose"), tr("Place every point not placed by hand, from the 8 anchors"),
             QStringLiteral("head.propose"));
  connect(proposeButton_, &QToolButton::clicked, this, &HeadWorkspace::proposePoints);
  saveButton_ =
      button(tr("Save…"), tr("Save the feature points (.fdp.json)"), QStringLiteral("head.save"));
  connect(saveButton_, &QToolButton::clicked, this, [this] {
    const QString suggested =
        setup_->fdpPath().isEmpty()
            ? QFileInfo(setup_->meshPath()).absolutePath() + QLatin1Char('/') +
                  QFileInfo(setup_->meshPath()).completeBaseName() + QStringLiteral(".fdp.json")
            : setup_->fdpPath();
    const QString path = QFileDialog::getSaveFileName(this, tr("Save feature points"), suggested,
                                                      tr("Feature points (*.fdp.json)"));
    if (!path.isEmpty()) saveTo(path);
  });
  useButton_ = button(tr("Use in project"),
                      tr("Animate this head in the project (saves the feature points first)"),
                      QStringLiteral("head.use"));
  connect(useButton_, &QToolButton::clicked, this, &HeadWorkspace::useInProject);

  // Undo and redo of head edits. Their shortcuts work while the workspace is shown (the main
  // window gives Ctrl+Z to the workspace then: MainWindow::setWorkspace).
  QAction* undo = setup_->undoStack()->createUndoAction(this, tr("Undo"));
  undo->setObjectName(QStringLiteral("head.undo"));
  undo->setShortcut(QKeySequence::Undo);
  QAction* redo = setup_->undoStack()->createRedoAction(this, tr("Redo"));
  redo->setObjectName(QStringLiteral("head.redo"));
  redo->setShortcuts(
      {QKeySequence(QStringLiteral("Ctrl+Shift+Z")), QKeySequence(QStringLiteral("Ctrl+Y"))});
  for (QAction* a : {undo, redo}) {
    addAction(a);
    auto* b = new QToolButton(bar);
    b->setDefaultAction(a);
    b->setObjectName(a->objectName());
    row->addWidget(b);
  }

  row->addStretch(1);
  progress_ = new QProgressBar(bar);
  progress_->setRange(0, 100);
  progress_->setMaximumWidth(260);
  progress_->setTextVisible(true);
  progress_->hide();
  row->addWidget(progress_);
  status_ = new QLabel(bar);
  status_->setObjectName(QStringLiteral("head.status"));
  row->addWidget(status_);
  for (QToolButton* b : {proposeButton_, saveButton_, useButton_}) b->setEnabled(false);
  return bar;
}

QWidget* HeadWorkspace::createSidePanel() {
  auto* side = new QSplitter(Qt::Vertical, this);

  parts_ = new PartsTableModel(*setup_, this);
  partsView_ = new QTableView(side);
  partsView_->setObjectName(QStringLiteral("head.parts"));
  partsView_->setModel(parts_);
  partsView_->setItemDelegateForColumn(PartsTableModel::Role, new PartRoleDelegate(partsView_));
  partsView_->setEditTriggers(QAbstractItemView::DoubleClicked |
                              QAbstractItemView::SelectedClicked |
                              QAbstractItemView::EditKeyPressed);
  partsView_->verticalHeader()->hide();
  partsView_->horizontalHeader()->setStretchLastSection(true);
  side->addWidget(partsView_);

  pointList_ = new PointListModel(
      *setup_,
      [](const std::string& id) {
        const std::string_view text = fdpDescription(id);
        return QString::fromUtf8(text.data(), static_cast<qsizetype>(text.size()));
      },
      this);
  pointsView_ = new QTableView(side);
  pointsView_->setObjectName(QStringLiteral("head.points"));
  pointsView_->setModel(pointList_);
  pointsView_->setSelectionBehavior(QAbstractItemView::SelectRows);
  pointsView_->setSelectionMode(QAbstractItemView::SingleSelection);
  pointsView_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  pointsView_->verticalHeader()->hide();
  pointsView_->horizontalHeader()->setSectionResizeMode(PointListModel::Description,
                                                        QHeaderView::Stretch);
  connect(pointsView_->selectionModel(), &QItemSelectionModel::currentRowChanged, this,
          [this](const QModelIndex& index) {
            if (index.isValid())
              setCurrentPoint(index.data(PointListModel::IdRole).toString().toStdString());
          });
  side->addWidget(pointsView_);

  auto* reference = new QWidget(side);
  auto* referenceLayout = new QHBoxLayout(reference);
  referenceLayout->setContentsMargins(4, 4, 4, 4);
  referencePicture_ = new QLabel(reference);
  referencePicture_->setObjectName(QStringLiteral("head.referencePicture"));
  referencePicture_->setFixedSize(160, 160);
  referencePicture_->setAlignment(Qt::AlignCenter);
  referenceText_ = new QLabel(reference);
  referenceText_->setObjectName(QStringLiteral("head.referenceText"));
  referenceText_->setWordWrap(true);
  referenceText_->setAlignment(Qt::AlignTop | Qt::AlignLeft);
  referenceLayout->addWidget(referencePicture_);
  referenceLayout->addWidget(referenceText_, 1);
  side->addWidget(reference);

  checksView_ = new QListWidget(side);
  checksView_->setObjectName(QStringLiteral("head.checks"));
  connect(checksView_, &QListWidget::itemActivated, this, [this](QListWidgetItem* item) {
    const QString id = item->data(Qt::UserRole).toString();
    if (!id.isEmpty()) setCurrentPoint(id.toStdString());
  });
  side->addWidget(checksView_);
  return side;
}

// --- actions -------------------------------------------------------------------------------

void HeadWorkspace::importHead(const QString& path) {
  if (importing_) {
    fail(tr("Import"), tr("an import is already running"));
    emit importFinished(false);
    return;
  }
  importing_ = true;
  setStatus(tr("Importing %1…").arg(QFileInfo(path).fileName()));
  auto* watcher = new QFutureWatcher<ImportResult>(this);
  connect(watcher, &QFutureWatcher<ImportResult>::finished, this, [this, watcher, path] {
    ImportResult result = watcher->result();
    watcher->deleteLater();
    importing_ = false;
    if (result.error.isEmpty()) {
      try {
        setup_->setMesh(path, std::move(result.mesh));
      } catch (const std::exception& e) {
        result.error = text(e);
      }
    }
    if (!result.error.isEmpty()) {
      fail(tr("Import"), result.error);
      emit importFinished(false);
      return;
    }
    lastError_.clear();
    setStatus(tr("Imported %1 in %2 ms: check the parts' roles, then click the anchors")
                  .arg(QFileInfo(path).fileName())
                  .arg(result.milliseconds, 0, 'f', 0));
    emit importFinished(true);
  });
  // assimp takes a good part of a second on a large head: never on the GUI thread.
  watcher->setFuture(QtConcurrent::run([path] {
    ImportResult r;
    QElapsedTimer timer;
    timer.start();
    try {
      r.mesh = editing::HeadSetup::importMesh(path);
    } catch (const std::exception& e) {
      r.error = text(e);
    }
    r.milliseconds = timer.nsecsElapsed() / 1e6;
    return r;
  }));
}

void HeadWorkspace::proposePoints() {
  if (!setup_->hasMesh() || proposing_) {
    emit proposalFinished(false);
    return;
  }
  proposing_ = true;
  proposeButton_->setEnabled(false);
  setStatus(tr("Proposing…"));
  auto* watcher = new QFutureWatcher<ProposalResult>(this);
  const std::shared_ptr<const HeadMesh> mesh = setup_->sharedMesh();
  connect(watcher, &QFutureWatcher<ProposalResult>::finished, this, [this, watcher, mesh] {
    ProposalResult result = watcher->result();
    watcher->deleteLater();
    proposing_ = false;
    proposeButton_->setEnabled(setup_->hasMesh());
    if (result.reference) reference_ = result.reference;
    if (setup_->sharedMesh() != mesh) {  // another head came in meanwhile
      emit proposalFinished(false);
      return;
    }
    if (!result.error.isEmpty()) {
      fail(tr("Propose"), result.error);
      emit proposalFinished(false);
      return;
    }
    setup_->applyProposal(result.points);
    lastError_.clear();
    setStatus(tr("Proposed %1 points in %2 ms%3: drag any that are off")
                  .arg(std::count_if(result.points.begin(), result.points.end(),
                                     [](const auto& p) { return !p.second.byHand(); }))
                  .arg(result.milliseconds, 0, 'f', 0)
                  .arg(result.warnings.empty()
                           ? QString()
                           : tr(" (%1 warnings: %2)")
                                 .arg(result.warnings.size())
                                 .arg(QString::fromStdString(result.warnings.front().message))));
    emit proposalFinished(true);
  });
  watcher->setFuture(
      QtConcurrent::run([mesh, hand = setup_->handFile(), reference = reference_]() mutable {
        ProposalResult r;
        QElapsedTimer timer;
        timer.start();
        try {
          if (!reference) reference = editing::ProposalReference::loadDefault();
          r.reference = reference;
          r.points = editing::HeadSetup::computeProposal(hand, *mesh, *reference, &r.warnings);
        } catch (const std::exception& e) {
          r.error = text(e);
        }
        r.milliseconds = timer.nsecsElapsed() / 1e6;
        return r;
      }));
}

bool HeadWorkspace::saveTo(const QString& path) {
  if (!setup_->hasMesh()) {
    fail(tr("Save"), tr("no head to save points for: import one first"));
    return false;
  }
  try {
    setup_->save(path);
  } catch (const std::exception& e) {
    fail(tr("Save"), text(e));
    return false;
  }
  lastError_.clear();
  setStatus(tr("Saved %1").arg(path));
  return true;
}

bool HeadWorkspace::openPoints(const QString& path) {
  Warnings warnings;
  try {
    setup_->openFeaturePoints(path, &warnings);
  } catch (const std::exception& e) {
    fail(tr("Open points"), text(e));
    return false;
  }
  lastError_.clear();
  setStatus(warnings.empty() ? tr("Opened %1").arg(path)
                             : tr("Opened %1 with %2 warnings: %3")
                                   .arg(path)
                                   .arg(warnings.size())
                                   .arg(QString::fromStdString(warnings.front().toString())));
  return true;
}

void HeadWorkspace::useInProject() {
  if (!setup_->hasMesh()) return;
  if (setup_->fdpPath().isEmpty() || !setup_->undoStack()->isClean()) {
    if (!interactive_) {
      if (setup_->fdpPath().isEmpty()) {
        fail(tr("Use in project"), tr("save the feature points first"));
        return;
      }
      if (!saveTo(setup_->fdpPath())) return;
    } else {
      saveButton_->click();
      if (setup_->fdpPath().isEmpty() || !setup_->undoStack()->isClean()) return;
    }
  }
  emit useInProjectRequested(setup_->meshPath(), setup_->fdpPath());
}

void HeadWorkspace::setCurrentPoint(const std::string& id) {
  if (id == current_) return;
  current_ = id;
  const int row = pointList_->rowOf(id);
  if (row >= 0 && pointsView_->currentIndex().row() != row) {
    const QSignalBlocker block(pointsView_->selectionModel());
    pointsView_->selectRow(row);
  }
  updateReference();
  updateMarkers();
}

void HeadWorkspace::selectNextMissingAnchor() {
  for (const std::string& id : rigging::proposalAnchors())
    if (!setup_->point(id)) {
      setCurrentPoint(id);
      return;
    }
}

bool HeadWorkspace::rigging() const { return rigJob_->running() || rigDelay_->isActive(); }

void HeadWorkspace::setRigDelay(int milliseconds) { rigDelay_->setInterval(milliseconds); }

QString HeadWorkspace::statusText() const { return statusText_; }

void HeadWorkspace::setStatus(const QString& text) {
  statusText_ = text;
  status_->setText(text);
  emit statusChanged(text);
}

void HeadWorkspace::fail(const QString& what, const QString& message) {
  lastError_ = message;
  setStatus(tr("%1 failed: %2").arg(what, message));
  if (interactive_) QMessageBox::warning(this, what, message);
}

// --- the document changed ------------------------------------------------------------------

void HeadWorkspace::onMeshChanged() {
  shownPositions_ = nullptr;
  producer_.reset();
  rig_.reset();
  checks_.clear();
  updateChecks();
  shownMesh_ = setup_->sharedMesh();
  viewport_->setHead(*shownMesh_);
  viewport_->resetView();
  updatePickable();
  for (QToolButton* b : {proposeButton_, saveButton_, useButton_}) b->setEnabled(true);
  current_.clear();
  selectNextMissingAnchor();
  partsView_->resizeColumnsToContents();
}

void HeadWorkspace::onDocumentEdited() {
  if (!setup_->hasMesh()) return;
  rigDelay_->start();  // restarts: a burst of edits rigs once
}

void HeadWorkspace::startRig() {
  if (!setup_->hasMesh()) return;
  rigging::FeaturePointFile file = setup_->toFile();
  QStringList missing;
  for (const std::string& id : rigging::fapuFeaturePoints())
    if (!file.points.count(id)) missing << QString::fromStdString(id);
  if (!missing.isEmpty()) {
    setStatus(tr("Not rigged yet: %1 missing (place the anchors, then Propose)")
                  .arg(missing.join(QStringLiteral(", "))));
    return;
  }
  auto checks = std::make_shared<std::vector<rigging::RigCheck>>();
  pendingChecks_ = checks;
  progress_->setValue(0);
  progress_->setFormat(tr("Rigging…"));
  progress_->show();
  rigJob_->start([mesh = setup_->sharedMesh(), file = std::move(file),
                  checks](const std::function<void(double, std::string_view)>& progress) {
    rigging::RigOptions options;
    options.progress = progress;
    auto rig = playback::rigHead(HeadMesh(*mesh), file, options);
    *checks = rigging::checkRig(rig->head, file, rig->rig);
    return rig;
  });
}

void HeadWorkspace::onRigFinished(std::shared_ptr<playback::HeadRig> rig) {
  progress_->hide();
  if (!rig || rig->head.vertexCount() != setup_->mesh().vertexCount()) return;  // stale head
  checks_ = pendingChecks_ ? *pendingChecks_ : std::vector<rigging::RigCheck>{};
  shownPositions_ = nullptr;
  producer_.reset();
  rig_ = std::move(rig);
  producer_ = std::make_unique<playback::FrameProducer>(*rig_, model_.document().scene);
  // Orbit about the face's own up axis once the rig knows it (a Z-up head turns upright).
  const Eigen::Matrix3d faceToMesh = rig_->frame.rotation.transpose();
  if (!viewport_->viewFrame().isApprox(faceToMesh)) viewport_->setViewFrame(faceToMesh);
  pose();
  updateChecks();
  const auto errors = std::count_if(checks_.begin(), checks_.end(), [](const auto& c) {
    return c.severity == rigging::RigCheck::Severity::Error;
  });
  setStatus(tr("Rigged: %1 errors, %2 warnings; move a FAP slider to try it")
                .arg(errors)
                .arg(static_cast<long long>(checks_.size()) - errors));
  emit rigFinished();
}

void HeadWorkspace::pose() {
  if (!producer_ || !shownMesh_) return;
  const playback::FrameView& posed = producer_->pose(model_.currentValues());
  // Shown on the imported mesh, not the rig's copy of it (same vertices), so a new rig does
  // not re-frame the camera. The rig is in the face frame (FaceFrame.h); the workspace works in
  // the mesh's own coordinates: imported = R^T rig, R one of the 24 axis rotations.
  playback::FrameView view = posed;
  view.neutral = shownMesh_.get();
  const Eigen::Matrix3d& rotation = rig_->frame.rotation;
  if (!rotation.isIdentity() && posed.positions && posed.normals) {
    posedPositions_ = *posed.positions;
    posedNormals_ = *posed.normals;
    rigging::applyAxisRotation(rotation.transpose(), posedPositions_);
    rigging::applyAxisRotation(rotation.transpose(), posedNormals_);
    view.positions = &posedPositions_;
    view.normals = &posedNormals_;
  }
  shownPositions_ = view.positions;
  viewport_->showFrame(view);
  updateMarkers();
}

// --- viewport ------------------------------------------------------------------------------

Eigen::Vector3d HeadWorkspace::shownPosition(const std::string& id) const {
  const editing::PlacedPoint* p = setup_->point(id);
  if (!p) return Eigen::Vector3d::Zero();
  const HeadMesh& mesh = setup_->mesh();
  const Eigen::Matrix3Xf& positions = shownPositions_ ? *shownPositions_ : mesh.positions;
  const std::vector<int> corners = rigging::surfaceVertices(p->spec.at, mesh);
  if (corners.size() == 1) return positions.col(corners[0]).cast<double>();
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (std::size_t k = 0; k < corners.size() && k < 3; ++k)
    sum += p->spec.at.barycentric[static_cast<Eigen::Index>(k)] *
           positions.col(corners[k]).cast<double>();
  return sum;
}

void HeadWorkspace::updateMarkers() {
  if (!setup_->hasMesh()) return;
  std::vector<viewport::Marker> markers;
  markers.reserve(setup_->points().size());
  for (const auto& [id, p] : setup_->points()) {
    viewport::Marker m;
    m.position = shownPosition(id);
    const bool current = id == current_;
    m.colour = current      ? PointColours::current()
               : p.byHand() ? PointColours::hand()
                            : PointColours::proposed();
    m.highlighted = current;
    m.onTop = current || id == dragged_;
    m.sizePixels = current ? 12 : 9;
    markers.push_back(m);
  }
  viewport_->setMarkers(std::move(markers));
}

void HeadWorkspace::updatePickable() {
  if (!setup_->hasMesh()) return;
  // Feature points sit on the skin, eyes, teeth and tongue: clicks go through lashes and tear
  // films (which lie over the eye corners) and through ignored parts.
  std::vector<bool> pickable;
  for (editing::PartRole role : setup_->roles())
    pickable.push_back(role != editing::PartRole::Ignored && role != editing::PartRole::Attached);
  viewport_->setPickableSubmeshes(std::move(pickable));
}

struct ReferenceResult {
  std::shared_ptr<const exporters::ReferenceHead> head;
  std::string id;
  QImage image;
  bool hidden = false;
  QString error;
};

void HeadWorkspace::updateReference() {
  const std::string_view description = fdpDescription(current_);
  QString caption;
  if (!current_.empty())
    caption =
        tr("<b>%1</b><br>%2")
            .arg(QString::fromStdString(current_),
                 QString::fromUtf8(description.data(), static_cast<qsizetype>(description.size())));
  if (!referenceProblem_.isEmpty())
    caption += QStringLiteral("<br><i>%1</i>").arg(referenceProblem_);
  referenceText_->setText(caption);

  if (current_.empty() || !referenceProblem_.isEmpty()) {
    referencePicture_->clear();
    return;
  }
  if (const auto cached = referencePictures_.find(current_); cached != referencePictures_.end()) {
    referencePicture_->setPixmap(QPixmap::fromImage(cached->second));
    emit referenceShown(QString::fromStdString(current_));
    return;
  }
  referencePicture_->setText(tr("…"));
  if (referenceRendering_) return;  // the finished render asks again for the current point
  referenceRendering_ = true;
  // Loading the default head takes about 0.1 s, a picture some tens of ms: off the GUI thread.
  auto* watcher = new QFutureWatcher<ReferenceResult>(this);
  connect(watcher, &QFutureWatcher<ReferenceResult>::finished, this, [this, watcher] {
    ReferenceResult r = watcher->result();
    watcher->deleteLater();
    referenceRendering_ = false;
    if (r.head) referenceHead_ = r.head;
    if (!r.error.isEmpty()) {
      referenceProblem_ = tr("No reference picture: %1").arg(r.error);
    } else if (!r.image.isNull()) {
      referencePictures_[r.id] =
          r.image.scaled(referencePicture_->size(), Qt::KeepAspectRatio, Qt::SmoothTransformation);
    }
    updateReference();
  });
  const int size = 2 * referencePicture_->width();
  watcher->setFuture(QtConcurrent::run([head = referenceHead_, id = current_, size]() mutable {
    ReferenceResult r;
    r.id = id;
    try {
      if (!head)
        head = std::make_shared<const exporters::ReferenceHead>(exporters::defaultReferenceHead());
      r.head = head;
      exporters::ReferenceStyle style;
      style.size = size;
      const exporters::ReferencePicture picture =
          exporters::renderFeaturePointReference(*head, id, style);
      r.image = picture.image;
      r.hidden = picture.hidden;
      if (r.image.isNull()) {  // a point the default head does not have: say so in place
        r.image = QImage(size, size, QImage::Format_RGB32);
        r.image.fill(QColor(40, 40, 44));
      }
    } catch (const std::exception& e) {
      r.error = text(e);
    }
    return r;
  }));
}

QImage HeadWorkspace::referencePicture() const {
  const auto it = referencePictures_.find(current_);
  return it == referencePictures_.end() ? QImage() : it->second;
}

void HeadWorkspace::updateChecks() {
  checksView_->clear();
  for (const rigging::RigCheck& check : checks_) {
    const bool error = check.severity == rigging::RigCheck::Severity::Error;
    auto* item =
        new QListWidgetItem(QStringLiteral("%1 %2").arg(error ? tr("Error:") : tr("Warning:"),
                                                        QString::fromStdString(check.message)),
                            checksView_);
    item->setForeground(error ? QColor(230, 90, 80) : QColor(230, 180, 60));
    item->setToolTip(QString::fromStdString(rigging::toString(check)));
    if (!check.points.empty()) item->setData(Qt::UserRole, QString::fromStdString(check.points[0]));
  }
  if (checks_.empty() && rig_) new QListWidgetItem(tr("No problems found"), checksView_);
}

std::string HeadWorkspace::markerAt(QPointF pixel) const {
  std::string best;
  double bestDistance = kGrabRadius;
  for (const auto& [id, p] : setup_->points()) {
    const auto at = viewport_->project(shownPosition(id));
    if (!at) continue;
    const double d = QLineF(*at, pixel).length();
    // The current point wins a tie: it is the one being worked on.
    if (d < bestDistance || (d <= bestDistance && id == current_)) {
      bestDistance = d;
      best = id;
    }
  }
  if (best.empty()) return best;
  // A marker behind the head (the far ear) is not grabbed through it: the surface under the
  // mouse must be about where the marker is.
  if (const auto hit = viewport_->pick(pixel)) {
    const HeadMesh& mesh = setup_->mesh();
    const double size = (mesh.boundsMax() - mesh.boundsMin()).norm();
    if ((hit->position - shownPosition(best)).norm() > 0.05 * size && best != current_) return {};
  }
  return best;
}

bool HeadWorkspace::clickPlaces(QPointF pixel) {
  if (current_.empty() || !setup_->hasMesh()) return false;
  const auto hit = viewport_->pick(pixel);
  if (!hit) {
    setStatus(tr("Missed the head: click on it to place %1").arg(QString::fromStdString(current_)));
    return false;
  }
  const HeadMesh& mesh = setup_->mesh();
  editing::SurfaceSpot spot{hit->submesh, localTriangle(mesh, hit->submesh, hit->triangle),
                            hit->barycentric};
  try {
    setup_->placePoint(current_, spot);
  } catch (const std::exception& e) {
    fail(tr("Place"), text(e));
    return false;
  }
  const auto& anchors = rigging::proposalAnchors();
  if (std::find(anchors.begin(), anchors.end(), current_) != anchors.end())
    selectNextMissingAnchor();
  return true;
}

bool HeadWorkspace::eventFilter(QObject* watched, QEvent* event) {
  if (watched != viewport_ || !setup_->hasMesh()) return QWidget::eventFilter(watched, event);
  switch (event->type()) {
    case QEvent::MouseButtonPress: {
      auto* e = static_cast<QMouseEvent*>(event);
      if (e->button() != Qt::LeftButton) break;
      pressAt_ = e->position();
      pressed_ = true;
      const std::string grabbed = markerAt(pressAt_);
      if (!grabbed.empty()) {
        dragged_ = grabbed;
        setCurrentPoint(grabbed);
        return true;  // the viewport does not orbit while a marker is dragged
      }
      break;
    }
    case QEvent::MouseMove: {
      if (dragged_.empty()) break;
      auto* e = static_cast<QMouseEvent*>(event);
      // Follow the mouse on the surface; the document changes once, on release.
      if (const auto hit = viewport_->pick(e->position())) {
        std::vector<viewport::Marker> markers;
        viewport::Marker m;
        m.position = hit->position;
        m.colour = PointColours::current();
        m.highlighted = true;
        m.sizePixels = 12;
        markers.push_back(m);
        for (const auto& [id, p] : setup_->points()) {
          if (id == dragged_) continue;
          viewport::Marker other;
          other.position = shownPosition(id);
          other.colour = p.byHand() ? PointColours::hand() : PointColours::proposed();
          other.onTop = false;
          markers.push_back(other);
        }
        viewport_->setMarkers(std::move(markers));
      }
      return true;
    }
    case QEvent::MouseButtonRelease: {
      auto* e = static_cast<QMouseEvent*>(event);
      if (e->button() != Qt::LeftButton) break;
      const bool click = pressed_ && (e->position() - pressAt_).manhattanLength() <= kClickSlop;
      pressed_ = false;
      if (!dragged_.empty()) {
        const std::string id = std::exchange(dragged_, std::string());
        if (!click) {
          if (const auto hit = viewport_->pick(e->position())) {
            // The neutral position under the hit (the head may be shown posed).
            const HeadMesh& mesh = setup_->mesh();
            const Eigen::Vector3i& tri = mesh.submeshes[static_cast<std::size_t>(hit->submesh)]
                                             .triangles[static_cast<std::size_t>(
                                                 localTriangle(mesh, hit->submesh, hit->triangle))];
            Eigen::Vector3d neutral = Eigen::Vector3d::Zero();
            for (int k = 0; k < 3; ++k)
              neutral += hit->barycentric[k] * mesh.positions.col(tri[k]).cast<double>();
            setup_->movePoint(id, neutral);
          }
        }
        updateMarkers();
        return true;
      }
      if (click) clickPlaces(e->position());
      break;
    }
    default:
      break;
  }
  return QWidget::eventFilter(watched, event);
}

}  // namespace lacrima::editor::head
