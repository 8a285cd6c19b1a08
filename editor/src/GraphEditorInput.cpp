// GraphEditor's input: what is under the pointer, selection, the drags (keys, handles, box,
// scrub, pan), the wheel, the keys and the menus.
#include <lacrima/editor/GraphEditor.h>

#include <lacrima/editor/ChannelKeyMenus.h>

#include "GraphEditorCurves.h"
#include "GraphEditorLayout.h"

#include <lacrima/common/CurveHandles.h>
#include <lacrima/editing/EditorModel.h>

#include <QContextMenuEvent>
#include <QCursor>
#include <QKeyEvent>
#include <QMenu>
#include <QMouseEvent>
#include <QWheelEvent>

#include <algorithm>
#include <cmath>

namespace lacrima::editor {

using editing::ChannelKey;
using editing::HandleSide;
using namespace detail;

namespace {

bool isDeleteKey(const QKeyEvent& event) {
  const Qt::KeyboardModifiers mods = event.modifiers() & ~Qt::KeypadModifier;
  return event.matches(QKeySequence::Delete) ||
         (mods == Qt::NoModifier && (event.key() == Qt::Key_X || event.key() == Qt::Key_Backspace));
}

}  // namespace

// --- selection and hits ---------------------------------------------------------------------

bool GraphEditor::isShownSelected(int fap, double time) const {
  if (preview_ && drag_ == Drag::MoveKeys) {
    return std::any_of(previewSelection_.begin(), previewSelection_.end(),
                       [&](const ChannelKey& k) { return k.fap == fap && sameTime(k.time, time); });
  }
  return model_.channelKeySelection().contains(ChannelKey{fap, time});
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
  std::vector<ChannelKey> selection = model_.channelKeySelection().keys();
  const bool selected = model_.channelKeySelection().contains(key);
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
  model_.channelKeySelection().select(std::move(selection));
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
  selectionAtPress_ = model_.channelKeySelection().keys();
  switch (pressed_.kind) {
    case HitKind::Key:
      selectFromHit(pressed_, additive);
      drag_ =
          model_.channelKeySelection().contains(ChannelKey{
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
    model_.channelKeySelection().clear();
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
  for (const ChannelKey& key : model_.channelKeySelection().keys()) {
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
  model_.channelKeySelection().select(std::move(selection));
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
    model_.editKeys(*change, text, std::nullopt,
                    drag == Drag::MoveKeys ? std::optional(selection) : std::nullopt);
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
  // The window binds T, F, Home and Delete to other commands; while the graph has focus, these
  // keys are the graph's (as in Blender, where keys act on the editor under the pointer); Delete,
  // X and Backspace delete the selected channel keys, not whole keys.
  if (event->type() == QEvent::ShortcutOverride) {
    const auto* key = static_cast<QKeyEvent*>(event);
    const Qt::KeyboardModifiers mods = key->modifiers() & ~Qt::KeypadModifier;
    const bool graphKey =
        isDeleteKey(*key) ||
        (mods == Qt::NoModifier &&
         (key->key() == Qt::Key_T || key->key() == Qt::Key_V || key->key() == Qt::Key_F ||
          key->key() == Qt::Key_Home ||
          (key->key() == Qt::Key_Period && (key->modifiers() & Qt::KeypadModifier))));
    if (graphKey) {
      event->accept();
      return true;
    }
  }
  return QWidget::event(event);
}

void GraphEditor::keyPressEvent(QKeyEvent* event) {
  if (moodsShown()) {  // the Moods view's keys came up unused: the window's, not the channels'
    event->ignore();
    return;
  }
  if (isDeleteKey(*event)) {
    ChannelKeyMenus::deleteSelected(model_);
    return;
  }
  switch (event->key()) {
    case Qt::Key_T:
      popupMenu(&ChannelKeyMenus::fillInterpolationMenu);
      return;
    case Qt::Key_V:
      popupMenu(&ChannelKeyMenus::fillHandleTypeMenu);
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

void GraphEditor::popupMenu(void (*fill)(QMenu&, editing::EditorModel&)) {
  QMenu menu(this);
  fill(menu, model_);
  menu.exec(QCursor::pos());
}

void GraphEditor::contextMenuEvent(QContextMenuEvent* event) {
  const Hit hit = hitAt(event->pos());
  if (hit.kind != HitKind::None) selectFromHit(hit, false);
  QMenu menu(this);
  ChannelKeyMenus::fillInterpolationMenu(*menu.addMenu(tr("&Interpolation (T)")), model_);
  ChannelKeyMenus::fillHandleTypeMenu(*menu.addMenu(tr("&Handles (V)")), model_);
  connect(menu.addAction(tr("&Delete (X)")), &QAction::triggered, this,
          [this] { ChannelKeyMenus::deleteSelected(model_); });
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
