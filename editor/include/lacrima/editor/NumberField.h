#pragma once
// The editor's one numeric field: a spin box that takes a number exactly as typed or refuses
// it visibly. QSpinBox "fixes up" input as it is typed (it drops characters its validator
// rejects and clamps on Enter), so "-5" became 5 and "999999" became 99999; this field never
// changes what was typed. Its text is read by editing::parseNumber (or a reader of its own, as
// the time field's "55f"), on Enter or when focus leaves:
//   - accepted: the value is taken and shown normalised ("1.5e3" -> "1500"), valueEntered fires;
//   - refused: nothing is taken, the field gets a red frame and red text, and the message
//     ("-5 refused: below 0 — tears_l_eye is 0 … 100000 whole particles") goes to the window's
//     status bar and the field's tooltip. Enter keeps the refused text for correction; Escape
//     puts the shown value back, and so does leaving the field, unless the field keeps refused
//     text (dialogs: their OK then calls commit() and stays open on a refusal, so a dialog
//     never closes with a value other than the one typed).
// Up/Down, Page Up/Down, the wheel (focused only) and the arrow buttons step by singleStep
// inside the range. The placeholder and tooltip show the range.
//
// Space: a number never holds a space, so the field never types one. While the user types
// (text edited and not yet entered) Space does nothing, so a half-typed number is not lost to
// playback; otherwise (focus from a click on the arrows, after Enter or Escape) Space goes on
// to the window's Space shortcut (play / pause), as it does from any other widget.
#include <lacrima/editing/NumberInput.h>

#include <QAbstractSpinBox>

#include <functional>
#include <initializer_list>

namespace lacrima::editor {

class NumberField : public QAbstractSpinBox {
  Q_OBJECT
 public:
  using Reader = std::function<editing::NumberParse(const QString& text)>;
  using Writer = std::function<QString(double value)>;

  explicit NumberField(QWidget* parent = nullptr);

  // The accepted numbers; the range's unit is shown after the value and may be typed.
  void setRange(const editing::NumberRange& range);
  const editing::NumberRange& range() const { return range_; }
  void setSingleStep(double step) { step_ = step; }
  void setDecimals(int decimals);
  // Names the field in refusals: "<subject> is <range text>" (range text: describeRange).
  void setSubject(const QString& subject, const QString& rangeText = {});
  // Replaces parseNumber and formatNumber (the time field reads "55f" and shows "55 f").
  void setReader(Reader reader);
  void setWriter(Writer writer);

  double value() const { return value_; }
  // Shows a value; emits nothing. While the user is typing, only the value is kept and the
  // typed text stays (playback or another edit must not overwrite a half-typed number).
  void setValue(double value);
  // Redraws the shown value with the writer (after its unit changed), unless the user types.
  void refreshText();

  // True while the text was edited by the user and not yet entered or discarded.
  bool isTyping() const { return typing_; }
  // The last refusal's message; empty once the field shows an accepted value again.
  QString refusal() const { return refusal_; }
  // Reads the typed text now, as Enter does; returns false when it was refused.
  bool commit();
  // Drops what was typed and shows the value again.
  void revert();
  // Whether leaving the field with refused text keeps it (red) instead of reverting it.
  void setKeepsRefusedText(bool keep) { keepsRefused_ = keep; }

  void stepBy(int steps) override;
  QValidator::State validate(QString& input, int& pos) const override;
  void fixup(QString& input) const override;

 signals:
  void valueEntered(double value);  // by the user: typed and entered, or stepped
  void entered();                   // Enter took the text (also when the value stayed)
  void refused(const QString& message);

 protected:
  StepEnabled stepEnabled() const override;
  bool event(QEvent* event) override;
  void keyPressEvent(QKeyEvent* event) override;
  void focusOutEvent(QFocusEvent* event) override;
  void paintEvent(QPaintEvent* event) override;

 private:
  void refuse(const QString& typed, const QString& reason);
  void showRefused(bool on);
  void take(double value);
  QString text(double value) const;
  QString rangeText() const;  // the given one, else describeRange(range_)

  editing::NumberRange range_;
  double step_ = 1;
  int decimals_ = 2;
  double value_ = 0;
  QString subject_, rangeText_, refusal_, baseTip_;  // rangeText_: empty = describeRange
  Reader reader_;
  Writer writer_;
  bool typing_ = false;
  bool refusedLook_ = false;
  bool keepsRefused_ = false;
};

// Commits each field (see NumberField::commit); false when any refuses. For a dialog's OK.
bool commitFields(std::initializer_list<NumberField*> fields);

}  // namespace lacrima::editor
