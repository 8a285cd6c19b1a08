#pragma once
// "⚠ 10 warnings": a button that says how many warnings there are (a rig's, a file's) and,
// clicked, lists every one in full in a window of its own, where long lines wrap and can be
// copied. Hidden while there are none. The editor's preview and the player show one, so a
// warning is read in the window, not only in a tooltip or on stderr.
#include <QStringList>
#include <QToolButton>

class QDialog;
class QPlainTextEdit;

namespace lacrima::viewport {

class WarningsButton : public QToolButton {
  Q_OBJECT
 public:
  explicit WarningsButton(QWidget* parent = nullptr);

  // `source` names what the warnings are about in the list's title ("ict.obj's rig").
  void setWarnings(const QStringList& warnings, const QString& source);
  QStringList warnings() const { return warnings_; }
  // Shows the list (what a click does); returns its window.
  QDialog* showList();
  // The list's window once shown, else null.
  QDialog* list() const { return list_; }

 private:
  void fillList();

  QStringList warnings_;
  QString source_;
  QDialog* list_ = nullptr;
  QPlainTextEdit* text_ = nullptr;
};

}  // namespace lacrima::viewport
