#pragma once
// Runs one job: the crying generator for a mood take, then lacrima-player once per kind of
// output, each a child process with a time limit, in a scratch folder the caller renames into
// place when the job is done (BatchRun.h).
#include <lacrima/batch/BatchJob.h>
#include <lacrima/batch/JobRecord.h>

#include <QProcessEnvironment>
#include <QString>

#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

namespace lacrima::batch {

// An X server of our own (Xvfb -displayfd) for the renders of a batch run on a machine without
// a display, such as a cluster node; stopped with the object.
class VirtualDisplay {
 public:
  VirtualDisplay(const QString& xvfb, int width, int height);  // throws std::runtime_error
  ~VirtualDisplay();
  VirtualDisplay(const VirtualDisplay&) = delete;
  VirtualDisplay& operator=(const VirtualDisplay&) = delete;
  const QString& name() const { return name_; }  // ":99"

 private:
  struct Server;
  std::unique_ptr<Server> server_;
  QString name_;
};

// The programs a job runs and how.
struct JobTools {
  QString player, fap;  // absolute paths
  QString xvfb;         // Xvfb, for a machine without a display ("" when not installed)
  QProcessEnvironment environment;
  int threads = 1;                             // lacrima-player --threads
  int timeoutSeconds = 3600;                   // per child process
  int screenWidth = 1280, screenHeight = 720;  // of the virtual display, if one is started
};

// lacrima-player and lacrima-fap beside `self` (this program's folder), else on PATH; Xvfb on
// PATH. Throws std::runtime_error naming a program that is missing.
JobTools findJobTools(const QString& selfFolder);

// The environment every child gets: the caller's, with the libraries that pick their code by
// the CPU at run time held to one choice, so every x86-64 machine with SSE4.1 computes the same
// bits (docs/batch.md): glibc's libm (GLIBC_TUNABLES), Mesa's llvmpipe
// (GALLIUM_OVERRIDE_CPU_CAPS, LP_NATIVE_VECTOR_WIDTH) and Qt's image code (QT_NO_CPU_FEATURE).
QProcessEnvironment pinnedEnvironment(QProcessEnvironment base);

struct JobOutcome {
  bool done = false;
  bool usageError = false;  // a child said "wrong usage" (exit 2): every job would fail alike
  std::string error;        // the failing step and the end of its stderr
  std::optional<RunFigures> statistics;
};

// Runs `job` into the empty folder `work`. The display is started on first need and shared by
// the jobs of a run (thread-safe).
class JobRunner {
 public:
  explicit JobRunner(JobTools tools) : tools_(std::move(tools)) {}
  ~JobRunner();
  // Before the workers start: the virtual display, if `jobs` draw and there is no display.
  // Started from the thread that outlives the workers, since its server dies with that thread.
  void prepare(const std::vector<const BatchJob*>& jobs);
  JobOutcome run(const BatchJob& job, const QString& work);

 private:
  void startDisplay();
  QString displayFor(const BatchJob& job);  // "" when the caller's DISPLAY serves

  JobTools tools_;
  std::mutex displayMutex_;
  std::unique_ptr<VirtualDisplay> display_;
};

}  // namespace lacrima::batch
