// Per-channel key edits (the dope sheet's): moving, deleting, copying and pasting one channel
// of a key leaves the key's other channels alone, carries the channel's shape, replaces what
// the channel had where it lands, removes keys left empty, and undoes exactly.
#include "../support/KeyBuilders.h"

#include <lacrima/common/FapTable.h>
#include <lacrima/editing/ChannelKeyEdits.h>
#include <lacrima/editing/EditorModel.h>

#include <QtTest>

#include <cmath>

using namespace lacrima;
using lacrima::test::keyAt;
using namespace lacrima::editing;

namespace {

constexpr double kFps = 22.0;

// A Bézier shape with free handles, unlike any default, so losing it shows.
KeyShape freeBezier() {
  KeyShape shape;
  shape.interpolation = Interpolation::Bezier;
  shape.handles = HandleType::Free;
  shape.in = {-0.2, 15.0};
  shape.out = {0.3, -40.0};
  return shape;
}

// open_jaw (3), lower_t_midlip (4) and a tear count (69) keyed together at 1 s, open_jaw alone
// at 0 s and at 2 s.
KeyframeSequence sample() {
  Keyframe first = keyAt(0.0, {{3, 100.0f}});
  Keyframe shared = keyAt(1.0, {{3, 300.0f}, {4, -50.0f}, {69, 60.0f}});
  shared.setShape(3, freeBezier());
  Keyframe last = keyAt(2.0, {{3, 0.0f}}, Interpolation::Smooth);
  return KeyframeSequence({first, shared, last});
}

const Keyframe* find(const KeyframeSequence& keys, double time) {
  const int index = findKey(keys, time);
  return index < 0 ? nullptr : &keys.keys()[static_cast<std::size_t>(index)];
}

KeyframeSequence applied(KeyframeSequence keys, const KeyChange& change) {
  applyKeys(keys, change.times, change.after);
  return keys;
}

ProjectDocument documentWith(KeyframeSequence keys) {
  ProjectDocument document;
  document.fps = kFps;
  document.keys = std::move(keys);
  return document;
}

}  // namespace

class ChannelKeyEditsTest : public QObject {
  Q_OBJECT

 private slots:
  void movingOneChannelLeavesTheOthers() {
    const KeyframeSequence keys = sample();
    const std::vector<ChannelKey> selection{{3, 1.0}};
    const ChannelKeyEdit edit = moveChannelKeys(keys, selection, 11, kFps);  // +0.5 s
    const KeyframeSequence after = applied(keys, edit.change);

    const Keyframe* left = find(after, 1.0);
    QVERIFY(left);
    QVERIFY(!left->has(3));
    QVERIFY(left->has(4) && left->has(69));
    QCOMPARE(left->value(4), -50.0f);
    QCOMPARE(left->value(69), 60.0f);

    const Keyframe* moved = find(after, 1.5);
    QVERIFY(moved);
    QCOMPARE(moved->channels.count(), std::size_t(1));
    QCOMPARE(moved->value(3), 300.0f);
    QCOMPARE(moved->shape(3), freeBezier());  // the shape travels with the channel
    QCOMPARE(after.keys().size(), std::size_t(4));
    QCOMPARE(edit.selection, (std::vector<ChannelKey>{{3, 1.5}}));
  }

  void aChannelKeyDroppedOnItsChannelReplacesIt() {
    const KeyframeSequence keys = sample();
    // open_jaw's key at 0 s onto its key at 1 s (22 frames): 100 replaces 300 there, and the
    // key at 1 s keeps its other channels; the key at 0 s, left empty, disappears.
    const std::vector<ChannelKey> selection{{3, 0.0}};
    const KeyframeSequence after = applied(keys, moveChannelKeys(keys, selection, 22, kFps).change);
    QVERIFY(!find(after, 0.0));
    const Keyframe* there = find(after, 1.0);
    QVERIFY(there);
    QCOMPARE(there->value(3), 100.0f);
    QVERIFY(there->shape(3).interpolation == Interpolation::Linear);  // the moved key's shape
    QCOMPARE(there->value(4), -50.0f);
    QCOMPARE(there->value(69), 60.0f);
    QCOMPARE(after.keys().size(), std::size_t(2));
  }

  void channelKeysMovingTogetherKeepTheirOrder() {
    const KeyframeSequence keys = sample();
    // All three open_jaw keys one second later: each lands where the next one leaves.
    const std::vector<ChannelKey> selection{{3, 0.0}, {3, 1.0}, {3, 2.0}};
    const ChannelKeyEdit edit = moveChannelKeys(keys, selection, 22, kFps);
    const KeyframeSequence after = applied(keys, edit.change);
    QCOMPARE(find(after, 1.0)->value(3), 100.0f);
    QCOMPARE(find(after, 2.0)->value(3), 300.0f);
    QCOMPARE(find(after, 2.0)->shape(3), freeBezier());
    QCOMPARE(find(after, 3.0)->value(3), 0.0f);
    QVERIFY(find(after, 3.0)->interpolation == Interpolation::Smooth);  // new key: the source's
    QVERIFY(!find(after, 0.0));
    QVERIFY(find(after, 1.0)->has(4));
    QCOMPARE(edit.selection, (std::vector<ChannelKey>{{3, 1.0}, {3, 2.0}, {3, 3.0}}));
  }

