#include <lacrima/editor/KeyToggle.h>

#include <lacrima/editor/EditorTheme.h>

#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>

namespace lacrima::editor {

KeyToggle::KeyToggle(QWidget* parent) : QWidget(parent) {
  setFixedSize(14, 18);
  setCursor(Qt::PointingHandCursor);
  setToolTip(tr("Key this channel at the current time (click again to remove it from the key)"));
}

void KeyToggle::setState(State state) {
  if (state == state_) return;
  state_ = state;
  update();
}

void KeyToggle::paintEvent(QPaintEvent*) {
  QPainter p(this);
  p.setRenderHint(QPainter::Antialiasing);
  const QPointF c(width() / 2.0, height() / 2.0);
  const double r = 4.5;
  QPainterPath diamond;
  diamond.moveTo(c.x(), c.y() - r);
  diamond.lineTo(c.x() + r, c.y());
  diamond.lineTo(c.x(), c.y() + r);
  diamond.lineTo(c.x() - r, c.y());
  diamond.closeSubpath();
  const QColor accent = theme::keyAccent();
  switch (state_) {
    case State::Keyed:
      p.fillPath(diamond, accent);
      break;
    case State::Animated:
      p.setPen(QPen(accent, 1.3));
      p.drawPath(diamond);
      break;
    case State::Unanimated: {
      QColor faint = palette().color(QPalette::WindowText);
      faint.setAlphaF(0.25);
      p.setPen(QPen(faint, 1.0));
      p.drawPath(diamond);
      break;
    }
  }
}

void KeyToggle::mousePressEvent(QMouseEvent* event) {
  if (event->button() == Qt::LeftButton) emit clicked();
}

}  // namespace lacrima::editor
