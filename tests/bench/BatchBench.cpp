// lacrima-bench batch: what a dataset costs. A typical dataset job (a 5 s take of the crying
// generator rendered at 640x360 with its tear masks) run by lacrima-batch with 1 and 2 jobs at a
// time, in jobs per hour; the cost of holding the run-time code choices to one (the pinned
// environment that makes every machine render the same bytes) on one job's render; and, with
// --slurm on a running cluster (tests/batch/one-node-slurm.sh), the overhead Slurm adds per task.
// The single render needs an X display: run it under xvfb-run.
#include "BenchCommandLine.h"

#include <lacrima/batch/JobRunner.h>
#include <lacrima/common/JsonWriter.h>

#include <QCoreApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QProcess>
#include <QTemporaryDir>

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

namespace lacrima::bench {

namespace {

struct Options {
  int jobs = 4;
  double seconds = 5;
  int width = 640, height = 360;
  bool slurm = false;
  bool json = false;
};

std::optional<int> parseOptions(int argc, char** argv, Options& o) {
  BenchCommandLine line(
      "batch",
      "Runs a dataset of N jobs (5 s takes of the crying generator at 640x360 with tear masks)\n"
      "through lacrima-batch with 1 and 2 jobs at a time and reports jobs per hour; times one\n"
      "job's render with and without the pinned environment; with --slurm, the same dataset as\n"
      "a job array on the cluster SLURM_CONF names, and Slurm's overhead per task. Needs an X\n"
      "display: run under xvfb-run.");
  line.wholeNumber("jobs", "N", "Jobs in the dataset (default 4).", 1, 1000, o.jobs);
  line.number("seconds", "S", "Seconds per take (default 5).", 0.5, 600, o.seconds);
  line.imageSize("size", "Image size (default 640x360).", o.width, o.height);
  line.flag("slurm", "Also run the dataset on the Slurm cluster SLURM_CONF names.", o.slurm);
  line.flag("json", "One JSON object instead of the table.", o.json);
  return line.parse(argc, argv);
}

QString bin(const char* program) {
  return QDir(QCoreApplication::applicationDirPath()).filePath(QString::fromLatin1(program));
}

// Wall seconds of `program arguments` with `environment`, or -1 when it failed.
double timed(const QString& program, const QStringList& arguments,
             const QProcessEnvironment& environment) {
  QProcess p;
  p.setProcessEnvironment(environment);
  p.setStandardOutputFile(QProcess::nullDevice());
  QElapsedTimer wall;
  wall.start();
  p.start(program, arguments);
  if (!p.waitForFinished(-1) || p.exitStatus() != QProcess::NormalExit || p.exitCode() != 0) {
    std::fprintf(stderr, "lacrima-bench batch: %s failed: %s\n", qPrintable(program),
                 p.readAllStandardError().right(2000).constData());
    return -1;
  }
  return static_cast<double>(wall.elapsed()) / 1000.0;
}

}  // namespace

int runBatch(int argc, char** argv) {
  Options o;
  if (const std::optional<int> status = parseOptions(argc, argv, o)) return *status;
  QCoreApplication app(argc, argv);  // applicationDirPath: the programs beside lacrima-bench
  QTemporaryDir dir;
  const int lastFrame = static_cast<int>(o.seconds * 22);
  // Distinct seeds: distinct jobs, each with its own tears.
  QString jobs;
  for (int k = 0; k < o.jobs; ++k)
    jobs += QStringLiteral("%1{ \"mood\": \"sadness=0.9\", \"seed\": %2 }")
                .arg(k ? ", " : "")
                .arg(k + 1);
  const QString manifest = dir.filePath("dataset.json");
  QFile m(manifest);
  if (!m.open(QIODevice::WriteOnly)) return 1;
  m.write(QStringLiteral(
              "{ \"defaults\": { \"seconds\": %1, \"size\": \"%2x%3\", \"frames\": \"0-%4\", "
              "\"outputs\": [\"frames\", \"masks\"] }, \"jobs\": [ %5 ] }")
              .arg(o.seconds)
              .arg(o.width)
              .arg(o.height)
              .arg(lastFrame)
              .arg(jobs)
              .toUtf8());
  m.close();
  const QProcessEnvironment system = QProcessEnvironment::systemEnvironment();

  // One job's render, pinned and as the machine would choose, interleaved.
  const QString take = dir.filePath("take.fap");
  if (timed(bin("lacrima-fap"),
            {"generate", "--mood", "sadness=0.9", "--seed", "1", "--seconds",
             QString::number(o.seconds), "-o", take},
            system) < 0)
    return 1;
  const QStringList render{"--render", dir.filePath("render"),
                           "--size",   QStringLiteral("%1x%2").arg(o.width).arg(o.height),
                           "--masks",  take};
  std::vector<double> pinned, native;
  for (int round = 0; round < 2; ++round) {
    pinned.push_back(timed(bin("lacrima-player"), render, batch::pinnedEnvironment(system)));
    native.push_back(timed(bin("lacrima-player"), render, system));
  }
  const double pinnedS = *std::min_element(pinned.begin(), pinned.end());
  const double nativeS = *std::min_element(native.begin(), native.end());

  struct Row {
    std::string name;
    int parallel = 1;
    double seconds = 0;
  };
  std::vector<Row> rows;
  for (int parallel : {1, 2}) {
    const QString out = dir.filePath(QStringLiteral("out-%1").arg(parallel));
    const double s = timed(bin("lacrima-batch"),
                           {manifest, "--out", out, "--jobs", QString::number(parallel)}, system);
    if (s < 0) return 1;
    rows.push_back({"local", parallel, s});
  }
  if (o.slurm) {
    if (!system.contains("SLURM_CONF"))
      std::fprintf(stderr, "lacrima-bench batch: --slurm needs SLURM_CONF (a running cluster)\n");
    const QString out = dir.filePath("out-slurm");
    const double s =
        timed(bin("lacrima-batch"),
              {"--slurm", manifest, "--out", out, "--array-size", QString::number(o.jobs),
               "--cpus-per-task", "1", "--mem-mib", "1024", "--submit", "--wait"},
              system);
    if (s < 0) return 1;
    rows.push_back({"slurm", 2, s});
  }

  const double local2 = rows[1].seconds;
  const double overhead = o.slurm ? (rows.back().seconds - local2) / o.jobs : 0;
  if (o.json) {
    JsonWriter json(JsonWriter::Layout::Compact);
    json.beginObject();
    json.field("benchmark", "batch");
    json.field("jobs", o.jobs);
    json.field("seconds_per_take", o.seconds);
    json.field("width", o.width);
    json.field("height", o.height);
    json.field("render_pinned_s", pinnedS);
    json.field("render_native_s", nativeS);
    json.key("runs");
    json.beginArray();
    for (const Row& r : rows) {
      json.beginObject();
      json.field("where", std::string_view(r.name));
      json.field("parallel", r.parallel);
      json.field("wall_s", r.seconds);
      json.field("jobs_per_hour", o.jobs / r.seconds * 3600);
      json.endObject();
    }
    json.endArray();
    if (o.slurm) json.field("slurm_overhead_per_task_s", overhead);
    json.endObject();
    std::fputs(std::move(json).finish().c_str(), stdout);
    return 0;
  }
  std::printf("lacrima-bench batch: %d jobs, %g s takes (%d frames) at %dx%d with masks\n", o.jobs,
              o.seconds, lastFrame + 1, o.width, o.height);
  std::printf(
      "  one job's render: %.2f s pinned, %.2f s as the machine chooses (pinning %+.0f %%)\n",
      pinnedS, nativeS, (pinnedS / nativeS - 1) * 100);
  for (const Row& r : rows)
    std::printf("  %-6s %d at a time: %7.1f s, %6.0f jobs per hour\n", r.name.c_str(), r.parallel,
                r.seconds, o.jobs / r.seconds * 3600);
  if (o.slurm)
    std::printf("  Slurm overhead: %.2f s per task against the local run, 2 at a time\n", overhead);
  return 0;
}

}  // namespace lacrima::bench
