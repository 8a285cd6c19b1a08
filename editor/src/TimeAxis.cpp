#include <lacrima/editor/TimeAxis.h>

#include <lacrima/editor/EditorTheme.h>

#include <QFontMetrics>
#include <QPainter>
#include <QPainterPath>
#include <QPalette>
#include <QPoint>

#include <algorithm>
#include <cmath>
#include <iterator>

namespace lacrima::editor {
QString rulerLabel(double seconds, double step) {
  if (seconds >= 60.0 && step >= 1.0) {
    const int s = static_cast<int>(std::lround(seconds));
    return QStringLiteral("%1:%2").arg(s / 60).arg(s % 60, 2, 10, QLatin1Char('0'));
  }
  // As many decimals as the step needs: quarter seconds read 0.25 and 0.75, not 0.3 and 0.8.
  int decimals = 0;
  while (decimals < 3 && std::abs(step * std::pow(10.0, decimals) -
                                  std::round(step * std::pow(10.0, decimals))) > 1e-9)
    ++decimals;
  return QString::number(seconds, 'f', decimals) + QStringLiteral("s");
}

void TimeAxis::set(double startSeconds, double pixelsPerSecond) {
  if (!std::isfinite(pixelsPerSecond)) pixelsPerSecond = scale_;
  if (!std::isfinite(startSeconds)) startSeconds = start_;
  scale_ = std::clamp(pixelsPerSecond, kMinScale, kMaxScale);
  start_ = std::max(-40.0 / scale_, startSeconds);
}

void TimeAxis::fit(double endSeconds, double width) {
  const double end = std::max(endSeconds, 2.0);
  const double usable = std::max(100.0, width - 40.0);
  set(-20.0 / (usable / end), usable / end);
}

bool TimeAxis::follow(double seconds, double width) {
  const double x = xOf(seconds);
  if (x >= 0 && x <= width - 10) return false;
  set(seconds - 0.1 * width / scale_, scale_);
  return true;
}

void TimeAxis::wheel(const QPoint& angleDelta, bool pan, double x) {
  if (pan || std::abs(angleDelta.x()) > std::abs(angleDelta.y())) {
    const int d = angleDelta.x() != 0 ? angleDelta.x() : angleDelta.y();
    set(start_ - d / 120.0 * 60.0 / scale_, scale_);
    return;
  }
  const double anchor = timeAt(x);
  const double factor = std::pow(1.15, angleDelta.y() / 120.0);
  const double scale = std::clamp(scale_ * factor, kMinScale, kMaxScale);
  set(anchor - x / scale, scale);
}

void paintTimeRuler(QPainter& p, const TimeAxis& axis, const QRectF& area, double gridBottom,
                    double frameSeconds, const QPalette& palette, const QFont& font) {
  const double left = area.left();
  const double width = area.width();
  const double bottom = area.bottom();
  const auto xOf = [&](double t) { return left + axis.xOf(t); };
  p.fillRect(area, palette.color(QPalette::Window).darker(108));
  static constexpr double kSteps[] = {0.05, 0.1, 0.25, 0.5, 1, 2, 5, 10, 15, 30, 60, 120, 300, 600};
  double step = kSteps[std::size(kSteps) - 1];
  for (double s : kSteps) {
    if (s * axis.scale() >= 70.0) {
      step = s;
      break;
    }
  }
  const double t0 = std::max(0.0, std::floor(axis.timeAt(0) / step) * step);
  const double t1 = axis.timeAt(width);
  QColor grid = palette.color(QPalette::Mid);
  grid.setAlphaF(0.6);
  // Frame ticks when frames are far enough apart to see.
  if (frameSeconds * axis.scale() >= 6.0) {
    p.setPen(QPen(palette.color(QPalette::WindowText).darker(220), 1));
    const long long first =
        static_cast<long long>(std::max(0.0, std::floor(axis.timeAt(0) / frameSeconds)));
    for (long long f = first;; ++f) {
      const double x = xOf(f * frameSeconds);
      if (x > left + width) break;
      p.drawLine(QPointF(x, bottom - 4), QPointF(x, bottom));
    }
  }
  p.setFont(font);
  for (double t = t0; t <= t1 + step; t += step) {
    const double x = std::round(xOf(t)) + 0.5;
    p.setPen(QPen(grid, 1));
    p.drawLine(QPointF(x, bottom), QPointF(x, gridBottom));
    p.setPen(QPen(palette.color(QPalette::WindowText).darker(130), 1));
    p.drawLine(QPointF(x, bottom - 8), QPointF(x, bottom));
    p.drawText(QRectF(x + 3, area.top(), 80, area.height() - 6), Qt::AlignLeft | Qt::AlignVCenter,
               rulerLabel(t, step));
    // Half steps, unlabelled.
    const double hx = std::round(xOf(t + step / 2)) + 0.5;
    p.drawLine(QPointF(hx, bottom - 5), QPointF(hx, bottom));
  }
}

void paintPlayhead(QPainter& p, const TimeAxis& axis, double seconds, int frame, double left,
                   double rulerHeight, double bottom, const QFont& font) {
  const double px = std::round(left + axis.xOf(seconds)) + 0.5;
  p.setPen(QPen(theme::playhead(), 1.5));
  p.drawLine(QPointF(px, 0), QPointF(px, bottom));
  const QString frameText = QString::number(frame);
  const QFontMetrics fm(font);
  const double w = fm.horizontalAdvance(frameText) + 10;
  QPainterPath tag;
  const QRectF box(px - w / 2, 2, w, rulerHeight - 5);
  tag.addRoundedRect(box, 3, 3);
  p.fillPath(tag, theme::playhead());
  p.setPen(Qt::white);
  p.setFont(font);
  p.drawText(box, Qt::AlignCenter, frameText);
}

}  // namespace lacrima::editor
