#pragma once
// The picture of a whole window as the user sees it. QWidget::grab() cannot read OpenGL
// windows, so every visible FaceViewport inside is shown black in it: each one's own rendered
// frame is painted over its place.
#include <QImage>

class QWidget;

namespace lacrima::appsupport {

// In device pixels: the image carries the window's device pixel ratio, and the viewports'
// frames (rendered at their device size) land on their logical place whatever that ratio is.
QImage grabWindowWithViewports(QWidget& window);

}  // namespace lacrima::appsupport
