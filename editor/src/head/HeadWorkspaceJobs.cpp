// The Head workspace's background work: import, proposal, rig and reference pictures, each on
// a worker thread, their results applied on the GUI thread (HeadWorkspace.h).
#include <lacrima/editor/head/HeadWorkspace.h>

#include <lacrima/common/FdpTable.h>
#include <lacrima/editing/EditorModel.h>
#include <lacrima/editing/HeadSetup.h>
#include <lacrima/editor/RigJob.h>
#include <lacrima/exporters/FeaturePointReference.h>
#include <lacrima/playback/FrameProducer.h>
#include <lacrima/playback/HeadRig.h>
#include <lacrima/rigging/ImportProcess.h>
#include <lacrima/viewport/FaceViewport.h>

#include <QElapsedTimer>
#include <QFileInfo>
#include <QFutureWatcher>
#include <QLabel>
#include <QPixmap>
#include <QProgressBar>
#include <QToolButton>
#include <QtConcurrent/QtConcurrentRun>

#include <algorithm>
#include <atomic>

namespace lacrima::editor::head {
namespace {

QString text(const std::exception& e) { return QString::fromUtf8(e.what()); }

struct ImportResult {
  HeadMesh mesh;
  QString error;
  bool cancelled = false;
  double milliseconds = 0;
};

struct ProposalResult {
  editing::PlacedPoints points;
  std::shared_ptr<const editing::ProposalReference> reference;
  Warnings warnings;
  QString error;
  double milliseconds = 0;
};

struct ReferenceResult {
  std::shared_ptr<const exporters::ReferenceHead> head;
  std::string id;
  QImage image;
  bool hidden = false;
  QString error;
};

}  // namespace

void HeadWorkspace::importHead(const QString& path) {
  if (importing_) {
    fail(tr("Import"), tr("an import is already running"));
    emit importFinished(false);
    return;
  }
  importing_ = true;
  showImportRunning(true);
  setStatus(tr("Importing %1…").arg(QFileInfo(path).fileName()));
  auto cancelled = std::make_shared<std::atomic<bool>>(false);
  importCancelled_ = cancelled;
  rigging::ImportOptions options;
  if (importSeconds_ > 0) options.seconds = importSeconds_;
  options.cancelled = [cancelled] { return cancelled->load(); };
  auto* watcher = new QFutureWatcher<ImportResult>(this);
  connect(watcher, &QFutureWatcher<ImportResult>::finished, this, [this, watcher, path] {
    ImportResult result = watcher->result();
    watcher->deleteLater();
    importing_ = false;
    importCancelled_.reset();
    showImportRunning(false);
    if (result.cancelled) {
      lastError_ = result.error;
      setStatus(tr("Import of %1 cancelled").arg(QFileInfo(path).fileName()));
      emit importFinished(false);
      return;
    }
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
  // assimp takes a good part of a second on a large head: never on the GUI thread. The worker
  // waits for the importer process, which a cancel kills.
  watcher->setFuture(QtConcurrent::run([path, options] {
    ImportResult r;
    QElapsedTimer timer;
    timer.start();
    try {
      r.mesh = editing::HeadSetup::importMesh(path, options);
    } catch (const rigging::ImportError& e) {
      r.error = text(e);
      r.cancelled = e.failure() == rigging::ImportFailure::Cancelled;
    } catch (const std::exception& e) {
      r.error = text(e);
    }
    r.milliseconds = timer.nsecsElapsed() / 1e6;
    return r;
  }));
}

void HeadWorkspace::cancelImport() {
  if (importCancelled_) *importCancelled_ = true;
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
    proposalWarnings_.clear();
    for (const Diagnostic& w : result.warnings)
      proposalWarnings_ << QString::fromStdString(w.message);
    setup_->applyProposal(result.points);
    updateChecks();
    lastError_.clear();
    setStatus(tr("Proposed %1 points in %2 ms%3: drag any that are off")
                  .arg(std::count_if(result.points.begin(), result.points.end(),
                                     [](const auto& p) { return !p.second.byHand(); }))
                  .arg(result.milliseconds, 0, 'f', 0)
                  .arg(result.warnings.empty()
                           ? QString()
                           : tr(" (%n warning(s), listed under the checks)", nullptr,
                                static_cast<int>(result.warnings.size()))));
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
  pendingMesh_ = setup_->sharedMesh();
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
  if (!rig || pendingMesh_ != setup_->sharedMesh()) return;  // rigged a head since replaced
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

}  // namespace lacrima::editor::head
