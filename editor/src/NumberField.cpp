#include <lacrima/editor/NumberField.h>

#include <QKeyEvent>
#include <QLineEdit>
#include <QMainWindow>
#include <QPainter>
#include <QStatusBar>
#include <QToolTip>

#include <algorithm>
#include <cmath>

namespace lacrima::editor {
namespace {
const QColor kRefusedRed(0xe0, 0x4f, 0x4f);
constexpr int kStatusMillis = 8000;
}  // namespace

NumberField::NumberField(QWidget* parent) : QAbstractSpinBox(parent) {
  // One value per Enter; with tracking off QAbstractSpinBox never interprets the text itself.
  setKeyboardTracking(false);
  setCorrectionMode(QAbstractSpinBox::CorrectToPreviousValue);
  setAccelerated(true);
  setAlignment(Qt::AlignRight | Qt::AlignVCenter);
  connect(lineEdit(), &QLineEdit::textEdited, this, [this] {
    typing_ = true;
    showRefused(false);  // the user is correcting it
  });
  setRange(range_);
}

void NumberField::setRange(const editing::NumberRange& range) {
  range_ = range;
  lineEdit()->setPlaceholderText(rangeText());
  setValue(std::clamp(value_, range_.min, range_.max));
}

void NumberField::setDecimals(int decimals) {
  decimals_ = std::max(0, decimals);
  refreshText();
}

void NumberField::setSubject(const QString& subject, const QString& rangeText) {
  subject_ = subject;
  rangeText_ = rangeText;
  lineEdit()->setPlaceholderText(this->rangeText());
}

QString NumberField::rangeText() const {
  return rangeText_.isEmpty() ? describeRange(range_) : rangeText_;
}

void NumberField::setReader(Reader reader) { reader_ = std::move(reader); }

void NumberField::setWriter(Writer writer) {
  writer_ = std::move(writer);
  refreshText();
}

QString NumberField::text(double value) const {
  if (writer_) return writer_(value);
  QString shown = editing::formatNumber(value, range_.wholeNumbers ? 0 : decimals_);
  if (!range_.unit.isEmpty()) shown += QLatin1Char(' ') + range_.unit;
  return shown;
}

void NumberField::setValue(double value) {
  value_ = value;
  if (!typing_) refreshText();
}

void NumberField::refreshText() {
  if (typing_) return;
  const QString shown = text(value_);
  if (lineEdit()->text() != shown) lineEdit()->setText(shown);
}

void NumberField::take(double value) {
  typing_ = false;
  showRefused(false);
  refusal_.clear();
  const bool changed = value != value_;
  value_ = value;
  refreshText();
  if (changed) emit valueEntered(value_);
}

bool NumberField::commit() {
  if (!typing_) return true;  // nothing typed: the field holds its value
  const QString typed = lineEdit()->text();
  const editing::NumberParse parse = reader_ ? reader_(typed) : editing::parseNumber(typed, range_);
  if (!parse.accepted()) {
    refuse(typed.trimmed(), parse.reason);
    return false;
  }
  take(*parse.value);
  return true;
}

void NumberField::revert() {
  typing_ = false;
  refusal_.clear();
  showRefused(false);
  refreshText();
}

void NumberField::refuse(const QString& typed, const QString& reason) {
  const QString shown = typed.isEmpty() ? tr("(empty)") : typed;
  refusal_ = subject_.isEmpty()
                 ? tr("%1 refused: %2; the field takes %3").arg(shown, reason, rangeText())
                 : tr("%1 refused: %2 — %3 is %4").arg(shown, reason, subject_, rangeText());
  showRefused(true);
  // Where the user looks: the window's status bar, or the field itself in a dialog.
  if (auto* main = qobject_cast<QMainWindow*>(window()))
    main->statusBar()->showMessage(refusal_, kStatusMillis);
  else if (isVisible())
    QToolTip::showText(mapToGlobal(QPoint(0, height())), refusal_, this);
  emit refused(refusal_);
}

void NumberField::showRefused(bool on) {
  if (on && !refusedLook_) baseTip_ = toolTip();
  if (on)  // also when refused again: the tooltip gives the latest reason
    setToolTip(baseTip_.isEmpty()
                   ? refusal_
                   : refusal_.toHtmlEscaped() + QStringLiteral("<br><br>") + baseTip_);
  if (on == refusedLook_) return;
  refusedLook_ = on;
  if (!on) setToolTip(baseTip_);
  QPalette p = lineEdit()->palette();
  p.setColor(QPalette::Text, on ? kRefusedRed : palette().color(QPalette::Text));
  lineEdit()->setPalette(p);
  update();
}

void NumberField::stepBy(int steps) {
  double v = value_ + steps * step_;
  if (range_.wholeNumbers) v = std::round(v);
  take(std::clamp(v, range_.min, range_.max));
  lineEdit()->selectAll();
}

QAbstractSpinBox::StepEnabled NumberField::stepEnabled() const {
  if (isReadOnly()) return StepNone;
  StepEnabled enabled = StepNone;
  if (value_ > range_.min) enabled |= StepDownEnabled;
  if (value_ < range_.max) enabled |= StepUpEnabled;
  return enabled;
}

// Every text is allowed while typing: the field reads it on Enter and refuses it there, with
// a reason, instead of dropping keystrokes the way QSpinBox's validator does.
QValidator::State NumberField::validate(QString&, int&) const { return QValidator::Acceptable; }

void NumberField::fixup(QString&) const {}

bool NumberField::event(QEvent* event) {
  if (event->type() == QEvent::ShortcutOverride) {
    const auto* key = static_cast<QKeyEvent*>(event);
    if (key->key() == Qt::Key_Space && (key->modifiers() & ~Qt::KeypadModifier) == 0) {
      // Typing: keep the key (keyPressEvent drops it). Otherwise leave it unclaimed, so the
      // window's Space shortcut (play / pause) takes it.
      event->setAccepted(typing_);
      return true;
    }
    if (key->matches(QKeySequence::Undo) || key->matches(QKeySequence::Redo)) {
      // Typing: the line edit undoes the typed text. Otherwise the field shows the document's
      // value, and undoing its text alone would show one the document does not have: the
      // window's Edit ▸ Undo / Redo take the key instead.
      event->setAccepted(typing_);
      return true;
    }
  }
  return QAbstractSpinBox::event(event);
}

void NumberField::keyPressEvent(QKeyEvent* event) {
  switch (event->key()) {
    case Qt::Key_Enter:
    case Qt::Key_Return:
      if (commit()) {
        lineEdit()->selectAll();
        emit entered();
        event->ignore();  // a dialog's default button may act on it, as with QSpinBox
      } else {
        event->accept();  // refused: the dialog stays, the text stays for correcting
      }
      return;
    case Qt::Key_Escape:
      if (typing_ || refusedLook_) {
        revert();
        event->accept();
      } else {
        event->ignore();
      }
      return;
    case Qt::Key_Space:
      event->accept();  // never part of a number
      return;
    default:
      if (!typing_ && (event->matches(QKeySequence::Undo) || event->matches(QKeySequence::Redo))) {
        event->ignore();  // no window action took it: the shown value stays (see event())
        return;
      }
      QAbstractSpinBox::keyPressEvent(event);
  }
}

void NumberField::focusOutEvent(QFocusEvent* event) {
  // Leaving the field enters what was typed, as a spin box does; a refusal is reported and
  // the shown value comes back, so the field never shows a number the document does not have.
  if (typing_ && !commit() && !keepsRefused_) revert();
  QAbstractSpinBox::focusOutEvent(event);
}

void NumberField::paintEvent(QPaintEvent* event) {
  QAbstractSpinBox::paintEvent(event);
  if (!refusedLook_) return;
  QPainter p(this);
  p.setRenderHint(QPainter::Antialiasing);
  p.setPen(QPen(kRefusedRed, 2.0));
  p.drawRoundedRect(QRectF(rect()).adjusted(1, 1, -1, -1), 2, 2);
}

bool commitFields(std::initializer_list<NumberField*> fields) {
  bool all = true;
  for (NumberField* field : fields) all = field->commit() && all;
  return all;
}

}  // namespace lacrima::editor
