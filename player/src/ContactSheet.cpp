#include <lacrima/player/ContactSheet.h>

#include <QFont>
#include <QPainter>

#include <algorithm>
#include <cmath>

namespace lacrima::player {

std::vector<int> evenlySpacedFrames(int frames, int count) {
  std::vector<int> picked;
  if (frames <= 0 || count <= 0) return picked;
  if (count == 1 || frames == 1) return {0};
  for (int i = 0; i < count; ++i) {
    const int f =
        static_cast<int>(std::lround(static_cast<double>(i) * (frames - 1) / (count - 1)));
    if (picked.empty() || picked.back() != f) picked.push_back(f);
  }
  return picked;
}

QImage contactSheet(const std::vector<SheetFrame>& frames, const QString& title, int columns,
                    int thumbWidth) {
  if (frames.empty()) return {};
  const QSize source = frames.front().image.size();
  const int thumbHeight =
      std::max(1, static_cast<int>(std::lround(static_cast<double>(thumbWidth) * source.height() /
                                               std::max(1, source.width()))));
  const int gap = 8, label = 26, header = 40;
  const int rows = (static_cast<int>(frames.size()) + columns - 1) / columns;
  QImage sheet(gap + columns * (thumbWidth + gap), header + rows * (thumbHeight + label + gap),
               QImage::Format_RGB32);
  sheet.fill(QColor(24, 24, 28));
  QPainter p(&sheet);
  p.setRenderHint(QPainter::SmoothPixmapTransform);
  p.setRenderHint(QPainter::TextAntialiasing);
  QFont font = p.font();
  font.setPixelSize(20);
  font.setBold(true);
  p.setFont(font);
  p.setPen(QColor(235, 235, 235));
  p.drawText(QRect(gap, 0, sheet.width() - 2 * gap, header), Qt::AlignVCenter | Qt::AlignLeft,
             title);
  font.setPixelSize(15);
  font.setBold(false);
  p.setFont(font);
  for (std::size_t i = 0; i < frames.size(); ++i) {
    const int col = static_cast<int>(i) % columns, row = static_cast<int>(i) / columns;
    const QRect cell(gap + col * (thumbWidth + gap), header + row * (thumbHeight + label + gap),
                     thumbWidth, thumbHeight);
    p.drawImage(cell, frames[i].image);
    p.setPen(QColor(200, 200, 205));
    p.drawText(
        QRect(cell.left(), cell.bottom() + 1, cell.width(), label),
        Qt::AlignVCenter | Qt::AlignLeft,
        QStringLiteral("frame %1  ·  %2 s").arg(frames[i].frame).arg(frames[i].seconds, 0, 'f', 2));
  }
  return sheet;
}

}  // namespace lacrima::player
