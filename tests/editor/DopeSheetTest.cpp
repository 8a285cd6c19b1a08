// The dope sheet as an animator uses it: real widgets on the offscreen platform, driven by
// QTest mouse and key events at the marks' positions. Rows follow the filter, the toggle and
// folding; clicks, Ctrl-clicks, names and boxes select channel keys; drags move them by whole
// frames as one undo step; the keys copy, paste, duplicate and delete; holds are drawn.
#include "../support/KeyBuilders.h"

#include <lacrima/common/FapTable.h>
#include <lacrima/editing/EditorModel.h>
#include <lacrima/editor/DopeSheet.h>
#include <lacrima/editor/DopeSheetView.h>
#include <lacrima/editor/EditorTheme.h>
#include <lacrima/editor/GraphEditor.h>
#include <lacrima/editor/MainWindow.h>
#include <lacrima/editor/TimeAxis.h>

#include <QLineEdit>
#include <QMenu>
#include <QTabWidget>
#include <QTemporaryDir>
#include <QTimer>
#include <QToolButton>
#include <QtTest>

#include <cmath>
#include <limits>
#include <memory>

using namespace lacrima;
using lacrima::test::keyAt;
using namespace lacrima::editor;
using editing::ChannelKey;

namespace {

constexpr double kFps = 22.0;

// open_jaw (3) keyed at 0, 1 and 2 s; lower_t_midlip (4) and a tear count (69) at 1 s.
ProjectDocument sampleDocument() {
  ProjectDocument document;
  document.fps = kFps;
  document.keys = KeyframeSequence({keyAt(0.0, {{3, 100.0f}}),
                                    keyAt(1.0, {{3, 300.0f}, {4, -50.0f}, {69, 60.0f}}),
                                    keyAt(2.0, {{3, 0.0f}}, Interpolation::Smooth)});
  return document;
}

const Keyframe* keyAtTime(const editing::EditorModel& model, double time) {
  const int index = editing::findKey(model.document().keys, time);
  return index < 0 ? nullptr : &model.document().keys.keys()[static_cast<std::size_t>(index)];
}

QPoint pt(QPointF p) { return p.toPoint(); }

// Triggers the action named `text` (accelerator marks ignored) of the next popup menu.
void pickFromNextMenu(const QString& text) {
  QTimer::singleShot(0, [text] {
    auto* menu = qobject_cast<QMenu*>(QApplication::activePopupWidget());
    if (!menu) return;
    for (QAction* action : menu->actions()) {
      if (action->text().remove(QLatin1Char('&')) == text) action->trigger();
    }
    menu->close();
  });
}

// A press, moves in steps (as a hand does) and a release.
void drag(QWidget* widget, QPointF from, QPointF to, Qt::KeyboardModifiers mods = {}) {
  QTest::mousePress(widget, Qt::LeftButton, mods, pt(from));
  for (int step = 1; step <= 6; ++step) {
    const QPointF at = from + (to - from) * (step / 6.0);
    QMouseEvent move(QEvent::MouseMove, at, widget->mapToGlobal(at), Qt::NoButton, Qt::LeftButton,
                     mods);
    QCoreApplication::sendEvent(widget, &move);
  }
  QTest::mouseRelease(widget, Qt::LeftButton, mods, pt(to));
}

}  // namespace

class DopeSheetTest : public QObject {
  Q_OBJECT

 private:
  std::unique_ptr<editing::EditorModel> model_;
  std::unique_ptr<DopeSheet> sheet_;

  editing::EditorModel& model() { return *model_; }
  DopeSheetView* view() { return sheet_->view(); }
  QPointF mark(int fap, double time) { return view()->markPosition(view()->channelRow(fap), time); }

 private slots:
  void initTestCase() { theme::apply(*qApp); }

