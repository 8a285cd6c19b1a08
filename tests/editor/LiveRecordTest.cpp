// Record live in the editor, offscreen: a Greta-style agent streams over TCP while the editor
// counts in and records from the playhead; the preview poses the stream meanwhile; Stop writes
// keys on the chosen channels, reduced, as one undo step that undo takes back. And
// planLiveTakeKeys alone: reduction within the tolerance, other channels and keys kept. And
// Animation > Generate crying, the other take that becomes keys: its dialog over the selected
// keys' span writes the crying generator's take as one undo step.
#include "../live/LiveTestSupport.h"

#include <lacrima/common/FapTable.h>
#include <lacrima/editing/EditorModel.h>
#include <lacrima/editing/LiveTake.h>
#include <lacrima/editor/LayerPanel.h>
#include <lacrima/editor/LiveRecording.h>
#include <lacrima/editor/MainWindow.h>
#include <lacrima/editor/MoodGenerationDialog.h>
#include <lacrima/editor/MoodLayerRow.h>
#include <lacrima/editor/RecordLiveDialog.h>

#include <QCheckBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QPushButton>

#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QStandardItemModel>
#include <QTcpSocket>
#include <QTemporaryDir>
#include <QUndoStack>
#include <QtTest>

#include <cstring>

using namespace lacrima;
using namespace lacrima::live::test;

namespace {

int fap(const char* name) { return *fapByName(name); }

ChannelMask maskOf(std::initializer_list<const char*> names) {
  ChannelMask mask;
  for (const char* name : names) mask.set(static_cast<std::size_t>(channelIndex(fap(name))));
  return mask;
}

// A window with no preview, no dialogs and its recovery files in `recovery`.
editor::EditorOptions quietOptions(const QTemporaryDir& recovery) {
  editor::EditorOptions options;
  options.preview = false;
  options.interactive = false;
  options.offerRecovery = false;
  options.recoveryDirectory = recovery.path();
  return options;
}

}  // namespace

class LiveRecordTest : public QObject {
  Q_OBJECT

 private slots:
  // A ramp and a hold on open_jaw: the reduction keeps the corners, and every frame of the take
  // is within the tolerance; a key already there keeps its other channels.
  void takeBecomesReducedKeys() {
    KeyframeSequence keys;
    Keyframe existing;
    existing.time = 2.0;
    existing.set(fap("open_jaw"), 999);
    existing.set(fap("raise_l_i_eyebrow"), 50);
    keys.insert(existing);
    Keyframe outside;
    outside.time = 10.0;
    outside.set(fap("open_jaw"), 7);
    keys.insert(outside);

    FapAnimation take;
    take.fps = 10;
    take.animated = maskOf({"open_jaw", "head_yaw"});
    for (int f = 0; f <= 30; ++f) {
      FapValues v{};
      v[channelIndex(fap("open_jaw"))] = static_cast<float>(f <= 10 ? 30 * f : 300);
      v[channelIndex(fap("head_yaw"))] = static_cast<float>(f * 100);
      take.frames.push_back(v);
    }
    const editing::LiveTakeKeys planned = editing::planLiveTakeKeys(
        keys, take, 1.0, maskOf({"open_jaw"}), 1.0, Interpolation::Linear);
    QCOMPARE(planned.framesRecorded, 31);
    QCOMPARE(planned.keysWritten, 3);  // 1 s, the corner at 2 s, 4 s
    QVERIFY(planned.maxError <= 1.0);
    KeyframeSequence after = keys;
    editing::applyKeys(after, planned.change.times, planned.change.after);
    for (int f = 0; f <= 30; ++f)
      QCOMPARE(after.evaluate(1.0 + f / 10.0)[channelIndex(fap("open_jaw"))],
               take.frames[f][channelIndex(fap("open_jaw"))]);
    const int at2 = editing::findKey(after, 2.0);
    QVERIFY(at2 >= 0);
    QCOMPARE(after.keys()[at2].value(fap("raise_l_i_eyebrow")), 50.0F);  // kept
    QCOMPARE(after.keys()[at2].value(fap("open_jaw")), 300.0F);          // the take's
    QVERIFY(!after.keys()[at2].has(fap("head_yaw")));                    // not chosen
    QCOMPARE(after.keys()[editing::findKey(after, 10.0)].value(fap("open_jaw")), 7.0F);
  }