  void movesStopAtZeroAndKeepOffGridOffsets() {
    const KeyframeSequence keys = sample();
    const std::vector<ChannelKey> selection{{4, 1.0}};
    const KeyframeSequence early =
        applied(keys, moveChannelKeys(keys, selection, -100, kFps).change);
    QVERIFY(find(early, 0.0)->has(4));
    QVERIFY(find(early, 0.0)->has(3));  // merged into the key at 0 s

    // A key 0.3 frames off the grid (a hand-edited file) keeps its offset.
    const double offGrid = 0.5 + 0.3 / kFps;
    const KeyframeSequence odd({keyAt(offGrid, {{31, 10.0f}})});
    const std::vector<ChannelKey> oddSelection{{31, offGrid}};
    const ChannelKeyEdit edit = moveChannelKeys(odd, oddSelection, 2, kFps);
    const KeyframeSequence moved = applied(odd, edit.change);
    QCOMPARE(moved.keys().size(), std::size_t(1));
    QVERIFY(std::abs(moved.keys().front().time - (offGrid + 2 / kFps)) < 1e-12);
  }

  void nothingToMoveIsNoChange() {
    const KeyframeSequence keys = sample();
    const std::vector<ChannelKey> unknown{{5, 1.0}, {3, 0.7}, {99, 1.0}, {0, 0.0}};
    QVERIFY(moveChannelKeys(keys, unknown, 3, kFps).change.times.empty());
    const std::vector<ChannelKey> selection{{3, 0.0}};
    QVERIFY(moveChannelKeys(keys, selection, -4, kFps).change.isNoOp());  // already at 0 s
    QVERIFY(moveChannelKeys(keys, selection, 4, 0.0).change.times.empty());
    QVERIFY(moveChannelKeys(keys, selection, 4, std::nan("")).change.times.empty());
    QVERIFY(deleteChannelKeys(keys, unknown).change.times.empty());
    QVERIFY(copyChannelKeys(keys, unknown).empty());
  }

  void deletingAChannelKeyKeepsTheKeysOtherChannels() {
    const KeyframeSequence keys = sample();
    const std::vector<ChannelKey> selection{{3, 1.0}, {3, 2.0}};
    const KeyframeSequence after = applied(keys, deleteChannelKeys(keys, selection).change);
    QCOMPARE(after.keys().size(), std::size_t(2));  // 2 s held only open_jaw
    QVERIFY(!find(after, 1.0)->has(3));
    QCOMPARE(find(after, 1.0)->value(69), 60.0f);
    QVERIFY(!find(after, 2.0));
  }

  void copyAndPasteLandOnTheSameChannels() {
    const KeyframeSequence keys = sample();
    const std::vector<ChannelKey> selection{{3, 1.0}, {69, 1.0}, {3, 2.0}};
    const ChannelKeyClip clip = copyChannelKeys(keys, selection);
    QCOMPARE(clip.keys.size(), std::size_t(2));
    QCOMPARE(clip.channelKeyCount(), std::size_t(3));
    QCOMPARE(clip.keys[0].time, 0.0);
    QCOMPARE(clip.keys[1].time, 1.0);
    QVERIFY(!clip.keys[0].has(4));  // only what was selected

    // Pasted at 2 s: 3 and 69 at 2 s (onto open_jaw's key there), 3 at 3 s.
    const ChannelKeyEdit edit = pasteChannelKeys(keys, clip, 2.0, kFps);
    const KeyframeSequence after = applied(keys, edit.change);
    QCOMPARE(find(after, 2.0)->value(3), 300.0f);
    QCOMPARE(find(after, 2.0)->shape(3), freeBezier());
    QCOMPARE(find(after, 2.0)->value(69), 60.0f);
    QCOMPARE(find(after, 3.0)->value(3), 0.0f);
    QVERIFY(find(after, 3.0)->shape(3).interpolation == Interpolation::Smooth);
    QCOMPARE(find(after, 1.0)->channels, find(keys, 1.0)->channels);  // the source is untouched
    QCOMPARE(edit.selection, (std::vector<ChannelKey>{{3, 2.0}, {3, 3.0}, {69, 2.0}}));

    // Off the grid, pasting snaps to the frame (0.51 s at 22 fps is frame 11, 0.5 s).
    const KeyframeSequence snapped = applied(keys, pasteChannelKeys(keys, clip, 0.51, kFps).change);
    QVERIFY(find(snapped, 0.5));
    QVERIFY(find(snapped, 1.5));
    QVERIFY(pasteChannelKeys(keys, clip, std::nan(""), kFps).change.times.empty());
  }

