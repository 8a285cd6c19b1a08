// Typed inputs, driven like a user on real widgets (offscreen): numbers are taken exactly
// as typed or refused visibly with nothing changed, the time field jumps, Space plays from a
// numeric field, slider drags scale with the channel's range, toggles show their state.
#include <lacrima/common/FapTable.h>
#include <lacrima/editing/EditorModel.h>
#include <lacrima/editing/FrameStepClock.h>
#include <lacrima/editor/ChannelRow.h>
#include <lacrima/editor/KeyListPanel.h>
#include <lacrima/editor/KeyTableModel.h>
#include <lacrima/editor/MainWindow.h>
#include <lacrima/editor/NumberField.h>
#include <lacrima/editor/PresetPanel.h>
#include <lacrima/editor/SliderPanel.h>
#include <lacrima/editor/TimelineWidget.h>
#include <lacrima/editor/TransportBar.h>
#include <lacrima/editor/ZeroSlider.h>

#include <QAction>
#include <QApplication>
#include <QLineEdit>
#include <QSettings>
#include <QStatusBar>
#include <QTableView>
#include <QTemporaryDir>
#include <QToolButton>
#include <QtTest>

#include <cmath>
#include <memory>

using namespace lacrima;
using namespace lacrima::editor;

namespace {

constexpr int kOpenJaw = 3;       // 0 … 10800
constexpr int kRaiseBMidlip = 5;  // slider -1860 … 1860, typed -18600 … 18600
constexpr int kTearsLeft = 69;    // 0 … 100000 whole particles

// Focuses a field, replaces its text by typing `text` key by key, and presses Enter.
void typeInto(NumberField* field, const QString& text) {
  field->setFocus();
  field->selectAll();
  QTest::keyClicks(field, text);
  QTest::keyClick(field, Qt::Key_Return);
}

QString shownText(NumberField* field) { return field->findChild<QLineEdit*>()->text(); }

// Moves the pointer of a drag begun with mousePress to x, with modifiers held.
void moveTo(QWidget* widget, int x, Qt::KeyboardModifiers modifiers = Qt::NoModifier) {
  QMouseEvent move(QEvent::MouseMove, QPointF(x, widget->height() / 2),
                   widget->mapToGlobal(QPointF(0, 0)), Qt::NoButton, Qt::LeftButton, modifiers);
  QCoreApplication::sendEvent(widget, &move);
}

// The x of a slider's handle (ZeroSlider's 6-px margins either side of the track).
int handleX(const ZeroSlider* slider) {
  const double span = slider->width() - 12;
  return static_cast<int>(std::lround(6 + double(slider->value() - slider->minimum()) /
                                              (slider->maximum() - slider->minimum()) * span));
}

}  // namespace

class EditorInputsTest : public QObject {
  Q_OBJECT

 private:
  QTemporaryDir recoveryDir_;
  std::unique_ptr<MainWindow> window_;

  MainWindow& window() { return *window_; }
  editing::EditorModel& model() { return window_->model(); }
  NumberField* field(int fap) { return window().sliders()->row(fap)->valueField(); }

  // Types `text` into a channel's field and checks it was refused with nothing changed: the
  // document, the undo stack, the shown value; the typed text stays as typed, marked, and the
  // status bar says why with the range.
  void expectRefused(int fap, const QString& text, const QString& reason) {
    const ProjectDocument before = model().document();
    const int steps = model().undoStack()->count();
    const double shown = field(fap)->value();
    typeInto(field(fap), text);
    QVERIFY(model().document() == before);
    QCOMPARE(model().undoStack()->count(), steps);
    QCOMPARE(field(fap)->value(), shown);
    QCOMPARE(shownText(field(fap)), text);  // not "5", not "153", not "99999"
    QVERIFY(field(fap)->isTyping());        // still there to correct
    const QString message = field(fap)->refusal();
    QVERIFY2(message.startsWith(text + QStringLiteral(" refused: ") + reason), qPrintable(message));
    QVERIFY2(message.contains(QString::fromUtf8(fapInfo(fap).name.data())), qPrintable(message));
    QCOMPARE(window().statusBar()->currentMessage(), message);
    QVERIFY(field(fap)->toolTip().startsWith(message));
    // Escape puts the shown value back and clears the mark.
    QTest::keyClick(field(fap), Qt::Key_Escape);
    QVERIFY(!field(fap)->isTyping());
    QCOMPARE(shownText(field(fap)), QString::number(shown));
    QVERIFY(!field(fap)->toolTip().startsWith(message));
  }

