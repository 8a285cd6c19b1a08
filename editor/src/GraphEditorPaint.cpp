// GraphEditor's painting: ruler, value axis, curves with their holds, keys and handles, the
// legend and the playhead.
#include <lacrima/editor/GraphEditor.h>

#include "GraphEditorCurves.h"
#include "GraphEditorLayout.h"

#include <lacrima/common/CurveHandles.h>
#include <lacrima/common/FapTable.h>
#include <lacrima/editing/EditorModel.h>
#include <lacrima/editor/EditorTheme.h>
#include <lacrima/editor/TimeAxis.h>

#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <cmath>

namespace lacrima::editor {

using namespace detail;

namespace {

// A colour per channel, the same in every session: hues spread by the golden ratio.
QColor channelColour(int fap) {
  return QColor::fromHsvF(std::fmod(0.07 + fap * 0.6180339887, 1.0), 0.62, 0.96);
}

// The smallest 1, 2, 5 x 10^k at least `minimum`.
double niceStep(double minimum) {
  const double power = std::pow(10.0, std::floor(std::log10(minimum)));
  for (double m : {1.0, 2.0, 5.0, 10.0})
    if (m * power >= minimum) return m * power;
  return 10.0 * power;
}

}  // namespace

void GraphEditor::paintEvent(QPaintEvent*) {
  ensureCurves();
  QPainter p(this);
  p.setRenderHint(QPainter::Antialiasing);
  const QPalette& pal = palette();
  p.fillRect(rect(), pal.color(QPalette::Base));
  const QRectF area = plotArea();

  const KeyframeSequence& keys = model_.document().keys;
  if (!keys.empty()) {
    const double x0 = std::max(area.left(), xOfTime(keys.startTime()));
    const double x1 = std::min(area.right(), xOfTime(keys.endTime()));
    if (x1 > x0)
      p.fillRect(QRectF(x0, area.top(), x1 - x0, area.height()),
                 pal.color(QPalette::AlternateBase).lighter(118));
  }
  paintValueAxis(p);
  paintRuler(p);

  lastPaintPoints_ = 0;
  p.save();
  p.setClipRect(area);
  for (const GraphCurve& curve : curves_) paintCurve(p, curve, channelColour(curve.fap));
  for (const GraphCurve& curve : curves_) paintKeys(p, curve, channelColour(curve.fap));
  p.restore();
  paintLegend(p);

  // Playhead, with its frame number on the ruler.
  const double px = std::round(xOfTime(model_.currentTime())) + 0.5;
  if (px >= area.left()) {
    p.setPen(QPen(theme::playhead(), 1.5));
    p.drawLine(QPointF(px, 0), QPointF(px, height()));
    const QString frameText = QString::number(model_.frameAt(model_.currentTime()));
    const double w = QFontMetrics(font()).horizontalAdvance(frameText) + 10;
    QPainterPath tag;
    tag.addRoundedRect(QRectF(px - w / 2, 2, w, kRulerHeight - 5), 3, 3);
    p.fillPath(tag, theme::playhead());
    p.setPen(Qt::white);
    p.drawText(QRectF(px - w / 2, 2, w, kRulerHeight - 5), Qt::AlignCenter, frameText);
  }

  if (drag_ == Drag::Band) {
    QColor fill = pal.color(QPalette::Highlight);
    fill.setAlphaF(0.2);
    p.fillRect(band_, fill);
    p.setPen(QPen(pal.color(QPalette::Highlight), 1));
    p.drawRect(band_);
  }
}

void GraphEditor::paintRuler(QPainter& p) const {
  const QPalette& pal = palette();
  p.fillRect(QRectF(0, 0, width(), kRulerHeight), pal.color(QPalette::Window).darker(108));
  // Labels at least 70 px apart; frame ticks once frames are 6 px apart.
  static constexpr double kSteps[] = {0.02, 0.05, 0.1, 0.25, 0.5, 1,   2,  5,
                                      10,   15,   30,  60,   120, 300, 600};
  double step = kSteps[std::size(kSteps) - 1];
  for (double s : kSteps) {
    if (s * scale_ >= 70.0) {
      step = s;
      break;
    }
  }
  const double frame = model_.frameDuration();
  const double left = timeAtX(kAxisWidth), right = timeAtX(width());
  if (frame * scale_ >= 6.0) {
    p.setPen(QPen(pal.color(QPalette::WindowText).darker(220), 1));
    for (double f = std::max(0.0, std::floor(left / frame)); f * frame <= right; f += 1.0) {
      const double x = xOfTime(f * frame);
      p.drawLine(QPointF(x, kRulerHeight - 4), QPointF(x, kRulerHeight));
    }
  }
  QColor grid = pal.color(QPalette::Mid);
  grid.setAlphaF(0.6);
  for (double t = std::max(0.0, std::floor(left / step) * step); t <= right + step; t += step) {
    const double x = std::round(xOfTime(t)) + 0.5;
    if (x < kAxisWidth) continue;
    p.setPen(QPen(grid, 1));
    p.drawLine(QPointF(x, kRulerHeight), QPointF(x, height()));
    p.setPen(QPen(pal.color(QPalette::WindowText).darker(130), 1));
    p.drawLine(QPointF(x, kRulerHeight - 8), QPointF(x, kRulerHeight));
    // Seconds, and the frame number when frames are whole at this step.
    QString label = rulerLabel(t, step);
    const double frames = t / frame;
    if (std::abs(frames - std::round(frames)) < 1e-6)
      label += QStringLiteral("  f%1").arg(static_cast<long long>(std::llround(frames)));
    p.drawText(QRectF(x + 3, 0, 90, kRulerHeight - 6), Qt::AlignLeft | Qt::AlignVCenter, label);
  }
}

void GraphEditor::paintValueAxis(QPainter& p) const {
  const QPalette& pal = palette();
  p.fillRect(QRectF(0, kRulerHeight, kAxisWidth, height() - kRulerHeight),
             pal.color(QPalette::Window).darker(104));
  const double step = niceStep(28.0 / vScale_);
  const int decimals = std::clamp(static_cast<int>(-std::floor(std::log10(step))), 0, 6);
  const double bottom = top_ - (height() - kRulerHeight) / vScale_;
  QColor grid = pal.color(QPalette::Mid);
  grid.setAlphaF(0.45);
  const double first = std::floor(bottom / step) * step;
  // At most one label per 28 px, so the loop is bounded by the height.
  for (int i = 0; i < 1000; ++i) {
    const double v = first + i * step;
    if (v > top_) break;
    const double y = std::round(kRulerHeight + (top_ - v) * vScale_) + 0.5;
    if (y < kRulerHeight || y > height()) continue;
    const bool zero = std::abs(v) < step * 1e-6;
    p.setPen(QPen(zero ? pal.color(QPalette::WindowText).darker(180) : grid, 1));
    p.drawLine(QPointF(kAxisWidth, y), QPointF(width(), y));
    p.setPen(pal.color(QPalette::WindowText).darker(130));
    p.drawText(QRectF(2, y - 8, kAxisWidth - 6, 16), Qt::AlignRight | Qt::AlignVCenter,
               QString::number(zero ? 0.0 : v, 'f', decimals));
  }
}

void GraphEditor::paintCurve(QPainter& p, const GraphCurve& curve, const QColor& colour) {
  if (curve.empty()) return;
  const double mid = normalized_ ? curve.mid() : 0.0;
  const double half = normalized_ ? curve.half() : 1.0;
  const auto xOf = [this](double t) { return xOfTime(t); };
  const auto yOf = [&](double v) { return kRulerHeight + (top_ - (v - mid) / half) * vScale_; };
  const double t0 = timeAtX(kAxisWidth), t1 = timeAtX(width());

  // Holds: dashed, so a channel that holds its first or last value is visible as such.
  QColor faint = colour;
  faint.setAlphaF(0.55);
  p.setPen(QPen(faint, 1.0, Qt::DashLine));
  if (t0 < curve.start) {
    const double y = yOf(curve.samples.front());
    p.drawLine(QPointF(kAxisWidth, y), QPointF(xOfTime(curve.start), y));
    lastPaintPoints_ += 2;
  }
  if (t1 > curve.end()) {
    const double y = yOf(curve.samples.back());
    p.drawLine(QPointF(xOfTime(curve.end()), y), QPointF(width(), y));
    lastPaintPoints_ += 2;
  }
  const QPolygonF line = curvePolyline(curve, t0, t1, xOf, yOf, scale_);
  lastPaintPoints_ += static_cast<int>(line.size());
  if (line.size() >= 2) {
    p.setPen(QPen(colour, 1.0));  // width 1: Qt's fast cosmetic stroker
    p.drawPolyline(line);
  }
}

void GraphEditor::paintKeys(QPainter& p, const GraphCurve& curve, const QColor& colour) const {
  const auto& keys = shownKeys().keys();
  const auto timeOf = [&](int k) { return keys[static_cast<std::size_t>(k)].time; };
  const double t0 = timeAtX(kAxisWidth), t1 = timeAtX(width());
  const auto first = std::lower_bound(curve.keys.begin(), curve.keys.end(), t0,
                                      [&](int k, double t) { return timeOf(k) < t; });
  const auto last =
      std::upper_bound(first, curve.keys.end(), t1, [&](double t, int k) { return t < timeOf(k); });
  // Handles of keys just outside the view still reach into it.
  const auto from = first == curve.keys.begin() ? first : first - 1;
  const auto to = last == curve.keys.end() ? last : last + 1;
  // Keys closer than 3 px apart on average: the curve alone says more than a row of dots.
  if ((to - from) * 3 > width()) return;

  QColor handleColour = colour.lighter(130);
  handleColour.setAlphaF(0.8);
  for (auto k = from; k != to; ++k) {
    const std::size_t position = static_cast<std::size_t>(k - curve.keys.begin());
    const QPointF at = keyPosition(curve.fap, *k);
    const bool selected = isShownSelected(curve.fap, timeOf(*k));
    if (showsHandles(curve, position)) {
      const EffectiveHandles handles = effectiveHandles(shownKeys(), curve.fap, *k);
      const QColor c = selected ? theme::keyAccent() : handleColour;
      p.setPen(QPen(c, 1.0));
      for (const editing::HandleSide side : {editing::HandleSide::In, editing::HandleSide::Out}) {
        if (side == editing::HandleSide::In && !handles.hasIn) continue;
        if (side == editing::HandleSide::Out && !handles.hasOut) continue;
        const QPointF end = handlePosition(curve.fap, *k, side);
        p.setBrush(Qt::NoBrush);
        p.drawLine(at, end);
        p.setBrush(c);
        p.drawEllipse(end, kHandleRadius, kHandleRadius);
      }
    }
    p.setPen(QPen(palette().color(QPalette::Base), 1.0));
    p.setBrush(selected ? theme::keyAccent() : palette().color(QPalette::Text));
    const double r = kKeyRadius;
    const QPointF diamond[4] = {
        {at.x(), at.y() - r}, {at.x() + r, at.y()}, {at.x(), at.y() + r}, {at.x() - r, at.y()}};
    p.drawConvexPolygon(diamond, 4);
  }
}

void GraphEditor::paintLegend(QPainter& p) const {
  const QFontMetrics fm(font());
  double y = kRulerHeight + 4;
  for (const GraphCurve& curve : curves_) {
    const FapInfo& info = fapInfo(curve.fap);
    QString text = QStringLiteral("%1 %2").arg(curve.fap).arg(
        QString::fromUtf8(info.name.data(), static_cast<qsizetype>(info.name.size())));
    if (curve.empty()) {
      text += tr("  (not animated)");
    } else if (normalized_) {
      text += QStringLiteral("   %1 … %2").arg(curve.low, 0, 'f', 0).arg(curve.high, 0, 'f', 0);
    }
    const QRectF box(kAxisWidth + 6, y, fm.horizontalAdvance(text) + 18, fm.height() + 2);
    QColor back = palette().color(QPalette::Base);
    back.setAlphaF(0.7);
    p.fillRect(box, back);
    p.fillRect(QRectF(box.left() + 2, box.center().y() - 1, 10, 3), channelColour(curve.fap));
    p.setPen(channelColour(curve.fap));
    p.drawText(box.adjusted(16, 0, 0, 0), Qt::AlignLeft | Qt::AlignVCenter, text);
    y += box.height() + 1;
    if (y > height() - fm.height()) break;
  }
}

}  // namespace lacrima::editor
