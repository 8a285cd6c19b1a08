#include <lacrima/appsupport/ExportDialog.h>

#include <lacrima/common/ImageSize.h>
#include <lacrima/scene/CameraPreset.h>

#include <QCheckBox>
#include <QComboBox>
#include <QCoreApplication>
#include <QDialogButtonBox>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QProgressBar>
#include <QPushButton>
#include <QRegularExpression>
#include <QSpinBox>
#include <QTimer>
#include <QVBoxLayout>

namespace lacrima::appsupport {
namespace {

struct FormatInfo {
  ExportFormat format;
  const char* label;
  const char* option;  // lacrima-player's
  bool folder;         // the output is a folder
  bool rendered;       // size and camera apply
  const char* suffix;  // of the default output: an extension, or a folder's name ending
};

constexpr FormatInfo kFormats[] = {
    {ExportFormat::Gltf, "glTF 2.0 with tears (.glb)", "--export-gltf", false, false, ".glb"},
    {ExportFormat::Video, "Video, H.264 (.mp4)", "--video", false, true, ".mp4"},
    {ExportFormat::Images, "Images, PNG (a folder)", "--render", true, true, "_frames"},
    {ExportFormat::TearMeshes, "Tear meshes, PLY (a folder)", "--export-tears", true, false,
     "_tears"},
};

const FormatInfo& infoOf(int index) {
  return kFormats[std::clamp(index, 0, static_cast<int>(std::size(kFormats)) - 1)];
}

}  // namespace

ExportDialog::ExportDialog(ExportSource source, QWidget* parent, QString player)
    : QDialog(parent),
      source_(std::move(source)),
      player_(player.isEmpty() ? QCoreApplication::applicationDirPath() + "/lacrima-player"
                               : std::move(player)) {
  setWindowTitle(
      tr("Export %1")
          .arg(source_.name.isEmpty() ? QFileInfo(source_.file).fileName() : source_.name));
  format_ = new QComboBox(this);
  for (const FormatInfo& f : kFormats) format_->addItem(tr(f.label));
  output_ = new QLineEdit(this);
  output_->setObjectName(QStringLiteral("output"));
  // Room for a whole path in a home folder, not only its last characters.
  output_->setMinimumWidth(output_->fontMetrics().averageCharWidth() * 48);
  browse_ = new QPushButton(tr("Browse..."), this);
  size_ = new QLineEdit(QStringLiteral("1280x720"), this);
  view_ = new QComboBox(this);
  for (const QString& name :
       QString::fromLatin1(scene::cameraPresetNames().data(),
                           static_cast<qsizetype>(scene::cameraPresetNames().size()))
           .split(QStringLiteral(", ")))
    view_->addItem(name);
  const int lastFrame = std::max(0, source_.frameCount - 1);
  first_ = new QSpinBox(this);
  last_ = new QSpinBox(this);
  for (QSpinBox* box : {first_, last_}) box->setRange(0, lastFrame);
  last_->setValue(lastFrame);
  alpha_ = new QCheckBox(tr("Transparent background"), this);
  masks_ = new QCheckBox(tr("Tear masks beside the frames"), this);
  progress_ = new QProgressBar(this);
  progress_->setRange(0, 100);
  progress_->hide();  // until an export starts: no "0%" before anything ran
  status_ = new QLabel(this);
  status_->setWordWrap(true);
  export_ = new QPushButton(tr("Export"), this);
  export_->setObjectName(QStringLiteral("export"));
  export_->setDefault(true);
  cancel_ = new QPushButton(tr("Cancel"), this);

  auto* outputRow = new QHBoxLayout;
  outputRow->addWidget(output_);
  outputRow->addWidget(browse_);
  auto* rangeRow = new QHBoxLayout;
  rangeRow->addWidget(first_);
  rangeRow->addWidget(new QLabel(tr("to"), this));
  rangeRow->addWidget(last_);
  auto* form = new QFormLayout;
  form->addRow(tr("Format"), format_);
  form->addRow(tr("Output"), outputRow);
  form->addRow(tr("Size"), size_);
  form->addRow(tr("View"), view_);
  form->addRow(tr("Frames"), rangeRow);
  form->addRow(QString(), alpha_);
  form->addRow(QString(), masks_);
  auto* buttons = new QDialogButtonBox(this);
  buttons->addButton(export_, QDialogButtonBox::AcceptRole);
  buttons->addButton(cancel_, QDialogButtonBox::RejectRole);
  auto* layout = new QVBoxLayout(this);
  layout->addLayout(form);
  layout->addWidget(progress_);
  layout->addWidget(status_);
  layout->addWidget(buttons);

  connect(format_, &QComboBox::currentIndexChanged, this, &ExportDialog::formatChanged);
  connect(output_, &QLineEdit::textEdited, this, [this] { outputChosen_ = true; });
  connect(browse_, &QPushButton::clicked, this, [this] {
    const FormatInfo& f = infoOf(format_->currentIndex());
    const QString path =
        f.folder ? QFileDialog::getExistingDirectory(this, tr("Export to"), output_->text())
                 : QFileDialog::getSaveFileName(this, tr("Export to"), output_->text());
    if (!path.isEmpty()) setOutput(path);
  });
  connect(export_, &QPushButton::clicked, this, &ExportDialog::start);
  connect(cancel_, &QPushButton::clicked, this, &ExportDialog::reject);
  formatChanged();
}

ExportDialog::~ExportDialog() {
  if (!running()) return;
  // Closed while exporting: the export goes with the dialog, and so does what it left.
  disconnect(process_, nullptr, this, nullptr);
  process_->kill();
  process_->waitForFinished(5000);
  removeLeftovers();
}

void ExportDialog::setFormat(ExportFormat format) {
  for (int i = 0; i < static_cast<int>(std::size(kFormats)); ++i)
    if (kFormats[i].format == format) format_->setCurrentIndex(i);
}

void ExportDialog::setOutput(const QString& path) {
  outputChosen_ = true;
  output_->setText(path);
}

QString ExportDialog::output() const { return output_->text().trimmed(); }

QString ExportDialog::defaultOutput() const {
  QString stem = source_.outputStem;
  if (stem.isEmpty()) {
    const QFileInfo file(source_.file);
    stem = file.dir().filePath(file.completeBaseName());
  }
  return stem + QLatin1String(infoOf(format_->currentIndex()).suffix);
}

void ExportDialog::setFrameRange(int first, int last) {
  first_->setValue(first);
  last_->setValue(last);
}

void ExportDialog::setImageSize(const QString& size) { size_->setText(size); }

void ExportDialog::setLayers(bool alpha, bool masks) {
  alpha_->setChecked(alpha);
  masks_->setChecked(masks);
}

void ExportDialog::formatChanged() {
  const FormatInfo& f = infoOf(format_->currentIndex());
  size_->setEnabled(f.rendered);
  view_->setEnabled(f.rendered);
  const bool images = f.format == ExportFormat::Images;
  alpha_->setEnabled(images);
  masks_->setEnabled(images);
  if (!outputChosen_) output_->setText(defaultOutput());
}

QStringList ExportDialog::arguments(QString* error) const {
  const FormatInfo& f = infoOf(format_->currentIndex());
  auto refuse = [&](const QString& why) {
    if (error) *error = why;
    return QStringList();
  };
  const QString output = output_->text().trimmed();
  if (output.isEmpty()) return refuse(tr("Choose where to export to."));
  if (first_->value() > last_->value())
    return refuse(tr("The first frame (%1) is after the last (%2).")
                      .arg(first_->value())
                      .arg(last_->value()));
  QStringList arguments{QString::fromLatin1(f.option), output};
  if (f.rendered) {
    const ParsedImageSize size = parseImageSize(size_->text().trimmed().toStdString());
    if (!size.error.empty()) return refuse(tr("Size: %1").arg(QString::fromStdString(size.error)));
    if (f.format == ExportFormat::Video && (size.size.width() % 2 || size.size.height() % 2))
      return refuse(tr("Size: H.264 video needs an even width and height."));
    arguments << "--size" << size_->text().trimmed() << "--view" << view_->currentText();
  }
  if (f.format == ExportFormat::Images) {
    if (alpha_->isChecked()) arguments << "--alpha";
    if (masks_->isChecked()) arguments << "--masks";
  }
  arguments << "--frames" << QStringLiteral("%1-%2").arg(first_->value()).arg(last_->value());
  return arguments + source_.headArguments + QStringList{source_.file};
}

bool ExportDialog::running() const { return process_ && process_->state() != QProcess::NotRunning; }

void ExportDialog::setRunning(bool running) {
  for (QWidget* w : std::initializer_list<QWidget*>{format_, output_, browse_, size_, view_, first_,
                                                    last_, alpha_, masks_, export_})
    w->setEnabled(!running);
  if (!running) formatChanged();
  cancel_->setText(running ? tr("Stop") : tr("Close"));
}

void ExportDialog::start() {
  if (running()) return;
  QString error;
  const QStringList args = arguments(&error);
  if (args.isEmpty()) {
    status_->setText(error);
    return;
  }
  delete process_;
  process_ = new QProcess(this);
  errors_.clear();
  cancelled_ = false;
  connect(process_, &QProcess::readyReadStandardError, this, &ExportDialog::readProgress);
  connect(process_, &QProcess::finished, this, &ExportDialog::processEnded);
  progress_->setRange(0, 0);  // busy until the first frame is reported
  progress_->show();
  status_->setText(tr("Exporting..."));
  setRunning(true);
  process_->start(player_, args);
  const bool started = process_->waitForStarted(10000);
  pid_ = process_->processId();
  if (!started) {
    setRunning(false);
    const QString why = tr("Cannot start %1: %2").arg(player_, process_->errorString());
    status_->setText(why);
    emit exportFinished(false, why);
  }
}

void ExportDialog::readProgress() {
  errors_ += process_->readAllStandardError();
  // "lacrima-player: rendered 31/309 frames" or "exported 31/309 frames", one line each.
  static const QRegularExpression line(QStringLiteral("(\\d+)/(\\d+) frames"));
  QRegularExpressionMatchIterator it = line.globalMatch(QString::fromLocal8Bit(errors_));
  while (it.hasNext()) {
    const QRegularExpressionMatch m = it.next();
    const int total = m.captured(2).toInt();
    if (total <= 0) continue;
    progress_->setRange(0, 100);
    progress_->setValue(100 * m.captured(1).toInt() / total);
  }
}

void ExportDialog::cancel() {
  if (!running()) return;
  cancelled_ = true;
  status_->setText(tr("Stopping..."));
  process_->terminate();
  // A process that ignores the request (stuck in a write) is killed.
  QTimer::singleShot(1000, process_, [process = process_] {
    if (process->state() != QProcess::NotRunning) process->kill();
  });
}

void ExportDialog::reject() {
  if (running())
    cancel();
  else
    QDialog::reject();
}

// A stopped video leaves its hidden temporary (".NAME.part-PID", H264Writer.h) behind.
void ExportDialog::removeLeftovers() {
  const QFileInfo output(output_->text().trimmed());
  const QString temporary = QStringLiteral(".%1.part-%2").arg(output.fileName()).arg(pid_);
  QFile::remove(output.dir().filePath(temporary));
}

void ExportDialog::processEnded(int exitCode, QProcess::ExitStatus status) {
  readProgress();
  setRunning(false);
  const bool ok = !cancelled_ && status == QProcess::NormalExit && exitCode == 0;
  // A bar that never left "busy" had nothing done to show.
  if (progress_->maximum() == 0) progress_->setVisible(ok);
  progress_->setRange(0, 100);
  QString message;
  if (ok) {
    progress_->setValue(100);
    message = tr("Exported to %1")
                  .arg(QString::fromLocal8Bit(process_->readAllStandardOutput()).trimmed());
  } else if (cancelled_) {
    removeLeftovers();
    message = tr("Export stopped.");
  } else {
    // The player's last line says why (file, line and what was expected).
    const QStringList lines = QString::fromLocal8Bit(errors_).split('\n', Qt::SkipEmptyParts);
    message = lines.isEmpty() ? tr("The export failed.") : lines.back();
  }
  status_->setText(message);
  emit exportFinished(ok, message);
}

}  // namespace lacrima::appsupport
