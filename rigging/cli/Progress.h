#pragma once
// Progress of a long step on stderr: a bar redrawn in place on a terminal, plain lines (one per
// stage) when stderr is a file or pipe, so logs stay readable.
#include <string>
#include <string_view>

namespace lacrima {

class Progress {
 public:
  Progress();
  ~Progress();  // ends a bar line that is still open
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  void update(double fraction, std::string_view stage);

 private:
  bool terminal_;
  bool open_ = false;  // a bar is on the current line
  int lastPercent_ = -1;
  std::string lastStage_;
};

}  // namespace lacrima