 private slots:
  void initTestCase() {
    QStandardPaths::setTestModeEnabled(true);
    QCoreApplication::setOrganizationName(QStringLiteral("lacrima-test"));
    QCoreApplication::setApplicationName(QStringLiteral("editor-inputs-test"));
    QSettings().clear();
  }

  void init() {
    EditorOptions options;
    options.preview = false;
    options.interactive = false;
    options.offerRecovery = false;
    options.recoveryDirectory = recoveryDir_.path();
    window_ = std::make_unique<MainWindow>(options);
    window_->resize(1400, 900);
    window_->show();
    window_->activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(window_.get()));
  }

  void cleanup() {
    window_->model().markSaved();
    window_->close();
    window_.reset();
  }

  void theIssuesNumbersAreRefusedNotRepaired() {
    expectRefused(kTearsLeft, QStringLiteral("-5"), QStringLiteral("below 0"));
    expectRefused(kTearsLeft, QStringLiteral("abc1.5e3"), QStringLiteral("not a number"));
    expectRefused(kTearsLeft, QStringLiteral("999999"), QStringLiteral("above 100000"));
    expectRefused(kTearsLeft, QStringLiteral("2.5"), QStringLiteral("not a whole number"));
    expectRefused(kOpenJaw, QStringLiteral("-300"), QStringLiteral("below 0"));
    QVERIFY(field(kTearsLeft)->refusal().isEmpty());  // Escape cleared it
    QVERIFY(model().document().keys.empty());
    QCOMPARE(model().undoStack()->count(), 0);
    // The refusal names the range the way the channel counts it.
    typeInto(field(kTearsLeft), QStringLiteral("-5"));
    QCOMPARE(field(kTearsLeft)->refusal(),
             QStringLiteral("-5 refused: below 0 — tears_l_eye is 0 … 100000 whole particles"));
  }

  void numbersInRangeAreTakenWithTheirSign() {
    typeInto(field(kRaiseBMidlip), QStringLiteral("-300"));
    QCOMPARE(model().currentValue(kRaiseBMidlip), -300.0f);
    QCOMPARE(model().undoStack()->count(), 1);
    QVERIFY(field(kRaiseBMidlip)->refusal().isEmpty());
    typeInto(field(kTearsLeft), QStringLiteral("1.5e3"));
    QCOMPARE(model().currentValue(kTearsLeft), 1500.0f);
    QCOMPARE(shownText(field(kTearsLeft)), QStringLiteral("1500"));  // shown normalised
    QCOMPARE(model().undoStack()->count(), 2);
    typeInto(field(kTearsLeft), QStringLiteral("100000"));  // the maximum itself
    QCOMPARE(model().currentValue(kTearsLeft), 100000.0f);
    QCOMPARE(model().undoStack()->count(), 3);
    // A refusal after accepted values leaves them all alone.
    expectRefused(kTearsLeft, QStringLiteral("100001"), QStringLiteral("above 100000"));
    QCOMPARE(model().currentValue(kTearsLeft), 100000.0f);
  }

  void leavingARefusedFieldPutsTheValueBack() {
    typeInto(field(kOpenJaw), QStringLiteral("120"));
    QCOMPARE(model().currentValue(kOpenJaw), 120.0f);
    typeInto(field(kOpenJaw), QStringLiteral("-300"));
    QVERIFY(!field(kOpenJaw)->refusal().isEmpty());
    field(kOpenJaw)->clearFocus();
    QCOMPARE(shownText(field(kOpenJaw)), QStringLiteral("120"));
    QCOMPARE(model().currentValue(kOpenJaw), 120.0f);
    QCOMPARE(model().undoStack()->count(), 1);
    // Typed and left without Enter: taken, as a spin box takes it.
    field(kOpenJaw)->setFocus();
    field(kOpenJaw)->selectAll();
    QTest::keyClicks(field(kOpenJaw), QStringLiteral("240"));
    field(kOpenJaw)->clearFocus();
    QCOMPARE(model().currentValue(kOpenJaw), 240.0f);
    QCOMPARE(model().undoStack()->count(), 2);
  }

  void arrowKeysStepByTheChannelsStep() {
    NumberField* jaw = field(kOpenJaw);
    typeInto(jaw, QStringLiteral("100"));
    QTest::keyClick(jaw, Qt::Key_Up);
    const int step = fapInfo(kOpenJaw).quantizerStep;
    QCOMPARE(model().currentValue(kOpenJaw), float(100 + step));
    QTest::keyClick(jaw, Qt::Key_Down);
    QTest::keyClick(jaw, Qt::Key_Down);
    QCOMPARE(model().currentValue(kOpenJaw), float(100 - step));
    QCOMPARE(model().undoStack()->count(), 4);
    // Stepping stops at the ends of the range instead of passing them.
    typeInto(jaw, QStringLiteral("0"));
    QTest::keyClick(jaw, Qt::Key_Down);
    QCOMPARE(model().currentValue(kOpenJaw), 0.0f);
    // The wheel steps a focused field; over an unfocused one it scrolls the list instead.
    const auto wheel = [jaw](int notches) {
      QWheelEvent event(QPointF(5, 5), jaw->mapToGlobal(QPointF(5, 5)), {}, {0, 120 * notches},
                        Qt::NoButton, Qt::NoModifier, Qt::NoScrollPhase, false);
      QCoreApplication::sendEvent(jaw, &event);
    };
    wheel(1);
    QCOMPARE(model().currentValue(kOpenJaw), float(step));
    jaw->clearFocus();
    wheel(1);
    QCOMPARE(model().currentValue(kOpenJaw), float(step));
  }

  void theTimeFieldJumps() {
    TransportBar* transport = window().transport();
    NumberField* time = transport->timeField();
    QCOMPARE(shownText(time), QStringLiteral("0 s"));
    typeInto(time, QStringLiteral("2.5"));
    QCOMPARE(model().currentTime(), 2.5);
    QCOMPARE(shownText(time), QStringLiteral("2.5 s"));
    typeInto(time, QStringLiteral("0s"));
    QCOMPARE(model().currentTime(), 0.0);
    typeInto(time, QStringLiteral("55f"));  // frames at the project's 22 fps
    QCOMPARE(model().currentTime(), 2.5);
    // Snapped to the frame grid as setCurrentTime snaps: 1.01 s is frame 22.
    typeInto(time, QStringLiteral("1.01"));
    QCOMPARE(model().currentTime(), 1.0);
    QCOMPARE(shownText(time), QStringLiteral("1 s"));
    // Frames shown: a bare number is a frame; the button shows that it is on.
    QTest::mouseClick(transport->timeUnitButton(), Qt::LeftButton);
    QVERIFY(transport->timeUnitButton()->isChecked());
    QCOMPARE(shownText(time), QStringLiteral("22 f"));
    typeInto(time, QStringLiteral("44"));
    QCOMPARE(model().currentTime(), 2.0);
    QCOMPARE(shownText(time), QStringLiteral("44 f"));
    QTest::keyClick(time, Qt::Key_Up);  // a frame on
    QCOMPARE(model().frameAt(model().currentTime()), 45);
    // Refused: the playhead stays.
    for (const char* bad : {"-1", "2.5f", "3601 s", "abc"}) {
      typeInto(time, QString::fromUtf8(bad));
      QVERIFY2(!time->refusal().isEmpty(), bad);
      QCOMPARE(model().frameAt(model().currentTime()), 45);
      QCOMPARE(window().statusBar()->currentMessage(), time->refusal());
      QTest::keyClick(time, Qt::Key_Escape);
    }
    QCOMPARE(model().undoStack()->count(), 0);  // moving the playhead edits nothing
  }

  // The Keys table's time cells are time fields too: typed as in the transport, refused alike.
  void keyTimesAreTypedLikeTheTimeField() {
    model().setCurrentTime(1.0);
    typeInto(field(kOpenJaw), QStringLiteral("10"));
    const int steps = model().undoStack()->count();
    QTableView* table = window().keyList()->view();
    const QModelIndex cell = table->model()->index(0, KeyTableModel::TimeColumn);
    const auto editTo = [&](const QString& text) {
      table->setCurrentIndex(cell);
      table->edit(cell);
      auto* editor = table->findChild<NumberField*>();
      QVERIFY(editor);
      QCOMPARE(shownText(editor), QStringLiteral("1 s"));
      typeInto(editor, text);
      QCoreApplication::processEvents();  // the view commits and closes the editor queued
    };
    editTo(QStringLiteral("-1"));
    QCOMPARE(model().document().keys.keys().front().time, 1.0);
    QCOMPARE(model().undoStack()->count(), steps);
    QVERIFY(window().statusBar()->currentMessage().startsWith(
        QStringLiteral("-1 refused: before 0 s")));
    QTRY_VERIFY(!table->findChild<NumberField*>());
    editTo(QStringLiteral("55f"));
    QCOMPARE(model().document().keys.keys().front().time, 2.5);
    QCOMPARE(model().undoStack()->count(), steps + 1);
  }

  void ctrlGFocusesTheTimeField() {
    model().setChannel(kOpenJaw, 100.0);  // a key at 0 s, so K has a channel to key
    window().sliders()->row(kOpenJaw)->slider()->setFocus();
    QTest::keySequence(&window(), QKeySequence(QStringLiteral("Ctrl+G")));
    NumberField* time = window().transport()->timeField();
    QVERIFY(time->hasFocus());
    QCOMPARE(time->findChild<QLineEdit*>()->selectedText(), shownText(time));
    QTest::keyClicks(time, QStringLiteral("33f"));
    QTest::keyClick(time, Qt::Key_Return);
    QCOMPARE(model().currentTime(), 1.5);
    // Enter hands the keys back to the animation view: K keys there, not into the field.
    QVERIFY(!time->hasFocus());
    QVERIFY(window().timeline()->hasFocus());
    QCOMPARE(model().document().keys.keys().size(), std::size_t{1});
    QTest::keyClick(QApplication::focusWidget(), Qt::Key_K);
    QCOMPARE(model().document().keys.keys().size(), std::size_t{2});
    QCOMPARE(model().document().keys.keys().back().time, 1.5);
  }

  // With the cursor in a value field that shows the document's value, Ctrl+Z is the document's
  // undo (the field, the slider and the document agree); while typing, it undoes the typing.
  void undoInAValueFieldUndoesTheDocument() {
    typeInto(field(kOpenJaw), QStringLiteral("500"));
    QCOMPARE(model().currentValue(kOpenJaw), 500.0f);
    QVERIFY(field(kOpenJaw)->hasFocus());
    QTest::keySequence(QApplication::focusWidget(), QKeySequence::Undo);
    QCOMPARE(model().currentValue(kOpenJaw), 0.0f);
    QCOMPARE(shownText(field(kOpenJaw)), QStringLiteral("0"));
    QCOMPARE(window().sliders()->row(kOpenJaw)->slider()->value(), 0);
    QTest::keySequence(QApplication::focusWidget(), QKeySequence(QStringLiteral("Ctrl+Shift+Z")));
    QCOMPARE(model().currentValue(kOpenJaw), 500.0f);
    QCOMPARE(shownText(field(kOpenJaw)), QStringLiteral("500"));
    // While typing: the typed text goes, the document stays.
    const int steps = model().undoStack()->count();
    QTest::keyClicks(field(kOpenJaw), QStringLiteral("7"));
    QVERIFY(field(kOpenJaw)->isTyping());
    QTest::keySequence(QApplication::focusWidget(), QKeySequence::Undo);
    QCOMPARE(model().undoStack()->count(), steps);
    QCOMPARE(model().currentValue(kOpenJaw), 500.0f);
  }

  void spacePlaysFromANumericFieldUnlessTyping() {
    typeInto(field(kOpenJaw), QStringLiteral("10"));
    model().setCurrentTime(1.0);
    typeInto(field(kOpenJaw), QStringLiteral("220"));  // Enter: the field keeps focus
    model().setCurrentTime(0.0);
    QVERIFY(field(kOpenJaw)->hasFocus());
    QVERIFY(!window().clock().isPlaying());
    QTest::keyClick(field(kOpenJaw), Qt::Key_Space);
    QVERIFY(window().clock().isPlaying());
    QTest::keyClick(field(kOpenJaw), Qt::Key_Space);
    QVERIFY(!window().clock().isPlaying());
    QCOMPARE(shownText(field(kOpenJaw)).contains(QLatin1Char(' ')), false);
    // Focus by a click (no typing yet), in the transport's rate field: Space plays too.
    NumberField* rate = window().transport()->rateBox();
    QTest::mouseClick(rate, Qt::LeftButton);
    QVERIFY(rate->hasFocus());
    QTest::keyClick(rate, Qt::Key_Space);
    QVERIFY(window().clock().isPlaying());
    QTest::keyClick(rate, Qt::Key_Space);
    QVERIFY(!window().clock().isPlaying());
    // While typing, Space neither plays nor types: the half-typed number stays as it is.
    field(kOpenJaw)->setFocus();
    field(kOpenJaw)->selectAll();
    QTest::keyClicks(field(kOpenJaw), QStringLiteral("12"));
    QTest::keyClick(field(kOpenJaw), Qt::Key_Space);
    QVERIFY(!window().clock().isPlaying());
    QCOMPARE(shownText(field(kOpenJaw)), QStringLiteral("12"));
    QTest::keyClick(field(kOpenJaw), Qt::Key_Return);
    QCOMPARE(model().currentValue(kOpenJaw), 12.0f);
    QTest::keyClick(field(kOpenJaw), Qt::Key_Space);  // entered: Space plays again
    QVERIFY(window().clock().isPlaying());
    window().clock().pause();
    // A free-text field (the channel filter) takes Space as a character.
    QLineEdit* filter = window().sliders()->filterBox();
    filter->setFocus();
    QTest::keyClicks(filter, QStringLiteral("left brow"));
    QCOMPARE(filter->text(), QStringLiteral("left brow"));
    QVERIFY(!window().clock().isPlaying());
  }

  void theRateAndIntensityFieldsAreHonestToo() {
    NumberField* rate = window().transport()->rateBox();
    QCOMPARE(shownText(rate), QStringLiteral("22 fps"));
    typeInto(rate, QStringLiteral("30fps"));
    QCOMPARE(window().clock().rate(), 30.0);
    QCOMPARE(shownText(rate), QStringLiteral("30 fps"));
    typeInto(rate, QStringLiteral("0"));
    QVERIFY(rate->refusal().startsWith(QStringLiteral("0 refused: below 1")));
    QCOMPARE(window().clock().rate(), 30.0);
    QTest::keyClick(rate, Qt::Key_Escape);

    NumberField* intensity = window().presets()->intensityField();
    QCOMPARE(shownText(intensity), QStringLiteral("100 %"));
    typeInto(intensity, QStringLiteral("200"));
    QVERIFY(!intensity->refusal().isEmpty());
    QCOMPARE(window().presets()->intensity(), 1.0);
    typeInto(intensity, QStringLiteral("80%"));
    QCOMPARE(window().presets()->intensity(), 0.8);
    QCOMPARE(shownText(intensity), QStringLiteral("80 %"));
  }

  // The drag rule: 600 px cross the slider's range; Shift is ten times finer, Ctrl five times
  // coarser. raise_b_midlip's slider spans 3720, so 60 px move it by 372 (the issue's drag
  // moved it by 1,410).
  void sliderDragsScaleWithTheChannelsRange() {
    ZeroSlider* slider = window().sliders()->row(kRaiseBMidlip)->slider();
    const double range = slider->maximum() - slider->minimum();
    QCOMPARE(range, 3720.0);
    int pressed = 0;  // the value right after the press
    const auto drag = [&](int dx, Qt::KeyboardModifiers modifiers) {
      typeInto(field(kRaiseBMidlip), QStringLiteral("50"));
      field(kRaiseBMidlip)->clearFocus();
      const int x = handleX(slider);
      QTest::mousePress(slider, Qt::LeftButton, modifiers, QPoint(x, slider->height() / 2));
      pressed = slider->value();
      for (int step = 1; step <= 6; ++step) moveTo(slider, x + dx * step / 6, modifiers);
      QTest::mouseRelease(slider, Qt::LeftButton, modifiers, QPoint(x + dx, slider->height() / 2));
      return model().currentValue(kRaiseBMidlip);
    };
    const int steps = model().undoStack()->count();
    QCOMPARE(drag(60, Qt::NoModifier), float(50 + std::lround(60 * range / 600)));  // 422
    QCOMPARE(pressed, 50);  // a press on the handle grabs it without a jump
    QCOMPARE(model().undoStack()->count(), steps + 2);  // the typed 50, then one drag step
    QCOMPARE(drag(60, Qt::ShiftModifier), float(50 + std::lround(60 * range / 6000)));  // 87
    QCOMPARE(drag(-60, Qt::ControlModifier), float(50 - std::lround(60 * range / 120)));
    QCOMPARE(drag(60, Qt::ControlModifier), 1860.0f);  // the slider's end
    // Shift pressed mid-drag goes on from where the value is, without a jump.
    typeInto(field(kRaiseBMidlip), QStringLiteral("0"));
    field(kRaiseBMidlip)->clearFocus();
    const int x = handleX(slider);
    QTest::mousePress(slider, Qt::LeftButton, {}, QPoint(x, slider->height() / 2));
    moveTo(slider, x + 30);
    const int before = slider->value();
    QCOMPARE(before, static_cast<int>(std::lround(30 * range / 600)));  // 186
    moveTo(slider, x + 30, Qt::ShiftModifier);
    QCOMPARE(slider->value(), before);
    moveTo(slider, x + 60, Qt::ShiftModifier);
    QCOMPARE(slider->value(), before + static_cast<int>(std::lround(30 * range / 6000)));
    QTest::mouseRelease(slider, Qt::LeftButton, Qt::ShiftModifier, QPoint(x + 60, 10));
    // A click on the track away from the handle still sets the value there.
    QTest::mouseClick(slider, Qt::LeftButton, {}, QPoint(6, slider->height() / 2));
    QCOMPARE(model().currentValue(kRaiseBMidlip), -1860.0f);
  }

  void togglesShowTheirState() {
    for (QToolButton* button :
         {window().transport()->loopButton(), window().transport()->timeUnitButton(),
          window().sliders()->symmetricButton()}) {
      const bool was = button->isChecked();
      button->setChecked(false);
      const QImage off = button->grab().toImage();
      button->setChecked(true);
      const QImage on = button->grab().toImage();
      button->setChecked(was);
      QCOMPARE(on.size(), off.size());
      // The checked look differs over much of the button, not in a pixel or two.
      int changed = 0;
      for (int y = 0; y < on.height(); ++y)
        for (int x = 0; x < on.width(); ++x) changed += on.pixel(x, y) != off.pixel(x, y);
      QVERIFY2(changed > on.width() * on.height() / 3, qPrintable(button->objectName()));
    }
  }
};

QTEST_MAIN(EditorInputsTest)
#include "EditorInputsTest.moc"
