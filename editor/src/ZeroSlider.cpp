#include <lacrima/editor/ZeroSlider.h>

#include <QKeyEvent>
#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>
#include <QWheelEvent>

#include <algorithm>
#include <cmath>

namespace lacrima::editor {
namespace {
constexpr double kMargin = 6.0;        // px left and right of the track, room for the handle
constexpr double kZeroMagnet = 0.015;  // fraction of the range that sticks to 0
constexpr double kHandleGrab = 6.0;    // px either side of the handle that grab it in place

double gainFor(Qt::KeyboardModifiers modifiers) {
  if (modifiers & Qt::ShiftModifier) return ZeroSlider::kFineGain;
  if (modifiers & Qt::ControlModifier) return ZeroSlider::kCoarseGain;
  return 1.0;
}
}  // namespace

ZeroSlider::ZeroSlider(int minimum, int maximum, int step, QColor colour, QWidget* parent)
    : QWidget(parent),
      min_(minimum),
      max_(std::max(maximum, minimum + 1)),
      step_(std::max(1, step)),
      colour_(colour) {
  setFocusPolicy(Qt::ClickFocus);
  setAttribute(Qt::WA_OpaquePaintEvent, false);
  setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
  setCursor(Qt::PointingHandCursor);
}

void ZeroSlider::setValue(int value) {
  if (value == value_) return;
  value_ = value;
  update();
}

void ZeroSlider::setEmphasis(bool on) {
  if (on == emphasis_) return;
  emphasis_ = on;
  update();
}

double ZeroSlider::xOf(double value) const {
  const double clamped = std::clamp(value, double(min_), double(max_));
  const double span = width() - 2 * kMargin;
  return kMargin + (clamped - min_) / (max_ - min_) * span;
}

int ZeroSlider::valueAt(double x) const {
  const double span = std::max(1.0, width() - 2 * kMargin);
  const double v = min_ + (x - kMargin) / span * (max_ - min_);
  return magnetised(v, 1.0);
}

int ZeroSlider::magnetised(double value, double gain) const {
  int rounded = static_cast<int>(std::lround(std::clamp(value, double(min_), double(max_))));
  const bool fine = gain < 1.0;
  if (!fine && std::abs(rounded) <= kZeroMagnet * (max_ - min_) && min_ <= 0 && max_ >= 0)
    rounded = 0;
  return rounded;
}

void ZeroSlider::edit(int value) {
  value = std::clamp(value, min_, max_);
  if (value == value_) return;
  value_ = value;
  update();
  emit valueEdited(value_);
}

void ZeroSlider::paintEvent(QPaintEvent*) {
  QPainter p(this);
  p.setRenderHint(QPainter::Antialiasing);
  const double cy = height() / 2.0;
  const double left = kMargin;
  const double right = width() - kMargin;
  const QColor trackColour = palette().color(QPalette::Mid);

  QPainterPath track;
  track.addRoundedRect(QRectF(left, cy - 2.5, right - left, 5), 2.5, 2.5);
  p.fillPath(track, trackColour);

  const double zeroX = xOf(0.0);
  const double valueX = xOf(value_);
  QColor fill = colour_;
  if (!emphasis_) fill.setAlphaF(0.55);
  if (value_ != 0)
    p.fillRect(QRectF(std::min(zeroX, valueX), cy - 2.5, std::abs(valueX - zeroX), 5), fill);

  // The neutral mark, only for ranges that straddle 0.
  if (min_ < 0 && max_ > 0) {
    p.setPen(QPen(palette().color(QPalette::WindowText).darker(150), 1.0));
    p.drawLine(QPointF(zeroX, cy - 6), QPointF(zeroX, cy + 6));
  }

  const bool over = value_ > max_ || value_ < min_;
  const QColor handle =
      hasFocus() || dragging_ ? QColor(Qt::white) : palette().color(QPalette::WindowText);
  p.setPen(Qt::NoPen);
  p.setBrush(handle);
  if (over) {
    // An arrow pointing out of the range: the value is beyond what the track shows.
    const double dir = value_ > max_ ? 1.0 : -1.0;
    QPainterPath arrow;
    arrow.moveTo(valueX + dir * 5, cy);
    arrow.lineTo(valueX - dir * 3, cy - 6);
    arrow.lineTo(valueX - dir * 3, cy + 6);
    arrow.closeSubpath();
    p.drawPath(arrow);
  } else {
    p.drawRoundedRect(QRectF(valueX - 3, cy - 7, 6, 14), 2, 2);
  }
}

void ZeroSlider::mousePressEvent(QMouseEvent* event) {
  if (event->button() != Qt::LeftButton) return QWidget::mousePressEvent(event);
  dragging_ = true;
  const double x = event->position().x();
  emit dragStarted();
  gain_ = gainFor(event->modifiers());
  // A click on the track sets the value there; a press on the handle (or any fine press) only
  // grabs it, so a drag starts from the value as it is.
  const bool onHandle = std::abs(x - xOf(value_)) <= kHandleGrab;
  if (!onHandle && gain_ >= 1.0) edit(valueAt(x));
  grabX_ = x;
  grabValue_ = dragValue_ = value_;
  update();
}

void ZeroSlider::mouseMoveEvent(QMouseEvent* event) {
  if (!dragging_) return;
  const double x = event->position().x();
  const double gain = gainFor(event->modifiers());
  if (gain != gain_) {  // Shift or Ctrl pressed or released mid-drag: go on from here
    gain_ = gain;
    grabX_ = x;
    grabValue_ = dragValue_;
  }
  const double perPixel = double(max_ - min_) / kPixelsPerRange * gain_;
  dragValue_ = grabValue_ + (x - grabX_) * perPixel;
  // Past an end the value waits there, and turning back moves it at once.
  if (dragValue_ < min_ || dragValue_ > max_) {
    dragValue_ = std::clamp(dragValue_, double(min_), double(max_));
    grabX_ = x;
    grabValue_ = dragValue_;
  }
  edit(magnetised(dragValue_, gain_));
}

void ZeroSlider::mouseReleaseEvent(QMouseEvent* event) {
  if (!dragging_ || event->button() != Qt::LeftButton) return;
  dragging_ = false;
  update();
  emit dragFinished();
}

void ZeroSlider::mouseDoubleClickEvent(QMouseEvent* event) {
  if (event->button() == Qt::LeftButton) emit resetRequested();
}

void ZeroSlider::keyPressEvent(QKeyEvent* event) {
  const int page = std::max(step_, (max_ - min_) / 10);
  switch (event->key()) {
    case Qt::Key_Left:
    case Qt::Key_Down:
      edit(value_ - step_);
      break;
    case Qt::Key_Right:
    case Qt::Key_Up:
      edit(value_ + step_);
      break;
    case Qt::Key_PageDown:
      edit(value_ - page);
      break;
    case Qt::Key_PageUp:
      edit(value_ + page);
      break;
    case Qt::Key_0:
      edit(0);
      break;
    default:
      QWidget::keyPressEvent(event);
      return;
  }
  event->accept();
}

bool ZeroSlider::event(QEvent* event) {
  if (event->type() == QEvent::ShortcutOverride) {
    const auto* key = static_cast<QKeyEvent*>(event);
    switch (key->key()) {
      case Qt::Key_Left:
      case Qt::Key_Right:
      case Qt::Key_Up:
      case Qt::Key_Down:
      case Qt::Key_PageUp:
      case Qt::Key_PageDown:
      case Qt::Key_0:
        if (key->modifiers() == Qt::NoModifier || key->modifiers() == Qt::KeypadModifier) {
          event->accept();
          return true;
        }
        break;
      default:
        break;
    }
  }
  return QWidget::event(event);
}

void ZeroSlider::wheelEvent(QWheelEvent* event) {
  if (!hasFocus()) {
    event->ignore();  // let the list scroll
    return;
  }
  const int notches = event->angleDelta().y() / 120;
  if (notches != 0) edit(value_ + notches * step_);
  event->accept();
}

}  // namespace lacrima::editor