  void windowRecordsAStreamAsOneUndoStep() {
    QTemporaryDir recovery;
    editor::MainWindow window(quietOptions(recovery));
    editing::EditorModel& model = window.model();
    model.setCurrentTime(1.0);
    QVERIFY(window.action("play.recordLive"));
    editor::LiveRecording& recording = window.liveRecording();
    live::ListenUrl url;  // fap+tcp, 127.0.0.1, a port of the system's choice
    recording.start(url, maskOf({"open_jaw", "head_pitch"}), 0.3);
    QCOMPARE(recording.state(), editor::LiveRecording::State::CountIn);
    const quint16 port = recording.session().inputs().front()->url().port;
    QTcpSocket agent;
    agent.connectToHost(QHostAddress::LocalHost, port);
    QVERIFY(agent.waitForConnected(3000));
    agent.write("2.1 greta 20 0\n");
    // During the count-in the preview poses the stream, nothing is recorded.
    agent.write(gretaFrame(0, {{3, 500}, {48, 1000}, {19, 80}}));
    QTRY_COMPARE_WITH_TIMEOUT(model.currentValue(3), 500.0F, 20000);
    QTRY_COMPARE_WITH_TIMEOUT(recording.state(), editor::LiveRecording::State::Recording, 20000);
    const int undoBefore = model.undoStack()->count();
    for (int f = 0; f < 12; ++f) {
      agent.write(gretaFrame(f, {{3, 20 * f}, {48, -500 * f}, {19, 80}}));
      agent.flush();
      waitFor([] { return false; }, 50);
    }
    QTRY_COMPARE_WITH_TIMEOUT(model.currentValue(3), 220.0F, 20000);  // the preview follows
    QVERIFY(recording.stop());
    QCOMPARE(recording.state(), editor::LiveRecording::State::Idle);
    QCOMPARE(model.undoStack()->count(), undoBefore + 1);  // one step
    const KeyframeSequence& keys = model.document().keys;
    QVERIFY(!keys.empty());
    QVERIFY(keys.startTime() >= 1.0 - 1e-9);  // from the playhead on
    QVERIFY(keys.keys().size() >= 2);         // the reduction itself: takeBecomesReducedKeys
    const Keyframe& last = keys.keys().back();
    QCOMPARE(last.value(3), 220.0F);
    QCOMPARE(last.value(48), -5500.0F);
    for (const Keyframe& k : keys.keys()) QVERIFY(!k.has(19));  // not chosen
    model.undoStack()->undo();
    QVERIFY(model.document().keys.empty());
  }

  // Animation > Generate crying over two selected keys: the range is theirs, the take lands
  // as keys between them in one undo step (the brows of sadness raised), a bad range is said
  // in the dialog and changes nothing, undo takes the take back.
  void generateCryingDialogWritesOneUndoStep() {
    QTemporaryDir recovery;
    editor::MainWindow window(quietOptions(recovery));
    editing::EditorModel& model = window.model();
    for (double t : {2.0, 6.0, 9.0}) {
      model.setCurrentTime(t);
      model.setChannel(fap("open_jaw"), 100 * t);
    }
    model.setSelectedTimes({2.0, 6.0});
    const int undoBefore = model.undoStack()->count();
    QVERIFY(window.action("anim.generateCrying"));
    editor::MoodGenerationDialog* dialog = window.openGenerateCrying();
    QCOMPARE(dialog->start()->value(), 2.0);
    QCOMPARE(dialog->end()->value(), 6.0);
    QPushButton* generate = dialog->findChild<QDialogButtonBox*>()->button(QDialogButtonBox::Ok);

    dialog->end()->setValue(1.0);  // before the start: said, nothing done
    generate->click();
    QVERIFY(dialog->isVisible());
    QVERIFY(dialog->findChild<QLabel*>("problem")->text().contains("To: expected a time after"));
    QCOMPARE(model.undoStack()->count(), undoBefore);

    dialog->end()->setValue(6.0);
    dialog->presets()->setCurrentIndex(2);  // Sad crying
    emit dialog->presets()->activated(2);
    QCOMPARE(dialog->level(Mood::Sadness)->value(), moodPresets()[1].levels[Mood::Sadness]);
    dialog->seed()->setText("5");
    generate->click();
    QCOMPARE(model.undoStack()->count(), undoBefore + 1);  // one step
    const KeyframeSequence& keys = model.document().keys;
    double brows = 0;
    int inside = 0;
    for (const Keyframe& k : keys.keys()) {
      if (k.time < 2.0 - 1e-9 || k.time > 6.0 + 1e-9) continue;
      ++inside;
      if (k.time > 3.5 && k.has(fap("raise_l_i_eyebrow")))
        brows = std::max(brows, double(k.value(fap("raise_l_i_eyebrow"))));
    }
    QVERIFY2(inside > 4, qPrintable(QString::number(inside)));
    QVERIFY2(brows > 100, qPrintable(QString::number(brows)));
    QCOMPARE(keys.keys().back().time, 9.0);  // outside the range: kept
    QCOMPARE(keys.keys().back().value(fap("open_jaw")), 900.0F);
    model.undoStack()->undo();
    QCOMPARE(int(model.document().keys.keys().size()), 3);
  }

