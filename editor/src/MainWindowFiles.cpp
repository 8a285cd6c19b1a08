// MainWindow: files, recent files, autosave and recovery, closing.
#include "MainWindowPrivate.h"

#include <lacrima/appsupport/ExportDialog.h>
#include <lacrima/common/ProjectPath.h>
#include <lacrima/editor/NumberField.h>
#include <lacrima/editor/PresetPanel.h>
#include <lacrima/editor/RecoveryBanner.h>
#include <lacrima/playback/TearQualityOptions.h>

#include <QCheckBox>
#include <QCloseEvent>
#include <QComboBox>
#include <QDialog>
#include <QDialogButtonBox>
#include <QDir>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QLabel>
#include <QMenu>
#include <QMessageBox>
#include <QMimeData>
#include <QSettings>
#include <QStatusBar>
#include <QTemporaryFile>
#include <QTimer>

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>

namespace lacrima::editor {
namespace {

constexpr int kMaxRecentFiles = 8;
const QString kRecentKey = QStringLiteral("files/recent");
const QString kToleranceKey = QStringLiteral("import/tolerance");
const QString kReduceKey = QStringLiteral("import/reduce");

bool isFapFile(const QString& path) { return !isProjectPath(path.toStdString()); }

const QString kProjectSuffix =
    QString::fromLatin1(kProjectExtension.data(), kProjectExtension.size());

QString joinWarnings(const Warnings& warnings) {
  QStringList lines;
  for (const Diagnostic& d : warnings) lines << QString::fromStdString(d.toString());
  return lines.join(QLatin1Char('\n'));
}

}  // namespace

void MainWindow::reportError(const QString& title, const QString& message) {
  d_->lastError = message;
  statusBar()->showMessage(message, 10000);
  if (d_->options.interactive) QMessageBox::warning(this, title, message);
}

bool MainWindow::maybeSave() {
  if (!d_->model->isModified() || !d_->options.interactive) return true;
  const auto answer = QMessageBox::warning(
      this, tr("Unsaved changes"),
      tr("“%1” has unsaved changes. Save them first?")
          .arg(QString::fromStdString(d_->model->document().name)),
      QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, QMessageBox::Save);
  if (answer == QMessageBox::Cancel) return false;
  if (answer == QMessageBox::Save)
    return d_->filePath.isEmpty() ? saveDialog() : saveTo(d_->filePath);
  return true;
}

void MainWindow::newDocument() {
  d_->clock->pause();
  ProjectDocument document;
  document.name = "untitled";
  d_->filePath.clear();
  d_->model->resetDocument(std::move(document), true);
  d_->recovery->discard();
  d_->autosaveDirty = false;
  updateTitle();
  updateStatusFigures();
}

bool MainWindow::openFile(const QString& path) {
  if (isFapFile(path)) {
    QSettings settings;
    const bool reduce = settings.value(kReduceKey, true).toBool();
    const double tolerance = settings.value(kToleranceKey, 1.0).toDouble();
    return importFap(path, reduce ? std::optional<double>(tolerance) : std::nullopt);
  }
  try {
    const TearMethodKeys methods = playback::tearMethodKeys();
    ProjectDocument document =
        ProjectDocument::load(path.toStdString(), ProjectDocument::Use::Edit, &methods);
    d_->clock->pause();
    d_->filePath = QFileInfo(path).absoluteFilePath();
    d_->model->resetDocument(std::move(document), true);
    d_->recovery->discard();
    d_->autosaveDirty = false;
    addRecentFile(d_->filePath);
    updateTitle();
    updateStatusFigures();
    // A head that moved does not stop the project from opening: the preview explains, and the
    // reference stays as it is so saving loses nothing.
    if (auto missing = d_->model->document().missingHeadFile(path.toStdString()))
      statusBar()->showMessage(QString::fromStdString(missing->toString()), 15000);
    else
      statusBar()->showMessage(tr("Opened %1").arg(path), 4000);
    return true;
  } catch (const std::exception& e) {
    reportError(tr("Cannot open the project"), QString::fromUtf8(e.what()));
    return false;
  }
}

bool MainWindow::saveTo(const QString& path) {
  try {
    // A first save names an untitled project after its file (one undo step, before saving).
    if (d_->model->document().name == "untitled") {
      ProjectDocument named = d_->model->document();
      named.name = QFileInfo(path).completeBaseName().toStdString();
      if (!named.name.empty()) d_->model->setSettings(named, tr("Name project"));
    }
    d_->model->document().save(path.toStdString());
    d_->filePath = QFileInfo(path).absoluteFilePath();
    d_->model->markSaved();
    d_->recovery->discard();
    d_->autosaveDirty = false;
    addRecentFile(d_->filePath);
    updateTitle();
    statusBar()->showMessage(tr("Saved %1").arg(path), 4000);
    return true;
  } catch (const std::exception& e) {
    reportError(tr("Cannot save"), QString::fromUtf8(e.what()));
    return false;
  }
}

bool MainWindow::setHead(const QString& meshPath, const QString& fdpPath) {
  for (const QString& file : {meshPath, fdpPath}) {
    if (!QFileInfo(file).isFile()) {
      reportError(tr("Cannot use the head"), tr("%1: no such file").arg(file));
      return false;
    }
  }
  ProjectDocument changed = d_->model->document();
  changed.head = HeadFiles{QFileInfo(meshPath).absoluteFilePath().toStdString(),
                           QFileInfo(fdpPath).absoluteFilePath().toStdString()};
  d_->model->setSettings(changed, tr("Choose head %1").arg(QFileInfo(meshPath).fileName()));
  return true;
}

bool MainWindow::importFap(const QString& path, std::optional<double> reductionTolerance) {
  try {
    editing::FapImportResult result =
        editing::importFap(path.toStdString(), editing::FapImportOptions{reductionTolerance});
    d_->clock->pause();
    d_->filePath.clear();
    d_->model->resetDocument(std::move(result.document), false);
    addRecentFile(QFileInfo(path).absoluteFilePath());
    updateTitle();
    updateStatusFigures();
    QString message = reductionTolerance
                          ? tr("Imported %1: %2 frames → %3 keys (tolerance %4, largest error %5)")
                                .arg(QFileInfo(path).fileName())
                                .arg(result.frames)
                                .arg(result.keys)
                                .arg(*reductionTolerance)
                                .arg(result.maxError, 0, 'g', 3)
                          : tr("Imported %1: %2 frames as %2 keys")
                                .arg(QFileInfo(path).fileName())
                                .arg(result.frames);
    if (!result.warnings.empty())
      message += tr(" · %n warning(s)", nullptr, static_cast<int>(result.warnings.size()));
    statusBar()->showMessage(message, 10000);
    if (!result.warnings.empty()) statusBar()->setToolTip(joinWarnings(result.warnings));
    autosaveNow();  // an import is unsaved work from the first moment
    return true;
  } catch (const std::exception& e) {
    reportError(tr("Cannot import the FAP file"), QString::fromUtf8(e.what()));
    return false;
  }
}

bool MainWindow::exportFap(const QString& path, const editing::FapExportOptions& options) {
  try {
    const editing::FapExportResult result =
        editing::exportFap(d_->model->document(), path.toStdString(), options);
    QString message = tr("Exported %1 frames at %2 fps to %3 (%4)")
                          .arg(result.frames)
                          .arg(options.fps)
                          .arg(QFileInfo(path).fileName())
                          .arg(options.strict      ? tr("strict 68 FAPs")
                               : result.wroteTears ? tr("with tear channels")
                                                   : tr("68 FAPs, no tears"));
    if (!result.warnings.empty()) message += QStringLiteral(" · ") + joinWarnings(result.warnings);
    statusBar()->showMessage(message, 10000);
    return true;
  } catch (const std::exception& e) {
    reportError(tr("Cannot export"), QString::fromUtf8(e.what()));
    return false;
  }
}

// --- dialogs --------------------------------------------------------------------------------

void MainWindow::openDialog() {
  if (!d_->options.interactive || !maybeSave()) return;
  const QString path = QFileDialog::getOpenFileName(
      this, tr("Open project or FAP file"), QFileInfo(d_->filePath).path(),
      tr("Projects and FAP files (*.lacrima *.json *.fap);;Projects (*.lacrima *.json);;FAP files "
         "(*.fap)"));
  if (!path.isEmpty()) openFile(path);
}

bool MainWindow::saveDialog() {
  if (!d_->options.interactive) return false;
  QString suggestion = d_->filePath;
  if (suggestion.isEmpty())
    suggestion = QString::fromStdString(d_->model->document().name) + kProjectSuffix;
  QString path = QFileDialog::getSaveFileName(this, tr("Save project"), suggestion,
                                              tr("Projects (*.lacrima *.json)"));
  if (path.isEmpty()) return false;
  // A .json name the user typed stays: older projects keep their name when saved again.
  if (!isProjectPath(path.toStdString())) path += kProjectSuffix;
  return saveTo(path);
}

void MainWindow::importDialog() {
  if (!d_->options.interactive || !maybeSave()) return;
  const QString path = QFileDialog::getOpenFileName(this, tr("Import FAP file"), QString(),
                                                    tr("FAP files (*.fap);;All files (*)"));
  if (path.isEmpty()) return;
  QSettings settings;
  QDialog dialog(this);
  dialog.setWindowTitle(tr("Import %1").arg(QFileInfo(path).fileName()));
  auto* form = new QFormLayout(&dialog);
  auto* reduce = new QCheckBox(tr("Reduce keys"), &dialog);
  reduce->setChecked(settings.value(kReduceKey, true).toBool());
  reduce->setToolTip(
      tr("Drop every frame that linear interpolation between the kept keys reproduces within the "
         "tolerance, on every channel"));
  auto* tolerance = new NumberField(&dialog);
  tolerance->setRange({0, 1000, false, tr("units")});
  tolerance->setSubject(tr("the tolerance"));
  tolerance->setDecimals(3);
  tolerance->setSingleStep(0.5);
  tolerance->setValue(std::clamp(settings.value(kToleranceKey, 1.0).toDouble(), 0.0, 1000.0));
  tolerance->setKeepsRefusedText(true);
  tolerance->setToolTip(
      tr("Largest difference allowed on any channel, in its own units (FAPU steps, AU, particles). "
         "1 follows the motion of integer files; 0 keeps every frame that is not on a straight "
         "line."));
  form->addRow(reduce);
  form->addRow(tr("Tolerance"), tolerance);
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, &dialog);
  form->addRow(buttons);
  connect(reduce, &QCheckBox::toggled, tolerance, &QWidget::setEnabled);
  tolerance->setEnabled(reduce->isChecked());
  connect(buttons, &QDialogButtonBox::accepted, &dialog, [&dialog, tolerance] {
    if (commitFields({tolerance})) dialog.accept();
  });
  connect(buttons, &QDialogButtonBox::rejected, &dialog, &QDialog::reject);
  if (dialog.exec() != QDialog::Accepted) return;
  settings.setValue(kReduceKey, reduce->isChecked());
  settings.setValue(kToleranceKey, tolerance->value());
  importFap(path, reduce->isChecked() ? std::optional<double>(tolerance->value()) : std::nullopt);
}

