#include <lacrima/player/BatchRender.h>

#include <lacrima/player/ContactSheet.h>
#include <lacrima/player/HeadViews.h>
#include <lacrima/player/PngWriter.h>

#include <lacrima/common/Diagnostics.h>
#include <lacrima/export/ExportOptions.h>
#include <lacrima/playback/Playback.h>
#include <lacrima/scene/FaceRenderer.h>
#include <lacrima/scene/FaceScene.h>

#include <QDir>
#include <QElapsedTimer>
#include <QFileInfo>

#include <algorithm>

namespace lacrima::player {

BatchRenderResult renderAnimation(const playback::HeadRig& rig, const BatchRenderOptions& options) {
  QElapsedTimer wall;
  wall.start();
  playback::Playback playback(rig);
  exporting::ExportOptions range;
  range.input = options.input.toStdString();
  range.quality = options.quality;
  range.threads = options.threads;
  range.firstFrame = options.firstFrame;
  range.lastFrame = options.lastFrame;
  range.tears = options.tears;
  const exporting::FrameSpan span = exporting::openForExport(playback, range);
  const QDir out(options.outputDir);
  if (!QDir().mkpath(options.outputDir))
    throw FileError({options.outputDir.toStdString(), 0, 0}, "cannot create the output folder");

  scene::FaceRenderer renderer(rig.head, options.size);
  renderer.scene().setView(presetView(rig, options.view));
  renderer.scene().setTransparentBackground(options.alpha);
  const int frames = span.count();
  std::vector<int> picked = evenlySpacedFrames(frames, options.sheetFrames);
  for (int& f : picked) f += span.first;
  std::vector<SheetFrame> sheet;
  PngWriter writer(2);
  for (int f = span.first; f <= span.last; ++f) {
    const double t = f / playback.frameRate();
    renderer.show(playback.seek(t));
    if (options.frameShown) options.frameShown(playback);
    const QImage image = renderer.render();
    if (std::binary_search(picked.begin(), picked.end(), f))
      sheet.push_back({image.scaledToWidth(400, Qt::SmoothTransformation), f, t});
    const QString number = QStringLiteral("%1").arg(f, 4, 10, QLatin1Char('0'));
    writer.write(image, out.filePath(QStringLiteral("frame_") + number + ".png"));
    if (options.masks)
      writer.write(renderer.renderMask(), out.filePath(QStringLiteral("mask_") + number + ".png"));
    if (options.progress) options.progress(f - span.first + 1, frames);
  }
  writer.finish();
  BatchRenderResult result;
  result.frames = frames;
  result.firstFrame = span.first;
  result.contactSheet = out.filePath("contact_sheet.png");
  QString title = QStringLiteral("%1  ·  %2 frames at %3 fps  ·  %4 x %5")
                      .arg(QFileInfo(options.input).fileName())
                      .arg(frames)
                      .arg(playback.frameRate())
                      .arg(options.size.width())
                      .arg(options.size.height());
  if (options.view != scene::CameraPreset::Framing) {
    const std::string_view view = toString(options.view);
    title += QStringLiteral("  ·  %1 view")
                 .arg(QLatin1String(view.data(), static_cast<qsizetype>(view.size())));
  }
  savePng(contactSheet(sheet, title), result.contactSheet);
  result.seconds = static_cast<double>(wall.elapsed()) / 1000.0;
  return result;
}

}  // namespace lacrima::player
