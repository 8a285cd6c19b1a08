// The graph editor driven like a user (real widget, offscreen, QTest mouse and key events):
// dragging a Bézier handle changes the baked frames exactly as the Bézier maths says (checked
// against an independent de Casteljau evaluation) and undo restores the document; dragging
// keys (whole frames, Ctrl whole values, tears whole particles); click, Shift-click and box
// selection; the T and V menus; framing, the normalised view, and a drawing cost that does not
// grow with the animation's length. Also: the tab in the main window.
#include "../support/BezierReference.h"

#include <lacrima/common/CurveHandles.h>
#include <lacrima/editing/EditorModel.h>
#include <lacrima/editor/GraphEditor.h>
#include <lacrima/editor/MainWindow.h>
#include <lacrima/editor/MoodGraph.h>

#include <QApplication>
#include <QMenu>
#include <QTabWidget>
#include <QTemporaryDir>
#include <QTimer>
#include <QtTest>

#include <cmath>
#include <memory>

using namespace lacrima;
using namespace lacrima::editor;
using editing::ChannelKey;
using editing::HandleSide;
using lacrima::test::Point2;

namespace {

constexpr int kJaw = 3;
constexpr int kLip = 5;
constexpr double kFps = 25.0;

ProjectDocument documentWith(std::vector<Keyframe> keys) {
  ProjectDocument document;
  document.fps = kFps;
  document.keys = KeyframeSequence(std::move(keys));
  return document;
}

Keyframe key(double time, Interpolation mode, std::initializer_list<std::pair<int, float>> values) {
  Keyframe k;
  k.time = time;
  k.interpolation = mode;
  for (const auto& [fap, v] : values) k.set(fap, v);
  return k;
}

// A left-button drag in `steps` moves, as a hand does it.
void drag(QWidget* widget, QPointF from, QPointF to, Qt::KeyboardModifiers modifiers = {},
          int steps = 6) {
  QTest::mousePress(widget, Qt::LeftButton, modifiers, from.toPoint());
  for (int i = 1; i <= steps; ++i) {
    const QPointF at = from + (to - from) * (double(i) / steps);
    QMouseEvent move(QEvent::MouseMove, at, widget->mapToGlobal(at), Qt::NoButton, Qt::LeftButton,
                     modifiers);
    QCoreApplication::sendEvent(widget, &move);
  }
  QTest::mouseRelease(widget, Qt::LeftButton, modifiers, to.toPoint());
}

// Triggers the action named `text` of the next popup menu, once it is open.
void pickFromNextMenu(const QString& text) {
  QTimer::singleShot(0, [text] {
    auto* menu = qobject_cast<QMenu*>(QApplication::activePopupWidget());
    if (!menu) return;
    for (QAction* action : menu->actions()) {
      QString name = action->text();
      name.remove(QLatin1Char('&'));
      if (name == text) action->trigger();
    }
    menu->close();
  });
}

}  // namespace

class GraphEditorTest : public QObject {
  Q_OBJECT

  std::unique_ptr<editing::EditorModel> model_;
  std::unique_ptr<GraphEditor> editor_;

  void open(ProjectDocument document, ChannelMask shown) {
    model_->resetDocument(std::move(document), true);
    model_->setSelectedChannels(shown);
    editor_->frameAll();
  }

  static ChannelMask channels(std::initializer_list<int> faps) {
    ChannelMask mask;
    for (int fap : faps) mask.set(channelIndex(fap));
    return mask;
  }

 private slots:
  void init() {
    model_ = std::make_unique<editing::EditorModel>();
    editor_ = std::make_unique<GraphEditor>(*model_);
    editor_->resize(900, 420);
    editor_->show();
    QVERIFY(QTest::qWaitForWindowExposed(editor_.get()));
  }

  void cleanup() {
    editor_.reset();
    model_.reset();
  }