void MainWindow::exportDialog() {
  if (!d_->options.interactive) return;
  QDialog dialog(this);
  dialog.setWindowTitle(tr("Export FAP"));
  auto* form = new QFormLayout(&dialog);
  auto* fps = new NumberField(&dialog);
  fps->setRange({1, 240, true, tr("fps")});
  fps->setSubject(tr("the frame rate"));
  fps->setValue(std::clamp(std::round(d_->model->document().fps), 1.0, 240.0));
  fps->setKeepsRefusedText(true);
  auto* profile = new QComboBox(&dialog);
  profile->addItem(tr("Extended: 68 FAPs + tear channels 69-70 (Lacrima player)"));
  profile->addItem(tr("Strict: the 68 standard FAPs (other players)"));
  form->addRow(tr("Frame rate"), fps);
  form->addRow(tr("Profile"), profile);
  form->addRow(new QLabel(
      tr("Frames cover the first key to the last; FAP 1 and 2 are not written (portable profile)."),
      &dialog));
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, &dialog);
  form->addRow(buttons);
  connect(buttons, &QDialogButtonBox::accepted, &dialog, [&dialog, fps] {
    if (commitFields({fps})) dialog.accept();
  });
  connect(buttons, &QDialogButtonBox::rejected, &dialog, &QDialog::reject);
  if (dialog.exec() != QDialog::Accepted) return;
  QString suggestion =
      d_->filePath.isEmpty()
          ? QString::fromStdString(d_->model->document().name) + QStringLiteral(".fap")
          : QFileInfo(d_->filePath).path() + '/' + QFileInfo(d_->filePath).completeBaseName() +
                QStringLiteral(".fap");
  QString path =
      QFileDialog::getSaveFileName(this, tr("Export FAP"), suggestion, tr("FAP files (*.fap)"));
  if (path.isEmpty()) return;
  if (!path.endsWith(QLatin1String(".fap"), Qt::CaseInsensitive)) path += QStringLiteral(".fap");
  exportFap(path, editing::FapExportOptions{fps->value(), profile->currentIndex() == 1});
}

