#include <lacrima/appsupport/WindowShot.h>

#include <lacrima/viewport/FaceViewport.h>

#include <QPainter>

namespace lacrima::appsupport {

QImage grabWindowWithViewports(QWidget& window) {
  QImage shot = window.grab().toImage().convertToFormat(QImage::Format_RGB32);
  // A painter on an image with a device pixel ratio works in logical pixels, so widget
  // geometry is used as it is; the source rectangle takes the frame's every device pixel.
  QPainter painter(&shot);
  for (viewport::FaceViewport* view : window.findChildren<viewport::FaceViewport*>()) {
    if (!view->isVisible()) continue;
    const QImage frame = view->grabFrame();
    if (frame.isNull()) continue;
    painter.drawImage(QRectF(view->mapTo(&window, QPoint(0, 0)), QSizeF(view->size())), frame,
                      QRectF(frame.rect()));
  }
  painter.end();
  return shot;
}

}  // namespace lacrima::appsupport