  void draggingAHandleBakesTheBezierAndUndoRestores() {
    open(documentWith({key(0.0, Interpolation::Bezier, {{kJaw, 0.0f}}),
                       key(1.0, Interpolation::Bezier, {{kJaw, 100.0f}})}),
         channels({kJaw}));
    const ProjectDocument before = model_->document();
    const FapAnimation bakedBefore = before.bake();
    const int steps = model_->undoStack()->count();

    const QPointF handle = editor_->handlePosition(kJaw, 0, HandleSide::Out);
    const QPointF target = handle + QPointF(80, -90);
    drag(editor_.get(), handle, target);

    // One undo step; the key's out handle is where the pointer let go, and dragging the auto
    // handle made the key Aligned.
    QCOMPARE(model_->undoStack()->count(), steps + 1);
    const KeyShape shape = model_->document().keys.keys()[0].shape(kJaw);
    QVERIFY(shape.handles == HandleType::Aligned);
    QVERIFY(shape.interpolation == Interpolation::Bezier);
    // The press was on the handle's exact position, rounded to a pixel; the handle follows the
    // motion from there.
    const double expectedDt =
        1.0 / 3.0 + editor_->timeAtX(target.x()) - editor_->timeAtX(handle.toPoint().x());
    const double expectedDv = 100.0 / 3.0 + editor_->valueAtY(kJaw, target.y()) -
                              editor_->valueAtY(kJaw, handle.toPoint().y());
    QVERIFY(std::abs(shape.out.dt - expectedDt) < 1e-9);
    QVERIFY(std::abs(shape.out.dv - expectedDv) < 1e-9);
    QVERIFY(shape.out.dv > 100.0 / 3.0 + 15.0);  // dragged up 90 px: well above the auto handle

    // The baked frames against an independent Bézier evaluation: key 1's in handle is auto,
    // a third of the segment along the secant (two keys: the Smooth slope is the secant).
    const FapAnimation baked = model_->document().bake();
    const std::array<Point2, 4> points{Point2{0.0, 0.0}, Point2{shape.out.dt, shape.out.dv},
                                       Point2{2.0 / 3.0, 200.0 / 3.0}, Point2{1.0, 100.0}};
    QCOMPARE(baked.frames.size(), std::size_t{26});
    double changed = 0;
    for (std::size_t f = 0; f < baked.frames.size(); ++f) {
      const double expected = lacrima::test::bezierValueAtTime(points, f / kFps);
      const float value = baked.frames[f][channelIndex(kJaw)];
      QVERIFY2(std::abs(value - expected) < 1e-3, qPrintable(QString("frame %1").arg(f)));
      changed =
          std::max(changed, double(std::abs(value - bakedBefore.frames[f][channelIndex(kJaw)])));
    }
    QVERIFY(changed > 5.0);

    model_->undoStack()->undo();
    QVERIFY(model_->document() == before);
    model_->undoStack()->redo();
    QCOMPARE(model_->document().bake().frames, baked.frames);
  }

  void alignedHandlesStayOnOneLine() {
    open(documentWith({key(0.0, Interpolation::Bezier, {{kJaw, 0.0f}}),
                       key(0.6, Interpolation::Bezier, {{kJaw, 200.0f}}),
                       key(1.2, Interpolation::Bezier, {{kJaw, 50.0f}})}),
         channels({kJaw}));
    const QPointF in = editor_->handlePosition(kJaw, 1, HandleSide::In);
    drag(editor_.get(), in, in + QPointF(-30, 70));
    const KeyShape shape = model_->document().keys.keys()[1].shape(kJaw);
    QVERIFY(shape.handles == HandleType::Aligned);
    QVERIFY(std::abs(shape.in.dt * shape.out.dv - shape.in.dv * shape.out.dt) <
            1e-9 * std::hypot(shape.in.dt, shape.in.dv) * std::hypot(shape.out.dt, shape.out.dv) +
                1e-12);
    QVERIFY(shape.in.dt < 0 && shape.out.dt > 0);
    // The in handle acts on the segment before: that key's interpolation is Bézier.
    QVERIFY(model_->document().keys.keys()[0].shape(kJaw).interpolation == Interpolation::Bezier);
    // On screen too: the key sits on the line between its two handles.
    const QPointF a = editor_->handlePosition(kJaw, 1, HandleSide::In);
    const QPointF b = editor_->handlePosition(kJaw, 1, HandleSide::Out);
    const QPointF k = editor_->keyPosition(kJaw, 1);
    const double cross = (a.x() - k.x()) * (b.y() - k.y()) - (a.y() - k.y()) * (b.x() - k.x());
    QVERIFY(std::abs(cross) < 1e-6 * QLineF(a, k).length() * QLineF(b, k).length() + 1e-6);
  }