  void plansAreWhatPlanReplaceGives() {
    // The edits build their KeyChange directly (for speed); it must be the one planReplace
    // gives for the same times and keys, so undo and redo behave as for every other edit.
    const KeyframeSequence keys = sample();
    const std::vector<ChannelKey> all{{3, 0.0}, {3, 1.0}, {4, 1.0}, {69, 1.0}, {3, 2.0}};
    const std::vector<ChannelKey> some{{3, 1.0}, {69, 1.0}};
    const ChannelKeyClip clip = copyChannelKeys(keys, some);
    for (const KeyChange& change :
         {moveChannelKeys(keys, all, 7, kFps).change, moveChannelKeys(keys, some, -22, kFps).change,
          deleteChannelKeys(keys, some).change, pasteChannelKeys(keys, clip, 1.5, kFps).change}) {
      const KeyChange expected = planReplace(keys, change.times, change.after);
      QCOMPARE(change.times, expected.times);
      QVERIFY(change.before == expected.before);
      QVERIFY(change.after == expected.after);
      QVERIFY(!change.isNoOp());
    }
  }

  void tearCountsStayWhole() {
    // The surprise: a tear count keyed 60 at 2 s reads 60 from 0 s. Moving it by a
    // channel key keeps it whole, and the hold before it moves with it.
    Keyframe tears = keyAt(2.0, {{69, 60.0f}, {70, 7.0f}});
    Keyframe later = keyAt(4.0, {{69, 13.0f}});
    const KeyframeSequence keys({tears, later});
    const std::vector<ChannelKey> selection{{69, 2.0}};
    const KeyframeSequence after =
        applied(keys, moveChannelKeys(keys, selection, -22, kFps).change);
    QCOMPARE(find(after, 1.0)->value(69), 60.0f);
    QCOMPARE(find(after, 2.0)->value(70), 7.0f);
    for (double t = 0.0; t <= 4.5; t += 0.05) {
      const float v = after.evaluate(t)[channelIndex(69)];
      QCOMPARE(v, std::round(v));
      QVERIFY(v >= 13.0f && v <= 60.0f);
    }
    const ChannelKeyClip clip = copyChannelKeys(keys, selection);
    const KeyframeSequence pasted = applied(keys, pasteChannelKeys(keys, clip, 3.0, kFps).change);
    QCOMPARE(find(pasted, 3.0)->value(69), 60.0f);
    QCOMPARE(pasted.evaluate(3.5)[channelIndex(69)],
             std::round(pasted.evaluate(3.5)[channelIndex(69)]));
  }

  void eachEditIsOneUndoStepThatRestoresTheDocument() {
    EditorModel model;
    model.resetDocument(documentWith(sample()), true);
    const ProjectDocument original = model.document();
    const std::vector<ChannelKey> moving{{3, 1.0}, {69, 1.0}};

    const ChannelKeyEdit move = moveChannelKeys(model.document().keys, moving, 5, kFps);
    model.editKeys(move.change, QStringLiteral("Move channel keys"));
    model.channelKeySelection().select(move.selection);
    QCOMPARE(model.undoStack()->count(), 1);
    QCOMPARE(model.channelKeySelection().keys(), move.selection);
    const ProjectDocument moved = model.document();
    QVERIFY(!(moved == original));

    const ChannelKeyClip clip =
        copyChannelKeys(model.document().keys, model.channelKeySelection().keys());
    const ChannelKeyEdit paste = pasteChannelKeys(model.document().keys, clip, 3.0, kFps);
    model.editKeys(paste.change, QStringLiteral("Paste channel keys"));
    const ProjectDocument pasted = model.document();

    const ChannelKeyEdit remove = deleteChannelKeys(model.document().keys, paste.selection);
    model.editKeys(remove.change, QStringLiteral("Delete channel keys"));
    QCOMPARE(model.document(), moved);  // deleting what was pasted gives the moved document
    QCOMPARE(model.undoStack()->count(), 3);

    model.undoStack()->undo();
    QCOMPARE(model.document(), pasted);
    model.undoStack()->undo();
    QCOMPARE(model.document(), moved);
    model.undoStack()->undo();
    QCOMPARE(model.document(), original);
    model.undoStack()->redo();
    QCOMPARE(model.document(), moved);
    model.undoStack()->redo();
    QCOMPARE(model.document(), pasted);
  }
};

QTEST_GUILESS_MAIN(ChannelKeyEditsTest)
#include "ChannelKeyEditsTest.moc"
