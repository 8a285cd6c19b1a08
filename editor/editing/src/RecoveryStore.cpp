#include <lacrima/editing/RecoveryStore.h>

#include <lacrima/common/AtomicSave.h>
#include <lacrima/common/JsonSyntaxError.h>
#include <lacrima/common/JsonWriter.h>

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
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
      throw FileError({lockPathFor(filePath()).toStdString(), 0, 0}, "cannot lock the recovery file");
    }
  }
  // The project text goes in verbatim, so the recovered document is exactly the saved one.
  JsonWriter header(JsonWriter::Layout::Compact);
  header.beginObject();
  header.field("format", kFormat);
  header.field("version", 1);
  header.field("sourcePath", sourcePath.toStdString());
  header.field("savedAt", QDateTime::currentDateTimeUtc().toString(Qt::ISODateWithMs).toStdString());
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
    lock.setStaleLockTime(0);  // only a dead process makes a lock stale
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

ProjectDocument RecoveryStore::read(const QString& file, QString* sourcePath, QDateTime* savedAt) {
  const std::string name = file.toStdString();
  QFile in(file);
  if (!in.open(QIODevice::ReadOnly)) throw FileError({name, 0, 0}, "cannot open: " + in.errorString().toStdString());
  if (in.size() > kMaxRecoveryBytes) throw FileError({name, 0, 0}, "too large for a recovery file");
  const QByteArray bytes = in.readAll();
  const std::string_view text(bytes.constData(), static_cast<std::size_t>(bytes.size()));
  QJsonParseError error;
  const QJsonDocument json = QJsonDocument::fromJson(bytes, &error);
  if (error.error != QJsonParseError::NoError)
    throw FileError(jsonSyntaxErrorLocation(text, error, name), "invalid JSON: " + error.errorString().toStdString());
  const QJsonObject root = json.object();
  if (root["format"].toString() != QLatin1String(kFormat))
    throw FileError({name, 0, 0}, "format: expected \"lacrima-recovery\"");
  if (root["version"].toInt() != 1) throw FileError({name, 0, 0}, "version: expected 1");
  if (!root["project"].isObject()) throw FileError({name, 0, 0}, "project: expected an object");
  // The project starts at its key's value; parse that text, not a re-serialisation.
  const qsizetype start = bytes.indexOf("\"project\":");
  const qsizetype end = bytes.lastIndexOf('}');
  if (start < 0 || end <= start) throw FileError({name, 0, 0}, "project: expected an object");
  const qsizetype body = start + 10;
  const std::string_view projectText(bytes.constData() + body, static_cast<std::size_t>(end - body));
  ProjectDocument document = ProjectDocument::fromJson(projectText, name);
  if (sourcePath) *sourcePath = root["sourcePath"].toString();
  if (savedAt) *savedAt = QDateTime::fromString(root["savedAt"].toString(), Qt::ISODateWithMs);
  return document;
}

void RecoveryStore::remove(const QString& file) {
  QFile::remove(file);
  QFile::remove(lockPathFor(file));
}

}  // namespace lacrima::editing
