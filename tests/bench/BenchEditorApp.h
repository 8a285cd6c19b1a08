#pragma once
// What the benches that open the editor share: a QApplication on the offscreen platform when
// there is no display (widget figures still mean something there) and in Qt's test mode (the
// user's settings, recent files and window state stay out of it), and editor options for a
// window that asks nothing and keeps its recovery files in a folder of its own.
#include <lacrima/editor/MainWindow.h>

#include <QApplication>
#include <QStandardPaths>
#include <QTemporaryDir>

#include <cstdlib>

namespace lacrima::bench {

class BenchEditorApp {
 public:
  BenchEditorApp() : app_((prepare(), argc_), argv_) { QStandardPaths::setTestModeEnabled(true); }

  bool hasDisplay() const { return display_; }

  // A window that shows no dialogs and offers no recovery.
  editor::EditorOptions editorOptions(bool preview) const {
    editor::EditorOptions options;
    options.interactive = false;
    options.offerRecovery = false;
    options.recoveryDirectory = recovery_.path();
    options.preview = preview;
    return options;
  }

 private:
  void prepare() {
    display_ = std::getenv("DISPLAY") && *std::getenv("DISPLAY");
    if (!display_ && !std::getenv("QT_QPA_PLATFORM")) setenv("QT_QPA_PLATFORM", "offscreen", 1);
  }

  bool display_ = false;
  int argc_ = 1;
  char name_[14] = "lacrima-bench";
  char* argv_[2] = {name_, nullptr};
  QApplication app_;
  QTemporaryDir recovery_;
};

}  // namespace lacrima::bench