appsupport::ExportDialog* MainWindow::exportAnimationDialog() {
  const ProjectDocument& document = d_->model->document();
  appsupport::ExportSource source;
  const QFileInfo project(d_->filePath);
  source.name = d_->filePath.isEmpty() ? QString::fromStdString(document.name) : project.fileName();
  source.outputStem = d_->filePath.isEmpty()
                          ? QDir::home().filePath(QString::fromStdString(document.name))
                          : project.dir().filePath(project.completeBaseName());
  std::unique_ptr<QTemporaryFile> copy;
  try {
    source.frameCount = std::max(1, document.bake().frameCount());
    if (!d_->filePath.isEmpty() && !isFapFile(d_->filePath) && !d_->model->isModified()) {
      source.file = d_->filePath;
    } else {
      // The export reads a file; the user's stays as they saved it.
      copy = std::make_unique<QTemporaryFile>(
          QDir::temp().filePath(QStringLiteral("lacrima-export-XXXXXX") + kProjectSuffix));
      if (!copy->open())
        throw std::runtime_error(copy->fileName().toStdString() +
                                 ": cannot create: " + copy->errorString().toStdString());
      copy->close();
      document.save(copy->fileName().toStdString());
      source.file = copy->fileName();
    }
  } catch (const std::exception& e) {
    reportError(tr("Cannot export"), QString::fromUtf8(e.what()));
    return nullptr;
  }
  auto* dialog = new appsupport::ExportDialog(source, this);
  if (copy) copy.release()->setParent(dialog);  // removed after the dialog's export ends
  dialog->setAttribute(Qt::WA_DeleteOnClose);
  dialog->show();
  return dialog;
}