  void draggingKeysSnapsTimeToFramesAndCtrlSnapsValues() {
    open(documentWith({key(0.0, Interpolation::Smooth, {{kJaw, 0.0f}, {kTearLeftFap, 0.0f}}),
                       key(0.4, Interpolation::Smooth, {{kJaw, 300.0f}, {kTearLeftFap, 40.0f}}),
                       key(1.0, Interpolation::Smooth, {{kJaw, 0.0f}, {kTearLeftFap, 0.0f}})}),
         channels({kJaw, kTearLeftFap}));
    // Select the jaw key and the tear key at 0.4 s (click, Shift-click).
    QTest::mouseClick(editor_.get(), Qt::LeftButton, {}, editor_->keyPosition(kJaw, 1).toPoint());
    QTest::mouseClick(editor_.get(), Qt::LeftButton, Qt::ShiftModifier,
                      editor_->keyPosition(kTearLeftFap, 1).toPoint());
    const std::vector<ChannelKey> both{{kJaw, 0.4}, {kTearLeftFap, 0.4}};
    QCOMPARE(model_->channelKeySelection().keys(), both);

    // Three frames to the right (plus a little: snapping), up by 37 px, Ctrl held.
    const QPointF from = editor_->keyPosition(kJaw, 1);
    const double frame = (editor_->xOfTime(1.0 / kFps) - editor_->xOfTime(0.0));
    const QPointF to = from + QPointF(3.3 * frame, -37.0);
    const double expectedJaw = std::round(300.0 + editor_->valueAtY(kJaw, to.y()) -
                                          editor_->valueAtY(kJaw, from.toPoint().y()));
    drag(editor_.get(), from, to, Qt::ControlModifier);

    const KeyframeSequence& keys = model_->document().keys;
    const int moved = editing::findKey(keys, 0.52);
    QVERIFY(moved >= 0);
    QCOMPARE(editing::findKey(keys, 0.4), -1);
    const Keyframe& landed = keys.keys()[static_cast<std::size_t>(moved)];
    QCOMPARE(landed.value(kJaw), float(expectedJaw));
    QCOMPARE(landed.value(kTearLeftFap), std::round(landed.value(kTearLeftFap)));
    QVERIFY(landed.value(kTearLeftFap) > 40.0f);
    // The selection followed the keys, and the whole drag is one undo step.
    const std::vector<ChannelKey> movedKeys{{kJaw, 0.52}, {kTearLeftFap, 0.52}};
    QCOMPARE(model_->channelKeySelection().keys().size(), movedKeys.size());
    model_->undoStack()->undo();
    QCOMPARE(model_->document().keys.keys()[1].value(kJaw), 300.0f);
  }

