// lacrima-batch: renders crying datasets from a manifest, on this machine or as a Slurm job
// array (docs/batch.md). Exit codes as the other programs: 0 every job done, 1 a job failed or
// bad input, 2 wrong usage.
#include <lacrima/batch/BatchManifest.h>
#include <lacrima/batch/BatchRun.h>
#include <lacrima/batch/JobRunner.h>
#include <lacrima/batch/SlurmScript.h>

#include <lacrima/common/AtomicSave.h>
#include <lacrima/common/CommandLineNumbers.h>
#include <lacrima/common/Diagnostics.h>

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QProcess>
#include <QThread>

#include <unistd.h>
#include <algorithm>
#include <cstdio>
#include <optional>
#include <string>

using namespace lacrima;
using namespace lacrima::batch;

namespace {

constexpr int kExitOk = 0, kExitFailed = 1, kExitUsage = 2;

std::string str(const QString& s) { return s.toStdString(); }

// Reads a whole-number option, or prints the usage error and returns nullopt.
std::optional<int> wholeNumber(const QCommandLineParser& parser, const char* name,
                               std::string_view what, int low, int high, int fallback) {
  if (!parser.isSet(name)) return fallback;
  std::string error;
  const std::optional<int> n = readWholeNumberOption(std::string("--") + name, what,
                                                     str(parser.value(name)), low, high, error);
  if (!n) std::fprintf(stderr, "lacrima-batch: %s\n", error.c_str());
  return n;
}

// "--shard I/N" with 1 <= I <= N <= 100000.
bool readShard(const QString& text, int& index, int& count) {
  const QStringList parts = text.split('/');
  bool okIndex = false, okCount = false;
  index = parts.value(0).toInt(&okIndex);
  count = parts.value(1).toInt(&okCount);
  return parts.size() == 2 && okIndex && okCount && count >= 1 &&
         count <= static_cast<int>(BatchManifest::kMaxJobs) && index >= 1 && index <= count;
}

// Jobs of `jobs` that are not done in `out` (JobRecord.h's test, as a rerun would make it).
int notDone(const std::vector<PlannedJob>& jobs, const QString& out) {
  return static_cast<int>(std::count_if(jobs.begin(), jobs.end(), [&](const PlannedJob& p) {
    return !isComplete(str(QDir(out).filePath(QString::fromStdString(p.id))), p.id, false);
  }));
}

// sbatch ARGS; the job id it prints with --parsable, or "" after saying what went wrong.
std::string sbatch(const QStringList& arguments) {
  QProcess p;
  p.start(QStringLiteral("sbatch"), arguments);
  if (!p.waitForStarted(30000)) {
    std::fprintf(stderr, "lacrima-batch: cannot run sbatch: %s\n", str(p.errorString()).c_str());
    return {};
  }
  p.waitForFinished(-1);  // with --wait, until the job ends
  if (p.exitStatus() != QProcess::NormalExit || p.exitCode() != 0) {
    std::fprintf(stderr, "lacrima-batch: sbatch failed: %s\n",
                 p.readAllStandardError().trimmed().constData());
    return {};
  }
  return p.readAllStandardOutput().trimmed().split(';').value(0).toStdString();
}

int slurmMode(const QCommandLineParser& parser, const std::vector<PlannedJob>& jobs,
              const QString& manifest, const QString& out) {
  SlurmSettings s;
  s.batchProgram = str(QCoreApplication::applicationFilePath());
  s.manifest = str(QFileInfo(manifest).absoluteFilePath());
  s.outDir = str(QDir(out).absolutePath());
  s.jobCount = static_cast<int>(jobs.size());
  const int jobCount = std::max(1, s.jobCount);
  const auto array =
      wholeNumber(parser, "array-size", "tasks", 1, jobCount, std::min(jobCount, 64));
  const auto cpus = wholeNumber(parser, "cpus-per-task", "CPUs", 1, 256, 2);
  const auto memory = wholeNumber(parser, "mem-mib", "MiB", 256, 1 << 22, 4096);
  const auto minutes = wholeNumber(parser, "minutes-per-job", "minutes", 1, 10080, 10);
  if (!array || !cpus || !memory || !minutes) return kExitUsage;
  s.arraySize = *array;
  s.cpusPerTask = *cpus;
  s.memoryMiB = *memory;
  s.minutesPerJob = *minutes;
  s.partition = str(parser.value("partition"));
  const std::string script = slurmScript(s);
  if (parser.isSet("dry-run")) {
    std::fputs(script.c_str(), stdout);
    return kExitOk;
  }
  const QDir logs(QDir(out).filePath(QStringLiteral("slurm")));
  if (!QDir().mkpath(logs.path()))
    throw FileError({str(logs.path()), 0, 0}, "cannot create the folder for Slurm's logs");
  const QString scriptPath = logs.filePath(QStringLiteral("lacrima-batch.sbatch"));
  saveAtomically(str(scriptPath), script);
  std::printf("%s\n", str(scriptPath).c_str());
  if (!parser.isSet("submit")) return kExitOk;

  const std::string array_id = sbatch({QStringLiteral("--parsable"), scriptPath});
  if (array_id.empty()) return kExitFailed;
  // The summary once every task has ended, however they ended.
  const QString summarize =
      QStringLiteral("'%1' '%2' --out '%3' --summarize")
          .arg(QString::fromStdString(s.batchProgram), QString::fromStdString(s.manifest),
               QString::fromStdString(s.outDir));
  QStringList summary{QStringLiteral("--parsable"),
                      QStringLiteral("--job-name=lacrima-batch-summary"),
                      QStringLiteral("--dependency=afterany:") + QString::fromStdString(array_id),
                      QStringLiteral("--output=") + logs.filePath(QStringLiteral("summary.out")),
                      QStringLiteral("--wrap=") + summarize};
  if (parser.isSet("wait")) summary.insert(1, QStringLiteral("--wait"));
  std::fprintf(stderr, "lacrima-batch: submitted job array %s (%d tasks)%s\n", array_id.c_str(),
               s.arraySize, parser.isSet("wait") ? "; waiting for it" : "");
  const std::string summary_id = sbatch(summary);
  if (summary_id.empty()) return kExitFailed;
  std::printf("%s\n%s\n", array_id.c_str(), summary_id.c_str());
  if (!parser.isSet("wait")) return kExitOk;
  const QString summaryCsv = QDir(out).filePath(QStringLiteral("summary.csv"));
  if (!QFileInfo::exists(summaryCsv)) {
    std::fprintf(stderr, "lacrima-batch: the summary was not written; see the Slurm logs\n");
    return kExitFailed;
  }
  if (const int bad = notDone(jobs, out); bad > 0) {
    std::fprintf(stderr, "lacrima-batch: %d jobs failed or did not run; see %s\n", bad,
                 str(summaryCsv).c_str());
    return kExitFailed;
  }
  return kExitOk;
}

}  // namespace

