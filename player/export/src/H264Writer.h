#pragma once
// Frames into an H.264 MP4 through Debian's FFmpeg libraries (libavformat, libavcodec with
// libx264, libswscale): yuv420p, constant frame rate, the "faststart" layout (the index before
// the frames) so players and browsers start at once. The file is written to a temporary beside
// `path` and renamed over it by finish(); destroying an unfinished writer removes the temporary.
#include <QImage>
#include <QSize>

#include <memory>
#include <string>

namespace lacrima::exporting {

class H264Writer {
 public:
  // Throws FileError naming `path` when the size is odd (yuv420p halves it), no H.264 encoder
  // is there, or the file cannot be opened.
  H264Writer(const std::string& path, QSize size, double fps);
  ~H264Writer();
  H264Writer(const H264Writer&) = delete;
  H264Writer& operator=(const H264Writer&) = delete;

  // The next frame, any QImage format, scaled to the size if it differs. Throws FileError.
  void write(const QImage& frame);
  // Flushes the encoder, writes the index and renames the file into place. Throws FileError.
  void finish();

  std::string encoderName() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace lacrima::exporting
