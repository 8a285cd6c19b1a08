#include <lacrima/editor/GraphEditor.h>

#include "GraphEditorCurves.h"

#include <lacrima/common/CurveHandles.h>
#include <lacrima/common/FapTable.h>
#include <lacrima/editing/EditorModel.h>

#include <QContextMenuEvent>
#include <QCursor>
#include <QKeyEvent>
#include <QMenu>
#include <QMouseEvent>
#include <QSignalBlocker>
#include <QToolButton>
#include <QWheelEvent>

#include <algorithm>
#include <cmath>

namespace lacrima::editor {

using editing::ChannelKey;
using editing::HandleSide;

namespace {

constexpr double kRulerHeight = 22.0;
constexpr double kAxisWidth = 56.0;
constexpr double kHitRadius = 7.0;
constexpr double kMinScale = 0.5;      // px per second
constexpr double kMaxScale = 20000.0;  // a frame at 25 fps is 800 px
constexpr double kMinValueScale = 1e-6;
constexpr double kMaxValueScale = 1e7;

bool sameTime(double a, double b) { return std::abs(a - b) < editing::kSameKeyTime; }

QString interpolationName(Interpolation mode) {
  switch (mode) {
    case Interpolation::Constant:
      return GraphEditor::tr("Constant");
    case Interpolation::Linear:
      return GraphEditor::tr("Linear");
    case Interpolation::Smooth:
      return GraphEditor::tr("Smooth");
    case Interpolation::Bezier:
      return GraphEditor::tr("Bézier");
  }
  return {};
}

QString handleTypeName(HandleType type) {
  switch (type) {
    case HandleType::Auto:
      return GraphEditor::tr("Auto");
    case HandleType::Aligned:
      return GraphEditor::tr("Aligned");
    case HandleType::Free:
      return GraphEditor::tr("Free");
  }
  return {};
}

}  // namespace

GraphEditor::GraphEditor(editing::EditorModel& model, QWidget* parent)
    : QWidget(parent), model_(model) {
  setObjectName(QStringLiteral("graphEditor"));
  setFocusPolicy(Qt::ClickFocus);
  setAttribute(Qt::WA_OpaquePaintEvent);

  normalizeButton_ = new QToolButton(this);
  normalizeButton_->setObjectName(QStringLiteral("graphNormalize"));
  normalizeButton_->setText(tr("Normalize"));
  normalizeButton_->setCheckable(true);
  normalizeButton_->setAutoRaise(true);
  normalizeButton_->setToolTip(
      tr("Map each curve to -1..1 by its own range, to compare channels of different ranges"));
  connect(normalizeButton_, &QToolButton::toggled, this, &GraphEditor::setNormalized);

  const auto keysEdited = [this] {
    // An edit arriving mid-drag (undo from the menu) makes the drag's plan stale.
    if (preview_) {
      clearPreview();
      drag_ = Drag::None;
    }
    invalidateAllCurves();
    update();
  };
  connect(&model_, &editing::EditorModel::keysChanged, this, keysEdited);
  connect(&model_, &editing::EditorModel::settingsChanged, this, keysEdited);
  connect(&model_, &editing::EditorModel::documentReset, this, [this, keysEdited] {
    keysEdited();
    viewTouched_ = false;
    frameAll();
  });
  connect(&model_, &editing::EditorModel::selectedChannelsChanged, this,
          &GraphEditor::shownChannelsChanged);
  connect(&model_, &editing::EditorModel::focusChannelChanged, this, [this] {
    if (model_.selectedChannels().none()) shownChannelsChanged();
  });
  connect(&model_, &editing::EditorModel::channelKeySelectionChanged, this,
          qOverload<>(&QWidget::update));
  connect(&model_, &editing::EditorModel::timeChanged, this, qOverload<>(&QWidget::update));
}

GraphEditor::~GraphEditor() = default;

// --- channels and curves --------------------------------------------------------------------

std::vector<int> GraphEditor::shownChannels() const {
  std::vector<int> faps;
  const ChannelMask& selected = model_.selectedChannels();
  for (int i = 0; i < kChannelCount; ++i)
    if (selected.test(i)) faps.push_back(fapNumber(i));
  if (faps.empty()) faps.push_back(model_.focusChannel());
  return faps;
}

void GraphEditor::shownChannelsChanged() {
  invalidateAllCurves();
  if (!viewTouched_) frameAll();
  update();
}

const KeyframeSequence& GraphEditor::shownKeys() const {
  return preview_ ? *preview_ : model_.document().keys;
}

void GraphEditor::invalidateAllCurves() { curvesValid_ = false; }

void GraphEditor::invalidateCurves(ChannelMask channels) { dirty_ |= channels; }

void GraphEditor::ensureCurves() const {
  const std::vector<int> faps = shownChannels();
  const double fps = model_.document().fps;
  if (!curvesValid_) {
    curves_.clear();
    for (int fap : faps) curves_.push_back(sampleChannel(shownKeys(), fap, fps));
    curvesValid_ = true;
    dirty_.reset();
    return;
  }
  if (dirty_.none()) return;
  for (GraphCurve& curve : curves_) {
    if (!dirty_.test(channelIndex(curve.fap))) continue;
    GraphCurve fresh = sampleChannel(shownKeys(), curve.fap, fps);
    // While dragging, the normalised view keeps the range it had when the drag started, so
    // the key under the pointer stays under it.
    if (drag_ != Drag::None) {
      fresh.low = curve.low;
      fresh.high = curve.high;
    }
    curve = std::move(fresh);
  }
  dirty_.reset();
}

const GraphCurve* GraphEditor::curveOf(int fap) const {
  ensureCurves();
  for (const GraphCurve& curve : curves_)
    if (curve.fap == fap) return &curve;
  return nullptr;
}

void GraphEditor::setPreview(const editing::KeyChange& change, ChannelMask channels) {
  if (!preview_) preview_ = model_.document().keys;
  // A plan that creates or removes keys shifts the key indices every curve holds.
  const auto addsOrRemovesKeys = [](const editing::KeyChange& c) {
    return c.before.size() != c.after.size() ||
           !std::equal(
               c.before.begin(), c.before.end(), c.after.begin(),
               [](const Keyframe& a, const Keyframe& b) { return sameTime(a.time, b.time); });
  };
  bool reindex = addsOrRemovesKeys(change);
  // Back to the document at the previous plan's times, then the new plan: O(keys touched).
  if (previewChange_) {
    reindex = reindex || addsOrRemovesKeys(*previewChange_);
    editing::applyKeys(*preview_, previewChange_->times, previewChange_->before);
    for (const Keyframe& key : previewChange_->before) channels |= key.channels;
    for (const Keyframe& key : previewChange_->after) channels |= key.channels;
  }
  editing::applyKeys(*preview_, change.times, change.after);
  previewChange_ = change;
  if (reindex) {
    // Every curve again, keeping the ranges the drag started with (see ensureCurves).
    const std::vector<GraphCurve> old = curves_;
    invalidateAllCurves();
    ensureCurves();
    for (GraphCurve& curve : curves_) {
      for (const GraphCurve& before : old) {
        if (before.fap != curve.fap) continue;
        curve.low = before.low;
        curve.high = before.high;
      }
    }
  } else {
    invalidateCurves(channels);
  }
  update();
}

void GraphEditor::clearPreview() {
  if (!preview_) return;
  preview_.reset();
  previewChange_.reset();
  previewSelection_.clear();
  invalidateAllCurves();
  update();
}

// --- view -----------------------------------------------------------------------------------

QRectF GraphEditor::plotArea() const {
  return {kAxisWidth, kRulerHeight, std::max(1.0, width() - kAxisWidth),
          std::max(1.0, height() - kRulerHeight)};
}

double GraphEditor::displayOf(int fap, double value) const {
  if (!normalized_) return value;
  const GraphCurve* curve = curveOf(fap);
  return curve ? (value - curve->mid()) / curve->half() : value;
}

double GraphEditor::valueOfDisplay(int fap, double display) const {
  if (!normalized_) return display;
  const GraphCurve* curve = curveOf(fap);
  return curve ? curve->mid() + display * curve->half() : display;
}

double GraphEditor::xOfTime(double seconds) const {
  return kAxisWidth + (seconds - start_) * scale_;
}
double GraphEditor::timeAtX(double x) const { return start_ + (x - kAxisWidth) / scale_; }

double GraphEditor::yOfValue(int fap, double value) const {
  return kRulerHeight + (top_ - displayOf(fap, value)) * vScale_;
}

double GraphEditor::valueAtY(int fap, double y) const {
  return valueOfDisplay(fap, top_ - (y - kRulerHeight) / vScale_);
}

QPointF GraphEditor::keyPosition(int fap, int keyIndex) const {
  const auto& keys = shownKeys().keys();
  if (keyIndex < 0 || keyIndex >= static_cast<int>(keys.size())) return {};
  const Keyframe& key = keys[static_cast<std::size_t>(keyIndex)];
  return {xOfTime(key.time), yOfValue(fap, key.value(fap))};
}

QPointF GraphEditor::handlePosition(int fap, int keyIndex, HandleSide side) const {
  const auto& keys = shownKeys().keys();
  if (keyIndex < 0 || keyIndex >= static_cast<int>(keys.size()) ||
      !keys[static_cast<std::size_t>(keyIndex)].has(fap))
    return {};
  const Keyframe& key = keys[static_cast<std::size_t>(keyIndex)];
  const EffectiveHandles handles = effectiveHandles(shownKeys(), fap, keyIndex);
  const Handle h = side == HandleSide::In ? handles.in : handles.out;
  return {xOfTime(key.time + h.dt), yOfValue(fap, key.value(fap) + h.dv)};
}

void GraphEditor::setView(double startSeconds, double pixelsPerSecond, double topValue,
                          double pixelsPerUnit) {
  if (!std::isfinite(startSeconds) || !std::isfinite(pixelsPerSecond) || !std::isfinite(topValue) ||
      !std::isfinite(pixelsPerUnit))
    return;
  scale_ = std::clamp(pixelsPerSecond, kMinScale, kMaxScale);
  start_ = startSeconds;
  vScale_ = std::clamp(pixelsPerUnit, kMinValueScale, kMaxValueScale);
  top_ = topValue;
  update();
}

void GraphEditor::frameRange(double t0, double t1, double v0, double v1) {
  if (!isVisible() || width() < 100 || height() < 60) {
    framePending_ = true;
    return;
  }
  framePending_ = false;
  if (t1 - t0 < 1e-6) {
    t0 -= 0.5;
    t1 += 0.5;
  }
  if (v1 - v0 < 1e-9) {
    const double pad = std::max(normalized_ ? 1.0 : 1.0, 0.1 * std::abs(v0));
    v0 -= pad;
    v1 += pad;
  }
  const QRectF area = plotArea();
  // A margin of 5% of the range on either side in time, 8% in value.
  const double pps = area.width() / (1.1 * (t1 - t0));
  const double ppu = area.height() / (1.16 * (v1 - v0));
  setView(t0 - 0.05 * (t1 - t0), pps, v1 + 0.08 * (v1 - v0), ppu);
}

void GraphEditor::frameAll() {
  ensureCurves();
  double t0 = 0.0, t1 = 2.0, v0 = 0.0, v1 = 0.0;
  bool any = false;
  for (const GraphCurve& curve : curves_) {
    if (curve.empty()) continue;
    const double lo = displayOf(curve.fap, curve.low), hi = displayOf(curve.fap, curve.high);
    t0 = any ? std::min(t0, curve.start) : curve.start;
    t1 = any ? std::max(t1, curve.end()) : curve.end();
    v0 = any ? std::min(v0, lo) : lo;
    v1 = any ? std::max(v1, hi) : hi;
    any = true;
  }
  if (!any) {
    // Nothing keyed: the first channel's practical range over two seconds.
    const FapInfo& info = fapInfo(shownChannels().front());
    v0 = normalized_ ? -1.0 : std::min(0, info.sliderMin);
    v1 = normalized_ ? 1.0 : std::max(1, info.sliderMax);
  }
  viewTouched_ = false;
  frameRange(t0, t1, v0, v1);
}

void GraphEditor::frameSelected() {
  const std::vector<int> faps = shownChannels();
  double t0 = 0, t1 = 0, v0 = 0, v1 = 0;
  bool any = false;
  for (const ChannelKey& key : model_.selectedChannelKeys()) {
    if (std::find(faps.begin(), faps.end(), key.fap) == faps.end()) continue;
    const int index = editing::findKey(shownKeys(), key.time);
    if (index < 0) continue;
    const double v = displayOf(key.fap, shownKeys().keys()[std::size_t(index)].value(key.fap));
    t0 = any ? std::min(t0, key.time) : key.time;
    t1 = any ? std::max(t1, key.time) : key.time;
    v0 = any ? std::min(v0, v) : v;
    v1 = any ? std::max(v1, v) : v;
    any = true;
  }
  if (!any) return frameAll();
  viewTouched_ = true;
  frameRange(t0, t1, v0, v1);
}

void GraphEditor::setNormalized(bool on) {
  if (normalized_ != on) {
    normalized_ = on;
    frameAll();
    update();
  }
  const QSignalBlocker block(normalizeButton_);
  normalizeButton_->setChecked(on);
}

void GraphEditor::resizeEvent(QResizeEvent*) {
  normalizeButton_->adjustSize();
  normalizeButton_->move(width() - normalizeButton_->width() - 4,
                         static_cast<int>(kRulerHeight) + 2);
  if (framePending_) frameAll();
}

void GraphEditor::showEvent(QShowEvent*) {
  if (framePending_) frameAll();
}

// --- selection and hits ---------------------------------------------------------------------

bool GraphEditor::isShownSelected(int fap, double time) const {
  if (preview_ && drag_ == Drag::MoveKeys) {
    return std::any_of(previewSelection_.begin(), previewSelection_.end(),
                       [&](const ChannelKey& k) { return k.fap == fap && sameTime(k.time, time); });
  }
  return model_.isSelected(ChannelKey{fap, time});
}

bool GraphEditor::showsHandles(const GraphCurve& curve, std::size_t position) const {
  if (isHighLevelFap(curve.fap)) return false;  // codes never blend: no segment to shape
  const auto& keys = shownKeys().keys();
  const auto interpolationAt = [&](std::size_t p) {
    return keys[static_cast<std::size_t>(curve.keys[p])].shape(curve.fap).interpolation;
  };
  return interpolationAt(position) == Interpolation::Bezier ||
         (position > 0 && interpolationAt(position - 1) == Interpolation::Bezier);
}

GraphEditor::Hit GraphEditor::hitAt(QPointF position) const {
  ensureCurves();
  Hit best;
  double bestDistance = kHitRadius;
  const auto consider = [&](QPointF at, HitKind kind, int fap, int keyIndex) {
    const double d = std::hypot(at.x() - position.x(), at.y() - position.y());
    // Keys win ties with their own handles (a zero-length handle sits on its key).
    if (d < bestDistance || (d == bestDistance && kind == HitKind::Key && best.kind != kind)) {
      bestDistance = d;
      best = {kind, fap, keyIndex};
    }
  };
  const auto& keys = shownKeys().keys();
  const double t0 = timeAtX(kAxisWidth), t1 = timeAtX(width());
  // Curves drawn last are on top: search them first.
  for (auto curve = curves_.rbegin(); curve != curves_.rend(); ++curve) {
    const auto timeOf = [&](int index) { return keys[static_cast<std::size_t>(index)].time; };
    const auto first = std::lower_bound(curve->keys.begin(), curve->keys.end(), t0,
                                        [&](int k, double t) { return timeOf(k) < t; });
    const auto last = std::upper_bound(first, curve->keys.end(), t1,
                                       [&](double t, int k) { return t < timeOf(k); });
    // Handles reach out of the view from keys just outside it.
    const auto from = first == curve->keys.begin() ? first : first - 1;
    const auto to = last == curve->keys.end() ? last : last + 1;
    if ((to - from) * 3 > width()) continue;  // too dense to pick (drawn as a curve only)
    for (auto k = from; k != to; ++k) {
      const std::size_t position = static_cast<std::size_t>(k - curve->keys.begin());
      consider(keyPosition(curve->fap, *k), HitKind::Key, curve->fap, *k);
      if (!showsHandles(*curve, position)) continue;
      // Only the handles drawn: an end key has none on its open side.
      const EffectiveHandles handles = effectiveHandles(shownKeys(), curve->fap, *k);
      if (handles.hasIn)
        consider(handlePosition(curve->fap, *k, HandleSide::In), HitKind::InHandle, curve->fap, *k);
      if (handles.hasOut)
        consider(handlePosition(curve->fap, *k, HandleSide::Out), HitKind::OutHandle, curve->fap,
                 *k);
    }
  }
  return best;
}

void GraphEditor::selectFromHit(const Hit& hit, bool additive) {
  const ChannelKey key{hit.fap, shownKeys().keys()[static_cast<std::size_t>(hit.keyIndex)].time};
  std::vector<ChannelKey> selection = model_.selectedChannelKeys();
  const bool selected = model_.isSelected(key);
  if (additive && hit.kind == HitKind::Key) {
    if (selected) {
      std::erase(selection, key);
    } else {
      selection.push_back(key);
    }
  } else if (additive) {
    if (!selected) selection.push_back(key);
  } else if (!selected) {
    selection = {key};
  }
  model_.setSelectedChannelKeys(std::move(selection));
}

// --- mouse ----------------------------------------------------------------------------------

void GraphEditor::mousePressEvent(QMouseEvent* event) {
  pressPos_ = event->position();
  if (event->button() == Qt::MiddleButton) {
    drag_ = Drag::Pan;
    panStart_ = start_;
    panTop_ = top_;
    return;
  }
  if (event->button() != Qt::LeftButton) return;
  if (pressPos_.y() < kRulerHeight) {
    drag_ = Drag::Scrub;
    model_.setCurrentTime(timeAtX(pressPos_.x()));
    return;
  }
  const bool additive = event->modifiers() & Qt::ShiftModifier;
  pressed_ = hitAt(pressPos_);
  selectionAtPress_ = model_.selectedChannelKeys();
  switch (pressed_.kind) {
    case HitKind::Key:
      selectFromHit(pressed_, additive);
      drag_ =
          model_.isSelected(ChannelKey{
              pressed_.fap, shownKeys().keys()[static_cast<std::size_t>(pressed_.keyIndex)].time})
              ? Drag::PendingKey
              : Drag::None;
      break;
    case HitKind::InHandle:
    case HitKind::OutHandle:
      selectFromHit(pressed_, additive);
      drag_ = Drag::Handle;
      break;
    case HitKind::None:
      bandAdds_ = additive;
      drag_ = Drag::PendingBand;
      break;
  }
}

void GraphEditor::mouseMoveEvent(QMouseEvent* event) {
  const QPointF pos = event->position();
  const bool moved = (pos - pressPos_).manhattanLength() >= 4;
  switch (drag_) {
    case Drag::Scrub:
      model_.setCurrentTime(timeAtX(pos.x()));
      break;
    case Drag::Pan:
      viewTouched_ = true;
      setView(panStart_ - (pos.x() - pressPos_.x()) / scale_, scale_,
              panTop_ + (pos.y() - pressPos_.y()) / vScale_, vScale_);
      break;
    case Drag::PendingKey:
      if (!moved) break;
      drag_ = Drag::MoveKeys;
      [[fallthrough]];
    case Drag::MoveKeys:
      updateKeyDrag(pos, event->modifiers());
      break;
    case Drag::Handle:
      updateHandleDrag(pos);
      break;
    case Drag::PendingBand:
      if (!moved) break;
      drag_ = Drag::Band;
      [[fallthrough]];
    case Drag::Band:
      updateBand(pos);
      break;
    case Drag::None:
      break;
  }
}

void GraphEditor::mouseReleaseEvent(QMouseEvent* event) {
  if (event->button() != Qt::LeftButton && event->button() != Qt::MiddleButton) return;
  if (drag_ == Drag::PendingBand && !(event->modifiers() & Qt::ShiftModifier))
    model_.setSelectedChannelKeys({});
  finishDrag();
}

void GraphEditor::updateKeyDrag(QPointF position, Qt::KeyboardModifiers modifiers) {
  const KeyframeSequence& keys = model_.document().keys;
  const double frame = model_.frameDuration();
  const int frames =
      static_cast<int>(std::lround((timeAtX(position.x()) - timeAtX(pressPos_.x())) / frame));
  const double displayShift = (pressPos_.y() - position.y()) / vScale_;
  std::vector<editing::ChannelKeyMove> moves;
  ChannelMask channels;
  for (const ChannelKey& key : model_.selectedChannelKeys()) {
    const int index = editing::findKey(keys, key.time);
    if (index < 0) continue;
    const double value = keys.keys()[static_cast<std::size_t>(index)].value(key.fap);
    // A shift on screen is a shift in display units; each channel converts it to its own.
    const double shift = valueOfDisplay(key.fap, displayOf(key.fap, value) + displayShift) - value;
    moves.push_back({key, value + shift});
    channels.set(channelIndex(key.fap));
  }
  const editing::ChannelKeyMoveResult result = editing::moveChannelKeys(
      keys, moves, frames, model_.document().fps, modifiers & Qt::ControlModifier);
  previewText_ = moves.size() == 1 ? tr("Move key") : tr("Move %1 keys").arg(moves.size());
  previewSelection_ = result.moved;
  setPreview(result.change, channels);
}

void GraphEditor::updateHandleDrag(QPointF position) {
  const KeyframeSequence& keys = model_.document().keys;
  const int fap = pressed_.fap;
  const Keyframe& key = keys.keys()[static_cast<std::size_t>(pressed_.keyIndex)];
  const HandleSide side = pressed_.kind == HitKind::InHandle ? HandleSide::In : HandleSide::Out;
  const EffectiveHandles start = effectiveHandles(keys, fap, pressed_.keyIndex);
  const Handle from = side == HandleSide::In ? start.in : start.out;
  // The handle follows the pointer's motion from where it was grabbed.
  const Handle offset{
      from.dt + timeAtX(position.x()) - timeAtX(pressPos_.x()),
      from.dv + valueAtY(fap, position.y()) - valueAtY(fap, pressPos_.y()),
  };
  previewText_ = tr("Move handle");
  ChannelMask channels;
  channels.set(channelIndex(fap));
  setPreview(editing::moveHandle(keys, fap, key.time, side, offset), channels);
}

void GraphEditor::updateBand(QPointF position) {
  band_ = QRectF(pressPos_, position).normalized();
  std::vector<ChannelKey> selection;
  if (bandAdds_) selection = selectionAtPress_;
  ensureCurves();
  const auto& keys = shownKeys().keys();
  const double t0 = timeAtX(band_.left()), t1 = timeAtX(band_.right());
  for (const GraphCurve& curve : curves_) {
    const auto first = std::lower_bound(
        curve.keys.begin(), curve.keys.end(), t0,
        [&](int k, double t) { return keys[static_cast<std::size_t>(k)].time < t; });
    for (auto k = first; k != curve.keys.end(); ++k) {
      const Keyframe& key = keys[static_cast<std::size_t>(*k)];
      if (key.time > t1) break;
      if (band_.contains(keyPosition(curve.fap, *k))) selection.push_back({curve.fap, key.time});
    }
  }
  model_.setSelectedChannelKeys(std::move(selection));
  update();
}

void GraphEditor::finishDrag() {
  const Drag drag = drag_;
  drag_ = Drag::None;
  std::optional<editing::KeyChange> change = previewChange_;
  const std::vector<ChannelKey> selection = previewSelection_;
  const QString text = previewText_;
  clearPreview();
  if (change && !change->isNoOp()) {
    model_.editKeys(*change, text);
    if (drag == Drag::MoveKeys) model_.setSelectedChannelKeys(selection);
  }
  update();
}

void GraphEditor::wheelEvent(QWheelEvent* event) {
  const QPoint delta = event->angleDelta();
  const QPointF at = event->position();
  viewTouched_ = true;
  if (event->modifiers() & Qt::ShiftModifier || std::abs(delta.x()) > std::abs(delta.y())) {
    const int d = delta.x() != 0 ? delta.x() : delta.y();
    setView(start_ - d / 120.0 * 60.0 / scale_, scale_, top_, vScale_);
  } else if (event->modifiers() & Qt::ControlModifier) {
    const double anchor = top_ - (at.y() - kRulerHeight) / vScale_;
    const double scale = vScale_ * std::pow(1.15, delta.y() / 120.0);
    setView(start_, scale_, anchor + (at.y() - kRulerHeight) / scale, scale);
  } else {
    const double anchor = timeAtX(at.x());
    const double scale =
        std::clamp(scale_ * std::pow(1.15, delta.y() / 120.0), kMinScale, kMaxScale);
    setView(anchor - (at.x() - kAxisWidth) / scale, scale, top_, vScale_);
  }
  event->accept();
}

// --- keys and menus -------------------------------------------------------------------------

bool GraphEditor::event(QEvent* event) {
  // The window binds T, F and Home to other commands; while the graph has focus, these keys
  // are the graph's (as in Blender, where keys act on the editor under the pointer).
  if (event->type() == QEvent::ShortcutOverride) {
    const auto* key = static_cast<QKeyEvent*>(event);
    const Qt::KeyboardModifiers mods = key->modifiers() & ~Qt::KeypadModifier;
    const bool graphKey =
        mods == Qt::NoModifier &&
        (key->key() == Qt::Key_T || key->key() == Qt::Key_V || key->key() == Qt::Key_F ||
         key->key() == Qt::Key_Home ||
         (key->key() == Qt::Key_Period && (key->modifiers() & Qt::KeypadModifier)));
    if (graphKey) {
      event->accept();
      return true;
    }
  }
  return QWidget::event(event);
}

void GraphEditor::keyPressEvent(QKeyEvent* event) {
  switch (event->key()) {
    case Qt::Key_T:
      popupMenu(&GraphEditor::fillInterpolationMenu);
      return;
    case Qt::Key_V:
      popupMenu(&GraphEditor::fillHandleTypeMenu);
      return;
    case Qt::Key_Home:
      frameAll();
      return;
    case Qt::Key_F:
      frameSelected();
      return;
    case Qt::Key_Period:
      if (event->modifiers() & Qt::KeypadModifier) {
        frameSelected();
        return;
      }
      break;
    default:
      break;
  }
  QWidget::keyPressEvent(event);
}

void GraphEditor::setSelectedInterpolation(Interpolation mode) {
  const auto& selection = model_.selectedChannelKeys();
  const editing::KeyChange change =
      editing::setChannelKeyShapes(model_.document().keys, selection, mode);
  if (change.isNoOp()) return;
  model_.editKeys(change, tr("Interpolation: %1").arg(interpolationName(mode)));
}

void GraphEditor::setSelectedHandleType(HandleType type) {
  const auto& selection = model_.selectedChannelKeys();
  const editing::KeyChange change =
      editing::setChannelKeyShapes(model_.document().keys, selection, type);
  if (change.isNoOp()) return;
  model_.editKeys(change, tr("Handles: %1").arg(handleTypeName(type)));
}

void GraphEditor::fillInterpolationMenu(QMenu& menu) {
  const std::pair<Interpolation, QString> entries[] = {
      {Interpolation::Constant, tr("&Constant")},
      {Interpolation::Linear, tr("&Linear")},
      {Interpolation::Smooth, tr("&Smooth")},
      {Interpolation::Bezier, tr("&Bézier")},
  };
  for (const auto& [mode, text] : entries) {
    connect(menu.addAction(text), &QAction::triggered, this,
            [this, mode = mode] { setSelectedInterpolation(mode); });
  }
  menu.setEnabled(!model_.selectedChannelKeys().empty());
}

void GraphEditor::fillHandleTypeMenu(QMenu& menu) {
  for (const HandleType type : {HandleType::Auto, HandleType::Aligned, HandleType::Free}) {
    connect(menu.addAction(handleTypeName(type)), &QAction::triggered, this,
            [this, type] { setSelectedHandleType(type); });
  }
  menu.setEnabled(!model_.selectedChannelKeys().empty());
}

void GraphEditor::popupMenu(void (GraphEditor::*fill)(QMenu&)) {
  QMenu menu(this);
  (this->*fill)(menu);
  menu.exec(QCursor::pos());
}

void GraphEditor::contextMenuEvent(QContextMenuEvent* event) {
  const Hit hit = hitAt(event->pos());
  if (hit.kind != HitKind::None) selectFromHit(hit, false);
  QMenu menu(this);
  fillInterpolationMenu(*menu.addMenu(tr("&Interpolation (T)")));
  fillHandleTypeMenu(*menu.addMenu(tr("&Handles (V)")));
  menu.addSeparator();
  connect(menu.addAction(tr("Frame &all (Home)")), &QAction::triggered, this,
          &GraphEditor::frameAll);
  connect(menu.addAction(tr("Frame &selected (F)")), &QAction::triggered, this,
          &GraphEditor::frameSelected);
  // Until channels are chosen elsewhere (dope sheet, channel list), these pick them here.
  connect(menu.addAction(tr("Show all &animated channels")), &QAction::triggered, this,
          [this] { model_.setSelectedChannels(model_.animatedChannels()); });
  connect(menu.addAction(tr("Show the &last touched channel only")), &QAction::triggered, this,
          [this] { model_.setSelectedChannels({}); });
  QAction* normalize = menu.addAction(tr("&Normalize"));
  normalize->setCheckable(true);
  normalize->setChecked(normalized_);
  connect(normalize, &QAction::toggled, this, &GraphEditor::setNormalized);
  menu.exec(event->globalPos());
}

}  // namespace lacrima::editor
