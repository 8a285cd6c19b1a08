// DopeSheetView's painting: row backgrounds, the ruler and its grid, holds, marks, the names
// column and the playhead. Only the rows and keys in view are drawn, and marks falling on one
// pixel column of a row are drawn once, so a long imported file costs what its view shows.
#include <lacrima/editor/DopeSheetView.h>

#include "ChannelText.h"

#include <lacrima/common/FapTable.h>
#include <lacrima/editor/EditorTheme.h>

#include <QPainter>
#include <QScrollBar>

#include <algorithm>
#include <cmath>
#include <limits>

namespace lacrima::editor {
namespace {

// A held value as the animator reads it: codes and particle counts whole, FAP units to 0.1.
QString heldValueText(int fap, float value) {
  if (isHighLevelFap(fap) || isTearChannel(fap)) return QString::number(std::lround(value));
  return QString::number(static_cast<double>(value), 'g', 6);
}

QColor withAlpha(QColor colour, double alpha) {
  colour.setAlphaF(static_cast<float>(alpha));
  return colour;
}

}  // namespace

void DopeSheetView::paintEvent(QPaintEvent*) {
  QPainter p(this);
  p.setRenderHint(QPainter::Antialiasing);
  const QPalette& pal = palette();
  p.fillRect(rect(), pal.color(QPalette::Base));
  const double right = kNamesWidth + keysWidth();
  const QRectF keysArea(kNamesWidth, kRulerHeight, keysWidth(), height() - kRulerHeight);

  const int firstRow = std::max(0, rowAtY(kRulerHeight));
  int lastRow = rowAtY(height() - 1.0);
  if (lastRow < 0) lastRow = static_cast<int>(rows_.size()) - 1;

  // Row backgrounds: the summary and the groups darker than the channels.
  for (int row = firstRow; row <= lastRow; ++row) {
    const DopeSheetRow& r = rows_[static_cast<std::size_t>(row)];
    QColor background = pal.color(row % 2 ? QPalette::Base : QPalette::AlternateBase);
    if (r.kind == DopeSheetRow::Kind::Summary) background = pal.color(QPalette::Window).darker(118);
    if (r.kind == DopeSheetRow::Kind::Group) background = pal.color(QPalette::Window).darker(106);
    p.fillRect(QRectF(kNamesWidth, rowRect(row).top(), keysWidth(), kRowHeight), background);
  }
  // The animated span, from the first key to the last, as on the timeline.
  const auto& keys = model_.document().keys;
  if (!keys.empty()) {
    const double x0 = std::max(kNamesWidth, xOfTime(keys.startTime()));
    const double x1 = std::min(right, xOfTime(keys.endTime()));
    if (x1 >= x0)
      p.fillRect(QRectF(x0, kRulerHeight, std::max(1.0, x1 - x0), height() - kRulerHeight),
                 withAlpha(pal.color(QPalette::AlternateBase).lighter(130), 0.35));
  }

  p.save();
  p.setClipRect(QRectF(kNamesWidth, 0, keysWidth(), height()));
  paintTimeRuler(p, axis_, QRectF(kNamesWidth, 0, keysWidth(), kRulerHeight), height(),
                 model_.frameDuration(), pal, font());
  p.setClipRect(keysArea);
  for (int row = firstRow; row <= lastRow; ++row) paintRow(p, row);
  p.restore();

  paintNames(p, firstRow, lastRow);

  p.save();
  p.setClipRect(QRectF(kNamesWidth, 0, keysWidth(), height()));
  paintPlayhead(p, axis_, model_.currentTime(), model_.frameAt(model_.currentTime()), kNamesWidth,
                kRulerHeight, height(), font());
  if (drag_ == Drag::Band) {
    p.fillRect(band_, withAlpha(pal.color(QPalette::Highlight), 0.2));
    p.setPen(QPen(pal.color(QPalette::Highlight), 1));
    p.setBrush(Qt::NoBrush);
    p.drawRect(band_);
  }
  p.restore();

  if (rows_.size() <= 1) {
    p.setPen(pal.color(QPalette::PlaceholderText));
    p.drawText(keysArea.adjusted(0, kRowHeight, 0, 0), Qt::AlignHCenter | Qt::AlignTop,
               options_.onlyAnimated
                   ? tr("No animated channel matches — key a channel, or show all channels")
                   : tr("No channel matches the filter"));
  }
}

void DopeSheetView::paintRow(QPainter& p, int row) {
  const DopeSheetRow& r = rows_[static_cast<std::size_t>(row)];
  const double cy = rowRect(row).center().y();
  if (r.kind == DopeSheetRow::Kind::Channel) paintHolds(p, r, cy);

  const auto& keys = model_.document().keys.keys();
  const auto timeOf = [&](int k) { return keys[static_cast<std::size_t>(k)].time; };
  // While dragging, selected marks are drawn `ghost` seconds away: look that much further.
  const double ghost = drag_ == Drag::Move ? ghostFrames_ * model_.frameDuration() : 0.0;
  const double t0 = timeAtX(kNamesWidth - 2 * kMarkRadius) - std::max(0.0, ghost);
  const double t1 = timeAtX(kNamesWidth + keysWidth() + 2 * kMarkRadius) - std::min(0.0, ghost);
  const auto first = std::lower_bound(r.keys.begin(), r.keys.end(), t0,
                                      [&](int k, double v) { return timeOf(k) < v; });
  const auto last =
      std::upper_bound(first, r.keys.end(), t1, [&](double v, int k) { return v < timeOf(k); });
  // Marks closer than a few pixels (a long imported file in view) are drawn as ticks, one per
  // pixel column, as the timeline does: shapes there would only overlap.
  const bool dense = (last - first) * 4 > keysWidth();
  if (dense) p.setRenderHint(QPainter::Antialiasing, false);
  int lastPixel = std::numeric_limits<int>::min();
  bool lastSelected = false;
  for (auto it = first; it != last; ++it) {
    const Keyframe& key = keys[static_cast<std::size_t>(*it)];
    // Not dragging, a pixel column already holding a selected mark needs no lookup.
    if (ghost == 0.0 && static_cast<int>(xOfTime(key.time)) == lastPixel && lastSelected) continue;
    const bool selected = isMarkSelected(row, *it);
    const double x = xOfTime(selected ? key.time + ghost : key.time);
    const int pixel = static_cast<int>(x);
    // One mark per pixel column (a selected one wins over an idle one).
    if (pixel == lastPixel && (selected == lastSelected || !selected)) continue;
    lastPixel = pixel;
    lastSelected = selected;
    if (dense) {
      p.setPen(selected ? theme::keyAccent() : theme::keyIdle());
      p.drawLine(QPointF(pixel + 0.5, cy - kMarkRadius), QPointF(pixel + 0.5, cy + kMarkRadius));
      continue;
    }
    if (selected && ghost != 0.0) {
      // Where it was, faintly, while dragging.
      p.setPen(Qt::NoPen);
      p.setBrush(withAlpha(theme::keyAccent(), 0.25));
      p.drawEllipse(QPointF(xOfTime(key.time), cy), kMarkRadius - 1, kMarkRadius - 1);
    }
    paintMark(p, QPointF(x, cy), r, key, selected);
  }
  p.setRenderHint(QPainter::Antialiasing, true);
}

void DopeSheetView::paintHolds(QPainter& p, const DopeSheetRow& row, double cy) {
  if (row.keys.empty()) return;
  const auto& keys = model_.document().keys.keys();
  const int fap = row.fap;
  const QColor colour = theme::groupColour(row.group);
  const double barHeight = 6.0;
  const auto bar = [&](double x0, double x1, const QColor& c) {
    p.fillRect(QRectF(x0, cy - barHeight / 2, std::max(0.0, x1 - x0), barHeight), c);
  };
  const auto at = [&](std::size_t i) -> const Keyframe& {
    return keys[static_cast<std::size_t>(row.keys[i])];
  };
  const double t0 = timeAtX(kNamesWidth);
  const double t1 = timeAtX(kNamesWidth + keysWidth());

  // Holds between keys: equal values, a constant segment, or codes (FAP 1/2 never blend).
  const auto firstInView =
      std::lower_bound(row.keys.begin(), row.keys.end(), t0,
                       [&](int k, double v) { return keys[static_cast<std::size_t>(k)].time < v; });
  std::size_t i = static_cast<std::size_t>(
      std::max<std::ptrdiff_t>(0, std::distance(row.keys.begin(), firstInView) - 1));
  // Consecutive holds are one bar (a long stretch at 0 in an imported file is one rectangle,
  // not one per frame).
  const QColor solid = withAlpha(colour, 0.55);
  double runStart = 0.0;
  bool inRun = false;
  for (; i + 1 < row.keys.size() && at(i).time <= t1; ++i) {
    const Keyframe& a = at(i);
    const Keyframe& b = at(i + 1);
    const bool holds = a.value(fap) == b.value(fap) ||
                       a.shape(fap).interpolation == Interpolation::Constant || isHighLevelFap(fap);
    if (holds && !inRun) {
      runStart = a.time;
      inRun = true;
    } else if (!holds && inRun) {
      bar(xOfTime(runStart), xOfTime(a.time), solid);
      inRun = false;
    }
  }
  if (inRun) bar(xOfTime(runStart), xOfTime(at(i).time), solid);

  // Before the first key and after the last the channel holds that key's value: faintly, with
  // the value, so nobody is surprised by a value at 0 s that was keyed later.
  const Keyframe& first = at(0);
  const Keyframe& last = at(row.keys.size() - 1);
  const QColor faint = withAlpha(colour, 0.18);
  const double start = std::max(kNamesWidth, xOfTime(0.0));
  const double end = kNamesWidth + keysWidth();
  const double firstX = xOfTime(first.time);
  const double lastX = xOfTime(last.time);
  QFont small = font();
  if (small.pointSizeF() > 0) small.setPointSizeF(small.pointSizeF() * 0.85);
  p.setFont(small);
  p.setPen(withAlpha(colour, 0.6));
  if (firstX > start) {
    bar(start, firstX, faint);
    if (firstX - start > 48)
      p.drawText(QRectF(firstX - 8 - 80, cy - kRowHeight / 2, 80, kRowHeight),
                 Qt::AlignRight | Qt::AlignVCenter, heldValueText(fap, first.value(fap)));
  }
  if (lastX < end) {
    bar(lastX, end, faint);
    if (end - lastX > 48)
      p.drawText(QRectF(lastX + 8, cy - kRowHeight / 2, 80, kRowHeight),
                 Qt::AlignLeft | Qt::AlignVCenter, heldValueText(fap, last.value(fap)));
  }
  p.setFont(font());
}

void DopeSheetView::paintMark(QPainter& p, QPointF c, const DopeSheetRow& row, const Keyframe& key,
                              bool selected) {
  const bool atPlayhead = std::abs(key.time - model_.currentTime()) < editing::kSameKeyTime;
  p.setPen(QPen(atPlayhead ? QColor(Qt::white) : palette().color(QPalette::Base),
                atPlayhead ? 1.6 : 1.0));
  p.setBrush(selected ? theme::keyAccent() : theme::keyIdle());
  const double x = c.x();
  const double y = c.y();
  double r = kMarkRadius;
  const auto diamond = [&] {
    const QPointF points[4] = {{x, y - r}, {x + r, y}, {x, y + r}, {x - r, y}};
    p.drawConvexPolygon(points, 4);
  };
  if (row.kind != DopeSheetRow::Kind::Channel) {
    if (row.kind == DopeSheetRow::Kind::Summary) r += 0.5;
    diamond();
    return;
  }
  switch (key.shape(row.fap).interpolation) {
    case Interpolation::Linear:
      diamond();
      break;
    case Interpolation::Smooth:
      p.drawEllipse(c, r - 0.5, r - 0.5);
      break;
    case Interpolation::Constant:
      p.drawRect(QRectF(x - r + 1, y - r + 1, 2 * r - 2, 2 * r - 2));
      break;
    case Interpolation::Bezier:
      // A diamond on a handle line: the key has tangents.
      p.save();
      p.setPen(QPen(selected ? theme::keyAccent() : theme::keyIdle(), 1.0));
      p.drawLine(QPointF(x - r - 3, y), QPointF(x + r + 3, y));
      p.restore();
      diamond();
      break;
  }
}

void DopeSheetView::paintNames(QPainter& p, int firstRow, int lastRow) {
  const QPalette& pal = palette();
  p.fillRect(QRectF(0, 0, kNamesWidth, height()), pal.color(QPalette::Window));
  p.setClipRect(QRectF(0, kRulerHeight, kNamesWidth, height() - kRulerHeight));
  const ChannelMask& chosen = model_.selectedChannels();
  QFont bold = font();
  bold.setBold(true);
  for (int row = firstRow; row <= lastRow; ++row) {
    const DopeSheetRow& r = rows_[static_cast<std::size_t>(row)];
    const QRectF cell(0, rowRect(row).top(), kNamesWidth, kRowHeight);
    QColor background = pal.color(QPalette::Window).darker(row % 2 ? 104 : 100);
    if (r.kind == DopeSheetRow::Kind::Summary) background = pal.color(QPalette::Window).darker(125);
    if (r.kind == DopeSheetRow::Kind::Group) background = pal.color(QPalette::Window).darker(112);
    p.fillRect(cell, background);
    if ((r.channels & chosen).any() && (r.channels & ~chosen).none())
      p.fillRect(cell, withAlpha(pal.color(QPalette::Highlight), 0.45));
    p.setPen(pal.color(QPalette::WindowText));
    switch (r.kind) {
      case DopeSheetRow::Kind::Summary:
        p.setFont(bold);
        p.drawText(cell.adjusted(8, 0, -4, 0), Qt::AlignVCenter | Qt::AlignLeft, tr("Summary"));
        p.setFont(font());
        p.drawText(cell.adjusted(8, 0, -6, 0), Qt::AlignVCenter | Qt::AlignRight,
                   tr("%n channel(s)", nullptr, static_cast<int>(r.channels.count())));
        break;
      case DopeSheetRow::Kind::Group: {
        p.fillRect(QRectF(0, cell.top() + 2, 3, kRowHeight - 4), theme::groupColour(r.group));
        const bool folded = isGroupFolded(r.group);
        const double cx = 12;
        const double cy = cell.center().y();
        QPolygonF arrow;
        if (folded)
          arrow << QPointF(cx - 2, cy - 4) << QPointF(cx - 2, cy + 4) << QPointF(cx + 3, cy);
        else
          arrow << QPointF(cx - 4, cy - 2) << QPointF(cx + 4, cy - 2) << QPointF(cx, cy + 3);
        p.setPen(Qt::NoPen);
        p.setBrush(pal.color(QPalette::WindowText));
        p.drawPolygon(arrow);
        p.setPen(pal.color(QPalette::WindowText));
        p.setFont(bold);
        p.drawText(cell.adjusted(22, 0, -4, 0), Qt::AlignVCenter | Qt::AlignLeft,
                   groupTitle(r.group));
        p.setFont(font());
        p.drawText(cell.adjusted(22, 0, -6, 0), Qt::AlignVCenter | Qt::AlignRight,
                   QString::number(r.channels.count()));
        break;
      }
      case DopeSheetRow::Kind::Channel: {
        p.fillRect(QRectF(0, cell.top(), 3, kRowHeight), theme::groupColour(r.group));
        const FapInfo& info = fapInfo(r.fap);
        p.drawText(cell.adjusted(26, 0, -4, 0), Qt::AlignVCenter | Qt::AlignLeft,
                   QStringLiteral("%1  %2").arg(r.fap).arg(fromView(info.name)));
        break;
      }
    }
  }
  p.setClipping(false);
  // The corner over the names: what the rows are.
  p.fillRect(QRectF(0, 0, kNamesWidth, kRulerHeight), pal.color(QPalette::Window).darker(108));
  p.setPen(pal.color(QPalette::Mid));
  p.drawLine(QPointF(kNamesWidth - 0.5, 0), QPointF(kNamesWidth - 0.5, height()));
}

}  // namespace lacrima::editor
