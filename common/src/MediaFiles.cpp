// Search order for media files (MediaFiles.h).
#include <lacrima/common/Diagnostics.h>
#include <lacrima/common/MediaFiles.h>

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>

namespace lacrima::inline common {

std::vector<std::string> mediaCandidates(std::string_view relative) {
  const QString name = QString::fromUtf8(relative.data(), static_cast<qsizetype>(relative.size()));
  std::vector<std::string> places;
  if (QCoreApplication::instance()) {
    const QString beside = QCoreApplication::applicationDirPath() + "/../share/lacrima/" + name;
    places.push_back(QDir::cleanPath(beside).toStdString());
  }
  places.push_back(QDir::cleanPath(QStringLiteral(LACRIMA_INSTALL_PREFIX "/share/lacrima/") + name)
                       .toStdString());
  places.push_back(
      QDir::cleanPath(QStringLiteral(LACRIMA_SOURCE_MEDIA_DIR "/") + name).toStdString());
  return places;
}

std::string findMediaFile(std::string_view relative) {
  const std::vector<std::string> places = mediaCandidates(relative);
  for (const std::string& place : places)
    if (QFileInfo(QString::fromStdString(place)).isFile()) return place;
  std::string looked;
  for (const std::string& place : places) looked += (looked.empty() ? "" : ", ") + place;
  throw FileError({std::string(relative), 0, 0},
                  "Lacrima's media file is missing; looked in " + looked);
}

}  // namespace lacrima::inline common
