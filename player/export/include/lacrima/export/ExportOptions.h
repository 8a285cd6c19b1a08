#pragma once
// What every animation export (glTF, video, image sequences, tear meshes) is asked: which file,
// where to, which frames, at which tear quality, and whom to tell about progress. The exports
// simulate exactly what the player would show: the same Playback, frame by frame, so a FAP
// without tear channels runs no simulation and writes no tear geometry.
#include <lacrima/common/TearQuality.h>
#include <lacrima/playback/Playback.h>

#include <functional>
#include <optional>
#include <stdexcept>
#include <string>

namespace lacrima::exporting {

struct ExportOptions {
  std::string input;                   // a .fap file or a project
  std::string output;                  // a file or a folder, as the format says
  std::optional<TearQuality> quality;  // replaces the file's tear quality
  int threads = 0;                     // tears::SimulationOptions::threads (0: its default)
  int firstFrame = 0;                  // the frames exported, both ends included;
  int lastFrame = -1;                  // -1: to the last frame of the file
  // false: the animation without its tear channels (Playback::removeTears), the "without tears"
  // half of a paired stimulus; nothing is simulated then.
  bool tears = true;
  // After each frame is produced, before `progress`: the playback showing it (--stats reads the
  // tears' state there).
  std::function<void(const playback::Playback&)> frameShown;
  // After each frame: (frames done, frames in all). Returning false cancels the export, which
  // then throws ExportCancelled and leaves no output behind.
  std::function<bool(int, int)> progress;
};

class ExportCancelled : public std::runtime_error {
 public:
  ExportCancelled() : std::runtime_error("export cancelled") {}
};

// The frames [first, last] an export covers.
struct FrameSpan {
  int first = 0, last = 0;
  int count() const { return last - first + 1; }
};

// Opens options.input on `playback` with the options' quality and threads, and checks the
// frame range against the file. Throws FileError for an unreadable file and
// std::invalid_argument naming the range and the file's frames for a range outside it.
FrameSpan openForExport(playback::Playback& playback, const ExportOptions& options);

// Heads come in any unit; files for other programs are in metres: head units times 0.063 m / ES0
// (the pupils' distance, FAPU; 63 mm is an adult's mean), or 1 when ES0 is unusable.
inline constexpr double kMeanEyeSeparationMetres = 0.063;
double metresPerUnit(const playback::HeadRig& rig);

// Calls options.frameShown, then options.progress; throws ExportCancelled when it asks to stop.
void reportProgress(const ExportOptions& options, const playback::Playback& playback, int done,
                    int total);

}  // namespace lacrima::exporting