  // A key dragged past a key of another channel: during the drag the key list changes (one
  // key goes, one appears), and the other curve's keys and handles must still be drawn from
  // the right keys.
  void draggingAKeyPastAnotherChannelsKey() {
    open(documentWith({key(0.0, Interpolation::Bezier, {{kJaw, 0.0f}, {kLip, 0.0f}}),
                       key(0.4, Interpolation::Bezier, {{kJaw, 100.0f}}),
                       key(0.5, Interpolation::Bezier, {{kLip, 20.0f}}),
                       key(1.0, Interpolation::Bezier, {{kJaw, 0.0f}, {kLip, 10.0f}})}),
         channels({kJaw, kLip}));
    const QPointF from = editor_->keyPosition(kJaw, 1);
    const QPointF to(editor_->xOfTime(0.6), from.toPoint().y());  // the pressed pixel row
    QTest::mousePress(editor_.get(), Qt::LeftButton, {}, from.toPoint());
    QMouseEvent move(QEvent::MouseMove, to, editor_->mapToGlobal(to), Qt::NoButton, Qt::LeftButton,
                     Qt::NoModifier);
    QCoreApplication::sendEvent(editor_.get(), &move);
    editor_->grab();  // paints the preview: the lip key at 0.5 is now key 1
    const QPointF lip = editor_->keyPosition(kLip, 1);
    QCOMPARE(lip.x(), editor_->xOfTime(0.5));
    QCOMPARE(lip.y(), editor_->yOfValue(kLip, 20.0));
    QTest::mouseRelease(editor_.get(), Qt::LeftButton, {}, to.toPoint());
    const KeyframeSequence& keys = model_->document().keys;
    QCOMPARE(editing::findKey(keys, 0.4), -1);
    QCOMPARE(keys.keys()[2].time, 0.6);
    QCOMPARE(keys.keys()[2].value(kJaw), 100.0f);
  }

  void boxSelectsTheKeysInside() {
    open(documentWith({key(0.0, Interpolation::Linear, {{kJaw, 0.0f}, {kLip, 0.0f}}),
                       key(0.5, Interpolation::Linear, {{kJaw, 100.0f}, {kLip, 20.0f}}),
                       key(1.0, Interpolation::Linear, {{kJaw, 50.0f}, {kLip, 10.0f}})}),
         channels({kJaw, kLip}));
    // A box around the jaw key at 0.5 s only.
    const QPointF k = editor_->keyPosition(kJaw, 1);
    drag(editor_.get(), k + QPointF(-15, -15), k + QPointF(15, 15));
    const std::vector<ChannelKey> one{{kJaw, 0.5}};
    QCOMPARE(model_->channelKeySelection().keys(), one);
    // Clicking empty space clears it.
    QTest::mouseClick(editor_.get(), Qt::LeftButton, {}, QPoint(editor_->width() - 20, 300));
    QVERIFY(model_->channelKeySelection().empty());
  }

  void tAndVMenusShapeTheSelectedChannelKeys() {
    open(documentWith({key(0.0, Interpolation::Linear, {{kJaw, 0.0f}, {kLip, 0.0f}}),
                       key(0.5, Interpolation::Linear, {{kJaw, 100.0f}, {kLip, 20.0f}}),
                       key(1.0, Interpolation::Linear, {{kJaw, 50.0f}, {kLip, 10.0f}})}),
         channels({kJaw, kLip}));
    model_->channelKeySelection().select({{kJaw, 0.0}, {kJaw, 0.5}});
    editor_->setFocus();
    pickFromNextMenu(QStringLiteral("Bézier"));
    QTest::keyClick(editor_.get(), Qt::Key_T);
    const auto& keys = model_->document().keys.keys();
    QVERIFY(keys[0].shape(kJaw).interpolation == Interpolation::Bezier);
    QVERIFY(keys[1].shape(kJaw).interpolation == Interpolation::Bezier);
    QVERIFY(keys[0].shape(kLip).interpolation == Interpolation::Linear);  // not selected
    // Bézier with auto handles is the Smooth curve: handles show, at a third of the segment.
    const QPointF out = editor_->handlePosition(kJaw, 1, HandleSide::Out);
    QVERIFY(std::abs(editor_->timeAtX(out.x()) - (0.5 + 0.5 / 3.0)) < 1e-9);
    pickFromNextMenu(QStringLiteral("Free"));
    QTest::keyClick(editor_.get(), Qt::Key_V);
    QVERIFY(model_->document().keys.keys()[1].shape(kJaw).handles == HandleType::Free);
    // A Free handle moves alone.
    const Handle in = model_->document().keys.keys()[1].shape(kJaw).in;
    drag(editor_.get(), out, out + QPointF(0, 60));
    QCOMPARE(model_->document().keys.keys()[1].shape(kJaw).in, in);
  }

