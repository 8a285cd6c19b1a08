#pragma once
// Writes PNG images on worker threads while the caller renders the next frame: at 1280x720 the
// encoding costs as much as a software render. At most `inFlight` images wait; write() blocks
// beyond that, so memory stays bounded. finish() (or the destructor) waits for all and
// rethrows the first failure as FileError naming the file.
#include <QImage>
#include <QString>

#include <deque>
#include <future>

namespace lacrima::player {

class PngWriter {
 public:
  explicit PngWriter(int inFlight);
  ~PngWriter();
  PngWriter(const PngWriter&) = delete;
  PngWriter& operator=(const PngWriter&) = delete;

  void write(QImage image, const QString& path);
  void finish();

 private:
  void waitOldest();

  int inFlight_;
  std::deque<std::future<void>> pending_;
};

// Synchronous save with the same settings; throws FileError.
void savePng(const QImage& image, const QString& path);

}  // namespace lacrima::player
