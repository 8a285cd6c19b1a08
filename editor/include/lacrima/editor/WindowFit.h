#pragma once
// A top-level window's size and place kept on the screen it opens on: a saved geometry from a
// larger screen (or from a window once widened by its contents) must not open a window whose
// edges or panels lie off-screen.
#include <QRect>
#include <QSize>

class QWidget;

namespace lacrima::editor {

// `wanted` shrunk to fit `room` (at most its size) and moved inside it; `frame` is what the
// window manager adds around the window's contents (left, top, right and bottom together).
QRect fitRect(const QRect& wanted, const QRect& room, const QSize& frame = QSize(0, 0));

// Fits `window` to the available area of the screen under its centre (else its own screen).
void fitToScreen(QWidget& window);

}  // namespace lacrima::editor
