#pragma once
// Autosave: each running editor keeps its unsaved document in a recovery file, and the next
// editor to start offers to restore files whose editor is gone.
//
// A session owns "<directory>/<id>.json" and holds "<id>.lock" (QLockFile: the PID, host and
// program that hold it) for as long as it runs. A recovery file is an orphan when its lock can
// be taken: either the lock file is gone (the session ended without cleaning up) or the process
// it names is no longer running (a crash; QLockFile treats that lock as stale). Live sessions'
// files are never offered, however long they have been running (age-based staleness is off).
//
// The file is written atomically (temporary file, then rename) and wraps the project JSON:
//   { "format": "lacrima-recovery", "version": 1, "sourcePath": "/path/or/empty",
//     "savedAt": "2024-05-01T12:00:00Z", "project": { ...ProjectDocument... } }
// A clean exit, and any save that makes the document clean, remove it (discard()).
#include <lacrima/common/ProjectDocument.h>

#include <QDateTime>
#include <QString>

#include <memory>
#include <vector>

class QLockFile;

namespace lacrima::editing {

class RecoveryStore {
 public:
  // <AppLocalDataLocation>/recovery
  static QString defaultDirectory();

  explicit RecoveryStore(QString directory = defaultDirectory());
  ~RecoveryStore();  // releases the lock; the file stays unless discard() ran
  RecoveryStore(const RecoveryStore&) = delete;
  RecoveryStore& operator=(const RecoveryStore&) = delete;

  // Writes this session's recovery file. Throws FileError when the folder is not writable.
  void save(const ProjectDocument& document, const QString& sourcePath);
  // Removes this session's recovery file (nothing left to recover).
  void discard();
  bool hasFile() const;
  QString filePath() const;
  const QString& directory() const { return directory_; }

  struct Orphan {
    QString file;
    QString sourcePath;  // where the document was saved before, empty if never
    QString name;        // the project's name
    QDateTime savedAt;
    int keys = 0;
  };
  // Recovery files of sessions that are no longer running, newest first. Unreadable files
  // are skipped (and left alone).
  std::vector<Orphan> orphans() const;

  // Throws FileError naming the file and what was expected; `methods` as in
  // ProjectDocument::read.
  static ProjectDocument read(const QString& file, QString* sourcePath = nullptr,
                              QDateTime* savedAt = nullptr,
                              const TearMethodKeys* methods = nullptr);
  // Removes an orphan (restored or declined).
  static void remove(const QString& file);

 private:
  QString directory_;
  QString id_;
  std::unique_ptr<QLockFile> lock_;
  bool hasFile_ = false;
};

}  // namespace lacrima::editing
