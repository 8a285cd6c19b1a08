#include <lacrima/editor/MoodGraph.h>

#include "GraphEditorLayout.h"

#include <lacrima/editing/EditorModel.h>
#include <lacrima/editor/EditorTheme.h>

#include <QContextMenuEvent>
#include <QKeyEvent>
#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <cmath>

namespace lacrima::editor {

using namespace detail;

namespace {

// The value axis shows a little beyond 0..1, so keys at the limits are easy to grab.
constexpr double kLowValue = -0.1, kHighValue = 1.1;
constexpr double kLegendRow = 16.0, kLegendWidth = 86.0;

QString moodLabel(Mood mood) {
  QString text = QString::fromLatin1(moodName(mood).data(), int(moodName(mood).size()));
  text[0] = text[0].toUpper();
  return text;
}

}  // namespace

QColor moodColour(Mood mood) {
  switch (mood) {
    case Mood::Sadness:
      return QColor(90, 150, 240);
    case Mood::Anger:
      return QColor(235, 80, 70);
    case Mood::Joy:
      return QColor(240, 200, 60);
    case Mood::Shame:
      return QColor(220, 120, 200);
  }
  return Qt::gray;
}

MoodGraph::MoodGraph(editing::EditorModel& model, QWidget* parent)
    : QWidget(parent), model_(model) {
  setObjectName(QStringLiteral("moodGraph"));
  setFocusPolicy(Qt::ClickFocus);
  setAttribute(Qt::WA_OpaquePaintEvent);
  const auto edited = [this] {
    // An edit arriving mid-drag (undo from the menu) makes the drag's plan stale.
    preview_.reset();
    drag_ = Drag::None;
    update();
  };
  connect(&model_, &editing::EditorModel::moodsChanged, this, edited);
  connect(&model_, &editing::EditorModel::documentReset, this, [this, edited] {
    selected_.reset();
    edited();
  });
  connect(&model_, &editing::EditorModel::timeChanged, this, qOverload<>(&QWidget::update));
  connect(&model_, &editing::EditorModel::moodLayerChanged, this, qOverload<>(&QWidget::update));
}

const MoodCurves& MoodGraph::documentMoods() const { return model_.document().moods; }

void MoodGraph::setTimeView(double startSeconds, double pixelsPerSecond) {
  axis_.set(startSeconds, pixelsPerSecond);
  framePending_ = false;
  viewTouched_ = true;
  update();
}

void MoodGraph::frameAll() {
  if (!isVisible() || width() < 100) {
    framePending_ = true;  // framed at its real size (showEvent, resizeEvent)
    return;
  }
  framePending_ = false;
  viewTouched_ = false;
  const MoodCurves& moods = documentMoods();
  double end = std::max(moods.endTime(), model_.endTime());
  if (end <= 0) end = 2;
  axis_.fit(end, std::max(1.0, plotArea().width()));
  update();
}

void MoodGraph::setActiveMood(Mood mood) {
  active_ = mood;
  update();
}

QRectF MoodGraph::plotArea() const {
  return {kAxisWidth, kRulerHeight, std::max(1.0, width() - kAxisWidth),
          std::max(1.0, height() - kRulerHeight)};
}

double MoodGraph::xOfTime(double seconds) const { return kAxisWidth + axis_.xOf(seconds); }
double MoodGraph::timeAtX(double x) const { return axis_.timeAt(x - kAxisWidth); }

double MoodGraph::yOfValue(double value) const {
  const QRectF area = plotArea();
  return area.top() + (kHighValue - value) / (kHighValue - kLowValue) * area.height();
}

double MoodGraph::valueAtY(double y) const {
  const QRectF area = plotArea();
  return kHighValue - (y - area.top()) / area.height() * (kHighValue - kLowValue);
}

QPointF MoodGraph::keyPosition(Mood mood, int index) const {
  const std::vector<IntensityKey>& keys = shownMoods()[mood].keys();
  if (index < 0 || index >= static_cast<int>(keys.size())) return {};
  const IntensityKey& key = keys[static_cast<std::size_t>(index)];
  return {xOfTime(key.time), yOfValue(key.value)};
}

std::optional<MoodGraph::KeyRef> MoodGraph::keyAt(QPointF position) const {
  std::optional<KeyRef> best;
  double bestDistance = kHitRadius;
  for (Mood mood : kMoods) {
    const std::vector<IntensityKey>& keys = shownMoods()[mood].keys();
    for (int i = 0; i < static_cast<int>(keys.size()); ++i) {
      const QPointF d = keyPosition(mood, i) - position;
      const double distance = std::hypot(d.x(), d.y());
      if (distance > bestDistance) continue;
      bestDistance = distance;
      best = KeyRef{mood, keys[static_cast<std::size_t>(i)].time};
    }
  }
  return best;
}

QRectF MoodGraph::legendBox(int row) const {
  return {kAxisWidth + 6, kRulerHeight + 6 + row * kLegendRow, kLegendWidth, kLegendRow};
}

std::optional<Mood> MoodGraph::legendAt(QPointF position) const {
  for (Mood mood : kMoods)
    if (legendBox(static_cast<int>(mood)).contains(position)) return mood;
  return std::nullopt;
}

MoodCurves MoodGraph::moved(QPointF position) const {
  MoodCurves moods = documentMoods();
  if (!selected_) return moods;
  const double time = std::max(0.0, model_.snapTime(timeAtX(position.x())));
  const double value = std::clamp(valueAtY(position.y()), 0.0, 1.0);
  std::vector<IntensityKey> keys = moods[selected_->mood].keys();
  const auto from = std::find_if(keys.begin(), keys.end(), [&](const IntensityKey& key) {
    return sameTime(key.time, selected_->time);
  });
  if (from == keys.end()) return moods;
  IntensityKey key = *from;
  keys.erase(from);
  key.time = time;
  key.value = value;
  keys.push_back(key);  // last: it wins a time it lands on (IntensityCurve)
  moods[selected_->mood] = IntensityCurve(std::move(keys));
  return moods;
}

// --- input ----------------------------------------------------------------------------------

void MoodGraph::mousePressEvent(QMouseEvent* event) {
  if (event->button() != Qt::LeftButton) return;
  const QPointF at = event->position();
  if (at.y() < kRulerHeight) {
    drag_ = Drag::Scrub;
    model_.setCurrentTime(timeAtX(at.x()));
    return;
  }
  if (const std::optional<Mood> mood = legendAt(at)) {
    setActiveMood(*mood);
    return;
  }
  selected_ = keyAt(at);
  if (selected_) {
    active_ = selected_->mood;
    drag_ = Drag::Key;
  }
  update();
}

void MoodGraph::mouseMoveEvent(QMouseEvent* event) {
  if (drag_ == Drag::Scrub) {
    model_.setCurrentTime(timeAtX(event->position().x()));
  } else if (drag_ == Drag::Key) {
    preview_ = moved(event->position());
    update();
  }
}

void MoodGraph::mouseReleaseEvent(QMouseEvent* event) {
  if (event->button() != Qt::LeftButton) return;
  const Drag drag = drag_;
  drag_ = Drag::None;
  if (drag != Drag::Key || !preview_) return;
  MoodCurves after = moved(event->position());
  preview_.reset();
  const double time = std::max(0.0, model_.snapTime(timeAtX(event->position().x())));
  const Mood mood = selected_->mood;
  selected_ = KeyRef{mood, time};
  model_.editMoods(std::move(after), tr("Move %1 key").arg(moodLabel(mood).toLower()));
  update();
}

void MoodGraph::mouseDoubleClickEvent(QMouseEvent* event) {
  const QPointF at = event->position();
  if (event->button() != Qt::LeftButton || at.y() < kRulerHeight || legendAt(at) || keyAt(at))
    return;
  const double time = std::max(0.0, model_.snapTime(timeAtX(at.x())));
  const double value = std::clamp(valueAtY(at.y()), 0.0, 1.0);
  MoodCurves after = documentMoods();
  std::vector<IntensityKey> keys = after[active_].keys();
  keys.push_back({time, value, Interpolation::Smooth});  // last: replaces a key at that time
  after[active_] = IntensityCurve(std::move(keys));
  selected_ = KeyRef{active_, time};
  model_.editMoods(std::move(after), tr("Key %1").arg(moodLabel(active_).toLower()));
  update();
}

void MoodGraph::resizeEvent(QResizeEvent*) {
  if (framePending_ || !viewTouched_) frameAll();
}

void MoodGraph::showEvent(QShowEvent*) {
  if (framePending_) frameAll();
}

void MoodGraph::wheelEvent(QWheelEvent* event) {
  viewTouched_ = true;
  axis_.wheel(event->angleDelta(), event->modifiers().testFlag(Qt::ShiftModifier),
              event->position().x() - kAxisWidth);
  update();
}

namespace {

bool isMoodKey(const QKeyEvent& key) {
  return key.modifiers() == Qt::NoModifier &&
         (key.key() == Qt::Key_Delete || key.key() == Qt::Key_Backspace ||
          key.key() == Qt::Key_Home);
}

}  // namespace

bool MoodGraph::event(QEvent* event) {
  // The window binds Delete and Home to its keys; while the Moods view has the focus they are
  // the view's, so Delete never removes keys the view does not show.
  if (event->type() == QEvent::ShortcutOverride && isMoodKey(*static_cast<QKeyEvent*>(event))) {
    event->accept();
    return true;
  }
  return QWidget::event(event);
}

void MoodGraph::contextMenuEvent(QContextMenuEvent* event) {
  event->accept();  // the channels' menu (the graph editor's) means nothing here
}

void MoodGraph::keyPressEvent(QKeyEvent* event) {
  if (!isMoodKey(*event)) {
    event->ignore();  // the window's keys; the graph editor's own act on hidden channels
    return;
  }
  if (event->key() == Qt::Key_Home) {
    frameAll();
    return;
  }
  if (!selected_) return;
  MoodCurves after = documentMoods();
  std::vector<IntensityKey> keys = after[selected_->mood].keys();
  std::erase_if(keys, [&](const IntensityKey& key) { return sameTime(key.time, selected_->time); });
  after[selected_->mood] = IntensityCurve(std::move(keys));
  selected_.reset();
  model_.editMoods(std::move(after), tr("Delete mood key"));
}

// --- painting -------------------------------------------------------------------------------

void MoodGraph::paintEvent(QPaintEvent*) {
  QPainter p(this);
  p.setRenderHint(QPainter::Antialiasing);
  const QPalette& pal = palette();
  p.fillRect(rect(), pal.color(QPalette::Base));
  paintValueAxis(p);
  p.fillRect(QRectF(0, 0, width(), kRulerHeight), pal.color(QPalette::Window).darker(108));
  paintTimeRuler(p, axis_, QRectF(kAxisWidth, 0, plotArea().width(), kRulerHeight), height(),
                 model_.frameDuration(), pal, font());
  p.save();
  p.setClipRect(plotArea());
  paintMoodLayer(p);
  paintCurves(p);
  p.restore();
  paintLegend(p);
  paintPlayhead(p, axis_, model_.currentTime(), model_.frameAt(model_.currentTime()), kAxisWidth,
                kRulerHeight, height(), font());
}

void MoodGraph::paintValueAxis(QPainter& p) const {
  const QPalette& pal = palette();
  QColor grid = pal.color(QPalette::Mid);
  grid.setAlphaF(0.6);
  for (double v : {0.0, 0.25, 0.5, 0.75, 1.0}) {
    const double y = std::round(yOfValue(v)) + 0.5;
    p.setPen(QPen(grid, 1));
    p.drawLine(QPointF(kAxisWidth, y), QPointF(width(), y));
    p.setPen(pal.color(QPalette::WindowText));
    p.drawText(QRectF(0, y - 8, kAxisWidth - 6, 16), Qt::AlignRight | Qt::AlignVCenter,
               QString::number(v, 'g', 2));
  }
}

// The crying layer's range, behind the curves it follows: what a key edited here changes.
void MoodGraph::paintMoodLayer(QPainter& p) const {
  const std::optional<MoodLayer>& layer = model_.document().moodLayer;
  if (!layer) return;
  const QRectF area = plotArea();
  const QRectF band(QPointF(xOfTime(layer->start), area.top()),
                    QPointF(xOfTime(layer->end), area.bottom()));
  QColor tint = palette().color(QPalette::Highlight);
  tint.setAlphaF(layer->muted ? 0.05 : 0.12);
  p.fillRect(band, tint);
  p.setPen(palette().color(QPalette::PlaceholderText));
  const QString text = layer->muted ? tr("crying layer, seed %1 (muted)").arg(layer->seed)
                                    : tr("crying layer, seed %1").arg(layer->seed);
  p.drawText(band.adjusted(6, 2, -6, -2), Qt::AlignRight | Qt::AlignBottom, text);
}

void MoodGraph::paintCurves(QPainter& p) const {
  const QRectF area = plotArea();
  for (Mood mood : kMoods) {
    const IntensityCurve& curve = shownMoods()[mood];
    if (curve.empty()) continue;
    const QColor colour = moodColour(mood);
    // One point per pixel column; the holds before the first key and after the last are faint.
    const double x0 = std::max(area.left(), xOfTime(curve.startTime()));
    const double x1 = std::min(area.right(), xOfTime(curve.endTime()));
    QColor faint = colour;
    faint.setAlphaF(0.35);
    p.setPen(QPen(faint, 1, Qt::DashLine));
    p.drawLine(QPointF(area.left(), yOfValue(curve.at(timeAtX(area.left())))),
               QPointF(x0, yOfValue(curve.at(curve.startTime()))));
    p.drawLine(QPointF(x1, yOfValue(curve.at(curve.endTime()))),
               QPointF(area.right(), yOfValue(curve.at(curve.endTime()))));
    QPolygonF line;
    for (double x = x0; x <= x1 + 0.5; x += 1.0)
      line << QPointF(x, yOfValue(curve.at(timeAtX(std::min(x, x1)))));
    p.setPen(QPen(colour, mood == active_ ? 2.0 : 1.0));
    p.drawPolyline(line);
    for (int i = 0; i < static_cast<int>(curve.keys().size()); ++i) {
      const bool selected = selected_ && selected_->mood == mood &&
                            sameTime(selected_->time, curve.keys()[std::size_t(i)].time);
      p.setPen(QPen(Qt::black, 1));
      p.setBrush(selected ? theme::keyAccent() : colour);
      p.drawEllipse(keyPosition(mood, i), kKeyRadius, kKeyRadius);
    }
  }
}

void MoodGraph::paintLegend(QPainter& p) const {
  QColor back = palette().color(QPalette::Base);
  back.setAlphaF(0.8);
  p.fillRect(QRectF(legendBox(0).topLeft(), legendBox(kMoodCount - 1).bottomRight()), back);
  for (Mood mood : kMoods) {
    const QRectF box = legendBox(static_cast<int>(mood));
    p.fillRect(QRectF(box.left() + 2, box.center().y() - 1, 10, 3), moodColour(mood));
    QFont font = p.font();
    font.setBold(mood == active_);
    p.setFont(font);
    p.setPen(moodColour(mood));
    p.drawText(box.adjusted(16, 0, 0, 0), Qt::AlignLeft | Qt::AlignVCenter, moodLabel(mood));
  }
}

}  // namespace lacrima::editor
