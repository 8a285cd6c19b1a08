#include <lacrima/editor/TransportBar.h>

#include <lacrima/editing/EditorModel.h>
#include <lacrima/editing/FrameStepClock.h>
#include <lacrima/editor/EditorTheme.h>
#include <lacrima/editor/NumberField.h>
#include <lacrima/editor/TimeField.h>
#include <lacrima/editor/ToggleLook.h>

#include <QHBoxLayout>
#include <QIcon>
#include <QLabel>
#include <QPainter>
#include <QPainterPath>
#include <QPixmap>
#include <QToolButton>

#include <algorithm>

namespace lacrima::editor {

double previousKeyTime(const editing::EditorModel& model) {
  const auto& keys = model.document().keys.keys();
  const double now = model.currentTime();
  double best = now;
  for (const Keyframe& k : keys)
    if (k.time < now - 1e-9) best = k.time;
  return best;
}

double nextKeyTime(const editing::EditorModel& model) {
  const double now = model.currentTime();
  for (const Keyframe& k : model.document().keys.keys())
    if (k.time > now + 1e-9) return k.time;
  return now;
}

QIcon TransportBar::icon(Glyph glyph, const QColor& colour) {
  QPixmap pixmap(32, 32);
  pixmap.fill(Qt::transparent);
  QPainter p(&pixmap);
  p.setRenderHint(QPainter::Antialiasing);
  p.setPen(Qt::NoPen);
  p.setBrush(colour);
  const auto triangle = [&](double x0, double x1, bool right) {
    QPainterPath t;
    if (right) {
      t.moveTo(x0, 8);
      t.lineTo(x1, 16);
      t.lineTo(x0, 24);
    } else {
      t.moveTo(x1, 8);
      t.lineTo(x0, 16);
      t.lineTo(x1, 24);
    }
    t.closeSubpath();
    p.drawPath(t);
  };
  switch (glyph) {
    case Glyph::Start:
      p.drawRect(QRectF(8, 8, 3, 16));
      triangle(11, 24, false);
      break;
    case Glyph::PreviousKey:
      triangle(6, 16, false);
      triangle(16, 26, false);
      break;
    case Glyph::Play:
      triangle(10, 25, true);
      break;
    case Glyph::Pause:
      p.drawRect(QRectF(9, 8, 5, 16));
      p.drawRect(QRectF(18, 8, 5, 16));
      break;
    case Glyph::NextKey:
      triangle(6, 16, true);
      triangle(16, 26, true);
      break;
    case Glyph::End:
      triangle(8, 21, true);
      p.drawRect(QRectF(21, 8, 3, 16));
      break;
    case Glyph::Loop: {
      p.setBrush(Qt::NoBrush);
      p.setPen(QPen(colour, 2.6));
      p.drawArc(QRectF(7, 9, 18, 14), 40 * 16, 280 * 16);
      p.setPen(Qt::NoPen);
      p.setBrush(colour);
      QPainterPath head;
      head.moveTo(22, 6);
      head.lineTo(27, 12);
      head.lineTo(20, 13);
      head.closeSubpath();
      p.drawPath(head);
      break;
    }
    case Glyph::Key: {
      QPainterPath d;
      d.moveTo(16, 6);
      d.lineTo(26, 16);
      d.lineTo(16, 26);
      d.lineTo(6, 16);
      d.closeSubpath();
      p.drawPath(d);
      break;
    }
  }
  return QIcon(pixmap);
}

TransportBar::TransportBar(editing::EditorModel& model, editing::FrameStepClock& clock,
                           QWidget* parent)
    : QWidget(parent), model_(model), clock_(clock) {
  auto* layout = new QHBoxLayout(this);
  layout->setContentsMargins(6, 2, 6, 2);
  layout->setSpacing(2);
  const QColor ink = palette().color(QPalette::ButtonText);
  const auto button = [&](Glyph glyph, const QString& tip) {
    auto* b = new QToolButton(this);
    b->setIcon(icon(glyph, ink));
    b->setIconSize(QSize(18, 18));
    b->setAutoRaise(true);
    b->setToolTip(tip);
    b->setFocusPolicy(Qt::NoFocus);
    layout->addWidget(b);
    return b;
  };
  QToolButton* start = button(Glyph::Start, tr("First key (Home)"));
  QToolButton* previous = button(Glyph::PreviousKey, tr("Previous key (,)"));
  play_ = button(Glyph::Play, tr("Play / pause (Space)"));
  play_->setObjectName(QStringLiteral("play"));
  QToolButton* next = button(Glyph::NextKey, tr("Next key (.)"));
  QToolButton* end = button(Glyph::End, tr("Last key (End)"));
  loop_ = button(Glyph::Loop, tr("Loop playback"));
  loop_->setObjectName(QStringLiteral("loop"));
  loop_->setCheckable(true);
  loop_->setChecked(clock_.loops());
  showCheckedState(loop_);

  // The unit button first: the field's writer reads it.
  unit_ = new QToolButton(this);
  unit_->setObjectName(QStringLiteral("timeUnit"));
  unit_->setText(tr("f"));
  unit_->setCheckable(true);
  unit_->setToolTip(tr("Show the time in frames (on) or seconds (off)"));
  unit_->setFocusPolicy(Qt::NoFocus);
  showCheckedState(unit_);
  timeField_ = new NumberField(this);
  timeField_->setObjectName(QStringLiteral("time"));
  setUpTimeField(*timeField_, model_, [this] { return timeUnit(); });
  timeField_->setButtonSymbols(QAbstractSpinBox::NoButtons);
  timeField_->setMinimumWidth(84);
  timeField_->setToolTip(
      tr("The playhead. Type a time and press Enter: 2.5 or 2.5s (seconds), 55f (frames); "
         "Up/Down step a frame (Ctrl+G)"));

  time_ = new QLabel(this);
  time_->setMinimumWidth(150);
  time_->setTextFormat(Qt::RichText);
  layout->addSpacing(8);
  layout->addWidget(timeField_);
  layout->addWidget(unit_);
  layout->addSpacing(4);
  layout->addWidget(time_);
  layout->addStretch(1);

  auto* rateLabel = new QLabel(tr("Playback"), this);
  rate_ = new NumberField(this);
  rate_->setObjectName(QStringLiteral("rate"));
  rate_->setRange({1, 120, true, tr("fps")});
  rate_->setSubject(tr("the playback rate"));
  rate_->setValue(static_cast<int>(clock_.rate()));
  rate_->setMinimumWidth(76);
  rate_->setToolTip(tr("Playback rate of the preview (the export rate is the project's fps)"));
  layout->addWidget(rateLabel);
  layout->addWidget(rate_);

  connect(start, &QToolButton::clicked, this,
          [this] { model_.setCurrentTime(model_.document().keys.startTime()); });
  connect(end, &QToolButton::clicked, this, [this] { model_.setCurrentTime(model_.endTime()); });
  connect(previous, &QToolButton::clicked, this,
          [this] { model_.setCurrentTime(previousKeyTime(model_)); });
  connect(next, &QToolButton::clicked, this,
          [this] { model_.setCurrentTime(nextKeyTime(model_)); });
  connect(play_, &QToolButton::clicked, &clock_, &editing::FrameStepClock::toggle);
  connect(loop_, &QToolButton::toggled, &clock_, &editing::FrameStepClock::setLoop);
  connect(rate_, &NumberField::valueEntered, &clock_, [this](double v) { clock_.setRate(v); });
  connect(timeField_, &NumberField::valueEntered, this, [this](double seconds) {
    model_.setCurrentTime(seconds);
    refreshTime();  // shows the snapped time, also when snapping lands where it was
  });
  connect(unit_, &QToolButton::toggled, this, &TransportBar::refreshTime);
  connect(&clock_, &editing::FrameStepClock::playingChanged, this, [this, ink](bool playing) {
    play_->setIcon(icon(playing ? Glyph::Pause : Glyph::Play, ink));
  });
  connect(&model_, &editing::EditorModel::timeChanged, this, &TransportBar::refreshTime);
  connect(&model_, &editing::EditorModel::keysChanged, this, &TransportBar::refreshTime);
  connect(&model_, &editing::EditorModel::settingsChanged, this, &TransportBar::refreshTime);
  refreshTime();
}

editing::TimeUnit TransportBar::timeUnit() const {
  return unit_->isChecked() ? editing::TimeUnit::Frames : editing::TimeUnit::Seconds;
}

void TransportBar::editTime() {
  timeField_->setFocus(Qt::ShortcutFocusReason);
  timeField_->selectAll();
}

void TransportBar::refreshTime() {
  const double t = model_.currentTime();
  const int frame = model_.frameAt(t);
  const int frames = model_.frameAt(model_.endTime());
  const bool onKey = model_.currentKeyIndex() >= 0;
  const QString key =
      onKey ? QStringLiteral(" <span style='color:%1'>◆</span>").arg(theme::keyAccent().name())
            : QString();
  // The field shows one unit; the label gives the other and the length.
  const QString other = timeUnit() == editing::TimeUnit::Frames
                            ? tr("%1 s of %2 s")
                                  .arg(QString::number(t, 'f', 3))
                                  .arg(QString::number(model_.endTime(), 'f', 3))
                            : tr("frame %1 / %2").arg(frame).arg(frames);
  time_->setText(other + key);
  timeField_->setSingleStep(1.0 / model_.document().fps);
  timeField_->setValue(t);
}

}  // namespace lacrima::editor
