#include <lacrima/player/PngWriter.h>

#include <lacrima/common/Diagnostics.h>

#include <algorithm>

namespace lacrima::player {

void savePng(const QImage& image, const QString& path) {
  // Opaque renders (FaceRenderer's Format_RGBA8888, alpha 255 throughout) lose nothing as RGB;
  // renders over a transparent background come premultiplied and keep their alpha (Qt writes
  // it straight, as PNG wants). Quality 80 is zlib level 1, which for these images is about 30%
  // larger than the default level and four times faster.
  const QImage rgb = image.format() == QImage::Format_RGBA8888
                         ? image.convertToFormat(QImage::Format_RGB888)
                         : image;
  if (!rgb.save(path, "PNG", 80))
    throw FileError({path.toStdString(), 0, 0},
                    "cannot write the PNG image (folder not writable or disk full?)");
}

PngWriter::PngWriter(int inFlight) : inFlight_(std::max(1, inFlight)) {}

PngWriter::~PngWriter() {
  // Errors were for finish() to report; here only wait so no thread outlives its images.
  for (auto& f : pending_)
    if (f.valid()) f.wait();
}

void PngWriter::waitOldest() {
  std::future<void> oldest = std::move(pending_.front());
  pending_.pop_front();
  oldest.get();
}

void PngWriter::write(QImage image, const QString& path) {
  while (static_cast<int>(pending_.size()) >= inFlight_) waitOldest();
  pending_.push_back(
      std::async(std::launch::async, [image = std::move(image), path] { savePng(image, path); }));
}

void PngWriter::finish() {
  while (!pending_.empty()) waitOldest();
}

}  // namespace lacrima::player
