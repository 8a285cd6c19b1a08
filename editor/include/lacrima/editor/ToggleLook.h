#pragma once
// Checkable tool buttons that show whether they are on. Under the dark Fusion palette an
// auto-raised QToolButton draws "checked" as a faint sunken panel that reads the same as "off";
// this gives the checked state the selection colour's fill and frame, as toggles in Blender's
// and Maya's headers have.
class QToolButton;

namespace lacrima::editor {

void showCheckedState(QToolButton* button);

}  // namespace lacrima::editor
