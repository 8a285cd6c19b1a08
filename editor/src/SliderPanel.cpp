#include <lacrima/editor/SliderPanel.h>

#include "ChannelText.h"

#include <lacrima/common/FapTable.h>
#include <lacrima/editing/ChannelFilter.h>
#include <lacrima/editing/EditorModel.h>
#include <lacrima/editing/HighLevelCodes.h>
#include <lacrima/editor/ChannelRow.h>
#include <lacrima/editor/EditorTheme.h>
#include <lacrima/editor/ToggleLook.h>

#include <QComboBox>
#include <QCoreApplication>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QMouseEvent>
#include <QPainter>
#include <QScrollArea>
#include <QScrollBar>
#include <QToolButton>
#include <QVBoxLayout>

#include <cmath>

namespace lacrima::editor {

// A foldable group: a painted header (colour, title, keyed count, reset) over its rows.
class GroupSection : public QWidget {
 public:
  GroupSection(FapGroup group, QWidget* parent) : QWidget(parent), group_(group) {
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 2);
    layout->setSpacing(0);
    header_ = new Header(this);
    body_ = new QWidget(this);
    bodyLayout_ = new QVBoxLayout(body_);
    bodyLayout_->setContentsMargins(0, 0, 0, 0);
    bodyLayout_->setSpacing(0);
    layout->addWidget(header_);
    layout->addWidget(body_);
    reset_ = new QToolButton(header_);
    reset_->setText(QStringLiteral("↺"));
    reset_->setAutoRaise(true);
    reset_->setFixedSize(20, 20);
    reset_->setFocusPolicy(Qt::NoFocus);
    reset_->setToolTip(QCoreApplication::translate(
                           "SliderPanel", "Reset every %1 channel to 0 at the current time")
                           .arg(fromView(toString(group))));
  }

  FapGroup group() const { return group_; }
  void addRow(QWidget* row, int fap) {
    bodyLayout_->addWidget(row);
    rows_.push_back({row, fap});
  }
  const std::vector<std::pair<QWidget*, int>>& rows() const { return rows_; }
  QToolButton* resetButton() const { return reset_; }
  std::vector<int> channels() const {
    std::vector<int> out;
    for (const auto& r : rows_) out.push_back(r.second);
    return out;
  }
  void setKeyedCount(int count) {
    if (count == keyed_) return;
    keyed_ = count;
    header_->update();
  }
  void setExpanded(bool on) {
    expanded_ = on;
    body_->setVisible(on || forced_);
    header_->update();
  }
  // A filter shows matching rows even in folded groups.
  void setForcedOpen(bool on) {
    forced_ = on;
    body_->setVisible(expanded_ || forced_);
    header_->update();
  }

 private:
  class Header : public QWidget {
   public:
    explicit Header(GroupSection* section) : QWidget(section), section_(section) {
      setFixedHeight(24);
      setCursor(Qt::PointingHandCursor);
    }

   protected:
    void paintEvent(QPaintEvent*) override {
      QPainter p(this);
      p.setRenderHint(QPainter::Antialiasing);
      p.fillRect(rect(), palette().color(QPalette::Window).darker(112));
      const QColor colour = theme::groupColour(section_->group_);
      p.fillRect(QRect(0, 3, 3, height() - 6), colour);
      // Fold arrow.
      const bool open = section_->expanded_ || section_->forced_;
      QPolygonF arrow;
      const double cx = 12;
      const double cy = height() / 2.0;
      if (open)
        arrow << QPointF(cx - 4, cy - 2) << QPointF(cx + 4, cy - 2) << QPointF(cx, cy + 3);
      else
        arrow << QPointF(cx - 2, cy - 4) << QPointF(cx - 2, cy + 4) << QPointF(cx + 3, cy);
      p.setPen(Qt::NoPen);
      p.setBrush(palette().color(QPalette::WindowText));
      p.drawPolygon(arrow);
      QFont bold = font();
      bold.setBold(true);
      p.setFont(bold);
      p.setPen(palette().color(QPalette::WindowText));
      const QRect textRect = rect().adjusted(22, 0, -30, 0);
      p.drawText(textRect, Qt::AlignVCenter | Qt::AlignLeft, groupTitle(section_->group_));
      if (section_->keyed_ > 0) {
        p.setFont(font());
        p.setPen(theme::keyAccent());
        p.drawText(
            textRect, Qt::AlignVCenter | Qt::AlignRight,
            QCoreApplication::translate("SliderPanel", "%n keyed", nullptr, section_->keyed_));
      }
    }
    void resizeEvent(QResizeEvent*) override {
      section_->reset_->move(width() - 24, (height() - 20) / 2);
    }
    void mousePressEvent(QMouseEvent* event) override {
      if (event->button() == Qt::LeftButton) section_->setExpanded(!section_->expanded_);
    }

