#include <lacrima/editor/GraphEditor.h>

#include "GraphEditorCurves.h"
#include "GraphEditorLayout.h"

#include <lacrima/common/CurveHandles.h>
#include <lacrima/common/FapTable.h>
#include <lacrima/editing/EditorModel.h>
#include <lacrima/editor/MoodGraph.h>

#include <QSignalBlocker>
#include <QToolButton>

#include <algorithm>
#include <cmath>

namespace lacrima::editor {

using editing::ChannelKey;
using editing::HandleSide;
using namespace detail;

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

  moodGraph_ = new MoodGraph(model_, this);
  moodGraph_->hide();
  moodsButton_ = new QToolButton(this);
  moodsButton_->setObjectName(QStringLiteral("graphMoods"));
  moodsButton_->setText(tr("Moods"));
  moodsButton_->setCheckable(true);
  moodsButton_->setAutoRaise(true);
  moodsButton_->setToolTip(
      tr("Show and key the project's mood curves (sadness, anger, joy, "
         "shame), which Generate crying... can follow"));
  connect(moodsButton_, &QToolButton::toggled, this, &GraphEditor::setMoodsShown);

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
  connect(&model_.channelKeySelection(), &editing::ChannelKeySelection::changed, this,
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
    const double pad = std::max(1.0, 0.1 * std::abs(v0));  // a flat curve: a band around it
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
  for (const ChannelKey& key : model_.channelKeySelection().keys()) {
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

void GraphEditor::setMoodsShown(bool on) {
  const bool showing = on && !moodGraph_->isVisible();
  moodGraph_->setGeometry(rect());
  moodGraph_->setVisible(on);
  // A view the user zoomed or panned is kept; else the moods are framed, as the channels are.
  if (showing && viewTouched_)
    moodGraph_->setTimeView(start_, scale_);
  else if (showing)
    moodGraph_->frameAll();
  normalizeButton_->setVisible(!on);
  moodsButton_->raise();
  const QSignalBlocker block(moodsButton_);
  moodsButton_->setChecked(on);
}

bool GraphEditor::moodsShown() const { return moodGraph_->isVisible(); }

void GraphEditor::resizeEvent(QResizeEvent*) {
  normalizeButton_->adjustSize();
  normalizeButton_->move(width() - normalizeButton_->width() - 4,
                         static_cast<int>(kRulerHeight) + 2);
  moodsButton_->adjustSize();
  moodsButton_->move(normalizeButton_->x() - moodsButton_->width() - 4, normalizeButton_->y());
  moodGraph_->setGeometry(rect());
  // A view the user has not zoomed or panned keeps showing everything as the panel resizes.
  if (framePending_ || !viewTouched_) frameAll();
}

void GraphEditor::showEvent(QShowEvent*) {
  if (framePending_) frameAll();
}

}  // namespace lacrima::editor