int main(int argc, char* argv[]) {
  QCoreApplication app(argc, argv);
  QCoreApplication::setApplicationName(QStringLiteral("lacrima-batch"));
  QCoreApplication::setApplicationVersion(QStringLiteral(LACRIMA_VERSION));
  QCommandLineParser parser;
  parser.setApplicationDescription(QStringLiteral(
      "Renders crying datasets from a manifest of jobs (docs/batch.md): on this machine, one\n"
      "shard of it, or as a Slurm job array. Every job writes DIR/ID/ with a job.json; a rerun\n"
      "skips finished jobs and redoes interrupted ones; DIR/summary.csv lists them all.\n\n"
      "Examples:\n"
      "  lacrima-batch dataset.json --out runs/ --jobs 2\n"
      "  lacrima-batch dataset.json --out runs/ --shard 3/10\n"
      "  lacrima-batch --slurm dataset.json --out /shared/runs --array-size 50 --submit"));
  parser.addHelpOption();
  parser.addVersionOption();
  parser.addPositionalArgument(QStringLiteral("MANIFEST"),
                               QStringLiteral("The batch manifest (.json)."));
  parser.addOptions({
      {"out", "Folder of the results (required).", "DIR"},
      {"shard", "Run the I-th of N equal shares of the jobs.", "I/N"},
      {"jobs", "Jobs run at a time on this machine (default 1).", "K"},
      {"threads", "Threads each job's tear simulation shares (default: cores / K).", "N"},
      {"timeout", "Seconds one program of a job may run before it is stopped (default 3600).",
       "SECONDS"},
      {"verify", "Rehash every output before skipping a finished job."},
      {"summarize", "Only write DIR/summary.csv from the jobs found."},
      {"list", "Print the shard's jobs (id, state, label) and run nothing."},
      {"slurm", "Write DIR/slurm/lacrima-batch.sbatch, a job array of shards."},
      {"array-size", "With --slurm: tasks in the array (default: jobs, at most 64).", "N"},
      {"cpus-per-task", "With --slurm: CPUs per task (default 2).", "N"},
      {"mem-mib", "With --slurm: memory per task in MiB (default 4096).", "MIB"},
      {"minutes-per-job", "With --slurm: time limit per job in a task (default 10).", "MINUTES"},
      {"partition", "With --slurm: the partition (default: the cluster's).", "NAME"},
      {"dry-run", "With --slurm: print the script instead of writing it."},
      {"submit", "With --slurm: submit the array and a summary job after it, with sbatch."},
      {"wait", "With --submit: wait until the summary job has run; exit 1 if a job failed."},
  });
  parser.process(app);
  const QStringList positional = parser.positionalArguments();
  if (positional.size() != 1 || !parser.isSet("out")) {
    std::fprintf(stderr, "lacrima-batch: give one MANIFEST and --out DIR (see --help)\n");
    return kExitUsage;
  }
  int shardIndex = 1, shardCount = 1;
  if (parser.isSet("shard") && !readShard(parser.value("shard"), shardIndex, shardCount)) {
    std::fprintf(stderr, "lacrima-batch: --shard: expected I/N with 1 <= I <= N, not '%s'\n",
                 str(parser.value("shard")).c_str());
    return kExitUsage;
  }
  const auto parallel = wholeNumber(parser, "jobs", "jobs at a time", 1, 256, 1);
  if (!parallel) return kExitUsage;
  const int cores = std::max(1, QThread::idealThreadCount());
  const auto threads =
      wholeNumber(parser, "threads", "threads", 1, 256, std::max(1, cores / *parallel));
  const auto timeout = wholeNumber(parser, "timeout", "seconds", 1, 7 * 86400, 3600);
  if (!threads || !timeout) return kExitUsage;
  const bool slurmOnly = parser.isSet("array-size") || parser.isSet("cpus-per-task") ||
                         parser.isSet("mem-mib") || parser.isSet("minutes-per-job") ||
                         parser.isSet("partition") || parser.isSet("dry-run") ||
                         parser.isSet("submit");
  if (slurmOnly && !parser.isSet("slurm")) {
    std::fprintf(stderr,
                 "lacrima-batch: --array-size, --cpus-per-task, --mem-mib, "
                 "--minutes-per-job, --partition, --dry-run and --submit go with --slurm\n");
    return kExitUsage;
  }
  if (parser.isSet("wait") && !parser.isSet("submit")) {
    std::fprintf(stderr, "lacrima-batch: --wait goes with --slurm --submit\n");
    return kExitUsage;
  }

  const QString manifestPath = positional.front();
  const QString out = parser.value("out");
  try {
    const BatchManifest manifest = readManifest(str(manifestPath));
    const std::vector<PlannedJob> jobs = planJobs(manifest);
    if (parser.isSet("slurm")) return slurmMode(parser, jobs, manifestPath, out);
    if (parser.isSet("summarize")) {
      writeSummary(jobs, str(out));
      return kExitOk;
    }
    if (parser.isSet("list")) {
      for (const PlannedJob& p : shardOf(jobs, shardIndex, shardCount)) {
        const bool done = isComplete(str(QDir(out).filePath(QString::fromStdString(p.id))), p.id,
                                     parser.isSet("verify"));
        std::printf("%s  %-7s  %s\n", p.id.c_str(), done ? "done" : "to do", p.job.label().c_str());
      }
      return kExitOk;
    }
    JobTools tools = findJobTools(QCoreApplication::applicationDirPath());
    tools.threads = *threads;
    tools.timeoutSeconds = *timeout;
    for (const PlannedJob& p : jobs) {
      tools.screenWidth = std::max(tools.screenWidth, p.job.width);
      tools.screenHeight = std::max(tools.screenHeight, p.job.height);
    }
    JobRunner runner(tools);
    BatchOptions options;
    options.outDir = str(out);
    options.shardIndex = shardIndex;
    options.shardCount = shardCount;
    options.parallel = *parallel;
    options.verifyHashes = parser.isSet("verify");
    options.progressLine = isatty(fileno(stderr)) != 0;
    options.version = LACRIMA_VERSION;
    const BatchResult result = runBatch(jobs, options, runner, stderr);
    writeSummary(jobs, str(out));
    std::fprintf(stderr,
                 "lacrima-batch: shard %d/%d: %d jobs, %d already done, %d done now, %d failed; "
                 "%s\n",
                 shardIndex, shardCount, result.planned, result.skipped, result.done, result.failed,
                 str(QDir(out).filePath(QStringLiteral("summary.csv"))).c_str());
    for (const std::string& failure : result.failures)
      std::fprintf(stderr, "lacrima-batch: failed: %s\n", failure.c_str());
    if (result.stoppedOnUsageError) {
      std::fprintf(stderr,
                   "lacrima-batch: stopped: a program refused the job's options, so every job "
                   "like it would fail; fix the manifest\n");
      return kExitUsage;
    }
    return result.failed > 0 ? kExitFailed : kExitOk;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "lacrima-batch: %s\n", e.what());
    return kExitFailed;
  }
}
