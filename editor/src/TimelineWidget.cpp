#include <lacrima/editor/TimelineWidget.h>

#include <lacrima/common/FapTable.h>
#include <lacrima/editing/EditorModel.h>
#include <lacrima/editor/EditorTheme.h>

#include <QContextMenuEvent>
#include <QMenu>
#include <QMouseEvent>
#include <QPainter>
#include <QWheelEvent>

#include <algorithm>
#include <cmath>
#include <limits>

namespace lacrima::editor {
namespace {

constexpr double kRulerHeight = 22.0;
constexpr double kLaneHeight = 30.0;
constexpr double kKeyRadius = 5.5;
constexpr double kCurveSampleRate = 60.0;
constexpr std::size_t kMaxCurveSamples = 60000;

double laneCentre() { return kRulerHeight + kLaneHeight / 2.0; }

}  // namespace

TimelineWidget::TimelineWidget(editing::EditorModel& model, QWidget* parent)
    : QWidget(parent), model_(model) {
  setObjectName(QStringLiteral("timeline"));
  setFocusPolicy(Qt::ClickFocus);
  setMouseTracking(false);
  setAttribute(Qt::WA_OpaquePaintEvent);
  connect(&model_, &editing::EditorModel::keysChanged, this, [this] {
    invalidateCurves();
    update();
  });
  connect(&model_, &editing::EditorModel::focusChannelChanged, this, [this] {
    invalidateCurves();
    update();
  });
  connect(&model_, &editing::EditorModel::selectionChanged, this, qOverload<>(&QWidget::update));
  connect(&model_, &editing::EditorModel::settingsChanged, this, [this] {
    invalidateCurves();
    update();
  });
  connect(&model_, &editing::EditorModel::timeChanged, this, [this] {
    followPlayhead();
    update();
  });
  connect(&model_, &editing::EditorModel::documentReset, this, &TimelineWidget::fitAll);
}

void TimelineWidget::setView(double startSeconds, double pixelsPerSecond) {
  axis_.set(startSeconds, pixelsPerSecond);
  update();
}

void TimelineWidget::fitAll() {
  if (!isVisible() || width() < 100) {
    fitPending_ = true;
    return;
  }
  fitPending_ = false;
  axis_.fit(model_.endTime(), width());
  update();
}

QPointF TimelineWidget::keyPosition(int index) const {
  const auto& keys = model_.document().keys.keys();
  if (index < 0 || index >= static_cast<int>(keys.size())) return {};
  return {xOfTime(keys[static_cast<std::size_t>(index)].time), laneCentre()};
}

int TimelineWidget::keyAt(QPointF position) const {
  if (position.y() < kRulerHeight || position.y() > kRulerHeight + kLaneHeight + 6) return -1;
  const auto& keys = model_.document().keys.keys();
  const double t = timeAtX(position.x());
  const double reach = (kKeyRadius + 2) / axis_.scale();
  const auto it = std::lower_bound(keys.begin(), keys.end(), t - reach,
                                   [](const auto& k, double v) { return k.time < v; });
  int best = -1;
  double bestDistance = reach;
  for (auto k = it; k != keys.end() && k->time <= t + reach; ++k) {
    const double d = std::abs(k->time - t);
    if (d <= bestDistance) {
      bestDistance = d;
      best = static_cast<int>(k - keys.begin());
    }
  }
  return best;
}

double TimelineWidget::frameStepSeconds() const { return model_.frameDuration(); }

void TimelineWidget::followPlayhead() {
  if (axis_.follow(model_.currentTime(), width())) update();
}

void TimelineWidget::resizeEvent(QResizeEvent*) {
  if (fitPending_) fitAll();
}

void TimelineWidget::showEvent(QShowEvent*) {
  if (fitPending_) fitAll();
}

// --- curves -------------------------------------------------------------------------------

void TimelineWidget::invalidateCurves() { curvesValid_ = false; }

TimelineWidget::Curve TimelineWidget::bakeChannel(int fap) const {
  Curve curve;
  std::vector<Keyframe> knots;
  for (const Keyframe& key : model_.document().keys.keys()) {
    if (!key.has(fap)) continue;
    Keyframe only;
    only.time = key.time;
    only.interpolation = key.interpolation;
    only.takeChannel(key, fap);  // with the channel's own shape (Bézier handles, holds)
    knots.push_back(only);
  }
  if (knots.empty()) return curve;
  const KeyframeSequence sequence(std::move(knots));
  const double duration = sequence.endTime() - sequence.startTime();
  double rate = std::max(kCurveSampleRate, model_.document().fps);
  if (duration * rate > kMaxCurveSamples) rate = kMaxCurveSamples / duration;
  const FapAnimation baked = sequence.bake(rate);
  curve.start = sequence.startTime();
  curve.rate = rate;
  curve.samples.reserve(baked.frames.size());
  for (const FapValues& frame : baked.frames)
    curve.samples.push_back(frame[static_cast<std::size_t>(channelIndex(fap))]);
  return curve;
}

void TimelineWidget::ensureCurves() {
  if (curvesValid_) return;
  focusCurve_ = bakeChannel(model_.focusChannel());
  tearLeft_ = bakeChannel(kTearLeftFap);
  tearRight_ = bakeChannel(kTearRightFap);
  tearMax_ = 0;
  for (const Curve* c : {&tearLeft_, &tearRight_})
    for (float v : c->samples) tearMax_ = std::max(tearMax_, v);
  curvesValid_ = true;
}

// --- painting -----------------------------------------------------------------------------

void TimelineWidget::paintEvent(QPaintEvent*) {
  QPainter p(this);
  p.setRenderHint(QPainter::Antialiasing);
  const QPalette& pal = palette();
  p.fillRect(rect(), pal.color(QPalette::Base));

  // The animated span, from the first key to the last.
  const auto& keys = model_.document().keys;
  if (!keys.empty()) {
    const double x0 = xOfTime(keys.startTime());
    const double x1 = xOfTime(keys.endTime());
    p.fillRect(QRectF(x0, kRulerHeight, std::max(1.0, x1 - x0), height() - kRulerHeight),
               pal.color(QPalette::AlternateBase).lighter(118));
  }
  paintTimeRuler(p, axis_, QRectF(0, 0, width(), kRulerHeight), height(), frameStepSeconds(), pal,
                 font());
  const QRectF curveArea(0, kRulerHeight + kLaneHeight + 4, width(),
                         height() - kRulerHeight - kLaneHeight - 8);
  paintCurves(p, curveArea);

  // Lane separator.
  p.setPen(QPen(pal.color(QPalette::Mid), 1));
  p.drawLine(QPointF(0, kRulerHeight + kLaneHeight + 0.5),
             QPointF(width(), kRulerHeight + kLaneHeight + 0.5));
  paintKeys(p);

  paintPlayhead(p, axis_, model_.currentTime(), model_.frameAt(model_.currentTime()), 0,
                kRulerHeight, height(), font());

  if (drag_ == Drag::Band) {
    QColor c = pal.color(QPalette::Highlight);
    c.setAlphaF(0.2);
    p.fillRect(band_, c);
    p.setPen(QPen(pal.color(QPalette::Highlight), 1));
    p.drawRect(band_);
  }
}

void TimelineWidget::paintCurves(QPainter& p, const QRectF& area) {
  ensureCurves();
  const double t0 = timeAtX(0);
  const double t1 = timeAtX(width());

  // At most one point per pixel column: a zoomed-out view of a long curve costs what a short
  // one does. Zoomed in, the baked samples themselves are the points.
  const auto polyline = [&](const Curve& curve, auto yOf) {
    QPolygonF line;
    if (curve.samples.empty()) return line;
    const double end = curve.start + (curve.samples.size() - 1) / curve.rate;
    const double from = std::max(t0, curve.start);
    const double to = std::min(t1, end);
    // Held before the first key and after the last.
    if (t0 < curve.start)
      line << QPointF(0, yOf(curve.samples.front()))
           << QPointF(xOfTime(curve.start), yOf(curve.samples.front()));
    if (from <= to) {
      const auto sampleAt = [&](double t) {
        const double f =
            std::clamp((t - curve.start) * curve.rate, 0.0, double(curve.samples.size() - 1));
        const std::size_t i = static_cast<std::size_t>(f);
        const std::size_t j = std::min(i + 1, curve.samples.size() - 1);
        return static_cast<float>(curve.samples[i] +
                                  (f - i) * (curve.samples[j] - curve.samples[i]));
      };
      if (curve.rate / axis_.scale() >= 1.0) {
        const double x0 = xOfTime(from);
        const double x1 = xOfTime(to);
        line.reserve(static_cast<qsizetype>(x1 - x0) + 4);
        for (double x = x0; x < x1; x += 1.0) line << QPointF(x, yOf(sampleAt(timeAtX(x))));
        line << QPointF(x1, yOf(sampleAt(to)));
      } else {
        const std::size_t i0 =
            static_cast<std::size_t>(std::max(0.0, std::floor((from - curve.start) * curve.rate)));
        const std::size_t i1 =
            std::min(curve.samples.size() - 1,
                     static_cast<std::size_t>(std::ceil((to - curve.start) * curve.rate)));
        for (std::size_t i = i0; i <= i1; ++i)
          line << QPointF(xOfTime(curve.start + i / curve.rate), yOf(curve.samples[i]));
      }
    }
    if (t1 > end)
      line << QPointF(xOfTime(end), yOf(curve.samples.back()))
           << QPointF(width(), yOf(curve.samples.back()));
    return line;
  };

  // Tears: a blue band along the bottom, height by particle count.
  if (tearMax_ > 0) {
    const double bandTop = area.top() + area.height() * 0.55;
    const double bandHeight = area.bottom() - bandTop;
    const auto yOf = [&](float v) { return area.bottom() - v / tearMax_ * bandHeight; };
    for (const Curve* c : {&tearLeft_, &tearRight_}) {
      QPolygonF line = polyline(*c, yOf);
      if (line.size() < 2) continue;
      QPolygonF fill = line;
      fill << QPointF(line.back().x(), area.bottom()) << QPointF(line.front().x(), area.bottom());
      QColor blue = theme::tearBlue();
      blue.setAlphaF(0.16);
      p.setPen(Qt::NoPen);
      p.setBrush(blue);
      p.setRenderHint(QPainter::Antialiasing, false);  // a soft band; edges need no smoothing
      p.drawPolygon(fill);
      p.setRenderHint(QPainter::Antialiasing, true);
      blue.setAlphaF(0.7);
      p.setPen(QPen(blue, 1.0));  // width 1: the fast cosmetic stroker (10x a 1.2 px pen)
      p.setBrush(Qt::NoBrush);
      p.drawPolyline(line);
    }
    p.setPen(theme::tearBlue());
    p.drawText(QRectF(6, bandTop, 300, 16), Qt::AlignLeft | Qt::AlignTop,
               tr("tears (max %1 particles)").arg(static_cast<int>(tearMax_)));
  }

  // The focused channel, scaled to what it spans (0 always in view), with its zero line.
  const int fap = model_.focusChannel();
  const FapInfo& info = fapInfo(fap);
  double lo = 0.0;
  double hi = 0.0;
  for (float v : focusCurve_.samples) {
    lo = std::min<double>(lo, v);
    hi = std::max<double>(hi, v);
  }
  if (hi - lo < 1.0) {
    lo = std::min<double>(info.sliderMin, 0);
    hi = std::max<double>(info.sliderMax, 1);
  } else {
    const double pad = 0.08 * (hi - lo);
    lo -= lo < 0 ? pad : 0;
    hi += pad;
  }
  const auto yOf = [&](float v) {
    const double s = (std::clamp<double>(v, lo, hi) - lo) / (hi - lo);
    return area.bottom() - 2 - s * (area.height() - 4);
  };
  const QColor colour = theme::groupColour(info.group);
  QColor zero = colour;
  zero.setAlphaF(0.25);
  p.setPen(QPen(zero, 1, Qt::DashLine));
  p.drawLine(QPointF(0, yOf(0)), QPointF(width(), yOf(0)));
  const QPolygonF line = polyline(focusCurve_, yOf);
  if (line.size() >= 2) {
    p.setPen(QPen(colour, 1.0));
    p.drawPolyline(line);
  }
  p.setPen(colour);
  QString label = QStringLiteral("%1 %2").arg(fap).arg(
      QString::fromUtf8(info.name.data(), static_cast<qsizetype>(info.name.size())));
  if (focusCurve_.samples.empty()) {
    label += tr("  (not animated)");
  } else {
    const auto [low, high] =
        std::minmax_element(focusCurve_.samples.begin(), focusCurve_.samples.end());
    label += QStringLiteral("   %1 … %2")
                 .arg(static_cast<double>(*low), 0, 'f', 0)
                 .arg(static_cast<double>(*high), 0, 'f', 0);
  }
  p.drawText(QRectF(6, area.top(), 400, 16), Qt::AlignLeft | Qt::AlignTop, label);
}

QString TimelineWidget::emptyHint() {
  return tr("No keys yet — move a slider or apply a preset: it is keyed at the playhead");
}

void TimelineWidget::paintKeys(QPainter& p) {
  const auto& keys = model_.document().keys.keys();
  if (keys.empty()) {
    p.setPen(palette().color(QPalette::PlaceholderText));
    p.drawText(QRectF(0, kRulerHeight, width(), kLaneHeight), Qt::AlignCenter, emptyHint());
    return;
  }
  const double cy = laneCentre();
  const double t0 = timeAtX(-kKeyRadius * 2);
  const double t1 = timeAtX(width() + kKeyRadius * 2);
  const double frame = frameStepSeconds();
  const double ghost = drag_ == Drag::MoveKeys ? ghostFrames_ * frame : 0.0;
  const double current = model_.currentTime();

  const auto first = std::lower_bound(keys.begin(), keys.end(), t0,
                                      [](const auto& k, double v) { return k.time < v; });
  const auto last =
      std::upper_bound(first, keys.end(), t1, [](double v, const auto& k) { return v < k.time; });
  // Keys closer than a few pixels (a whole imported file in view) are drawn as ticks on one line.
  const bool dense = (last - first) * 4 > width();

  // Segments: a line from each key to the next; smooth segments are drawn brighter.
  if (dense) {
    QColor c = theme::keyIdle();
    c.setAlphaF(0.3);
    p.setPen(QPen(c, 1.0));
    p.drawLine(QPointF(xOfTime(keys.front().time), cy), QPointF(xOfTime(keys.back().time), cy));
  } else {
    const auto from = first == keys.begin() ? first : first - 1;
    for (auto k = from; k + 1 != keys.end() && k->time <= t1; ++k) {
      QColor c = theme::keyIdle();
      c.setAlphaF(k->interpolation == Interpolation::Smooth ? 0.45 : 0.25);
      p.setPen(QPen(c, k->interpolation == Interpolation::Smooth ? 2.0 : 1.0));
      p.drawLine(QPointF(xOfTime(k->time), cy), QPointF(xOfTime((k + 1)->time), cy));
    }
  }

  const double r = kKeyRadius;
  int lastPixel = std::numeric_limits<int>::min();
  bool lastSelected = false;
  if (dense) p.setRenderHint(QPainter::Antialiasing, false);
  for (auto k = first; k != last; ++k) {
    const bool selected = model_.isSelected(k->time);
    const double t = selected ? k->time + ghost : k->time;
    const double x = xOfTime(t);
    const int pixel = static_cast<int>(x);
    if (pixel == lastPixel && (selected == lastSelected || !selected)) continue;
    lastPixel = pixel;
    lastSelected = selected;
    const QColor fill = selected ? theme::keyAccent() : theme::keyIdle();
    if (dense) {
      p.setPen(fill);
      p.drawLine(QPointF(pixel + 0.5, cy - r), QPointF(pixel + 0.5, cy + r));
      continue;
    }
    if (selected && ghost != 0.0) {
      // Where it was, faintly, while dragging.
      QColor faint = theme::keyAccent();
      faint.setAlphaF(0.25);
      p.setPen(Qt::NoPen);
      p.setBrush(faint);
      p.drawEllipse(QPointF(xOfTime(k->time), cy), r - 1, r - 1);
    }
    const bool atPlayhead = std::abs(k->time - current) < 1e-9;
    p.setPen(QPen(atPlayhead ? QColor(Qt::white) : palette().color(QPalette::Base),
                  atPlayhead ? 1.6 : 1.0));
    p.setBrush(fill);
    if (k->interpolation == Interpolation::Smooth) {
      p.drawEllipse(QPointF(x, cy), r - 0.5, r - 0.5);
    } else {
      const QPointF diamond[4] = {{x, cy - r}, {x + r, cy}, {x, cy + r}, {x - r, cy}};
      p.drawConvexPolygon(diamond, 4);
    }
  }
  p.setRenderHint(QPainter::Antialiasing, true);
}

// --- mouse --------------------------------------------------------------------------------

int TimelineWidget::dragFrames(double x) const {
  const double perFrame = frameStepSeconds() * axis_.scale();
  return static_cast<int>(std::lround((x - pressPos_.x()) / perFrame));
}

void TimelineWidget::mousePressEvent(QMouseEvent* event) {
  pressPos_ = event->position();
  if (event->button() == Qt::MiddleButton) {
    drag_ = Drag::Pan;
    panStart_ = axis_.start();
    return;
  }
  if (event->button() != Qt::LeftButton) return;
  if (pressPos_.y() < kRulerHeight) {
    drag_ = Drag::Scrub;
    model_.setCurrentTime(timeAtX(pressPos_.x()));
    return;
  }
  const int key = keyAt(pressPos_);
  const bool additive = event->modifiers() & (Qt::ControlModifier | Qt::ShiftModifier);
  if (key >= 0) {
    const double t = model_.document().keys.keys()[static_cast<std::size_t>(key)].time;
    if (additive) {
      std::vector<double> selection = model_.selectedTimes();
      if (model_.isSelected(t)) {
        selection.erase(std::remove_if(selection.begin(), selection.end(),
                                       [&](double s) { return std::abs(s - t) < 1e-9; }),
                        selection.end());
      } else {
        selection.push_back(t);
      }
      model_.setSelectedTimes(selection);
    } else if (!model_.isSelected(t)) {
      model_.setSelectedTimes({t});
    }
    pressedKey_ = key;
    drag_ = model_.isSelected(t) ? Drag::PendingKey : Drag::None;
    return;
  }
  if (!additive) model_.clearSelection();
  drag_ = Drag::PendingBand;
}

void TimelineWidget::mouseMoveEvent(QMouseEvent* event) {
  const QPointF pos = event->position();
  const bool moved = (pos - pressPos_).manhattanLength() >= 4;
  switch (drag_) {
    case Drag::Scrub:
      model_.setCurrentTime(timeAtX(pos.x()));
      break;
    case Drag::Pan:
      setView(panStart_ - (pos.x() - pressPos_.x()) / axis_.scale(), axis_.scale());
      break;
    case Drag::PendingKey:
      if (moved) drag_ = Drag::MoveKeys;
      [[fallthrough]];
    case Drag::MoveKeys:
      if (drag_ == Drag::MoveKeys) {
        ghostFrames_ = dragFrames(pos.x());
        update();
      }
      break;
    case Drag::PendingBand:
      if (!moved) break;
      drag_ = Drag::Band;
      [[fallthrough]];
    case Drag::Band: {
      band_ = QRectF(pressPos_, pos).normalized();
      const double a = timeAtX(band_.left());
      const double b = timeAtX(band_.right());
      std::vector<double> selection;
      if (event->modifiers() & (Qt::ControlModifier | Qt::ShiftModifier))
        selection = model_.selectedTimes();
      for (const Keyframe& k : model_.document().keys.keys())
        if (k.time >= a && k.time <= b) selection.push_back(k.time);
      model_.setSelectedTimes(selection);
      update();
      break;
    }
    case Drag::None:
      break;
  }
}

void TimelineWidget::mouseReleaseEvent(QMouseEvent* event) {
  const Drag drag = drag_;
  drag_ = Drag::None;
  switch (drag) {
    case Drag::MoveKeys: {
      const int frames = dragFrames(event->position().x());
      ghostFrames_ = 0;
      if (frames != 0) model_.moveKeys(model_.selectedTimes(), frames);
      update();
      break;
    }
    case Drag::PendingKey: {
      const auto& keys = model_.document().keys.keys();
      if (pressedKey_ >= 0 && pressedKey_ < static_cast<int>(keys.size()))
        model_.setCurrentTime(keys[static_cast<std::size_t>(pressedKey_)].time);
      break;
    }
    case Drag::PendingBand:
      model_.setCurrentTime(timeAtX(event->position().x()));
      break;
    default:
      update();
      break;
  }
  pressedKey_ = -1;
}

void TimelineWidget::mouseDoubleClickEvent(QMouseEvent* event) {
  if (event->button() != Qt::LeftButton || event->position().y() < kRulerHeight) return;
  if (keyAt(event->position()) >= 0) return;
  model_.setCurrentTime(timeAtX(event->position().x()));
  model_.addKey();
  drag_ = Drag::None;
}

void TimelineWidget::wheelEvent(QWheelEvent* event) {
  axis_.wheel(event->angleDelta(), event->modifiers() & Qt::ShiftModifier, event->position().x());
  update();
  event->accept();
}

void TimelineWidget::contextMenuEvent(QContextMenuEvent* event) {
  const QPointF pos = event->pos();
  const int key = keyAt(pos);
  QMenu menu(this);
  if (key >= 0) {
    const Keyframe& k = model_.document().keys.keys()[static_cast<std::size_t>(key)];
    if (!model_.isSelected(k.time)) model_.setSelectedTimes({k.time});
    const std::vector<double> selection = model_.selectedTimes();
    QAction* linear = menu.addAction(tr("Linear"));
    QAction* smooth = menu.addAction(tr("Smooth"));
    linear->setCheckable(true);
    smooth->setCheckable(true);
    linear->setChecked(k.interpolation == Interpolation::Linear);
    smooth->setChecked(k.interpolation == Interpolation::Smooth);
    connect(linear, &QAction::triggered, this,
            [this, selection] { model_.setInterpolation(selection, Interpolation::Linear); });
    connect(smooth, &QAction::triggered, this,
            [this, selection] { model_.setInterpolation(selection, Interpolation::Smooth); });
    menu.addSeparator();
    connect(menu.addAction(tr("Copy")), &QAction::triggered, this, &TimelineWidget::copyRequested);
    connect(menu.addAction(tr("Mirror left ↔ right")), &QAction::triggered, this,
            &TimelineWidget::mirrorRequested);
    connect(menu.addAction(tr("Delete")), &QAction::triggered, this,
            [this, selection] { model_.deleteKeys(selection); });
  } else {
    const double t = model_.snapTime(timeAtX(pos.x()));
    connect(menu.addAction(tr("Add key here")), &QAction::triggered, this, [this, t] {
      model_.setCurrentTime(t);
      model_.addKey();
    });
    connect(menu.addAction(tr("Paste here")), &QAction::triggered, this,
            [this, t] { emit pasteRequested(t); });
    menu.addSeparator();
    connect(menu.addAction(tr("Frame all")), &QAction::triggered, this, &TimelineWidget::fitAll);
  }
  menu.exec(event->globalPos());
}

}  // namespace lacrima::editor
