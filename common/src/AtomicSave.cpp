#include <lacrima/common/AtomicSave.h>
#include <lacrima/common/Diagnostics.h>

#include <QSaveFile>
#include <QString>

#include <sys/stat.h>

namespace lacrima::inline common {
namespace {

// What the file system holds for the open file, past Qt's buffering (-1 when it cannot say).
qint64 sizeOnDisk(const QSaveFile& file) {
  struct stat info {};
  return ::fstat(file.handle(), &info) == 0 ? static_cast<qint64>(info.st_size) : -1;
}

}  // namespace

void saveAtomically(const std::string& path, std::string_view bytes) {
  // QSaveFile writes a temporary file beside the target (unnamed where the file system allows
  // it, else "<path>.XXXXXX") and puts it in place on commit(); on any error it discards the
  // temporary file, leaving the original as it was.
  QSaveFile file(QString::fromStdString(path));
  auto fail = [&](const QString& why) {
    throw FileError({path, 0, 0}, "cannot save: " + why.toStdString());
  };
  if (!file.open(QIODevice::WriteOnly)) fail(file.errorString());
  const auto size = static_cast<qint64>(bytes.size());
  // A disk that fills up (ENOSPC) or a file-size limit (EFBIG) part-way through a write makes
  // write(2) return a short count first. Qt 6.4 may take that count as the end of the write and
  // report success, so that commit() would put a truncated file in the old one's place, or
  // report the error with errno lost ("Unknown error"). The size on disk is the check that
  // cannot be fooled, and the reason it gives is the one the user can act on.
  const bool wrote = file.write(bytes.data(), size) == size && file.flush();
  const qint64 onDisk = sizeOnDisk(file);
  if (!wrote || onDisk != size) {
    const QString why = onDisk >= 0 && onDisk < size
                            ? QStringLiteral(
                                  "only %1 of %2 bytes reached the disk (it is full, or the "
                                  "file size limit was reached); the old file is unchanged")
                                  .arg(onDisk)
                                  .arg(size)
                            : file.errorString();
    file.cancelWriting();
    fail(why);
  }
  if (!file.commit()) fail(file.errorString());
}

}  // namespace lacrima::inline common
