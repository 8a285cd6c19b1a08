#include <lacrima/editor/head/HeadWorkspace.h>

#include <lacrima/common/FapTable.h>
#include <lacrima/common/FdpTable.h>
#include <lacrima/editing/EditorModel.h>
#include <lacrima/editing/HeadSetup.h>
#include <lacrima/editor/RigJob.h>
#include <lacrima/editor/head/PartRoleDelegate.h>
#include <lacrima/editor/head/PartsTableModel.h>
#include <lacrima/editor/head/PointListModel.h>
#include <lacrima/playback/FrameProducer.h>
#include <lacrima/playback/HeadRig.h>
#include <lacrima/rigging/FeaturePointProposal.h>
#include <lacrima/viewport/FaceViewport.h>

#include <QAction>
#include <QFileDialog>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QListWidget>
#include <QMessageBox>
#include <QProgressBar>
#include <QRegularExpression>
#include <QSplitter>
#include <QTableView>
#include <QTimer>
#include <QToolButton>
#include <QVBoxLayout>

namespace lacrima::editor::head {
namespace {

QString text(const std::exception& e) { return QString::fromUtf8(e.what()); }

}  // namespace

HeadWorkspace::HeadWorkspace(editing::EditorModel& model, QWidget* parent)
    : QWidget(parent), model_(model), setup_(std::make_unique<editing::HeadSetup>()) {
  setObjectName(QStringLiteral("headWorkspace"));
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->setSpacing(0);
  layout->addWidget(createToolBar());

  auto* split = new QSplitter(Qt::Horizontal, this);
  auto* view = new QWidget(split);
  auto* viewLayout = new QVBoxLayout(view);
  viewLayout->setContentsMargins(0, 0, 0, 0);
  viewLayout->setSpacing(0);
  viewLayout->addWidget(createPoseBar(view));
  viewport_ = new viewport::FaceViewport(view);
  viewport_->setObjectName(QStringLiteral("headViewport"));
  viewport_->setMinimumSize(240, 240);
  connectViewport();
  viewLayout->addWidget(viewport_, 1);
  split->addWidget(view);
  QWidget* side = createSidePanel();
  side->setMinimumWidth(300);  // the parts' roles and the points' descriptions stay readable
  split->addWidget(side);
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
  connect(setup_.get(), &editing::HeadSetup::rolesChanged, this, &HeadWorkspace::onRolesChanged);
  connect(&model_, &editing::EditorModel::valuesChanged, this, &HeadWorkspace::pose);

  setStatus(tr("Import a head (OBJ, FBX, glTF, ...) to start"));
}

HeadWorkspace::~HeadWorkspace() {
  // A running import's worker must not wait for a process nobody will look at.
  if (importCancelled_) *importCancelled_ = true;
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
  importButton_ = button(tr("Import…"), tr("Read a head mesh (any format assimp reads)"),
                         QStringLiteral("head.import"));
  connect(importButton_, &QToolButton::clicked, this, [this] {
    const QString path = QFileDialog::getOpenFileName(
        this, tr("Import a head"), {},
        tr("Meshes (*.obj *.fbx *.glb *.gltf *.dae *.ply *.stl *.3ds *.blend);;"
           "All files (*)"));
    if (!path.isEmpty()) importHead(path);
  });
  openPointsButton_ =
      button(tr("Open points…"), tr("Open a feature-point file (.fdp.json) for this head"),
             QStringLiteral("head.open"));
  connect(openPointsButton_, &QToolButton::clicked, this, [this] {
    const QString path = QFileDialog::getOpenFileName(this, tr("Open feature points"),
                                                      QFileInfo(setup_->meshPath()).absolutePath(),
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

  // Undo and redo of head edits as buttons. Their shortcuts are the main window's Edit ▸ Undo
  // and Redo, which act on this history while the workspace is shown (MainWindow's QUndoGroup).
  QAction* undo = setup_->undoStack()->createUndoAction(this, tr("Undo"));
  undo->setObjectName(QStringLiteral("head.undo"));
  QAction* redo = setup_->undoStack()->createRedoAction(this, tr("Redo"));
  redo->setObjectName(QStringLiteral("head.redo"));
  for (const auto& [action, label] : {std::pair{undo, tr("Undo")}, std::pair{redo, tr("Redo")}}) {
    QAction* a = action;  // a variable, not a binding, so that clang 14 can capture it
    addAction(a);
    // A short fixed label; the action's own text ("Undo Propose points") goes to the tooltip,
    // so a long command name never widens the bar (and the window with it).
    auto* b = new QToolButton(bar);
    b->setText(label);
    b->setObjectName(a->objectName());
    b->setEnabled(a->isEnabled());
    b->setToolTip(a->text());
    connect(b, &QToolButton::clicked, a, &QAction::trigger);
    connect(a, &QAction::changed, b, [a, b] {
      b->setEnabled(a->isEnabled());
      b->setToolTip(a->text());
    });
    row->addWidget(b);
  }

  // Shown in place of Import… and Open points… while an import runs, so the bar never grows
  // (a window grown to fit a wider bar would not shrink back).
  cancelImportButton_ = new QToolButton(bar);
  cancelImportButton_->setText(tr("Cancel import"));
  cancelImportButton_->setToolTip(tr("Stop reading the head file"));
  cancelImportButton_->setObjectName(QStringLiteral("head.cancelImport"));
  row->insertWidget(row->indexOf(importButton_), cancelImportButton_);
  connect(cancelImportButton_, &QToolButton::clicked, this, &HeadWorkspace::cancelImport);
  cancelImportButton_->hide();

  progress_ = new QProgressBar(bar);
  progress_->setRange(0, 100);
  progress_->setMaximumWidth(260);
  progress_->setMinimumWidth(80);  // its text ("Rigging: weights") must not widen the window
  progress_->setTextVisible(true);
  progress_->hide();
  row->addWidget(progress_);
  status_ = new QLabel(bar);
  status_->setObjectName(QStringLiteral("head.status"));
  // Messages can be long (a file's path and what was wrong with it): the label takes the room
  // left over and the tooltip carries the whole text, so a message never widens the window.
  status_->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
  status_->setAlignment(Qt::AlignLeft | Qt::AlignVCenter);
  row->addWidget(status_, 1);
  for (QToolButton* b : {proposeButton_, saveButton_, useButton_}) b->setEnabled(false);
  return bar;
}

void HeadWorkspace::showImportRunning(bool running) {
  // Hide before showing: a child shown lays its window out at once, and a window grown to fit
  // both for that moment would not shrink back.
  const std::initializer_list<QWidget*> idle = {importButton_, openPointsButton_};
  if (running) {
    for (QWidget* w : idle) w->hide();
    cancelImportButton_->show();
  } else {
    cancelImportButton_->hide();
    for (QWidget* w : idle) w->show();
  }
}

// Checking a rig is not animating: say that the sliders pose without keys, and offer the way
// back to the neutral face.
QWidget* HeadWorkspace::createPoseBar(QWidget* parent) {
  auto* bar = new QWidget(parent);
  auto* row = new QHBoxLayout(bar);
  row->setContentsMargins(6, 2, 6, 2);
  auto* note =
      new QLabel(tr("The sliders pose this head to check its rig; nothing is keyed here."), bar);
  note->setObjectName(QStringLiteral("head.poseNote"));
  note->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
  auto* neutral = new QToolButton(bar);
  neutral->setObjectName(QStringLiteral("head.neutral"));
  neutral->setText(tr("Neutral pose"));
  neutral->setToolTip(tr("Every slider back to 0 (the animation is not touched)"));
  connect(neutral, &QToolButton::clicked, this, [this] {
    std::vector<int> all;
    for (int fap = 1; fap <= kChannelCount; ++fap) all.push_back(fap);
    model_.resetChannels(all, tr("Neutral pose"));
  });
  row->addWidget(note, 1);
  row->addWidget(neutral);
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
  partsView_->verticalHeader()->setSectionResizeMode(QHeaderView::Fixed);
  partsView_->verticalHeader()->setDefaultSectionSize(partsView_->fontMetrics().height() + 8);
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
  // One line a point (descriptions are cut; the tooltip and the reference text give them whole),
  // so the list shows many points at once.
  pointsView_->setWordWrap(false);
  pointsView_->setTextElideMode(Qt::ElideRight);
  pointsView_->verticalHeader()->setSectionResizeMode(QHeaderView::Fixed);
  pointsView_->verticalHeader()->setDefaultSectionSize(pointsView_->fontMetrics().height() + 6);
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
  checksView_->setWordWrap(true);
  // A check names its points; a click selects the first (the list and the markers follow).
  const auto selectPoints = [this](QListWidgetItem* item) {
    const QStringList ids = item->data(Qt::UserRole).toStringList();
    if (!ids.isEmpty()) setCurrentPoint(ids.front().toStdString());
  };
  connect(checksView_, &QListWidget::itemClicked, this, selectPoints);
  connect(checksView_, &QListWidget::itemActivated, this, selectPoints);
  side->addWidget(checksView_);
  // The point list takes the height the others leave.
  side->setStretchFactor(0, 1);
  side->setStretchFactor(1, 4);
  side->setStretchFactor(2, 0);
  side->setStretchFactor(3, 1);
  return side;
}

// --- actions ---------------------------------------------------------------------------------

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
  if (row >= 0) pointsView_->scrollTo(pointList_->index(row, 0));
  updateReference();
  updateMarkers();
}

void HeadWorkspace::selectNextMissingAnchor() {
  for (const std::string& id : PointListModel::anchorOrder())
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
  status_->setToolTip(text);
  emit statusChanged(text);
}

void HeadWorkspace::fail(const QString& what, const QString& message) {
  lastError_ = message;
  setStatus(tr("%1 failed: %2").arg(what, message));
  if (interactive_) QMessageBox::warning(this, what, message);
}

// --- the document changed ----------------------------------------------------------------

namespace {

// The rig's name for a part's role (RigBuilder's roles), which the scene draws by.
const char* rigRole(editing::PartRole role) {
  switch (role) {
    case editing::PartRole::Skin:
      return "skin";
    case editing::PartRole::EyeLeft:
    case editing::PartRole::CorneaLeft:
      return "eye_left";
    case editing::PartRole::EyeRight:
    case editing::PartRole::CorneaRight:
      return "eye_right";
    case editing::PartRole::TeethLower:
      return "jaw";
    case editing::PartRole::Tongue:
      return "tongue";
    case editing::PartRole::Attached:
      return "attached";
    case editing::PartRole::Ignored:
      return "ignored";
    case editing::PartRole::TeethUpper:
    case editing::PartRole::Rigid:
      break;
  }
  return "rigid";
}

}  // namespace

// The imported head with its parts' guessed roles, so its untextured eyes, skin and teeth are
// drawn as the rigged head's will be (UntexturedParts.h), from the first look.
std::shared_ptr<const HeadMesh> HeadWorkspace::withRigRoles(
    const HeadMesh& mesh, const std::vector<editing::PartRole>& roles) {
  auto shown = std::make_shared<HeadMesh>(mesh);
  for (std::size_t i = 0; i < shown->submeshes.size() && i < roles.size(); ++i)
    shown->submeshes[i].role = rigRole(roles[i]);
  return shown;
}

// A part's role decides how an untextured part is drawn (an eye gets an iris, the skin a skin
// tone), so a role changed in the table or read from a points file shows at once, not at the
// next import. The import itself already drew the guessed roles.
void HeadWorkspace::onRolesChanged() {
  updatePickable();
  if (!setup_->hasMesh() || !shownMesh_) return;
  const std::vector<editing::PartRole>& roles = setup_->roles();
  bool same = true;
  for (std::size_t i = 0; i < shownMesh_->submeshes.size() && i < roles.size(); ++i)
    same = same && shownMesh_->submeshes[i].role == rigRole(roles[i]);
  if (same) return;
  shownMesh_ = withRigRoles(*setup_->sharedMesh(), roles);
  viewport_->setHead(*shownMesh_);
  orientView();
  if (producer_)
    pose();
  else
    updateMarkers();
}

void HeadWorkspace::onMeshChanged() {
  proposalWarnings_.clear();
  shownPositions_ = nullptr;
  producer_.reset();
  rig_.reset();
  checks_.clear();
  updateChecks();
  shownMesh_ = withRigRoles(*setup_->sharedMesh(), setup_->roles());
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
  orientView();
  rigDelay_->start();  // restarts: a burst of edits rigs once
}

void HeadWorkspace::updateChecks() {
  checksView_->clear();
  for (const rigging::RigCheck& check : checks_) {
    const bool error = check.severity == rigging::RigCheck::Severity::Error;
    QStringList ids;
    for (const std::string& id : check.points) ids << QString::fromStdString(id);
    const QString where = ids.isEmpty() ? QString() : QStringLiteral(" (%1)").arg(ids.join(", "));
    auto* item = new QListWidgetItem(
        QStringLiteral("%1%2 %3").arg(error ? tr("Error") : tr("Warning"), where + ':',
                                      QString::fromStdString(check.message)),
        checksView_);
    item->setForeground(error ? QColor(230, 90, 80) : QColor(230, 180, 60));
    item->setToolTip(QString::fromStdString(rigging::toString(check)) +
                     (ids.isEmpty() ? QString() : tr("\nClick to select %1").arg(ids.front())));
    item->setData(Qt::UserRole, ids);
  }
  // The rig's and the proposal's warnings are sentences naming their points: the points they
  // name are selected by a click as a check's are.
  const auto addNote = [this](const QString& kind, const QString& message) {
    auto* item = new QListWidgetItem(QStringLiteral("%1: %2").arg(kind, message), checksView_);
    item->setForeground(QColor(230, 180, 60));
    const QStringList ids = fdpIdsIn(message);
    item->setToolTip(ids.isEmpty() ? message : message + tr("\nClick to select %1").arg(ids[0]));
    item->setData(Qt::UserRole, ids);
  };
  if (rig_)
    for (const std::string& w : rig_->warnings) addNote(tr("Rig"), QString::fromStdString(w));
  for (const QString& w : proposalWarnings_) addNote(tr("Proposal"), w);
  if (checksView_->count() == 0 && rig_) new QListWidgetItem(tr("No problems found"), checksView_);
}

// The FDP ids ("6.1", "10.7") a warning names, in order, each once.
QStringList HeadWorkspace::fdpIdsIn(const QString& text) {
  static const QRegularExpression number(
      QStringLiteral("(?<![\\d.])(\\d{1,2}\\.\\d{1,2})(?![\\d.])"));
  QStringList ids;
  for (auto it = number.globalMatch(text); it.hasNext();) {
    const QString id = it.next().captured(1);
    if (!fdpDescription(id.toStdString()).empty() && !ids.contains(id)) ids << id;
  }
  return ids;
}

}  // namespace lacrima::editor::head
