#pragma once
// The undo commands. Key edits store a KeyChange (see KeyChange.h), so undo and redo restore
// the keys exactly; settings edits store the document's settings before and after.
//
// Slider drags merge: QUndoStack asks the newest command to absorb the next one (mergeWith)
// when both have the same id(). A SetChannelsCommand absorbs another when both come from the
// same drag session and write the same channels at the same time; the merged step keeps the
// first command's "before" and the last one's "after", and drops out of the history when a
// drag ends where it started.
#include <lacrima/common/ProjectDocument.h>
#include <lacrima/editing/EditorModel.h>
#include <lacrima/editing/KeyChange.h>

#include <QUndoCommand>

#include <optional>
#include <vector>

namespace lacrima::editing {

class EditorModel;

class KeyEditCommand : public QUndoCommand {
 public:
  // Selections are restored on undo/redo when given (edits that move or create keys).
  KeyEditCommand(EditorModel& model, KeyChange change, const QString& text,
                 std::optional<std::vector<double>> selectionBefore,
                 std::optional<std::vector<double>> selectionAfter);
  void redo() override;
  void undo() override;
  // Channel keys (dope sheet, graph editor) to select after redo and before undo, like the
  // key-row selections above.
  void setChannelKeySelections(std::vector<ChannelKey> before, std::vector<ChannelKey> after);

 protected:
  EditorModel& model_;
  KeyChange change_;
  std::optional<std::vector<double>> selectionBefore_, selectionAfter_;
  std::optional<std::vector<ChannelKey>> channelKeysBefore_, channelKeysAfter_;
};

class SetChannelsCommand : public KeyEditCommand {
 public:
  static constexpr int kId = 0x4c41;  // any constant unique among Lacrima's commands

  SetChannelsCommand(EditorModel& model, KeyChange change, const QString& text, double time,
                     ChannelMask channels, int dragSession);
  int id() const override { return kId; }
  bool mergeWith(const QUndoCommand* other) override;

 private:
  double time_;
  ChannelMask channels_;
  int session_;
};

// Layer edits (add, remove, mute, intensity keys) store the whole list before and after: a
// project has a handful of layers, each a pose and a few intensity keys.
class LayersCommand : public QUndoCommand {
 public:
  LayersCommand(EditorModel& model, std::vector<PoseLayer> before, std::vector<PoseLayer> after,
                const QString& text);
  void redo() override;
  void undo() override;

 private:
  EditorModel& model_;
  std::vector<PoseLayer> before_, after_;
};

// Mood curve edits (the graph editor's Moods view) store the four curves before and after: a
// few keys each.
class MoodsCommand : public QUndoCommand {
 public:
  MoodsCommand(EditorModel& model, MoodCurves before, MoodCurves after, const QString& text);
  void redo() override;
  void undo() override;

 private:
  EditorModel& model_;
  MoodCurves before_, after_;
};

// Mood layer edits (add, mute, seed, remove, bake) store the layer and the colour curves before
// and after (a bake keys the layer's colours; its keys are a KeyEditCommand in the same macro).
class MoodLayerCommand : public QUndoCommand {
 public:
  MoodLayerCommand(EditorModel& model, MoodLayerState before, MoodLayerState after,
                   const QString& text);
  void redo() override;
  void undo() override;

 private:
  EditorModel& model_;
  MoodLayerState before_, after_;
};

class SettingsCommand : public QUndoCommand {
 public:
  SettingsCommand(EditorModel& model, ProjectDocument before, ProjectDocument after,
                  const QString& text);
  void redo() override;
  void undo() override;

 private:
  EditorModel& model_;
  ProjectDocument before_, after_;  // keys left empty
};

}  // namespace lacrima::editing
