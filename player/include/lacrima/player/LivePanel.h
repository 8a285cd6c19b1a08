#pragma once
// The Live box of the player's side panel, shown while listening: each input with what it has
// received and every problem counted (malformed, over-long lines, floods, disconnects, peers
// from other machines), and the tear counts the player adds to streams that carry none (a
// phone's blendshapes cannot).
#include <QWidget>

class QLabel;
class QSpinBox;

namespace lacrima::player {

class LivePanel : public QWidget {
  Q_OBJECT
 public:
  explicit LivePanel(QWidget* parent = nullptr);

  void showStatus(const QString& text);
  QString statusText() const;
  int tearsLeft() const;
  int tearsRight() const;
  void setTears(int left, int right);

 signals:
  void tearsEdited(int left, int right);

 private:
  QLabel* status_;
  QSpinBox *left_, *right_;
};

}  // namespace lacrima::player
