#include <lacrima/common/AtomicSave.h>
#include <lacrima/common/Diagnostics.h>

#include <QSaveFile>
#include <QString>

namespace lacrima::inline common {

void saveAtomically(const std::string& path, std::string_view bytes) {
  // QSaveFile writes "<path>.XXXXXX" beside the target and renames on commit(); on any error
  // it discards the temporary file, leaving the original as it was.
  QSaveFile file(QString::fromStdString(path));
  auto fail = [&](const QString& why) {
    throw FileError({path, 0, 0}, "cannot save: " + why.toStdString());
  };
  if (!file.open(QIODevice::WriteOnly)) fail(file.errorString());
  const auto size = static_cast<qint64>(bytes.size());
  if (file.write(bytes.data(), size) != size) {
    const QString why = file.errorString();
    file.cancelWriting();
    fail(why);
  }
  if (!file.commit()) fail(file.errorString());
}

}  // namespace lacrima::inline common
