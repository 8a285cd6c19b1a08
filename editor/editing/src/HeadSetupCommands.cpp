#include <lacrima/editing/HeadSetupCommands.h>

#include <utility>

namespace lacrima::editing {

SetPartRoleCommand::SetPartRoleCommand(HeadSetup& setup, int submesh, PartRole before,
                                       PartRole after)
    : setup_(setup), submesh_(submesh), before_(before), after_(after) {
  const auto& name = setup.mesh().submeshes.at(static_cast<std::size_t>(submesh)).name;
  setText(QStringLiteral("%1: %2").arg(
      QString::fromStdString(name),
      QString::fromUtf8(partRoleName(after).data(), static_cast<int>(partRoleName(after).size()))));
}

void SetPartRoleCommand::redo() { setup_.assignRole(submesh_, after_); }
void SetPartRoleCommand::undo() { setup_.assignRole(submesh_, before_); }

SetPointCommand::SetPointCommand(HeadSetup& setup, std::string id,
                                 std::optional<PlacedPoint> before,
                                 std::optional<PlacedPoint> after, const QString& text)
    : setup_(setup), id_(std::move(id)), before_(std::move(before)), after_(std::move(after)) {
  setText(text);
}

void SetPointCommand::redo() { setup_.assignPoint(id_, after_); }
void SetPointCommand::undo() { setup_.assignPoint(id_, before_); }

SetPointsCommand::SetPointsCommand(HeadSetup& setup, PlacedPoints before, PlacedPoints after,
                                   const QString& text)
    : setup_(setup), before_(std::move(before)), after_(std::move(after)) {
  setText(text);
}

void SetPointsCommand::redo() { setup_.assignPoints(after_); }
void SetPointsCommand::undo() { setup_.assignPoints(before_); }

}  // namespace lacrima::editing