void MainWindow::chooseHeadDialog() {
  if (!d_->options.interactive) return;
  const std::optional<HeadFiles>& current = d_->model->document().head;
  const QString start = current ? QFileInfo(QString::fromStdString(current->mesh)).path()
                                : QFileInfo(d_->filePath).path();
  const QString mesh = QFileDialog::getOpenFileName(
      this, tr("Choose head: the mesh"), start,
      tr("Meshes (*.obj *.glb *.gltf *.fbx *.dae *.ply);;All files (*)"));
  if (mesh.isEmpty()) return;
  // Feature-point files usually sit beside their mesh as NAME.fdp.json: offer that one.
  const QFileInfo meshInfo(mesh);
  const QString beside = meshInfo.path() + '/' + meshInfo.completeBaseName() + ".fdp.json";
  const QString fdp =
      QFileDialog::getOpenFileName(this, tr("Choose head: its feature points"),
                                   QFileInfo::exists(beside) ? beside : meshInfo.path(),
                                   tr("Feature points (*.fdp.json *.json);;All files (*)"));
  if (fdp.isEmpty()) return;
  setHead(mesh, fdp);
}

void MainWindow::loadPresetsDialog() {
  if (!d_->options.interactive) return;
  const QString path =
      QFileDialog::getOpenFileName(this, tr("Load presets"), QString(), tr("Presets (*.json)"));
  if (path.isEmpty()) return;
  try {
    d_->presets->setLibrary(editing::PresetLibrary::load(path.toStdString()), path);
    statusBar()->showMessage(tr("Loaded %n preset(s) from %1", nullptr,
                                static_cast<int>(d_->presets->library().presets().size()))
                                 .arg(path),
                             5000);
  } catch (const FileError& e) {
    reportError(tr("Cannot load the presets"), QString::fromUtf8(e.what()));
  }
}

// --- recent files ---------------------------------------------------------------------------

void MainWindow::addRecentFile(const QString& path) {
  QSettings settings;
  QStringList recent = settings.value(kRecentKey).toStringList();
  recent.removeAll(path);
  recent.prepend(path);
  while (recent.size() > kMaxRecentFiles) recent.removeLast();
  settings.setValue(kRecentKey, recent);
  rebuildRecentMenu();
}