  // Generate crying from the project's mood curves: offered once moods are keyed, the range
  // reaches the curves' end, the take follows the keyed rise (the inner brows rise later, not
  // at once), one undo step.
  void generateCryingFollowsTheMoodCurves() {
    QTemporaryDir recovery;
    editor::MainWindow window(quietOptions(recovery));
    editing::EditorModel& model = window.model();
    auto* source = window.openGenerateCrying()->source();
    QVERIFY(!qobject_cast<QStandardItemModel*>(source->model())->item(1)->isEnabled());
    source->window()->close();
    model.setCurrentTime(0);
    model.keyMood(Mood::Sadness, 0);
    model.setCurrentTime(8);
    model.keyMood(Mood::Sadness, 1);
    QCOMPARE(model.document().moods[Mood::Sadness].keys().size(), std::size_t(2));
    const int undoBefore = model.undoStack()->count();
    editor::MoodGenerationDialog* dialog = window.openGenerateCrying();
    QVERIFY(qobject_cast<QStandardItemModel*>(dialog->source()->model())->item(1)->isEnabled());
    QCOMPARE(dialog->end()->value(), 8.0);
    dialog->source()->setCurrentIndex(1);
    QVERIFY(!dialog->level(Mood::Sadness)->isEnabled());
    dialog->findChild<QDialogButtonBox*>()->button(QDialogButtonBox::Ok)->click();
    QCOMPARE(model.undoStack()->count(), undoBefore + 1);
    const KeyframeSequence& keys = model.document().keys;
    const int brow = fap("raise_l_i_eyebrow");
    QVERIFY2(keys.evaluate(1.5)[channelIndex(brow)] < keys.evaluate(7.5)[channelIndex(brow)],
             qPrintable(QString("%1 %2")
                            .arg(keys.evaluate(1.5)[channelIndex(brow)])
                            .arg(keys.evaluate(7.5)[channelIndex(brow)])));
    model.undoStack()->undo();
    QVERIFY(model.document().keys.empty());
    QCOMPARE(model.document().moods[Mood::Sadness].keys().size(), std::size_t(2));
  }

