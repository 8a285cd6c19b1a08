#include <lacrima/editing/EditCommands.h>

#include <lacrima/editing/EditorModel.h>

#include <cmath>

namespace lacrima::editing {

KeyEditCommand::KeyEditCommand(EditorModel& model, KeyChange change, const QString& text,
                               std::optional<std::vector<double>> selectionBefore,
                               std::optional<std::vector<double>> selectionAfter)
    : QUndoCommand(text),
      model_(model),
      change_(std::move(change)),
      selectionBefore_(std::move(selectionBefore)),
      selectionAfter_(std::move(selectionAfter)) {}

void KeyEditCommand::setChannelKeySelections(std::vector<ChannelKey> before,
                                             std::vector<ChannelKey> after) {
  channelKeysBefore_ = std::move(before);
  channelKeysAfter_ = std::move(after);
}

void KeyEditCommand::redo() {
  model_.applyKeyChange(change_, true);
  if (selectionAfter_) model_.setSelectedTimes(*selectionAfter_);
  if (channelKeysAfter_) model_.channelKeySelection().select(*channelKeysAfter_);
}

void KeyEditCommand::undo() {
  model_.applyKeyChange(change_, false);
  if (selectionBefore_) model_.setSelectedTimes(*selectionBefore_);
  if (channelKeysBefore_) model_.channelKeySelection().select(*channelKeysBefore_);
}

SetChannelsCommand::SetChannelsCommand(EditorModel& model, KeyChange change, const QString& text,
                                       double time, ChannelMask channels, int dragSession)
    : KeyEditCommand(model, std::move(change), text, std::nullopt, std::nullopt),
      time_(time),
      channels_(channels),
      session_(dragSession) {}

bool SetChannelsCommand::mergeWith(const QUndoCommand* other) {
  const auto* next = dynamic_cast<const SetChannelsCommand*>(other);
  if (!next || session_ == 0 || next->session_ != session_ || next->channels_ != channels_ ||
      std::abs(next->time_ - time_) >= kSameKeyTime) {
    return false;
  }
  // Same single time, so the affected times agree; only the end state moves on.
  change_.after = next->change_.after;
  setObsolete(change_.isNoOp());
  return true;
}

LayersCommand::LayersCommand(EditorModel& model, std::vector<PoseLayer> before,
                             std::vector<PoseLayer> after, const QString& text)
    : QUndoCommand(text), model_(model), before_(std::move(before)), after_(std::move(after)) {}

void LayersCommand::redo() { model_.applyLayers(after_); }
void LayersCommand::undo() { model_.applyLayers(before_); }

MoodsCommand::MoodsCommand(EditorModel& model, MoodCurves before, MoodCurves after,
                           const QString& text)
    : QUndoCommand(text), model_(model), before_(std::move(before)), after_(std::move(after)) {}

void MoodsCommand::redo() { model_.applyMoods(after_); }
void MoodsCommand::undo() { model_.applyMoods(before_); }

MoodLayerCommand::MoodLayerCommand(EditorModel& model, MoodLayerState before, MoodLayerState after,
                                   const QString& text)
    : QUndoCommand(text), model_(model), before_(std::move(before)), after_(std::move(after)) {}

void MoodLayerCommand::redo() { model_.applyMoodLayer(after_); }
void MoodLayerCommand::undo() { model_.applyMoodLayer(before_); }

SettingsCommand::SettingsCommand(EditorModel& model, ProjectDocument before, ProjectDocument after,
                                 const QString& text)
    : QUndoCommand(text), model_(model), before_(std::move(before)), after_(std::move(after)) {
  before_.keys = {};
  after_.keys = {};
}

void SettingsCommand::redo() { model_.applySettings(after_); }
void SettingsCommand::undo() { model_.applySettings(before_); }

}  // namespace lacrima::editing
