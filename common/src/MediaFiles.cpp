// Search order for media files (MediaFiles.h).
#include <lacrima/common/Diagnostics.h>
#include <lacrima/common/MediaFiles.h>

#include <QDir>
#include <QFileInfo>

#include <filesystem>
#include <system_error>

namespace lacrima::inline common {

namespace {

// Whether `dir` is this build's bin/: equivalence, not string equality, so a build reached
// through a symbolic link still finds the sources.
bool isBuildRuntimeDir(const std::string& dir) {
  std::error_code error;
  return !dir.empty() && std::filesystem::equivalent(dir, LACRIMA_BUILD_RUNTIME_DIR, error);
}

}  // namespace

std::string executableDir() {
  std::error_code error;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", error);
  return error ? std::string() : exe.parent_path().string();
}

std::vector<std::string> mediaCandidatesFor(const std::string& executableDir,
                                            std::string_view relative) {
  const QString name = QString::fromUtf8(relative.data(), static_cast<qsizetype>(relative.size()));
  std::vector<std::string> places;
  if (!executableDir.empty())
    places.push_back(
        QDir::cleanPath(QString::fromStdString(executableDir) + "/../share/lacrima/" + name)
            .toStdString());
  if (isBuildRuntimeDir(executableDir))
    places.push_back(
        QDir::cleanPath(QStringLiteral(LACRIMA_SOURCE_MEDIA_DIR "/") + name).toStdString());
  return places;
}

std::vector<std::string> mediaCandidates(std::string_view relative) {
  return mediaCandidatesFor(executableDir(), relative);
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