  void init() {
    model_ = std::make_unique<editing::EditorModel>();
    model_->resetDocument(sampleDocument(), true);
    sheet_ = std::make_unique<DopeSheet>(*model_);
    sheet_->resize(1000, 420);
    sheet_->show();
    QVERIFY(QTest::qWaitForWindowExposed(sheet_.get()));
    // 200 px per second from -0.1 s: a frame is 9 px, marks 200 px apart.
    view()->setView(-0.1, 200.0);
  }

  void cleanup() {
    sheet_.reset();
    model_.reset();
  }

  void rowsFollowTheFilterTheToggleAndFolding() {
    using Kind = DopeSheetRow::Kind;
    const auto& rows = view()->rows();
    QCOMPARE(rows.size(), std::size_t(6));  // summary, jaw group, 3, 4, tears group, 69
    QVERIFY(rows[0].kind == Kind::Summary);
    QVERIFY(rows[1].kind == Kind::Group && rows[1].group == FapGroup::JawChinInnerLips);
    QCOMPARE(rows[2].fap, 3);
    QCOMPARE(rows[3].fap, 4);
    QVERIFY(rows[4].kind == Kind::Group && rows[4].group == FapGroup::Tears);
    QCOMPARE(rows[5].fap, 69);
    QCOMPARE(rows[0].keys.size(), std::size_t(3));
    QCOMPARE(rows[3].keys, std::vector<int>{1});

    sheet_->onlyAnimatedButton()->click();  // every channel
    QCOMPARE(view()->rows().size(), std::size_t(1 + 11 + 70));
    sheet_->onlyAnimatedButton()->click();

    sheet_->filterBox()->setText(QStringLiteral("tears"));
    QCOMPARE(view()->rows().size(), std::size_t(3));
    QCOMPARE(view()->channelRow(3), -1);
    QCOMPARE(view()->rows()[0].keys, std::vector<int>{1});  // the summary follows the filter
    sheet_->filterBox()->clear();

    // The arrow of a group row folds it; its row still summarises the folded channels.
    const int jaw = view()->groupRow(FapGroup::JawChinInnerLips);
    QTest::mouseClick(view(), Qt::LeftButton, {},
                      QPoint(10, static_cast<int>(view()->rowRect(jaw).center().y())));
    QVERIFY(view()->isGroupFolded(FapGroup::JawChinInnerLips));
    QCOMPARE(view()->channelRow(3), -1);
    QCOMPARE(view()->rows().size(), std::size_t(4));
    QCOMPARE(view()->rows()[static_cast<std::size_t>(jaw)].keys.size(), std::size_t(3));
  }

  void clicksSelectChannelKeys() {
    QTest::mouseClick(view(), Qt::LeftButton, {}, pt(mark(3, 1.0)));
    QCOMPARE(model().channelKeySelection().keys(), (std::vector<ChannelKey>{{3, 1.0}}));
    QTest::mouseClick(view(), Qt::LeftButton, Qt::ControlModifier, pt(mark(4, 1.0)));
    QCOMPARE(model().channelKeySelection().keys(), (std::vector<ChannelKey>{{3, 1.0}, {4, 1.0}}));
    QTest::mouseClick(view(), Qt::LeftButton, Qt::ShiftModifier, pt(mark(3, 1.0)));  // toggles
    QCOMPARE(model().channelKeySelection().keys(), (std::vector<ChannelKey>{{4, 1.0}}));

    // A group's mark selects its channels' keys there; the summary's every channel's.
    const int jaw = view()->groupRow(FapGroup::JawChinInnerLips);
    QTest::mouseClick(view(), Qt::LeftButton, {}, pt(view()->markPosition(jaw, 1.0)));
    QCOMPARE(model().channelKeySelection().keys(), (std::vector<ChannelKey>{{3, 1.0}, {4, 1.0}}));
    QTest::mouseClick(view(), Qt::LeftButton, {}, pt(view()->markPosition(0, 1.0)));
    QCOMPARE(model().channelKeySelection().keys(),
             (std::vector<ChannelKey>{{3, 1.0}, {4, 1.0}, {69, 1.0}}));

    // A click on empty space clears.
    QTest::mouseClick(view(), Qt::LeftButton, {}, pt(mark(3, 0.5)));
    QVERIFY(model().channelKeySelection().empty());
  }

