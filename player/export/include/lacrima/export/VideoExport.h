#pragma once
// lacrima-player --video: an animation as an H.264 MP4 (yuv420p, the file's frame rate, constant
// rate, no audio) that plays in common players and video editors, drawn through the same scene
// as the player's window and --render (FaceRenderer) and encoded in the process through Debian's
// FFmpeg libraries. Needs an X display (xvfb-run), as every render does.
#include <lacrima/export/ExportOptions.h>
#include <lacrima/playback/HeadRig.h>
#include <lacrima/scene/OrbitView.h>

#include <QSize>

#include <string>

namespace lacrima::exporting {

struct VideoExportResult {
  int frames = 0;
  double fps = 0;
  std::string encoder;  // "libx264"
  double seconds = 0;   // wall time
};

// `view`: the camera (player::presetView gives the named ones). Width and height must be even.
// Throws FileError for an unreadable input, an odd size or an unwritable output (naming it),
// std::invalid_argument for a bad frame range, std::runtime_error without a display, and
// ExportCancelled when the progress callback asks to stop (nothing is left behind then).
VideoExportResult exportVideo(const playback::HeadRig& rig, const ExportOptions& options,
                              QSize size, const scene::OrbitView& view);

}  // namespace lacrima::exporting
