#pragma once
// A one-line label that never asks for more width than it gets: its text is cut with "…" to
// fit, and the whole text is in its tooltip. For status lines whose text can hold a path or a
// rig warning, which a QLabel would turn into the window's minimum width.
#include <QFrame>
#include <QString>

namespace lacrima::viewport {

class ElidedLabel : public QFrame {
  Q_OBJECT
 public:
  explicit ElidedLabel(QWidget* parent = nullptr);

  QString text() const { return text_; }
  void setText(const QString& text);
  // The text as painted at the current width (ends in "…" when cut).
  QString shownText() const;
  void setAlignment(Qt::Alignment alignment);

  QSize sizeHint() const override;
  QSize minimumSizeHint() const override;

 protected:
  void paintEvent(QPaintEvent* event) override;

 private:
  QString text_;
  Qt::Alignment alignment_ = Qt::AlignLeft | Qt::AlignVCenter;
};

}  // namespace lacrima::viewport