  void framingAndTheNormalisedView() {
    open(documentWith({key(1.0, Interpolation::Smooth, {{kJaw, -200.0f}, {kLip, 2.0f}}),
                       key(3.0, Interpolation::Smooth, {{kJaw, 800.0f}, {kLip, 6.0f}})}),
         channels({kJaw, kLip}));
    // Frame all puts every key in the plot.
    for (int fap : {kJaw, kLip}) {
      for (int k : {0, 1}) {
        const QPointF p = editor_->keyPosition(fap, k);
        QVERIFY(QRectF(editor_->rect()).contains(p));
      }
    }
    // The small channel is a flat line beside the big one...
    QVERIFY(std::abs(editor_->keyPosition(kLip, 0).y() - editor_->keyPosition(kLip, 1).y()) < 5);
    // ...until normalised: both span the same height.
    editor_->setNormalized(true);
    QCOMPARE(editor_->keyPosition(kLip, 0).y(), editor_->keyPosition(kJaw, 0).y());
    QCOMPARE(editor_->keyPosition(kLip, 1).y(), editor_->keyPosition(kJaw, 1).y());
    QVERIFY(editor_->keyPosition(kLip, 0).y() - editor_->keyPosition(kLip, 1).y() > 200);
    // Dragging in the normalised view moves each channel in its own units: a quarter of the
    // height moves the lip by a quarter of its range.
    model_->channelKeySelection().select({{kLip, 3.0}});
    const QPointF from = editor_->keyPosition(kLip, 1);
    const double quarter = (editor_->keyPosition(kLip, 0).y() - from.y()) / 4.0;
    drag(editor_.get(), from, from + QPointF(0, quarter));
    QVERIFY(std::abs(model_->document().keys.keys()[1].value(kLip) - 5.0f) < 0.05f);
    editor_->setNormalized(false);

    // Frame selected (F) zooms to the selected key; Home gives everything back.
    model_->channelKeySelection().select({{kJaw, 1.0}});
    editor_->setFocus();
    QTest::keyClick(editor_.get(), Qt::Key_F);
    const QPointF selected = editor_->keyPosition(kJaw, 0);
    QVERIFY(std::abs(selected.x() - (56 + (editor_->width() - 56) / 2.0)) < 2);
    QVERIFY(!QRectF(editor_->rect()).contains(editor_->keyPosition(kJaw, 1)));
    QTest::keyClick(editor_.get(), Qt::Key_Home);
    QVERIFY(QRectF(editor_->rect()).contains(editor_->keyPosition(kJaw, 1)));
  }

  // A channel with nothing selected in the channel list: the focus channel is drawn, and the
  // ruler scrubs.
  void focusChannelAndScrubbing() {
    open(documentWith({key(0.0, Interpolation::Linear, {{kLip, 0.0f}}),
                       key(2.0, Interpolation::Linear, {{kLip, 90.0f}})}),
         ChannelMask{});
    model_->setFocusChannel(kLip);
    QCOMPARE(editor_->shownChannels(), std::vector<int>{kLip});
    QTest::mouseClick(editor_.get(), Qt::LeftButton, {},
                      QPoint(static_cast<int>(editor_->xOfTime(1.0)), 10));
    QCOMPARE(model_->currentTime(), 1.0);
  }

  // Drawing cost: a view of a very long animation draws no more curve points than there are
  // pixel columns, as a short one does.
  void drawingCostDoesNotGrowWithTheAnimation() {
    const auto pointsFor = [&](int keyCount) {
      std::vector<Keyframe> keys;
      for (int k = 0; k < keyCount; ++k)
        keys.push_back(key(k / kFps, Interpolation::Bezier,
                           {{kJaw, float(100 * std::sin(k * 0.3))}, {kLip, float(k % 7)}}));
      open(documentWith(std::move(keys)), channels({kJaw, kLip}));
      editor_->grab();
      return editor_->lastPaintPoints();
    };
    const int shortOne = pointsFor(50);
    const int longOne = pointsFor(40000);  // 26 minutes at 25 fps
    QVERIFY(shortOne > 0);
    // Two channels, at most one point per pixel column each (plus the holds' ends).
    QVERIFY2(longOne <= 2 * (editor_->width() + 4),
             qPrintable(QString("%1 points drawn").arg(longOne)));
  }