  // Generate crying as a procedural layer: the dialog adds it (one undo step), the Layers panel
  // shows it, a mood key edited afterwards changes the face at once and undo restores the very
  // values; muting and a new seed go through the panel; Bake to keys writes it as keys.
  void generateCryingAsALayerStaysEditable() {
    QTemporaryDir recovery;
    editor::MainWindow window(quietOptions(recovery));
    editing::EditorModel& model = window.model();
    model.setCurrentTime(0);
    model.keyMood(Mood::Sadness, 0.2);
    model.setCurrentTime(6);
    model.keyMood(Mood::Sadness, 0.9);
    const int undoBefore = model.undoStack()->count();
    editor::MoodGenerationDialog* dialog = window.openGenerateCrying();
    dialog->source()->setCurrentIndex(1);
    dialog->output()->setCurrentIndex(1);
    dialog->end()->setValue(12);
    dialog->seed()->setText(QStringLiteral("5"));
    auto* ok = dialog->findChild<QDialogButtonBox*>()->button(QDialogButtonBox::Ok);
    QCOMPARE(ok->text(), QStringLiteral("Add layer"));
    ok->click();
    QCOMPARE(model.undoStack()->count(), undoBefore + 1);
    QVERIFY(model.document().keys.empty());
    QCOMPARE(model.document().moodLayer, std::optional<MoodLayer>(MoodLayer{5, 0, 12, false}));
    editor::MoodLayerRow* row = window.layers()->moodLayer();
    QVERIFY(!row->isHidden());
    QCOMPARE(row->seed()->text(), QStringLiteral("5"));

    model.setCurrentTime(10);
    const int brow = channelIndex(fap("raise_l_i_eyebrow"));
    const FapValues before = model.currentValues();
    QVERIFY(before[brow] > 0);  // the sad face, with no key at all
    model.setCurrentTime(6);
    model.keyMood(Mood::Sadness, 0);  // as the Moods view keys it
    model.setCurrentTime(10);
    QVERIFY2(model.currentValues()[brow] < before[brow],
             qPrintable(QString("%1 %2").arg(model.currentValues()[brow]).arg(before[brow])));
    model.undoStack()->undo();
    QVERIFY(std::memcmp(model.currentValues().data(), before.data(), sizeof before) == 0);

    row->enabled()->click();  // mute
    QVERIFY(model.document().moodLayer->muted);
    QCOMPARE(model.currentValues()[brow], 0.0f);
    QVERIFY(!row->bake()->isEnabled());
    model.undoStack()->undo();
    row->newSeed()->click();
    QCOMPARE(model.document().moodLayer->seed, std::uint64_t(6));
    model.undoStack()->undo();
    QVERIFY(std::memcmp(model.currentValues().data(), before.data(), sizeof before) == 0);

    row->bake()->click();
    QVERIFY(!model.document().moodLayer);
    QVERIFY(row->isHidden());
    QVERIFY(!model.document().keys.empty());
    QVERIFY(std::abs(model.currentValues()[brow] - before[brow]) <= 1.0f);
    model.undoStack()->undo();
    QVERIFY(model.document().moodLayer && model.document().keys.empty());
  }

  // The Record live dialog: by default the selected channels, else every channel the stream
  // sets (as before it existed); a group left out is not keyed; nothing to key offers no Record.
  void dialogChoosesCountInAndChannels() {
    using editor::RecordLiveSettings;
    const ChannelMask selected = maskOf({"open_jaw", "head_yaw"});
    RecordLiveSettings settings;
    QCOMPARE(editor::recordedChannels(settings, {}), std::optional<ChannelMask>(ChannelMask{}));
    QCOMPARE(editor::recordedChannels(settings, selected), std::optional<ChannelMask>(selected));
    settings.skippedGroups = {FapGroup::Head};
    QCOMPARE(editor::recordedChannels(settings, selected),
             std::optional<ChannelMask>(maskOf({"open_jaw"})));
    const std::optional<ChannelMask> noHead = editor::recordedChannels(settings, {});
    QVERIFY(noHead && noHead->test(channelIndex(fap("open_jaw"))) &&
            noHead->test(channelIndex(kTearLeftFap)) &&
            !noHead->test(channelIndex(fap("head_yaw"))));
    settings.onlySelected = false;
    QCOMPARE(editor::recordedChannels(settings, selected), noHead);

    editor::RecordLiveDialog dialog(RecordLiveSettings{}, selected);
    QCOMPARE(dialog.countInField()->value(), 3.0);
    QVERIFY(dialog.onlySelectedBox()->isChecked() && dialog.onlySelectedBox()->isEnabled());
    dialog.countInField()->setValue(1.5);
    dialog.groupBox(FapGroup::Head)->setChecked(false);
    const RecordLiveSettings chosen = dialog.settings();
    QCOMPARE(chosen.countIn, 1.5);
    QVERIFY(chosen.skippedGroups == std::set<FapGroup>{FapGroup::Head});
    QCOMPARE(editor::recordedChannels(chosen, selected),
             std::optional<ChannelMask>(maskOf({"open_jaw"})));
    QPushButton* record = dialog.buttons()->button(QDialogButtonBox::Ok);
    QVERIFY(record->isEnabled());
    dialog.groupBox(FapGroup::JawChinInnerLips)->setChecked(false);  // neither selected channel
    QVERIFY(!record->isEnabled());
  }
};

QTEST_MAIN(LiveRecordTest)
#include "LiveRecordTest.moc"