   private:
    GroupSection* section_;
  };

  FapGroup group_;
  Header* header_;
  QWidget* body_;
  QVBoxLayout* bodyLayout_;
  QToolButton* reset_;
  std::vector<std::pair<QWidget*, int>> rows_;
  int keyed_ = 0;
  bool expanded_ = true;
  bool forced_ = false;
};

SliderPanel::SliderPanel(editing::EditorModel& model, QWidget* parent)
    : QWidget(parent), model_(model) {
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(4, 4, 0, 0);
  layout->setSpacing(4);

  auto* top = new QHBoxLayout;
  top->setContentsMargins(0, 0, 4, 0);
  filter_ = new QLineEdit(this);
  filter_->setObjectName(QStringLiteral("channelFilter"));
  filter_->setPlaceholderText(tr("Filter: name, number or group  (jaw, 31, 19-22, left brow)"));
  filter_->setClearButtonEnabled(true);
  matchCount_ = new QLabel(this);
  matchCount_->setMinimumWidth(44);
  matchCount_->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
  symmetric_ = new QToolButton(this);
  symmetric_->setText(tr("Symmetric"));
  symmetric_->setCheckable(true);
  showCheckedState(symmetric_);
  symmetric_->setToolTip(
      tr("Symmetric editing: moving a left or right channel moves its mirror channel too"));
  top->addWidget(filter_, 1);
  top->addWidget(matchCount_);
  top->addWidget(symmetric_);
  layout->addLayout(top);

  scroll_ = new QScrollArea(this);
  scroll_->setWidgetResizable(true);
  scroll_->setFrameShape(QFrame::NoFrame);
  scroll_->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
  layout->addWidget(scroll_, 1);
  buildGroups();

  connect(filter_, &QLineEdit::textChanged, this, [this] { applyFilter(); });
  connect(symmetric_, &QToolButton::toggled, &model_, &editing::EditorModel::setSymmetricEdit);
  connect(&model_, &editing::EditorModel::symmetricEditChanged, symmetric_,
          &QToolButton::setChecked);
  connect(&model_, &editing::EditorModel::valuesChanged, this, &SliderPanel::refresh);
  connect(&model_, &editing::EditorModel::focusChannelChanged, this, [this](int fap) {
    if (highlighted_ && rows_[static_cast<std::size_t>(highlighted_)])
      rows_[static_cast<std::size_t>(highlighted_)]->setHighlighted(false);
    highlighted_ = fap;
    if (rows_[static_cast<std::size_t>(fap)])
      rows_[static_cast<std::size_t>(fap)]->setHighlighted(true);
  });
  applyFilter();
  refresh();
  highlighted_ = model_.focusChannel();
  if (ChannelRow* focused = row(highlighted_)) focused->setHighlighted(true);
}