  void clickingANameSelectsTheRowAndItsChannels() {
    QTest::mouseClick(view(), Qt::LeftButton, {}, pt(view()->namePosition(view()->channelRow(3))));
    QCOMPARE(model().channelKeySelection().keys(),
             (std::vector<ChannelKey>{{3, 0.0}, {3, 1.0}, {3, 2.0}}));
    ChannelMask expected;
    expected.set(channelIndex(3));
    QCOMPARE(model().selectedChannels(), expected);
    QCOMPARE(model().focusChannel(), 3);

    QTest::mouseClick(view(), Qt::LeftButton, Qt::ControlModifier,
                      pt(view()->namePosition(view()->channelRow(69))));
    expected.set(channelIndex(69));
    QCOMPARE(model().selectedChannels(), expected);
    QCOMPARE(model().channelKeySelection().keys().size(), std::size_t(4));
  }

  void boxSelectsTheMarksItSpans() {
    // From empty space left of 1 s on row 3 to right of it on row 4.
    const QPointF from = mark(3, 0.8) + QPointF(0, -4);
    const QPointF to = mark(4, 1.2) + QPointF(0, 4);
    drag(view(), from, to);
    QCOMPARE(model().channelKeySelection().keys(), (std::vector<ChannelKey>{{3, 1.0}, {4, 1.0}}));
    // Ctrl adds a second box.
    drag(view(), mark(3, 1.8) + QPointF(0, -4), mark(3, 2.2) + QPointF(0, 4), Qt::ControlModifier);
    QCOMPARE(model().channelKeySelection().keys(),
             (std::vector<ChannelKey>{{3, 1.0}, {3, 2.0}, {4, 1.0}}));
  }

  void draggingAMarkMovesItsChannelByWholeFrames() {
    const ProjectDocument before = model().document();
    const double perFrame = view()->axis().scale() / kFps;
    const QPointF from = mark(3, 1.0);
    // 5 frames and a bit: whole frames only.
    drag(view(), from, from + QPointF(5 * perFrame + 0.3 * perFrame, 3));
    const double moved = 1.0 + 5.0 / kFps;
    QVERIFY(!keyAtTime(model(), 1.0)->has(3));  // the key at 1 s keeps 4 and 69
    QVERIFY(keyAtTime(model(), 1.0)->has(4) && keyAtTime(model(), 1.0)->has(69));
    QVERIFY(keyAtTime(model(), moved));
    QCOMPARE(keyAtTime(model(), moved)->value(3), 300.0f);
    QCOMPARE(model().channelKeySelection().keys(), (std::vector<ChannelKey>{{3, moved}}));
    QCOMPARE(model().undoStack()->count(), 1);
    model().undoStack()->undo();
    QCOMPARE(model().document(), before);
    // Undo and redo carry the selection with the key, as they do for whole keys.
    QCOMPARE(model().channelKeySelection().keys(), (std::vector<ChannelKey>{{3, 1.0}}));
    model().undoStack()->redo();
    QCOMPARE(model().channelKeySelection().keys(), (std::vector<ChannelKey>{{3, moved}}));
    model().undoStack()->undo();

    // Dropped on a time where its channel is keyed, it replaces that channel key.
    drag(view(), mark(3, 0.0), mark(3, 1.0));
    QVERIFY(!keyAtTime(model(), 0.0));  // left empty: gone
    QCOMPARE(keyAtTime(model(), 1.0)->value(3), 100.0f);
    QCOMPARE(keyAtTime(model(), 1.0)->value(69), 60.0f);
  }

