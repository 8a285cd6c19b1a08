#pragma once
// The offer to restore unsaved work after a crash, as a bar across the top of the window
// rather than a modal dialog: the editor is usable at once, and the choice stays visible until
// it is made.
#include <QWidget>

class QLabel;
class QPushButton;

namespace lacrima::editor {

class RecoveryBanner : public QWidget {
  Q_OBJECT
 public:
  explicit RecoveryBanner(QWidget* parent = nullptr);
  void setText(const QString& text);
  QPushButton* restoreButton() const { return restore_; }
  QPushButton* discardButton() const { return discard_; }

 signals:
  void restoreRequested();
  void discardRequested();

 protected:
  void paintEvent(QPaintEvent* event) override;

 private:
  QLabel* text_;
  QPushButton* restore_;
  QPushButton* discard_;
};

}  // namespace lacrima::editor
