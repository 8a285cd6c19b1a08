#include <lacrima/export/VideoExport.h>

#include "H264Writer.h"

#include <lacrima/scene/FaceRenderer.h>
#include <lacrima/scene/FaceScene.h>

#include <QElapsedTimer>

namespace lacrima::exporting {

VideoExportResult exportVideo(const playback::HeadRig& rig, const ExportOptions& options,
                              QSize size, const scene::OrbitView& view) {
  QElapsedTimer wall;
  wall.start();
  playback::Playback playback(rig);
  const FrameSpan span = openForExport(playback, options);
  // The encoder first: an odd size or an unwritable path fails before any frame is simulated.
  H264Writer writer(options.output, size, playback.frameRate());
  scene::FaceRenderer renderer(rig.head, size);
  renderer.scene().setView(view);
  for (int f = span.first; f <= span.last; ++f) {
    renderer.show(playback.seek(f / playback.frameRate()));
    writer.write(renderer.render());
    reportProgress(options, playback, f - span.first + 1, span.count());
  }
  writer.finish();
  VideoExportResult result;
  result.frames = span.count();
  result.fps = playback.frameRate();
  result.encoder = writer.encoderName();
  result.seconds = static_cast<double>(wall.elapsed()) / 1000.0;
  return result;
}

}  // namespace lacrima::exporting
