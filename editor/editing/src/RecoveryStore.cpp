#include <lacrima/editing/RecoveryStore.h>

#include <lacrima/common/AtomicSave.h>
#include <lacrima/common/JsonInput.h>
#include <lacrima/common/JsonWriter.h>

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QLockFile>
#include <QStandardPaths>

#include <algorithm>

namespace lacrima::editing {
namespace {

constexpr const char* kFormat = "lacrima-recovery";
constexpr qint64 kMaxRecoveryBytes = 512LL * 1024 * 1024;

QString lockPathFor(const QString& jsonPath) {
  return jsonPath.left(jsonPath.size() - 5) + QStringLiteral(".lock");  // "x.json" -> "x.lock"
}

}  // namespace

QString RecoveryStore::defaultDirectory() {
  return QStandardPaths::writableLocation(QStandardPaths::AppLocalDataLocation) +
         QStringLiteral("/recovery");
}

RecoveryStore::RecoveryStore(QString directory) : directory_(std::move(directory)) {
  id_ = QStringLiteral("session-%1-%2")
            .arg(QCoreApplication::applicationPid())
            .arg(QDateTime::currentMSecsSinceEpoch());
  // Two stores in one process (tests, several windows) must not share a file.
  static int counter = 0;
  id_ += QStringLiteral("-%1").arg(++counter);
}

RecoveryStore::~RecoveryStore() = default;

QString RecoveryStore::filePath() const { return directory_ + '/' + id_ + QStringLiteral(".json"); }

bool RecoveryStore::hasFile() const { return hasFile_; }

void RecoveryStore::save(const ProjectDocument& document, const QString& sourcePath) {
  if (!QDir().mkpath(directory_))
    throw FileError({directory_.toStdString(), 0, 0}, "cannot create the recovery folder");
  if (!lock_) {
    lock_ = std::make_unique<QLockFile>(lockPathFor(filePath()));
    lock_->setStaleLockTime(0);
    if (!lock_->tryLock(0)) {
      lock_.reset();
      throw FileError({lockPathFor(filePath()).toStdString(), 0, 0},
                      "cannot lock the recovery file");
    }
  }
  // The project text goes in verbatim, so the recovered document is exactly the saved one.
  JsonWriter header(JsonWriter::Layout::Compact);
  header.beginObject();
  header.field("format", kFormat);
  header.field("version", 1);
  header.field("sourcePath", sourcePath.toStdString());
  header.field("savedAt",
               QDateTime::currentDateTimeUtc().toString(Qt::ISODateWithMs).toStdString());
  header.endObject();
  std::string text = std::move(header).finish();
  while (!text.empty() && (text.back() == '\n' || text.back() == '}')) text.pop_back();
  text += ", \"project\": " + document.toJson() + "}\n";
  saveAtomically(filePath().toStdString(), text);
  hasFile_ = true;
}

void RecoveryStore::discard() {
  if (hasFile_) QFile::remove(filePath());
  hasFile_ = false;
  if (lock_) {
    lock_->unlock();
    lock_.reset();
  }
}

std::vector<RecoveryStore::Orphan> RecoveryStore::orphans() const {
  std::vector<Orphan> found;
  const QDir dir(directory_);
  const QStringList files = dir.entryList({QStringLiteral("session-*.json")}, QDir::Files);
  for (const QString& name : files) {
    const QString path = dir.filePath(name);
    if (path == filePath()) continue;
    QLockFile lock(lockPathFor(path));
    lock.setStaleLockTime(0);        // only a dead process makes a lock stale
    if (!lock.tryLock(0)) continue;  // its editor is still running
    lock.unlock();
    try {
      Orphan orphan;
      orphan.file = path;
      const ProjectDocument document = read(path, &orphan.sourcePath, &orphan.savedAt);
      orphan.name = QString::fromStdString(document.name);
      orphan.keys = static_cast<int>(document.keys.keys().size());
      found.push_back(orphan);
    } catch (const FileError&) {
      // A file we cannot read is not something to offer; it stays for a person to inspect.
    }
  }
  std::sort(found.begin(), found.end(),
            [](const Orphan& a, const Orphan& b) { return a.savedAt > b.savedAt; });
  return found;
}

ProjectDocument RecoveryStore::read(const QString& file, QString* sourcePath, QDateTime* savedAt,
                                    const TearMethodKeys* methods) {
  const JsonValue root =
      JsonInput::load(file.toStdString(), {"recovery file", kMaxRecoveryBytes}).root();
  const JsonValue format = root["format"];
  if (!format.isString() || format.string() != kFormat)
    format.fail("expected \"lacrima-recovery\", got " + format.describe());
  const JsonValue version = root["version"];
  if (!version.isNumber() || version.number() != 1)
    version.fail("expected 1, got " + version.describe());
  ProjectDocument document =
      ProjectDocument::read(root["project"], ProjectDocument::Use::Edit, methods);
  if (sourcePath) *sourcePath = QString::fromStdString(root["sourcePath"].string());
  if (savedAt)
    *savedAt =
        QDateTime::fromString(QString::fromStdString(root["savedAt"].string()), Qt::ISODateWithMs);
  return document;
}

void RecoveryStore::remove(const QString& file) {
  QFile::remove(file);
  QFile::remove(lockPathFor(file));
}

}  // namespace lacrima::editing
