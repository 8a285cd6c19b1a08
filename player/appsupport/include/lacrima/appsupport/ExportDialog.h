#pragma once
// File > Export in both applications: one dialog for the format (glTF, H.264 video, PNG images
// with optional alpha and tear masks, PLY tear meshes), the output, the image size and camera,
// and the frame range, with progress and cancel. The export runs as a separate lacrima-player
// process (its --export-gltf, --video, --render, --export-tears), so the window never waits for
// it, a crash of the export cannot take the window and its unsaved work with it, and cancelling
// is stopping that process. Progress comes from the process's progress lines on stderr.
#include <QDialog>
#include <QProcess>
#include <QString>
#include <QStringList>

class QCheckBox;
class QComboBox;
class QLabel;
class QLineEdit;
class QProgressBar;
class QPushButton;
class QSpinBox;

namespace lacrima::appsupport {

// What to export: a .fap file or a project on disk (the editor saves its document to a
// temporary first), the head options that go with it (--mesh, --fdp), and its length.
struct ExportSource {
  QString file;
  QString name;  // in the title; empty: the file's name
  QStringList headArguments;
  int frameCount = 1;
  // Where the output goes unless the user says otherwise: this path with the format's extension
  // (crying.glb, crying.mp4) or suffix (crying_frames/, crying_tears/). Empty: beside `file`,
  // named after it; the editor gives its project's path, since `file` is then a temporary.
  QString outputStem;
};

enum class ExportFormat { Gltf, Video, Images, TearMeshes };

class ExportDialog : public QDialog {
  Q_OBJECT

 public:
  // `player`: the lacrima-player to run; by default the one beside this program.
  explicit ExportDialog(ExportSource source, QWidget* parent = nullptr, QString player = {});
  ~ExportDialog() override;

  void setFormat(ExportFormat format);
  // As if the user typed it: a format chosen afterwards no longer changes it.
  void setOutput(const QString& path);
  QString output() const;
  void setFrameRange(int first, int last);
  void setImageSize(const QString& size);  // "WxH"
  void setLayers(bool alpha, bool masks);  // images only
  // The arguments start() gives lacrima-player, or an empty list and the reason in `error`.
  QStringList arguments(QString* error = nullptr) const;
  bool running() const;

 public slots:
  void start();
  // Stops the running export: ends the lacrima-player process (terminated, killed if it has
  // not ended within a second) and removes what a stopped export leaves behind.
  void cancel();
  // Escape and the window's close button stop a running export rather than hide it.
  void reject() override;

 signals:
  // The export ended: `ok` and what it says (the written path, or why not).
  void exportFinished(bool ok, const QString& message);

 private:
  void formatChanged();
  QString defaultOutput() const;
  void readProgress();
  void processEnded(int exitCode, QProcess::ExitStatus status);
  void removeLeftovers();
  void setRunning(bool running);

  ExportSource source_;
  QString player_;
  QComboBox* format_;
  QLineEdit* output_;
  QPushButton* browse_;
  QLineEdit* size_;
  QComboBox* view_;
  QSpinBox* first_;
  QSpinBox* last_;
  QCheckBox* alpha_;
  QCheckBox* masks_;
  QProgressBar* progress_;
  QLabel* status_;
  QPushButton* export_;
  QPushButton* cancel_;
  QProcess* process_ = nullptr;
  qint64 pid_ = 0;  // of the running export: its temporaries are named by it
  QByteArray errors_;
  bool cancelled_ = false;
  bool outputChosen_ = false;  // typed, browsed or set: no longer follows the format
};

}  // namespace lacrima::appsupport