  void draggingAGroupOrSummaryMarkMovesAllItsChannels() {
    const double perFrame = view()->axis().scale() / kFps;
    // The jaw group's mark at 1 s, two frames later: open_jaw and lower_t_midlip go, the tear
    // count stays.
    const int jaw = view()->groupRow(FapGroup::JawChinInnerLips);
    const QPointF from = view()->markPosition(jaw, 1.0);
    drag(view(), from, from + QPointF(2 * perFrame, 0));
    const double moved = 1.0 + 2.0 / kFps;
    QCOMPARE(keyAtTime(model(), 1.0)->channels.count(), std::size_t(1));
    QVERIFY(keyAtTime(model(), 1.0)->has(69));
    QVERIFY(keyAtTime(model(), moved)->has(3) && keyAtTime(model(), moved)->has(4));
    QCOMPARE(model().channelKeySelection().keys(),
             (std::vector<ChannelKey>{{3, moved}, {4, moved}}));

    // The summary's mark at 2 s dragged a second to the left, onto 1 s: open_jaw's 0 there
    // joins the tear count's key.
    QTest::mouseClick(view(), Qt::LeftButton, {}, pt(view()->markPosition(0, 2.0)));
    drag(view(), view()->markPosition(0, 2.0), view()->markPosition(0, 1.0));
    QVERIFY(!keyAtTime(model(), 2.0));
    QCOMPARE(keyAtTime(model(), 1.0)->value(3), 0.0f);
    QCOMPARE(keyAtTime(model(), 1.0)->value(69), 60.0f);
    QCOMPARE(model().undoStack()->count(), 2);
  }

  void keysSelectCopyPasteDuplicateAndDelete() {
    view()->setFocus();
    QTest::keyClick(view(), Qt::Key_A);
    QCOMPARE(model().channelKeySelection().keys().size(), std::size_t(5));
    QTest::keyClick(view(), Qt::Key_A, Qt::AltModifier);
    QVERIFY(model().channelKeySelection().empty());

    QTest::mouseClick(view(), Qt::LeftButton, {}, pt(mark(69, 1.0)));
    QTest::keyClick(view(), Qt::Key_C, Qt::ControlModifier);
    QCOMPARE(view()->clip().channelKeyCount(), std::size_t(1));
    model().setCurrentTime(2.0);
    QTest::keyClick(view(), Qt::Key_V, Qt::ControlModifier);
    QCOMPARE(keyAtTime(model(), 2.0)->value(69), 60.0f);
    QCOMPARE(keyAtTime(model(), 2.0)->value(3), 0.0f);  // pasted into the key there
    QCOMPARE(model().channelKeySelection().keys(), (std::vector<ChannelKey>{{69, 2.0}}));

    QTest::keyClick(view(), Qt::Key_Delete);
    QVERIFY(!keyAtTime(model(), 2.0)->has(69));
    QVERIFY(keyAtTime(model(), 2.0)->has(3));

    // Shift+D: the selection duplicated to the playhead.
    QTest::mouseClick(view(), Qt::LeftButton, {}, pt(mark(4, 1.0)));
    model().setCurrentTime(1.5);
    QTest::keyClick(view(), Qt::Key_D, Qt::ShiftModifier);
    QCOMPARE(keyAtTime(model(), 1.5)->value(4), -50.0f);
    QCOMPARE(keyAtTime(model(), 1.0)->value(4), -50.0f);
    QTest::keyClick(view(), Qt::Key_X);
    QVERIFY(!keyAtTime(model(), 1.5));
    QCOMPARE(model().undoStack()->count(), 4);  // paste, delete, duplicate, delete
  }

  // T and V (and the context menu) shape the selected channel keys, one undo step each.
  void tAndVShapeTheSelectedChannelKeys() {
    QTest::mouseClick(view(), Qt::LeftButton, {}, pt(mark(3, 1.0)));
    view()->setFocus();
    pickFromNextMenu(QStringLiteral("Constant"));
    QTest::keyClick(view(), Qt::Key_T);
    QVERIFY(keyAtTime(model(), 1.0)->shape(3).interpolation == Interpolation::Constant);
    QVERIFY(keyAtTime(model(), 1.0)->shape(4).interpolation == Interpolation::Linear);  // kept
    pickFromNextMenu(QStringLiteral("Free"));
    QTest::keyClick(view(), Qt::Key_V);
    QVERIFY(keyAtTime(model(), 1.0)->shape(3).handles == HandleType::Free);
    QCOMPARE(model().undoStack()->count(), 2);
    model().undoStack()->undo();
    model().undoStack()->undo();
    QCOMPARE(model().document(), sampleDocument());
  }

