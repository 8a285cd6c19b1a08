#include <lacrima/editor/DopeSheetView.h>

#include <lacrima/editor/ChannelKeyMenus.h>

#include <lacrima/common/FapTable.h>
#include <lacrima/editing/ChannelFilter.h>

#include <QContextMenuEvent>
#include <QCursor>
#include <QKeyEvent>
#include <QMenu>
#include <QMouseEvent>
#include <QScrollBar>
#include <QStyle>
#include <QWheelEvent>

#include <algorithm>
#include <cmath>

namespace lacrima::editor {

using editing::ChannelKey;

namespace {

// The fold arrow of a group row takes the first this many pixels of its name.
constexpr double kFoldArrowWidth = 22.0;

bool additiveClick(const QInputEvent& event) {
  return event.modifiers() & (Qt::ControlModifier | Qt::ShiftModifier);
}

}  // namespace

DopeSheetView::DopeSheetView(editing::EditorModel& model, QWidget* parent)
    : QWidget(parent), model_(model), scroll_(new QScrollBar(Qt::Vertical, this)) {
  setObjectName(QStringLiteral("dopeSheetView"));
  setFocusPolicy(Qt::ClickFocus);
  setAttribute(Qt::WA_OpaquePaintEvent);
  options_.shown.set();
  scroll_->setSingleStep(static_cast<int>(kRowHeight));
  connect(scroll_, &QScrollBar::valueChanged, this, qOverload<>(&QWidget::update));
  // Hidden (another tab in front), the rows wait for the sheet to be shown: a slider drag on
  // a long animation does not pay for rows nobody sees.
  connect(&model_, &editing::EditorModel::keysChanged, this, [this] {
    if (isVisible())
      rebuildRows();
    else
      rowsValid_ = false;
  });
  connect(&model_.channelKeySelection(), &editing::ChannelKeySelection::changed, this, [this] {
    selectedByTimeValid_ = false;
    update();
  });
  connect(&model_, &editing::EditorModel::selectedChannelsChanged, this,
          qOverload<>(&QWidget::update));
  connect(&model_, &editing::EditorModel::settingsChanged, this, qOverload<>(&QWidget::update));
  connect(&model_, &editing::EditorModel::timeChanged, this, [this] {
    if (!isVisible()) return;
    axis_.follow(model_.currentTime(), keysWidth());
    update();
  });
  connect(&model_, &editing::EditorModel::documentReset, this, &DopeSheetView::fitAll);
  rebuildRows();
}

// --- rows ---------------------------------------------------------------------------------

void DopeSheetView::rebuildRows() {
  selectedByTimeValid_ = false;
  rows_ = buildDopeSheetRows(model_.document().keys, options_);
  rowsValid_ = true;
  updateScrollRange();
  update();
}

const std::vector<DopeSheetRow>& DopeSheetView::rows() {
  if (!rowsValid_) rebuildRows();
  return rows_;
}

void DopeSheetView::setFilterText(const QString& text) {
  options_.shown = editing::ChannelFilter(text.toStdString()).matching();
  rebuildRows();
}

void DopeSheetView::setOnlyAnimated(bool on) {
  if (on == options_.onlyAnimated) return;
  options_.onlyAnimated = on;
  rebuildRows();
}

void DopeSheetView::setGroupFolded(FapGroup group, bool folded) {
  options_.folded.set(static_cast<std::size_t>(group), folded);
  rebuildRows();
}

bool DopeSheetView::isGroupFolded(FapGroup group) const {
  return options_.folded.test(static_cast<std::size_t>(group));
}

int DopeSheetView::channelRow(int fap) {
  rows();
  for (std::size_t i = 0; i < rows_.size(); ++i)
    if (rows_[i].kind == DopeSheetRow::Kind::Channel && rows_[i].fap == fap)
      return static_cast<int>(i);
  return -1;
}

int DopeSheetView::groupRow(FapGroup group) {
  rows();
  for (std::size_t i = 0; i < rows_.size(); ++i)
    if (rows_[i].kind == DopeSheetRow::Kind::Group && rows_[i].group == group)
      return static_cast<int>(i);
  return -1;
}

// --- geometry -----------------------------------------------------------------------------

double DopeSheetView::keysWidth() const {
  return std::max(1.0, width() - kNamesWidth - scroll_->width());
}

void DopeSheetView::updateScrollRange() {
  const double content = rows_.size() * kRowHeight;
  const double visible = std::max(0.0, height() - kRulerHeight);
  scroll_->setPageStep(static_cast<int>(visible));
  scroll_->setRange(0, static_cast<int>(std::max(0.0, std::ceil(content - visible))));
}

void DopeSheetView::resizeEvent(QResizeEvent*) {
  const int w = style()->pixelMetric(QStyle::PM_ScrollBarExtent, nullptr, this);
  scroll_->setGeometry(width() - w, static_cast<int>(kRulerHeight), w,
                       height() - static_cast<int>(kRulerHeight));
  updateScrollRange();
  if (fitPending_) fitAll();
}

void DopeSheetView::showEvent(QShowEvent*) {
  if (!rowsValid_) rebuildRows();
  if (fitPending_) fitAll();
}

void DopeSheetView::setView(double startSeconds, double pixelsPerSecond) {
  axis_.set(startSeconds, pixelsPerSecond);
  update();
}

void DopeSheetView::fitAll() {
  if (!isVisible() || keysWidth() < 100) {
    fitPending_ = true;
    return;
  }
  fitPending_ = false;
  axis_.fit(model_.endTime(), keysWidth());
  update();
}

QRectF DopeSheetView::rowRect(int row) const {
  return {0, kRulerHeight + row * kRowHeight - scroll_->value(), width() - scroll_->width() * 1.0,
          kRowHeight};
}

QPointF DopeSheetView::markPosition(int row, double seconds) const {
  return {xOfTime(seconds), rowRect(row).center().y()};
}

QPointF DopeSheetView::namePosition(int row) const {
  return {kFoldArrowWidth + 40.0, rowRect(row).center().y()};
}

int DopeSheetView::rowAtY(double y) const {
  if (y < kRulerHeight) return -1;
  const int row = static_cast<int>(std::floor((y - kRulerHeight + scroll_->value()) / kRowHeight));
  return row < static_cast<int>(rows_.size()) ? row : -1;
}

int DopeSheetView::markAt(int row, double x) const {
  if (row < 0) return -1;
  const auto& keys = model_.document().keys.keys();
  const std::vector<int>& marks = rows_[static_cast<std::size_t>(row)].keys;
  const double t = timeAtX(x);
  const double reach = (kMarkRadius + 2.0) / axis_.scale();
  auto it = std::lower_bound(marks.begin(), marks.end(), t - reach, [&](int k, double v) {
    return keys[static_cast<std::size_t>(k)].time < v;
  });
  int best = -1;
  double bestDistance = reach;
  for (; it != marks.end() && keys[static_cast<std::size_t>(*it)].time <= t + reach; ++it) {
    const double d = std::abs(keys[static_cast<std::size_t>(*it)].time - t);
    if (d <= bestDistance) {
      bestDistance = d;
      best = *it;
    }
  }
  return best;
}

DopeSheetView::Hit DopeSheetView::hitAt(QPointF position) const {
  Hit hit;
  if (position.x() >= width() - scroll_->width()) return hit;
  if (position.y() < kRulerHeight) {
    if (position.x() >= kNamesWidth) hit.area = Hit::Area::Ruler;
    return hit;
  }
  hit.row = rowAtY(position.y());
  if (hit.row < 0) {
    hit.area = position.x() < kNamesWidth ? Hit::Area::None : Hit::Area::Keys;
    return hit;
  }
  if (position.x() < kNamesWidth) {
    hit.area = Hit::Area::Names;
    return hit;
  }
  hit.area = Hit::Area::Keys;
  hit.key = markAt(hit.row, position.x());
  return hit;
}

// --- selection ----------------------------------------------------------------------------

std::vector<ChannelKey> DopeSheetView::markKeys(int row, int key) const {
  if (row < 0 || key < 0) return {};
  return channelKeysOf(rows_[static_cast<std::size_t>(row)],
                       model_.document().keys.keys()[static_cast<std::size_t>(key)]);
}

const std::vector<std::pair<double, ChannelMask>>& DopeSheetView::selectedByTime() const {
  if (selectedByTimeValid_) return selectedByTime_;
  std::vector<ChannelKey> keys =
      model_.channelKeySelection().keys();  // sorted by channel, then time
  std::sort(keys.begin(), keys.end(),
            [](const ChannelKey& a, const ChannelKey& b) { return a.time < b.time; });
  selectedByTime_.clear();
  for (const ChannelKey& k : keys) {
    // Times in the selection are exact key times (the model keeps them so).
    if (selectedByTime_.empty() || selectedByTime_.back().first != k.time)
      selectedByTime_.emplace_back(k.time, ChannelMask{});
    selectedByTime_.back().second.set(static_cast<std::size_t>(channelIndex(k.fap)));
  }
  selectedByTimeValid_ = true;
  return selectedByTime_;
}

bool DopeSheetView::isMarkSelected(int row, int key) const {
  const auto& selected = selectedByTime();
  if (selected.empty()) return false;
  const double t = model_.document().keys.keys()[static_cast<std::size_t>(key)].time;
  const auto it = std::lower_bound(selected.begin(), selected.end(), t,
                                   [](const auto& entry, double v) { return entry.first < v; });
  return it != selected.end() && it->first == t &&
         (it->second & rows_[static_cast<std::size_t>(row)].channels).any();
}

void DopeSheetView::selectRow(int row, bool additive) {
  const DopeSheetRow& r = rows_[static_cast<std::size_t>(row)];
  std::vector<ChannelKey> keys =
      additive ? model_.channelKeySelection().keys() : std::vector<ChannelKey>{};
  for (int k : r.keys) {
    const std::vector<ChannelKey> mark = markKeys(row, k);
    keys.insert(keys.end(), mark.begin(), mark.end());
  }
  model_.channelKeySelection().select(std::move(keys));
  model_.setSelectedChannels(additive ? (model_.selectedChannels() | r.channels) : r.channels);
  if (r.kind == DopeSheetRow::Kind::Channel) model_.setFocusChannel(r.fap);
}

std::vector<ChannelKey> DopeSheetView::keysInBand(const QRectF& band) const {
  std::vector<ChannelKey> out;
  const auto& keys = model_.document().keys.keys();
  const double a = timeAtX(band.left());
  const double b = timeAtX(band.right());
  const int first = std::max(0, rowAtY(std::max(band.top(), kRulerHeight)));
  for (int row = first; row < static_cast<int>(rows_.size()); ++row) {
    const QRectF rect = rowRect(row);
    if (rect.top() > band.bottom()) break;
    if (rect.bottom() < band.top()) continue;
    for (int k : rows_[static_cast<std::size_t>(row)].keys) {
      const double t = keys[static_cast<std::size_t>(k)].time;
      if (t < a) continue;
      if (t > b) break;
      const std::vector<ChannelKey> mark = markKeys(row, k);
      out.insert(out.end(), mark.begin(), mark.end());
    }
  }
  return out;
}

void DopeSheetView::selectAll() {
  if (!rows().empty()) selectRow(0, false);
}

void DopeSheetView::clearSelection() { model_.channelKeySelection().clear(); }

// --- edits --------------------------------------------------------------------------------

void DopeSheetView::apply(const editing::ChannelKeyEdit& edit, const QString& text) {
  if (edit.change.isNoOp()) return;
  model_.editKeys(edit.change, text, std::nullopt, edit.selection);
}

void DopeSheetView::deleteSelected() { ChannelKeyMenus::deleteSelected(model_); }

void DopeSheetView::copySelected() {
  editing::ChannelKeyClip clip =
      editing::copyChannelKeys(model_.document().keys, model_.channelKeySelection().keys());
  if (clip.empty()) {
    emit model_.message(tr("Select channel keys to copy (click marks in the dope sheet)"));
    return;
  }
  clip_ = std::move(clip);
  emit model_.message(
      tr("Copied %n channel key(s)", nullptr, static_cast<int>(clip_.channelKeyCount())));
}

void DopeSheetView::pasteAtPlayhead() {
  if (clip_.empty()) {
    emit model_.message(tr("Nothing to paste: copy channel keys in the dope sheet first"));
    return;
  }
  const int count = static_cast<int>(clip_.channelKeyCount());
  apply(editing::pasteChannelKeys(model_.document().keys, clip_, model_.currentTime(),
                                  model_.document().fps),
        count == 1 ? tr("Paste channel key") : tr("Paste %1 channel keys").arg(count));
}

void DopeSheetView::duplicateToPlayhead() {
  const editing::ChannelKeyClip copy =
      editing::copyChannelKeys(model_.document().keys, model_.channelKeySelection().keys());
  if (copy.empty()) {
    emit model_.message(tr("Select channel keys to duplicate (click marks in the dope sheet)"));
    return;
  }
  apply(editing::pasteChannelKeys(model_.document().keys, copy, model_.currentTime(),
                                  model_.document().fps),
        tr("Duplicate channel keys"));
}

// --- mouse --------------------------------------------------------------------------------

int DopeSheetView::dragFrames(double x) const {
  const double perFrame = model_.frameDuration() * axis_.scale();
  return static_cast<int>(std::lround((x - pressPos_.x()) / perFrame));
}

void DopeSheetView::mousePressEvent(QMouseEvent* event) {
  pressPos_ = event->position();
  if (event->button() == Qt::MiddleButton) {
    drag_ = Drag::Pan;
    panStart_ = axis_.start();
    panScrollStart_ = scroll_->value();
    return;
  }
  if (event->button() != Qt::LeftButton) return;
  const Hit hit = hitAt(pressPos_);
  const bool additive = additiveClick(*event);
  switch (hit.area) {
    case Hit::Area::Ruler:
      drag_ = Drag::Scrub;
      model_.setCurrentTime(timeAtX(pressPos_.x()));
      return;
    case Hit::Area::Names: {
      const DopeSheetRow& row = rows_[static_cast<std::size_t>(hit.row)];
      if (row.kind == DopeSheetRow::Kind::Group && pressPos_.x() < kFoldArrowWidth) {
        setGroupFolded(row.group, !isGroupFolded(row.group));
        return;
      }
      selectRow(hit.row, additive);
      return;
    }
    case Hit::Area::Keys:
      break;
    case Hit::Area::None:
      return;
  }
  if (hit.key >= 0) {
    std::vector<ChannelKey> mark = markKeys(hit.row, hit.key);
    const bool selected = isMarkSelected(hit.row, hit.key);
    if (additive) {
      std::vector<ChannelKey> keys = model_.channelKeySelection().keys();
      const bool all = std::all_of(mark.begin(), mark.end(), [&](const ChannelKey& k) {
        return model_.channelKeySelection().contains(k);
      });
      if (all) {
        std::erase_if(keys, [&](const ChannelKey& k) {
          return std::binary_search(mark.begin(), mark.end(), k);
        });
      } else {
        keys.insert(keys.end(), mark.begin(), mark.end());
      }
      model_.channelKeySelection().select(std::move(keys));
    } else if (!selected) {
      model_.channelKeySelection().select(std::move(mark));
    }
    // A plain click on a mark already selected among others keeps them for a drag, and
    // narrows the selection to the mark when released without one.
    narrowTo_ = !additive && selected ? markKeys(hit.row, hit.key) : std::vector<ChannelKey>{};
    drag_ = isMarkSelected(hit.row, hit.key) ? Drag::PendingMove : Drag::None;
    return;
  }
  bandBase_ = additive ? model_.channelKeySelection().keys() : std::vector<ChannelKey>{};
  if (!additive) clearSelection();
  drag_ = Drag::PendingBand;
}

void DopeSheetView::mouseMoveEvent(QMouseEvent* event) {
  const QPointF pos = event->position();
  const bool moved = (pos - pressPos_).manhattanLength() >= 4;
  switch (drag_) {
    case Drag::Scrub:
      model_.setCurrentTime(timeAtX(pos.x()));
      break;
    case Drag::Pan:
      setView(panStart_ - (pos.x() - pressPos_.x()) / axis_.scale(), axis_.scale());
      scroll_->setValue(panScrollStart_ - static_cast<int>(pos.y() - pressPos_.y()));
      break;
    case Drag::PendingMove:
      if (!moved) break;
      drag_ = Drag::Move;
      [[fallthrough]];
    case Drag::Move:
      ghostFrames_ = dragFrames(pos.x());
      update();
      break;
    case Drag::PendingBand:
      if (!moved) break;
      drag_ = Drag::Band;
      [[fallthrough]];
    case Drag::Band: {
      band_ = QRectF(pressPos_, pos).normalized();
      band_.setLeft(std::max(band_.left(), kNamesWidth));
      std::vector<ChannelKey> keys = bandBase_;
      const std::vector<ChannelKey> spanned = keysInBand(band_);
      keys.insert(keys.end(), spanned.begin(), spanned.end());
      model_.channelKeySelection().select(std::move(keys));
      update();
      break;
    }
    case Drag::None:
      break;
  }
}

void DopeSheetView::mouseReleaseEvent(QMouseEvent* event) {
  const Drag drag = drag_;
  drag_ = Drag::None;
  if (drag == Drag::PendingMove && !narrowTo_.empty())
    model_.channelKeySelection().select(narrowTo_);
  narrowTo_.clear();
  if (drag == Drag::Move) {
    const int frames = dragFrames(event->position().x());
    ghostFrames_ = 0;
    const auto& selected = model_.channelKeySelection().keys();
    if (frames != 0) {
      const QString text = selected.size() == 1 ? tr("Move channel key")
                                                : tr("Move %1 channel keys").arg(selected.size());
      apply(
          editing::moveChannelKeys(model_.document().keys, selected, frames, model_.document().fps),
          text);
    }
  }
  update();
}

void DopeSheetView::wheelEvent(QWheelEvent* event) {
  const bool scrollRows =
      event->position().x() < kNamesWidth || (event->modifiers() & Qt::ControlModifier);
  if (scrollRows) {
    scroll_->setValue(scroll_->value() -
                      static_cast<int>(event->angleDelta().y() / 120.0 * 3 * kRowHeight));
  } else {
    axis_.wheel(event->angleDelta(), event->modifiers() & Qt::ShiftModifier,
                event->position().x() - kNamesWidth);
    update();
  }
  event->accept();
}

void DopeSheetView::contextMenuEvent(QContextMenuEvent* event) {
  const Hit hit = hitAt(event->pos());
  if (hit.key >= 0 && !isMarkSelected(hit.row, hit.key))
    model_.channelKeySelection().select(markKeys(hit.row, hit.key));
  QMenu menu(this);
  const bool any = !model_.channelKeySelection().empty();
  QAction* copy = menu.addAction(tr("Copy"), this, &DopeSheetView::copySelected);
  QAction* paste = menu.addAction(tr("Paste at playhead"), this, &DopeSheetView::pasteAtPlayhead);
  QAction* duplicate =
      menu.addAction(tr("Duplicate to playhead"), this, &DopeSheetView::duplicateToPlayhead);
  QAction* remove = menu.addAction(tr("Delete"), this, &DopeSheetView::deleteSelected);
  ChannelKeyMenus::fillInterpolationMenu(*menu.addMenu(tr("&Interpolation (T)")), model_);
  ChannelKeyMenus::fillHandleTypeMenu(*menu.addMenu(tr("&Handles (V)")), model_);
  copy->setEnabled(any);
  duplicate->setEnabled(any);
  remove->setEnabled(any);
  paste->setEnabled(!clip_.empty());
  menu.addSeparator();
  menu.addAction(tr("Select all"), this, &DopeSheetView::selectAll);
  menu.addAction(tr("Select none"), this, &DopeSheetView::clearSelection);
  menu.addAction(tr("Frame all"), this, &DopeSheetView::fitAll);
  menu.exec(event->globalPos());
}

// --- keys ---------------------------------------------------------------------------------

// The keys the sheet takes from the window's shortcuts while it has focus (Delete, Ctrl+C,
// Ctrl+V and Ctrl+A would otherwise act on whole keys, F would frame the timeline).
bool DopeSheetView::handlesKey(const QKeyEvent& event) const {
  if (event.matches(QKeySequence::Copy) || event.matches(QKeySequence::Paste) ||
      event.matches(QKeySequence::SelectAll) || event.matches(QKeySequence::Delete))
    return true;
  const Qt::KeyboardModifiers mods = event.modifiers() & ~Qt::KeypadModifier;
  switch (event.key()) {
    case Qt::Key_A:
      return mods == Qt::NoModifier || mods == Qt::AltModifier;
    case Qt::Key_X:
    case Qt::Key_Backspace:
    case Qt::Key_F:
    case Qt::Key_T:
    case Qt::Key_V:
      return mods == Qt::NoModifier;
    case Qt::Key_D:
      return mods == Qt::ShiftModifier;
    default:
      return false;
  }
}

bool DopeSheetView::event(QEvent* event) {
  if (event->type() == QEvent::ShortcutOverride && handlesKey(*static_cast<QKeyEvent*>(event))) {
    event->accept();
    return true;
  }
  return QWidget::event(event);
}

void DopeSheetView::keyPressEvent(QKeyEvent* event) {
  if (!handlesKey(*event)) {
    QWidget::keyPressEvent(event);
    return;
  }
  if (event->matches(QKeySequence::Copy)) {
    copySelected();
  } else if (event->matches(QKeySequence::Paste)) {
    pasteAtPlayhead();
  } else if (event->matches(QKeySequence::SelectAll)) {
    selectAll();
  } else if (event->key() == Qt::Key_A) {
    if (event->modifiers() & Qt::AltModifier)
      clearSelection();
    else
      selectAll();
  } else if (event->key() == Qt::Key_D) {
    duplicateToPlayhead();
  } else if (event->key() == Qt::Key_F) {
    fitAll();
  } else if (event->key() == Qt::Key_T || event->key() == Qt::Key_V) {
    QMenu menu(this);
    if (event->key() == Qt::Key_T) {
      ChannelKeyMenus::fillInterpolationMenu(menu, model_);
    } else {
      ChannelKeyMenus::fillHandleTypeMenu(menu, model_);
    }
    menu.exec(QCursor::pos());
  } else {
    deleteSelected();
  }
  event->accept();
}

}  // namespace lacrima::editor
