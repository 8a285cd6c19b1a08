#pragma once
// What the lacrima-batch suites share: a small dataset, running the program, comparing results.
#include "../support/RunProcess.h"

#include <QCryptographicHash>
#include <QDir>
#include <QDirIterator>
#include <QFile>
#include <QMap>
#include <QProcess>
#include <QProcessEnvironment>
#include <QString>

namespace lacrima::batch::test {

inline const QString kBatch = QStringLiteral(LACRIMA_BIN_DIR "/lacrima-batch");

// Two moods, with and without tears: four jobs of 12 small frames late enough to hold tears.
inline QByteArray fourJobManifest() {
  return R"({ "format": "lacrima-batch", "version": 1,
    "defaults": { "size": "160x90", "frames": "130-141", "seconds": 7,
                  "outputs": ["frames", "masks"] },
    "grid": { "take": [ { "mood": "sadness=1", "seed": 1 }, { "mood": "anger=1", "seed": 2 } ] },
    "paired": true })";
}

inline bool writeFile(const QString& path, const QByteArray& bytes) {
  QFile f(path);
  return f.open(QIODevice::WriteOnly) && f.write(bytes) == bytes.size();
}

// The environment of a cluster node: no display, so lacrima-batch starts its own.
inline QProcessEnvironment withoutDisplay() {
  QProcessEnvironment e = QProcessEnvironment::systemEnvironment();
  e.remove(QStringLiteral("DISPLAY"));
  return e;
}

inline testsupport::ProcessRun runBatch(const QStringList& arguments, int timeoutMs = 240000,
                                        const QProcessEnvironment& environment = withoutDisplay()) {
  return testsupport::runProcess(kBatch, arguments, timeoutMs, environment);
}

// Relative path -> SHA-256 of every file under `folder` but the job records (whose wall times
// and hosts differ) and the Slurm logs.
inline QMap<QString, QByteArray> contents(const QString& folder) {
  QMap<QString, QByteArray> files;
  const QDir root(folder);
  QDirIterator it(folder, QDir::Files, QDirIterator::Subdirectories);
  while (it.hasNext()) {
    const QString path = it.next();
    const QString relative = root.relativeFilePath(path);
    if (relative.endsWith(QLatin1String("job.json")) ||
        relative.startsWith(QLatin1String("slurm/")))
      continue;
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly)) continue;
    files.insert(relative, QCryptographicHash::hash(f.readAll(), QCryptographicHash::Sha256));
  }
  return files;
}

// The first differing path, or "" when both folders hold the same files, byte for byte.
inline QString firstDifference(const QString& a, const QString& b) {
  const QMap<QString, QByteArray> x = contents(a), y = contents(b);
  for (auto it = x.begin(); it != x.end(); ++it)
    if (y.value(it.key()) != it.value()) return it.key();
  for (auto it = y.begin(); it != y.end(); ++it)
    if (!x.contains(it.key())) return it.key();
  return {};
}

}  // namespace lacrima::batch::test
