#include <lacrima/batch/BatchRun.h>

#include <lacrima/common/AtomicSave.h>
#include <lacrima/common/Diagnostics.h>

#include <QCoreApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QSysInfo>

#include <algorithm>
#include <atomic>
#include <map>
#include <mutex>
#include <set>
#include <thread>

namespace lacrima::batch {

namespace {

QString qs(const std::string& s) { return QString::fromStdString(s); }

std::string clock(double seconds) {
  const long long s = std::max(0LL, static_cast<long long>(seconds + 0.5));
  char text[32];
  std::snprintf(text, sizeof text, "%lld:%02lld:%02lld", s / 3600, s / 60 % 60, s % 60);
  return text;
}

// Progress: a line rewritten in place on a terminal, else a line per finished job for logs.
class Progress {
 public:
  Progress(std::FILE* log, bool live, int total, int parallel)
      : log_(log), live_(live), total_(total), parallel_(std::max(1, parallel)) {}

  void finished(const PlannedJob& job, bool done, double seconds) {
    std::lock_guard lock(mutex_);
    (done ? done_ : failed_) += 1;
    spent_ += seconds;
    const int finished = done_ + failed_;
    const double left = finished > 0 ? spent_ / finished * (total_ - finished) / parallel_ : 0;
    if (live_) {
      std::fprintf(log_, "\r\033[Klacrima-batch: %d of %d jobs done, %d failed, %s left", done_,
                   total_, failed_, clock(left).c_str());
    } else {
      std::fprintf(log_, "lacrima-batch: [%d/%d] %s %s in %.1f s (%s)\n", finished, total_,
                   job.id.c_str(), done ? "done" : "FAILED", seconds, job.job.label().c_str());
    }
    std::fflush(log_);
  }

  void end() {
    if (live_ && total_ > 0) std::fprintf(log_, "\n");
  }