  void rulerScrubsAndWheelZoomsAboutThePointer() {
    const QPointF onRuler(view()->xOfTime(1.5), DopeSheetView::kRulerHeight / 2);
    QTest::mouseClick(view(), Qt::LeftButton, {}, pt(onRuler));
    QCOMPARE(model().frameAt(model().currentTime()), 33);

    const double scale = view()->axis().scale();
    const QPointF at(view()->xOfTime(1.0), mark(3, 1.0).y());
    QWheelEvent wheel(at, view()->mapToGlobal(at), {}, QPoint(0, 240), Qt::NoButton, {},
                      Qt::NoScrollPhase, false);
    QCoreApplication::sendEvent(view(), &wheel);
    QVERIFY(view()->axis().scale() > scale * 1.3);
    QVERIFY(std::abs(view()->timeAtX(at.x()) - 1.0) < 1e-9);  // the time under the pointer
  }

  void holdsAreDrawnAndTheHoldBeforeTheFirstKeyIsFaint() {
    // The tear count keyed 60 at 1 s and again at 2 s: a hold between, and 60 held from 0 s.
    Keyframe again = keyAt(2.0, {{3, 0.0f}, {69, 60.0f}}, Interpolation::Smooth);
    model().editKeys(
        editing::planReplace(model().document().keys, {}, std::span<const Keyframe>(&again, 1)),
        QStringLiteral("Key tears"));
    const QImage image = view()->grab().toImage();
    const auto blueness = [&](double time, int fap) {
      const QPoint p = pt(mark(fap, time));
      const QColor c = image.pixelColor(p.x(), p.y());
      return c.blue() - c.red();
    };
    const auto background = [&](double time, int fap) {
      const QPoint p = pt(mark(fap, time) + QPointF(0, -7));  // above the bar, same row
      const QColor c = image.pixelColor(p.x(), p.y());
      return c.blue() - c.red();
    };
    QVERIFY2(blueness(1.3, 69) > background(1.3, 69) + 40, "no hold bar between equal keys");
    QVERIFY2(blueness(0.3, 69) > background(0.3, 69) + 8, "no faint hold before the first key");
    QVERIFY(blueness(0.3, 69) < blueness(1.3, 69));  // fainter than a hold between keys
    const QPoint noHold = pt(mark(3, 0.3));          // 100 -> 300: no hold
    const QPoint above = pt(mark(3, 0.3) + QPointF(0, -7));
    QCOMPARE(image.pixelColor(noHold), image.pixelColor(above));
  }

  void timeAxisStaysFiniteAndInRange() {
    TimeAxis axis;
    axis.set(std::nan(""), std::numeric_limits<double>::infinity());
    QVERIFY(std::isfinite(axis.start()) && std::isfinite(axis.scale()));
    axis.set(-100.0, 1e9);
    QCOMPARE(axis.scale(), TimeAxis::kMaxScale);
    QCOMPARE(axis.start(), -40.0 / TimeAxis::kMaxScale);  // at most 40 px before 0 s
    axis.set(5.0, 0.0);
    QCOMPARE(axis.scale(), TimeAxis::kMinScale);
    axis.fit(10.0, 1040.0);  // 10 s across 1000 px, 20 px margin
    QCOMPARE(axis.scale(), 100.0);
    QCOMPARE(axis.xOf(0.0), 20.0);
    QCOMPARE(axis.timeAt(axis.xOf(3.25)), 3.25);
    QVERIFY(!axis.follow(5.0, 1040.0));
    QVERIFY(axis.follow(30.0, 1040.0));  // off the right edge: a tenth of the way in
    QVERIFY(std::abs(axis.xOf(30.0) - 104.0) < 1e-9);
    axis.wheel(QPoint(0, 120), false, 300.0);  // one notch in about x = 300
    QVERIFY(std::abs(axis.scale() - 115.0) < 1e-9);
    axis.wheel(QPoint(0, 120), true, 300.0);  // Shift: 60 px later
    QVERIFY(std::abs(axis.scale() - 115.0) < 1e-9);
  }

