#include <lacrima/editor/WindowFit.h>

#include <QGuiApplication>
#include <QScreen>
#include <QWidget>

#include <algorithm>

namespace lacrima::editor {

QRect fitRect(const QRect& wanted, const QRect& room, const QSize& frame) {
  const QSize margins = frame.expandedTo(QSize(0, 0));  // an unknown frame adds nothing
  const QSize most = (room.size() - margins).expandedTo(QSize(1, 1));
  QRect fitted(wanted.topLeft(), wanted.size().boundedTo(most));
  const int right = room.right() - margins.width() - fitted.width() + 1;
  const int bottom = room.bottom() - margins.height() - fitted.height() + 1;
  fitted.moveTo(std::clamp(fitted.left(), room.left(), std::max(room.left(), right)),
                std::clamp(fitted.top(), room.top(), std::max(room.top(), bottom)));
  return fitted;
}

void fitToScreen(QWidget& window) {
  QScreen* screen = QGuiApplication::screenAt(window.geometry().center());
  if (!screen) screen = window.screen();
  if (!screen) return;
  // Before the window is first shown its frame is not known (frameGeometry() equals geometry()).
  const QSize frame = window.frameGeometry().size() - window.geometry().size();
  const QRect fitted = fitRect(window.geometry(), screen->availableGeometry(), frame);
  if (fitted.size() != window.size()) window.resize(fitted.size());
  // move() places the frame, whose corner lies this far from the contents'.
  const QPoint frameOffset = window.geometry().topLeft() - window.pos();
  if (fitted.topLeft() != window.geometry().topLeft()) window.move(fitted.topLeft() - frameOffset);
}

}  // namespace lacrima::editor