void MainWindow::rebuildRecentMenu() {
  if (!d_->recentMenu) return;
  d_->recentMenu->clear();
  const QStringList recent = QSettings().value(kRecentKey).toStringList();
  int number = 1;
  for (const QString& path : recent) {
    QAction* a = d_->recentMenu->addAction(
        QStringLiteral("&%1  %2").arg(number++).arg(QFileInfo(path).fileName()));
    a->setStatusTip(path);
    a->setEnabled(QFileInfo::exists(path));
    connect(a, &QAction::triggered, this, [this, path] {
      if (maybeSave()) openFile(path);
    });
  }
  if (recent.isEmpty()) d_->recentMenu->addAction(tr("(none yet)"))->setEnabled(false);
  d_->recentMenu->addSeparator();
  connect(d_->recentMenu->addAction(tr("Clear list")), &QAction::triggered, this, [this] {
    QSettings().remove(kRecentKey);
    rebuildRecentMenu();
  });
}

// --- autosave and recovery ------------------------------------------------------------------

void MainWindow::autosaveNow() {
  d_->autosaveSoon->stop();
  d_->autosaveDirty = false;
  try {
    if (d_->model->isModified())
      d_->recovery->save(d_->model->document(), d_->filePath);
    else
      d_->recovery->discard();
  } catch (const FileError& e) {
    statusBar()->showMessage(tr("Autosave failed: %1").arg(QString::fromUtf8(e.what())), 8000);
  }
}

void MainWindow::checkForRecovery() {
  const auto orphans = d_->recovery->orphans();
  if (orphans.empty()) {
    d_->banner->hide();
    d_->pendingRecovery.clear();
    return;
  }
  const editing::RecoveryStore::Orphan& newest = orphans.front();
  d_->pendingRecovery = newest.file;
  QString where = newest.sourcePath.isEmpty() ? tr("never saved") : newest.sourcePath;
  QString text = tr("<b>Unsaved work was found</b> from an editor that did not close cleanly: “%1” "
                    "(%n key(s), %2, autosaved %3).",
                    nullptr, newest.keys)
                     .arg(newest.name.toHtmlEscaped(), where.toHtmlEscaped(),
                          QLocale().toString(newest.savedAt.toLocalTime(), QLocale::ShortFormat));
  if (orphans.size() > 1)
    text += tr(" %n older one(s) too.", nullptr, static_cast<int>(orphans.size() - 1));
  d_->banner->setText(text);
  d_->banner->show();
}

bool MainWindow::restoreRecovery() {
  if (d_->pendingRecovery.isEmpty()) return false;
  bool restored = false;
  try {
    QString source;
    const TearMethodKeys methods = playback::tearMethodKeys();
    ProjectDocument document =
        editing::RecoveryStore::read(d_->pendingRecovery, &source, nullptr, &methods);
    d_->clock->pause();
    d_->model->resetDocument(std::move(document), false);
    d_->filePath = source;
    editing::RecoveryStore::remove(d_->pendingRecovery);
    autosaveNow();  // the restored work is this session's to protect now
    updateTitle();
    updateStatusFigures();
    statusBar()->showMessage(tr("Restored the unsaved work; save it to keep it"), 8000);
    restored = true;
  } catch (const std::exception& e) {
    reportError(tr("Cannot restore"), QString::fromUtf8(e.what()));
  }
  checkForRecovery();
  return restored;
}

void MainWindow::discardRecovery() {
  if (!d_->pendingRecovery.isEmpty()) editing::RecoveryStore::remove(d_->pendingRecovery);
  checkForRecovery();
}

// --- closing and dropping -------------------------------------------------------------------

void MainWindow::closeEvent(QCloseEvent* event) {
  if (!maybeSave()) {
    event->ignore();
    return;
  }
  d_->clock->pause();
  d_->recovery->discard();  // a clean exit leaves nothing to recover
  QSettings settings;
  settings.setValue(QStringLiteral("window/geometry"), saveGeometry());
  settings.setValue(QStringLiteral("window/state"), animateLayout());
  event->accept();
}

void MainWindow::dragEnterEvent(QDragEnterEvent* event) {
  if (event->mimeData()->hasUrls()) event->acceptProposedAction();
}

void MainWindow::dropEvent(QDropEvent* event) {
  const auto urls = event->mimeData()->urls();
  if (urls.isEmpty() || !urls.front().isLocalFile()) return;
  if (maybeSave()) openFile(urls.front().toLocalFile());
}

}  // namespace lacrima::editor