void SliderPanel::buildGroups() {
  auto* content = new QWidget;
  auto* column = new QVBoxLayout(content);
  column->setContentsMargins(0, 0, 4, 0);
  column->setSpacing(0);
  for (int g = static_cast<int>(FapGroup::VisemeExpression); g <= static_cast<int>(FapGroup::Tears);
       ++g) {
    const auto group = static_cast<FapGroup>(g);
    auto* section = new GroupSection(group, content);
    section->setObjectName(QStringLiteral("group-%1").arg(g));
    groups_.push_back(section);
    column->addWidget(section);
    for (const FapInfo& info : fapTable()) {
      if (info.group != group) continue;
      if (isHighLevelFap(info.number)) {
        auto* row = new QWidget(section);
        auto* h = new QHBoxLayout(row);
        h->setContentsMargins(22, 2, 4, 2);
        h->setSpacing(6);
        auto* label =
            new QLabel(QStringLiteral("%1  %2").arg(info.number).arg(fromView(info.name)), row);
        label->setFixedWidth(96);
        label->setToolTip(fromView(info.description));
        auto* combo = new QComboBox(row);
        combo->installEventFilter(WheelGuard::instance());
        combo->setFocusPolicy(Qt::StrongFocus);
        const auto codes = info.number == 1 ? editing::visemeCodes() : editing::expressionCodes();
        for (const editing::HighLevelCode& c : codes) {
          combo->addItem(QStringLiteral("%1 · %2").arg(c.code).arg(fromView(c.name)), c.code);
          combo->setItemData(combo->count() - 1, fromView(c.detail), Qt::ToolTipRole);
        }
        combo->setToolTip(
            fromView(info.description) +
            tr("\nSets FAP %1 at the current time (a code: it holds until the next key).")
                .arg(info.number));
        h->addWidget(label);
        h->addWidget(combo, 1);
        const int fap = info.number;
        connect(combo, &QComboBox::activated, this, [this, fap, combo](int index) {
          model_.setFocusChannel(fap);
          model_.setChannel(fap, combo->itemData(index).toInt());
        });
        if (fap == 1) {
          viseme_ = combo;
          visemeRow_ = row;
        } else {
          expression_ = combo;
          expressionRow_ = row;
          auto* expand = new QToolButton(row);
          expand->setText(tr("Pose"));
          expand->setToolTip(
              tr("Spell the chosen expression out as low-level FAPs (its preset) at the current "
                 "time"));
          expand->setFocusPolicy(Qt::NoFocus);
          h->addWidget(expand);
          connect(expand, &QToolButton::clicked, this, [this, combo] {
            const int code = combo->currentData().toInt();
            if (code > 0) emit expressionPresetRequested(code);
          });
        }
        section->addRow(row, info.number);
        continue;
      }
      auto* row = new ChannelRow(model_, info.number, section);
      rows_[static_cast<std::size_t>(info.number)] = row;
      section->addRow(row, info.number);
    }
    connect(section->resetButton(), &QToolButton::clicked, this, [this, section] {
      const std::vector<int> channels = section->channels();
      model_.resetChannels(channels, tr("Reset %1").arg(fromView(toString(section->group()))));
    });
  }
  column->addStretch(1);
  scroll_->setWidget(content);
}

void SliderPanel::refresh() {
  const FapValues& values = model_.currentValues();
  const ChannelMask keyed = model_.keyedAtCurrentTime();
  const ChannelMask& animated = model_.animatedChannels();
  for (int fap = 3; fap <= kChannelCount; ++fap) {
    const int i = channelIndex(fap);
    const auto state = keyed.test(i)      ? KeyToggle::State::Keyed
                       : animated.test(i) ? KeyToggle::State::Animated
                                          : KeyToggle::State::Unanimated;
    rows_[static_cast<std::size_t>(fap)]->show(values[static_cast<std::size_t>(i)], state);
  }
  for (QComboBox* combo : {viseme_, expression_}) {
    const int fap = combo == viseme_ ? 1 : 2;
    const int code =
        static_cast<int>(std::lround(values[static_cast<std::size_t>(channelIndex(fap))]));
    const int index = combo->findData(code);
    if (index != combo->currentIndex()) {
      const QSignalBlocker block(combo);
      combo->setCurrentIndex(index);
    }
  }
  for (GroupSection* section : groups_) {
    int count = 0;
    for (const auto& r : section->rows()) count += keyed.test(channelIndex(r.second)) ? 1 : 0;
    section->setKeyedCount(count);
  }
}

void SliderPanel::setFilterText(const QString& text) { filter_->setText(text); }

void SliderPanel::applyFilter() {
  const editing::ChannelFilter filter(filter_->text().toStdString());
  int shown = 0;
  QWidget* first = nullptr;
  for (GroupSection* section : groups_) {
    int visible = 0;
    for (const auto& [row, fap] : section->rows()) {
      const bool match = filter.matches(fapInfo(fap));
      row->setVisible(match);
      if (match) {
        ++visible;
        if (!first) first = row;
      }
    }
    section->setVisible(visible > 0);
    section->setForcedOpen(!filter.isEmpty());
    shown += visible;
  }
  matchCount_->setText(filter.isEmpty() ? QString() : tr("%1 / 70").arg(shown));
  if (!filter.isEmpty() && first) scroll_->ensureWidgetVisible(first, 0, 30);
  if (filter.isEmpty()) scroll_->verticalScrollBar()->setValue(0);
}

std::vector<int> SliderPanel::visibleChannels() const {
  std::vector<int> out;
  for (GroupSection* section : groups_) {
    if (section->isHidden()) continue;
    for (const auto& [row, fap] : section->rows())
      if (!row->isHidden()) out.push_back(fap);
  }
  return out;
}

ChannelRow* SliderPanel::row(int fap) const {
  return isValidFap(fap) ? rows_[static_cast<std::size_t>(fap)] : nullptr;
}

QToolButton* SliderPanel::groupResetButton(int group) const {
  for (GroupSection* section : groups_)
    if (static_cast<int>(section->group()) == group) return section->resetButton();
  return nullptr;
}

}  // namespace lacrima::editor
