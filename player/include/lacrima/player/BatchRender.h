#pragma once
// lacrima-player --render: every frame of an animation as a PNG (frame_0000.png, ...) and a
// contact sheet of 12 evenly spaced frames (contact_sheet.png), through the same scene the
// viewport shows (FaceRenderer), with progress on stderr; optionally with a transparent
// background (--alpha) and a tear mask per frame (--masks). Needs an X display (xvfb-run).
#include <lacrima/common/TearQuality.h>
#include <lacrima/playback/HeadRig.h>
#include <lacrima/playback/Playback.h>
#include <lacrima/scene/CameraPreset.h>

#include <QSize>
#include <QString>

#include <functional>
#include <optional>

namespace lacrima::player {

struct BatchRenderOptions {
  QString input;      // .fap or project
  QString outputDir;  // created if missing
  QSize size{1280, 720};
  scene::CameraPreset view = scene::CameraPreset::Framing;  // --view
  int sheetFrames = 12;
  // --alpha: RGBA frames with a transparent background (no backdrop), for compositing.
  bool alpha = false;
  // --masks: beside each frame_NNNN.png a mask_NNNN.png of the same size, the ID pass of the
  // same render (FaceRenderer::renderMask): 255 tear water, 128 wet trail, 0 the rest.
  bool masks = false;
  std::optional<TearQuality> quality;  // --quality: replaces the file's level
  int threads = 0;                     // --threads: SimulationOptions::threads (0: its default)
  int firstFrame = 0, lastFrame = -1;  // --frames, both included; -1: to the last frame
  bool tears = true;                   // --no-tears: exporting::ExportOptions::tears
  // After each frame is produced (exporting::ExportOptions::frameShown).
  std::function<void(const playback::Playback&)> frameShown;
  // Called after each frame with (frames done, frames in all).
  std::function<void(int, int)> progress;
};

struct BatchRenderResult {
  int frames = 0;
  int firstFrame = 0;    // the frames are firstFrame ... firstFrame + frames - 1
  QString contactSheet;  // its path
  double seconds = 0;    // wall time
};

// Throws FileError for an unreadable input or an unwritable output folder or image, and
// std::runtime_error when there is no display to render with.
BatchRenderResult renderAnimation(const playback::HeadRig& rig, const BatchRenderOptions& options);

}  // namespace lacrima::player
