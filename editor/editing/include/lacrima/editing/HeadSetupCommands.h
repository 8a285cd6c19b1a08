#pragma once
// The Head workspace's undo commands: each stores the state before and after, so undo and redo
// restore it exactly (see HeadSetup.h for the edits that push them).
#include <lacrima/editing/HeadSetup.h>

#include <QUndoCommand>

#include <optional>
#include <string>

namespace lacrima::editing {

class SetPartRoleCommand : public QUndoCommand {
 public:
  SetPartRoleCommand(HeadSetup& setup, int submesh, PartRole before, PartRole after);
  void redo() override;
  void undo() override;

 private:
  HeadSetup& setup_;
  int submesh_;
  PartRole before_, after_;
};

// Place, move or remove one point (a nullopt side: the point is absent).
class SetPointCommand : public QUndoCommand {
 public:
  SetPointCommand(HeadSetup& setup, std::string id, std::optional<PlacedPoint> before,
                  std::optional<PlacedPoint> after, const QString& text);
  void redo() override;
  void undo() override;

 private:
  HeadSetup& setup_;
  std::string id_;
  std::optional<PlacedPoint> before_, after_;
};

// Every point at once (a proposal).
class SetPointsCommand : public QUndoCommand {
 public:
  SetPointsCommand(HeadSetup& setup, PlacedPoints before, PlacedPoints after, const QString& text);
  void redo() override;
  void undo() override;

 private:
  HeadSetup& setup_;
  PlacedPoints before_, after_;
};

}  // namespace lacrima::editing