  void rulerLabelsShowTheirStepExactly() {
    // The timeline's and the dope sheet's ruler (and the graph editor's) label with this.
    QCOMPARE(rulerLabel(0.25, 0.25), QStringLiteral("0.25s"));
    QCOMPARE(rulerLabel(0.75, 0.25), QStringLiteral("0.75s"));
    QCOMPARE(rulerLabel(0.5, 0.25), QStringLiteral("0.50s"));
    QCOMPARE(rulerLabel(1.5, 0.5), QStringLiteral("1.5s"));
    QCOMPARE(rulerLabel(0.1 + 0.05, 0.05), QStringLiteral("0.15s"));
    QCOMPARE(rulerLabel(2.0, 1.0), QStringLiteral("2s"));
    QCOMPARE(rulerLabel(90.0, 30.0), QStringLiteral("1:30"));
  }

  void theWindowHasTheTabsAndTheirKeysActOnChannelKeys() {
    QTemporaryDir recovery;
    EditorOptions options;
    options.preview = false;
    options.interactive = false;
    options.offerRecovery = false;
    options.recoveryDirectory = recovery.path();
    MainWindow window(options);
    window.resize(1400, 900);
    window.show();
    window.activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(&window));
    window.model().resetDocument(sampleDocument(), true);
    QTabWidget* tabs = window.animationViews();
    const int index = tabs->indexOf(window.dopeSheet());
    QVERIFY(index >= 0);
    QCOMPARE(tabs->tabText(index), QStringLiteral("Dope sheet"));
    tabs->setCurrentIndex(index);
    DopeSheetView* sheet = window.dopeSheet()->view();
    sheet->setView(-0.1, 200.0);
    QTest::mouseClick(sheet, Qt::LeftButton, {},
                      pt(sheet->markPosition(sheet->channelRow(4), 1.0)));
    QVERIFY(sheet->hasFocus());
    // Delete goes to the sheet (one channel key), not to the window's whole-key delete.
    QTest::keyClick(sheet, Qt::Key_Delete);
    QVERIFY(!keyAtTime(window.model(), 1.0)->has(4));
    QVERIFY(keyAtTime(window.model(), 1.0)->has(3));
    QVERIFY(keyAtTime(window.model(), 1.0)->has(69));

    // The graph editor takes Delete the same way: the channel keys selected, not whole keys.
    QVERIFY(!window.showAnimationView(QStringLiteral("curves")));  // --view's names only
    QVERIFY(window.showAnimationView(QStringLiteral("graph")));
    QCOMPARE(tabs->currentWidget(), window.graphEditor());
    window.model().channelKeySelection().select({{3, 1.0}});
    window.graphEditor()->setFocus();
    QVERIFY(window.graphEditor()->hasFocus());
    QTest::keyClick(window.graphEditor(), Qt::Key_Delete);
    QVERIFY(!keyAtTime(window.model(), 1.0)->has(3));
    QVERIFY(keyAtTime(window.model(), 1.0)->has(69));
    QVERIFY(keyAtTime(window.model(), 0.0)->has(3));
    window.model().undoStack()->undo();
    QCOMPARE(window.model().channelKeySelection().keys(), (std::vector<ChannelKey>{{3, 1.0}}));
    window.model().markSaved();
  }
};

QTEST_MAIN(DopeSheetTest)
#include "DopeSheetTest.moc"
