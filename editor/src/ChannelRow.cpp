#include <lacrima/editor/ChannelRow.h>

#include "ChannelText.h"

#include <lacrima/common/FapTable.h>
#include <lacrima/editing/ChannelLimits.h>
#include <lacrima/editing/EditorModel.h>
#include <lacrima/editor/EditorTheme.h>
#include <lacrima/editor/NumberField.h>
#include <lacrima/editor/ZeroSlider.h>

#include <QCoreApplication>
#include <QHBoxLayout>
#include <QLabel>
#include <QMouseEvent>
#include <QPainter>
#include <QToolButton>

#include <cmath>

namespace lacrima::editor {
namespace {

QString tooltipFor(const FapInfo& info) {
  const editing::ChannelLimits limits = editing::editLimits(info.number);
  QString unit = fromView(toString(info.unit));
  if (info.unit == FapUnit::AU) unit = QStringLiteral("AU (10⁻⁵ rad)");
  QString text = QStringLiteral("<b>%1 &nbsp;%2</b><br>%3<br><br>")
                     .arg(info.number)
                     .arg(fromView(info.name), fromView(info.description));
  text += QCoreApplication::translate("ChannelRow", "Unit: %1 · %2")
              .arg(unit, info.bidirectional
                             ? QCoreApplication::translate("ChannelRow", "bidirectional")
                             : QCoreApplication::translate("ChannelRow", "unidirectional"));
  if (!info.featurePoint.empty())
    text += QCoreApplication::translate("ChannelRow", " · feature point %1")
                .arg(fromView(info.featurePoint));
  text += QStringLiteral("<br>") +
          QCoreApplication::translate("ChannelRow", "Slider %1 … %2, typed values %3 … %4")
              .arg(info.sliderMin)
              .arg(info.sliderMax)
              .arg(limits.min)
              .arg(limits.max);
  text += QStringLiteral("<br><i>") +
          QCoreApplication::translate("ChannelRow",
                                      "Drag the handle: %1 px cross the slider's range; Shift: "
                                      "10x finer, Ctrl: 5x coarser. Double-click resets.")
              .arg(ZeroSlider::kPixelsPerRange) +
          QStringLiteral("</i>");
  return text;
}

// What a channel's field takes, in words: "0 … 100000 whole particles", "-18600 … 18600 AU".
QString rangeText(const FapInfo& info, const editing::ChannelLimits& limits) {
  const QString span = QStringLiteral("%1 … %2").arg(limits.min).arg(limits.max);
  if (isTearChannel(info.number))
    return QCoreApplication::translate("ChannelRow", "%1 whole particles").arg(span);
  if (isHighLevelFap(info.number))
    return QCoreApplication::translate("ChannelRow", "%1 (codes)").arg(span);
  return QCoreApplication::translate("ChannelRow", "%1 %2, whole numbers")
      .arg(span, fromView(toString(info.unit)));
}

}  // namespace

WheelGuard* WheelGuard::instance() {
  static WheelGuard* guard = new WheelGuard(QCoreApplication::instance());
  return guard;
}

bool WheelGuard::eventFilter(QObject* watched, QEvent* event) {
  if (event->type() == QEvent::Wheel) {
    auto* widget = qobject_cast<QWidget*>(watched);
    if (widget && !widget->hasFocus()) {
      event->ignore();
      return true;
    }
  }
  return QObject::eventFilter(watched, event);
}

ChannelRow::ChannelRow(editing::EditorModel& model, int fap, QWidget* parent)
    : QWidget(parent), model_(model), fap_(fap) {
  const FapInfo& info = fapInfo(fap);
  const editing::ChannelLimits limits = editing::editLimits(fap);
  setObjectName(QStringLiteral("channel-%1").arg(fap));

  auto* layout = new QHBoxLayout(this);
  layout->setContentsMargins(4, 1, 4, 1);
  layout->setSpacing(4);

  key_ = new KeyToggle(this);
  number_ = new QLabel(QString::number(fap), this);
  number_->setFixedWidth(20);
  number_->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
  QPalette dim = number_->palette();
  dim.setColor(QPalette::WindowText, dim.color(QPalette::WindowText).darker(150));
  number_->setPalette(dim);

  name_ = new QLabel(fromView(info.name), this);
  name_->setFixedWidth(138);
  name_->setTextFormat(Qt::PlainText);

  slider_ = new ZeroSlider(info.sliderMin, info.sliderMax, info.quantizerStep,
                           theme::groupColour(info.group), this);

  field_ = new NumberField(this);
  field_->setObjectName(QStringLiteral("value"));
  field_->setRange({double(limits.min), double(limits.max), true, {}});
  field_->setSubject(fromView(info.name), rangeText(info, limits));
  field_->setButtonSymbols(QAbstractSpinBox::NoButtons);
  field_->setFixedWidth(58);
  field_->setFocusPolicy(Qt::StrongFocus);
  field_->installEventFilter(WheelGuard::instance());
  field_->setSingleStep(info.quantizerStep);

  reset_ = new QToolButton(this);
  reset_->setText(QStringLiteral("↺"));
  reset_->setAutoRaise(true);
  reset_->setFixedSize(20, 20);
  reset_->setToolTip(tr("Reset %1 to 0 at the current time").arg(fromView(info.name)));
  reset_->setFocusPolicy(Qt::NoFocus);

  layout->addWidget(key_);
  layout->addWidget(number_);
  layout->addWidget(name_);
  layout->addWidget(slider_, 1);
  layout->addWidget(field_);
  layout->addWidget(reset_);

  const QString tip = tooltipFor(info);
  name_->setToolTip(tip);
  number_->setToolTip(tip);
  slider_->setToolTip(tip);
  field_->setToolTip(tip);

  connect(slider_, &ZeroSlider::dragStarted, this, [this] {
    session_ = model_.beginDragSession();
    model_.setFocusChannel(fap_);
  });
  connect(slider_, &ZeroSlider::valueEdited, this, [this](int v) { edit(v); });
  connect(slider_, &ZeroSlider::dragFinished, this, [this] { session_ = 0; });
  connect(slider_, &ZeroSlider::resetRequested, this, [this] {
    const int one[] = {fap_};
    model_.resetChannels(one, tr("Reset %1").arg(name_->text()));
  });
  connect(field_, &NumberField::valueEntered, this, [this](double v) {
    model_.setFocusChannel(fap_);
    edit(static_cast<int>(std::lround(v)));
  });
  connect(reset_, &QToolButton::clicked, this, [this] {
    const int one[] = {fap_};
    model_.setFocusChannel(fap_);
    model_.resetChannels(one, tr("Reset %1").arg(name_->text()));
  });
  connect(key_, &KeyToggle::clicked, this, [this] {
    model_.setFocusChannel(fap_);
    if (model_.keyedAtCurrentTime().test(channelIndex(fap_))) {
      model_.unkeyChannel(fap_);
    } else {
      model_.setChannels({{fap_, model_.currentValue(fap_)}}, tr("Key %1").arg(name_->text()));
    }
  });
}

void ChannelRow::edit(int value) {
  if (value == shownValue_) return;
  shownValue_ = value;
  model_.setChannel(fap_, value, slider_->isDragging() ? session_ : 0);
}

void ChannelRow::show(float value, KeyToggle::State state) {
  const int v = static_cast<int>(std::lround(value));
  key_->setState(state);
  slider_->setEmphasis(state == KeyToggle::State::Keyed);
  if (v == shownValue_ && field_->value() == v && slider_->value() == v) return;
  shownValue_ = v;
  slider_->setValue(v);
  field_->setValue(v);
}

void ChannelRow::setHighlighted(bool on) {
  if (on == highlighted_) return;
  highlighted_ = on;
  update();
}

void ChannelRow::paintEvent(QPaintEvent*) {
  if (!highlighted_) return;
  QPainter p(this);
  QColor c = palette().color(QPalette::Highlight);
  c.setAlphaF(0.16);
  p.fillRect(rect(), c);
}

void ChannelRow::mousePressEvent(QMouseEvent* event) {
  model_.setFocusChannel(fap_);
  QWidget::mousePressEvent(event);
}

}  // namespace lacrima::editor