 private:
  std::FILE* log_;
  bool live_;
  int total_, parallel_;
  int done_ = 0, failed_ = 0;
  double spent_ = 0;
  std::mutex mutex_;
};

// Replaces `target` (a folder, maybe absent) by `source` with one rename.
void moveIntoPlace(const QString& source, const QString& target, const QString& trash) {
  if (QFileInfo::exists(target)) {
    if (!QDir().rename(target, trash) || !QDir(trash).removeRecursively())
      throw FileError({target.toStdString(), 0, 0}, "cannot replace the old results");
  }
  if (!QDir().rename(source, target))
    throw FileError({target.toStdString(), 0, 0}, "cannot move the job's results into place");
}

std::string csvField(const std::string& text) {
  if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

// A row per job, also for tools that read lines: a multi-line message is joined with " / ".
std::string oneLine(const std::string& text) {
  std::string line;
  for (char c : text) {
    if (c == '\r') continue;
    if (c == '\n')
      line += " / ";
    else
      line += c;
  }
  return line;
}

}  // namespace

std::vector<PlannedJob> planJobs(const BatchManifest& manifest) {
  std::map<std::string, std::string> digests;
  const auto fingerprint = [&digests](const std::string& path) {
    auto it = digests.find(path);
    if (it == digests.end()) it = digests.emplace(path, fileSha256(path)).first;
    return it->second;
  };
  std::vector<PlannedJob> jobs;
  std::set<std::string> seen;
  for (const BatchJob& job : manifest.jobs) {
    PlannedJob planned{job, canonicalJson(job, fingerprint), {}};
    planned.id = jobId(planned.canonical);
    if (seen.insert(planned.id).second) jobs.push_back(std::move(planned));
  }
  std::sort(jobs.begin(), jobs.end(),
            [](const PlannedJob& a, const PlannedJob& b) { return a.id < b.id; });
  return jobs;
}

std::vector<PlannedJob> shardOf(const std::vector<PlannedJob>& jobs, int index, int count) {
  std::vector<PlannedJob> share;
  for (std::size_t k = static_cast<std::size_t>(index - 1); k < jobs.size();
       k += static_cast<std::size_t>(count))
    share.push_back(jobs[k]);
  return share;
}

BatchResult runBatch(const std::vector<PlannedJob>& all, const BatchOptions& options,
                     JobRunner& runner, std::FILE* log) {
  const QDir out(qs(options.outDir));
  const QString scratch = out.filePath(QStringLiteral(".partial"));
  if (!QDir().mkpath(scratch))
    throw FileError({options.outDir, 0, 0}, "cannot create the output folder");
  const std::vector<PlannedJob> mine = shardOf(all, options.shardIndex, options.shardCount);

  // Scratch folders of this shard's jobs are left by a run that was killed: clear them. Other
  // shards' may be in use by their runs on other nodes.
  std::set<QString> ids;
  for (const PlannedJob& p : mine) ids.insert(qs(p.id));
  for (const QString& name : QDir(scratch).entryList(QDir::Dirs | QDir::NoDotAndDotDot))
    if (ids.contains(name.section('.', 0, 0)))
      QDir(QDir(scratch).filePath(name)).removeRecursively();

  BatchResult result;
  result.planned = static_cast<int>(mine.size());
  std::vector<const PlannedJob*> todo;
  for (const PlannedJob& p : mine)
    if (!isComplete(out.filePath(qs(p.id)).toStdString(), p.id, options.verifyHashes))
      todo.push_back(&p);
  result.skipped = result.planned - static_cast<int>(todo.size());

  std::vector<const BatchJob*> drawn;
  for (const PlannedJob* p : todo) drawn.push_back(&p->job);
  runner.prepare(drawn);

  const QString host = QSysInfo::machineHostName();
  const QString tag = QStringLiteral(".%1.%2").arg(host).arg(QCoreApplication::applicationPid());
  Progress progress(log, options.progressLine, static_cast<int>(todo.size()), options.parallel);
  std::atomic<std::size_t> next{0};
  std::atomic<bool> stop{false};
  std::mutex resultMutex;

  const auto work = [&]() {
    for (std::size_t k = next++; k < todo.size() && !stop; k = next++) {
      const PlannedJob& p = *todo[k];
      QElapsedTimer wall;
      wall.start();
      const QString folder = QDir(scratch).filePath(qs(p.id) + tag);
      JobRecord record;
      record.id = p.id;
      record.job = p.canonical;
      record.label = p.job.label();
      record.version = options.version;
      record.host = host.toStdString();
      try {
        if (!QDir().mkpath(folder))
          throw FileError({folder.toStdString(), 0, 0}, "cannot create the job's folder");
        const JobOutcome outcome = runner.run(p.job, folder);
        record.done = outcome.done;
        record.error = outcome.error;
        record.statistics = outcome.statistics;
        if (outcome.usageError) stop = true;
        if (record.done) record.outputs = listOutputs(folder.toStdString());
        record.wallSeconds = static_cast<double>(wall.elapsed()) / 1000.0;
        // job.json last: until it is there the folder is not a finished job.
        saveAtomically(QDir(folder).filePath(QStringLiteral("job.json")).toStdString(),
                       record.toJson());
        moveIntoPlace(folder, out.filePath(qs(p.id)), folder + QStringLiteral(".old"));
      } catch (const std::exception& e) {
        record.done = false;
        record.error = e.what();
      }
      {
        std::lock_guard lock(resultMutex);
        if (record.done) {
          ++result.done;
        } else {
          ++result.failed;
          result.failures.push_back(p.id + " (" + record.label + "): " + record.error);
        }
      }
      progress.finished(p, record.done, static_cast<double>(wall.elapsed()) / 1000.0);
    }
  };
  const int threads = std::clamp(options.parallel, 1, std::max(1, static_cast<int>(todo.size())));
  std::vector<std::thread> workers;
  for (int t = 1; t < threads; ++t) workers.emplace_back(work);
  work();
  for (std::thread& t : workers) t.join();
  progress.end();
  result.stoppedOnUsageError = stop;
  std::sort(result.failures.begin(), result.failures.end());
  return result;
}

void writeSummary(const std::vector<PlannedJob>& all, const std::string& outDir) {
  const QDir out(qs(outDir));
  std::string csv =
      "id,status,label,animation,mood,seed,seconds,mesh,tears,quality,view,size,frames,outputs,"
      "frames_simulated,frames_with_tears,peak_particles,tear_state_hash,outputs_sha256,error\n";
  for (const PlannedJob& p : all) {
    const BatchJob& j = p.job;
    std::optional<JobRecord> record;
    const QString path = out.filePath(qs(p.id) + QStringLiteral("/job.json"));
    if (QFileInfo(path).isFile()) {
      try {
        record = JobRecord::read(path.toStdString());
        if (record->id != p.id) record.reset();
      } catch (const FileError&) {
        record.reset();  // damaged: the job is pending until it is redone
      }
    }
    std::string outputs;
    for (Output o : j.outputs) {
      if (!outputs.empty()) outputs += ' ';
      outputs += outputName(o);
    }
    const bool generated = !j.mood.empty();
    const std::vector<std::string> row{
        p.id,
        record ? (record->done ? "done" : "failed") : "pending",
        j.label(),
        j.animation ? j.animation->written : "",
        j.mood,
        generated ? std::to_string(j.seed) : "",
        generated ? QString::number(j.seconds, 'g', 17).toStdString() : "",
        j.mesh ? j.mesh->written : "",
        j.tears ? "yes" : "no",
        j.quality.empty() ? "file" : j.quality,
        j.view,
        std::to_string(j.width) + "x" + std::to_string(j.height),
        j.framesText(),
        outputs,
        record && record->statistics ? std::to_string(record->statistics->frames) : "",
        record && record->statistics ? std::to_string(record->statistics->framesWithTears) : "",
        record && record->statistics ? std::to_string(record->statistics->peakParticles) : "",
        record && record->statistics ? record->statistics->tearStateHash : "",
        record && record->done ? record->outputsSha256() : "",
        record && !record->done ? oneLine(record->error) : ""};
    for (std::size_t k = 0; k < row.size(); ++k) {
      if (k > 0) csv += ',';
      csv += csvField(row[k]);
    }
    csv += '\n';
  }
  saveAtomically(out.filePath(QStringLiteral("summary.csv")).toStdString(), csv);
}

}  // namespace lacrima::batch
