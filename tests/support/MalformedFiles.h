#pragma once
// The malformed files every app must refuse through its UI (tests/fixtures/malformed: one file
// per way to be wrong, named after it), and a stand-in for the user at the modal dialogs that
// File ▸ Open shows: the file dialog is given a path and accepted; a message box is read and
// closed.
#include <QApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QFileDialog>
#include <QLineEdit>
#include <QMessageBox>
#include <QStringList>
#include <QTimer>

#include <functional>

namespace lacrima::test {

inline QStringList malformedFiles() {
  const QDir dir(QStringLiteral(LACRIMA_SOURCE_DIR "/tests/fixtures/malformed"));
  QStringList files;
  for (const QString& name : dir.entryList(QDir::Files, QDir::Name)) files << dir.filePath(name);
  return files;
}

// Runs `action` (which opens modal dialogs) while answering them: a file dialog gets `path` and
// is accepted, and the text of every message box is appended to `messages` before it is closed.
// Any other dialog, or a file dialog still open after its answer, is closed after 5 s with a
// note in `messages`, so that a test fails rather than waits for a user who is not there.
inline void answeringDialogs(const QString& path, QStringList& messages,
                             const std::function<void()>& action) {
  QTimer user;
  user.setInterval(10);
  QElapsedTimer waiting;
  QObject::connect(&user, &QTimer::timeout, [&] {
    QWidget* modal = QApplication::activeModalWidget();
    if (!modal) {
      waiting.invalidate();
      return;
    }
    if (!waiting.isValid()) waiting.start();
    if (waiting.elapsed() > 5000) {
      messages << QStringLiteral("still open after 5 s: a %1")
                      .arg(QString::fromLatin1(modal->metaObject()->className()));
      modal->close();
      waiting.invalidate();
    } else if (auto* dialog = qobject_cast<QFileDialog*>(modal)) {
      // Typed into the file name field, as a user would: selectFile() leaves the field alone
      // once it has the focus, and the dialog would then accept whatever it held.
      if (auto* name = dialog->findChild<QLineEdit*>(QStringLiteral("fileNameEdit")))
        name->setText(path);
      else
        dialog->selectFile(path);
      static_cast<QDialog*>(dialog)->accept();  // QFileDialog::accept, as the Open button does
    } else if (auto* box = qobject_cast<QMessageBox*>(modal)) {
      messages << box->text();
      box->accept();
    }
  });
  user.start();
  action();
}

}  // namespace lacrima::test
