#include <lacrima/batch/JobRecord.h>

#include <lacrima/batch/BatchJob.h>
#include <lacrima/common/JsonInput.h>
#include <lacrima/common/JsonWriter.h>

#include <QCryptographicHash>
#include <QDir>
#include <QDirIterator>
#include <QFileInfo>

#include <algorithm>

namespace lacrima::batch {

namespace {

bool isHex(const std::string& text, std::size_t length) {
  return text.size() == length && std::all_of(text.begin(), text.end(), [](char c) {
           return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f');
         });
}

RunFigures figuresFrom(const JsonValue& v) {
  v.rejectUnknownMembers({"frames", "frames_with_tears", "peak_particles", "tear_state_hash"});
  RunFigures f;
  constexpr int kMaxFrames = 100000000;
  f.frames = v.required("frames").integer(0, kMaxFrames);
  f.framesWithTears = v.required("frames_with_tears").integer(0, kMaxFrames);
  f.peakParticles = v.required("peak_particles").integer(0, kMaxFrames);
  f.tearStateHash = v.required("tear_state_hash").string();
  if (!isHex(f.tearStateHash, 16)) v["tear_state_hash"].fail("expected 16 lower-case hex digits");
  return f;
}

}  // namespace

RunFigures readRunFigures(const std::string& path) {
  return figuresFrom(JsonInput::load(path, {"statistics file", 1 << 20}).root());
}

std::string JobRecord::toJson() const {
  JsonWriter json;
  json.beginObject();
  json.field("format", "lacrima-job");
  json.field("version", 1);
  json.field("id", std::string_view(id));
  json.field("status", done ? "done" : "failed");
  if (!done) json.field("error", std::string_view(error));
  json.field("label", std::string_view(label));
  json.field("job", std::string_view(job));
  json.field("lacrima", std::string_view(version));
  json.field("host", std::string_view(host));
  json.field("wall_seconds", wallSeconds);
  if (statistics) {
    json.key("statistics");
    json.beginObject();
    json.field("frames", statistics->frames);
    json.field("frames_with_tears", statistics->framesWithTears);
    json.field("peak_particles", statistics->peakParticles);
    json.field("tear_state_hash", std::string_view(statistics->tearStateHash));
    json.endObject();
  }
  json.key("outputs");
  json.beginArray();
  for (const OutputFile& o : outputs) {
    json.beginObject();
    json.field("file", std::string_view(o.file));
    json.field("bytes", o.bytes);
    json.field("sha256", std::string_view(o.sha256));
    json.endObject();
  }
  json.endArray();
  json.endObject();
  return std::move(json).finish();
}

JobRecord JobRecord::read(const std::string& path) {
  const JsonValue root = JsonInput::load(path, {"job record", kMaxFileBytes}).root();
  root.rejectUnknownMembers({"format", "version", "id", "status", "error", "label", "job",
                             "lacrima", "host", "wall_seconds", "statistics", "outputs"});
  if (root.required("format").string() != "lacrima-job")
    root["format"].fail("expected \"lacrima-job\"");
  root.required("version").integer(1, 1);
  JobRecord r;
  r.id = root.required("id").string();
  if (!isHex(r.id, 16)) root["id"].fail("expected a job id of 16 hex digits");
  r.done = root.required("status").oneOf({"failed", "done"}) == 1;
  if (root.has("error")) r.error = root["error"].string();
  r.label = root.required("label").string();
  r.job = root.required("job").string();
  r.version = root.required("lacrima").string();
  r.host = root.required("host").string();
  r.wallSeconds = root.required("wall_seconds").number(0, 1e9);
  if (root.has("statistics")) r.statistics = figuresFrom(root["statistics"]);
  for (const JsonValue& o : root.required("outputs").array(kMaxOutputs)) {
    o.rejectUnknownMembers({"file", "bytes", "sha256"});
    OutputFile f;
    f.file = o.required("file").string();
    // Within the job's folder: no absolute path, no way up.
    const QString file = QString::fromStdString(f.file);
    if (f.file.empty() || QDir::isAbsolutePath(file) || file.split('/').contains(".."))
      o["file"].fail("expected a path inside the job's folder");
    f.bytes = static_cast<long long>(o.required("bytes").number(0, 9e15));
    f.sha256 = o.required("sha256").string();
    if (!isHex(f.sha256, 64)) o["sha256"].fail("expected 64 lower-case hex digits");
    r.outputs.push_back(std::move(f));
  }
  return r;
}

std::string JobRecord::outputsSha256() const {
  QCryptographicHash hash(QCryptographicHash::Sha256);
  for (const OutputFile& o : outputs) {
    hash.addData(QByteArray::fromStdString(o.file + " " + o.sha256 + "\n"));
  }
  return hash.result().toHex().toStdString();
}

std::vector<OutputFile> listOutputs(const std::string& folder) {
  // Absolute: relativeFilePath() of a relative folder would hand back the paths unchanged.
  const QDir root(QFileInfo(QString::fromStdString(folder)).absoluteFilePath());
  std::vector<OutputFile> files;
  QDirIterator it(root.path(), QDir::Files | QDir::NoSymLinks, QDirIterator::Subdirectories);
  while (it.hasNext()) {
    const QString path = it.next();
    const QString relative = root.relativeFilePath(path);
    if (relative == QLatin1String("job.json")) continue;
    files.push_back(
        {relative.toStdString(), QFileInfo(path).size(), fileSha256(path.toStdString())});
  }
  std::sort(files.begin(), files.end(),
            [](const OutputFile& a, const OutputFile& b) { return a.file < b.file; });
  return files;
}

bool isComplete(const std::string& folder, const std::string& id, bool verifyHashes) {
  const QDir dir(QString::fromStdString(folder));
  const QString record = dir.filePath(QStringLiteral("job.json"));
  if (!QFileInfo(record).isFile()) return false;
  try {
    const JobRecord r = JobRecord::read(record.toStdString());
    if (!r.done || r.id != id) return false;
    for (const OutputFile& o : r.outputs) {
      const QString path = dir.filePath(QString::fromStdString(o.file));
      const QFileInfo info(path);
      if (!info.isFile() || info.size() != o.bytes) return false;
      if (verifyHashes && fileSha256(path.toStdString()) != o.sha256) return false;
    }
    return true;
  } catch (const FileError&) {
    return false;  // a damaged record: the job is redone
  }
}

}  // namespace lacrima::batch
