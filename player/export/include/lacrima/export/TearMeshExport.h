#pragma once
// lacrima-player --export-tears: the tear geometry of every frame as a mesh sequence, the way
// fluid simulators hand their caches to other programs: OUT_DIR/tears_0000.ply, tears_0001.ply,
// ... one binary little-endian PLY per exported frame (numbered by the file's frame), empty
// (no vertices) where the frame shows no tears, so the sequence has no gaps. Each holds the
// frame's water (tear surface and drops on the skin) and wet trails as one triangle mesh:
//   vertex: float x, y, z (metres, Y up, +Z out of the face; metresPerUnit), float nx, ny, nz,
//           uchar red, green, blue, alpha: water (0, 128, 255, 255), trail (255, 128, 0,
//           255 x wetness), the colours Blender's and MeshLab's PLY readers show;
//   face:   list uchar int vertex_indices, counter-clockwise seen from outside the water.
// Every file is written to a temporary and renamed. A file without tear channels simulates
// nothing and writes only empty frames.
#include <lacrima/export/ExportOptions.h>
#include <lacrima/playback/HeadRig.h>

#include <cstddef>

namespace lacrima::exporting {

struct TearMeshExportResult {
  int frames = 0;  // files written
  int framesWithTears = 0;
  std::size_t bytes = 0;  // all files
  double seconds = 0;     // wall time
};

// options.output is the folder (created if missing). Throws FileError for an unreadable input or
// an unwritable folder or file (naming it), std::invalid_argument for a bad frame range and
// ExportCancelled when the progress callback asks to stop (frames written so far stay).
TearMeshExportResult exportTearMeshes(const playback::HeadRig& rig, const ExportOptions& options);

}  // namespace lacrima::exporting
