#pragma once
// The QGuiApplication of a bench subcommand that renders with OGRE (after missingDisplayOrHead):
// Qt keeps a reference to argc, so the arguments live as long as the application.
#include <QGuiApplication>

namespace lacrima::bench {

class BenchGuiApp {
 public:
  BenchGuiApp() : app_(argc_, argv_) {}

 private:
  int argc_ = 1;
  char name_[14] = "lacrima-bench";
  char* argv_[2] = {name_, nullptr};
  QGuiApplication app_;
};

}  // namespace lacrima::bench