  // The Moods view: the project's mood curves, a key dragged (whole frames, 0..1), a key added
  // by double-click to the chosen mood, one deleted; each one undo step that undo restores
  // exactly.
  void moodCurvesAreEditedInTheMoodsView() {
    ProjectDocument document = documentWith(
        {key(0, Interpolation::Linear, {{kJaw, 0}}), key(4, Interpolation::Linear, {{kJaw, 100}})});
    document.moods[Mood::Sadness] =
        IntensityCurve({{0, 0, Interpolation::Smooth}, {2, 0.4, Interpolation::Smooth}});
    open(document, channels({kJaw}));
    const MoodCurves original = model_->document().moods;
    editor_->setMoodsShown(true);
    MoodGraph* graph = editor_->moodGraph();
    QVERIFY(editor_->moodsShown() && graph->isVisible());
    graph->frameAll();

    drag(graph, graph->keyPosition(Mood::Sadness, 1),
         QPointF(graph->xOfTime(2.6), graph->yOfValue(0.8)));
    QCOMPARE(model_->undoStack()->count(), 1);
    const std::vector<IntensityKey> moved = model_->document().moods[Mood::Sadness].keys();
    QCOMPARE(moved.size(), std::size_t(2));
    QVERIFY2(std::abs(moved[1].time - 2.6) < 1e-9, qPrintable(QString::number(moved[1].time)));
    QVERIFY2(std::abs(moved[1].value - 0.8) < 0.01, qPrintable(QString::number(moved[1].value)));
    const MoodCurves afterDrag = model_->document().moods;
    drag(graph, graph->keyPosition(Mood::Sadness, 1),
         QPointF(graph->xOfTime(3), graph->yOfValue(1.5)));  // above the axis: clamped
    QCOMPARE(model_->document().moods[Mood::Sadness].keys()[1].value, 1.0);
    model_->undoStack()->undo();
    QVERIFY(model_->document().moods == afterDrag);

    graph->setActiveMood(Mood::Anger);
    QTest::mouseDClick(graph, Qt::LeftButton, {},
                       QPointF(graph->xOfTime(1), graph->yOfValue(0.5)).toPoint());
    QCOMPARE(model_->undoStack()->count(), 2);
    const std::vector<IntensityKey> anger = model_->document().moods[Mood::Anger].keys();
    QCOMPARE(anger.size(), std::size_t(1));
    QVERIFY(std::abs(anger[0].time - 1) < 1e-9 && std::abs(anger[0].value - 0.5) < 0.01);

    QTest::mouseClick(graph, Qt::LeftButton, {}, graph->keyPosition(Mood::Anger, 0).toPoint());
    QCOMPARE(graph->selectedKey()->mood, Mood::Anger);
    QTest::keyClick(graph, Qt::Key_Delete);
    QVERIFY(model_->document().moods[Mood::Anger].empty());
    QCOMPARE(model_->undoStack()->count(), 3);
    while (model_->undoStack()->canUndo()) model_->undoStack()->undo();
    QVERIFY(model_->document().moods == original);

    editor_->setMoodsShown(false);
    QVERIFY(!graph->isVisible());
    QCOMPARE(editor_->shownChannels(), std::vector<int>{kJaw});
  }

  void theMainWindowHasAGraphTab() {
    QTemporaryDir recovery;
    EditorOptions options;
    options.preview = false;
    options.interactive = false;
    options.recoveryDirectory = recovery.path();
    MainWindow window(options);
    QTabWidget* views = window.animationViews();
    QVERIFY(window.graphEditor());
    QCOMPARE(views->tabText(views->indexOf(window.graphEditor())), QStringLiteral("Graph"));
  }
};

QTEST_MAIN(GraphEditorTest)
#include "GraphEditorTest.moc"
