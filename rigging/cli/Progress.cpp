#include "Progress.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>

namespace lacrima {

Progress::Progress() : terminal_(isatty(fileno(stderr)) == 1) {}

Progress::~Progress() {
  if (open_) std::fputc('\n', stderr);
}

void Progress::update(double fraction, std::string_view stage) {
  const int percent = static_cast<int>(std::clamp(fraction, 0.0, 1.0) * 100.0 + 0.5);
  if (!terminal_) {
    // Per-point stages ("influence of 2.1") would flood a log; one line per kind of stage.
    const std::string_view kind = stage.substr(0, stage.find(" of "));
    if (kind == lastStage_) return;
    lastStage_ = std::string(kind);
    std::fprintf(stderr, "lacrima-rig: %3d%% %.*s\n", percent, static_cast<int>(kind.size()),
                 kind.data());
    return;
  }
  if (percent == lastPercent_ && stage == lastStage_) return;
  lastPercent_ = percent;
  lastStage_ = std::string(stage);
  constexpr int kWidth = 30;
  const int filled = percent * kWidth / 100;
  std::fprintf(stderr, "\r[%.*s%*s] %3d%% %-32.32s", filled, "##############################",
               kWidth - filled, "", percent, lastStage_.c_str());
  std::fflush(stderr);
  open_ = true;
}

}  // namespace lacrima
