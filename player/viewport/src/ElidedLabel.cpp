#include <lacrima/viewport/ElidedLabel.h>

#include <QPainter>
#include <QStyle>

#include <algorithm>

namespace lacrima::viewport {
namespace {
// Wide enough for "…" and a word; anything more is up to the layout.
constexpr int kMinimumWidth = 48;
}  // namespace

ElidedLabel::ElidedLabel(QWidget* parent) : QFrame(parent) {
  setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
}

void ElidedLabel::setText(const QString& text) {
  if (text == text_) return;
  text_ = text;
  setToolTip(text);
  updateGeometry();
  update();
}

QString ElidedLabel::shownText() const {
  const int room = std::max(0, contentsRect().width());
  return fontMetrics().elidedText(text_, Qt::ElideRight, room);
}

void ElidedLabel::setAlignment(Qt::Alignment alignment) {
  alignment_ = alignment;
  update();
}

QSize ElidedLabel::sizeHint() const {
  const QMargins m = contentsMargins();
  return {fontMetrics().horizontalAdvance(text_) + m.left() + m.right(),
          fontMetrics().height() + m.top() + m.bottom()};
}

QSize ElidedLabel::minimumSizeHint() const {
  const QMargins m = contentsMargins();
  return {std::min(sizeHint().width(), kMinimumWidth + m.left() + m.right()),
          fontMetrics().height() + m.top() + m.bottom()};
}

void ElidedLabel::paintEvent(QPaintEvent* event) {
  QFrame::paintEvent(event);
  QPainter p(this);
  p.setPen(
      palette().color(isEnabled() ? QPalette::Active : QPalette::Disabled, QPalette::WindowText));
  p.drawText(contentsRect(), alignment_.toInt(), shownText());
}

}  // namespace lacrima::viewport
