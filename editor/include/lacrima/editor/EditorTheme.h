#pragma once
// The editor's look: a dark Fusion palette (the face and the tears read best on dark grey, as
// in other animation tools), one accent for keys, and a colour per FAP group so the eye finds
// a group in the slider list and in the timeline's curve.
#include <lacrima/common/FapTable.h>

#include <QColor>

class QApplication;

namespace lacrima::editor::theme {

void apply(QApplication& app);

QColor keyAccent();  // keys at the current time, selected keys
QColor keyIdle();    // other keys
QColor playhead();
QColor tearBlue();
QColor groupColour(FapGroup group);

}  // namespace lacrima::editor::theme
