#pragma once
// The look both applications share: Fusion with a dark palette, on which the face and its tears
// read best (as in other animation tools), so the player and the editor look like one suite.
class QApplication;

namespace lacrima::viewport {

void applyDarkTheme(QApplication& app);

}  // namespace lacrima::viewport
