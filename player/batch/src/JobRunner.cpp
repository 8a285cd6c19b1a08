#include <lacrima/batch/JobRunner.h>

#include <QDir>
#include <QFileInfo>
#include <QProcess>
#include <QStandardPaths>
#include <QStringList>

#include <algorithm>

#include <sys/prctl.h>
#include <csignal>
#include <stdexcept>

namespace lacrima::batch {

namespace {

constexpr int kExitUsage = 2;  // every Lacrima program's "wrong usage"
constexpr int kErrorTail = 1500;

QString findProgram(const QString& name, const QString& folder) {
  const QString beside = QDir(folder).filePath(name);
  if (QFileInfo(beside).isExecutable()) return beside;
  return QStandardPaths::findExecutable(name);
}

// One child: what it is for (in messages), the program and its arguments, whether it draws.
struct Step {
  QString what;
  QString program;
  QStringList arguments;
  bool draws = false;
};

QString sizeText(const BatchJob& job) {
  return QStringLiteral("%1x%2").arg(job.width).arg(job.height);
}

// The player's options every output of the job shares.
QStringList playerOptions(const BatchJob& job, const JobTools& tools) {
  QStringList a;
  if (job.lastFrame >= 0)
    a << QStringLiteral("--frames")
      << QStringLiteral("%1-%2").arg(job.firstFrame).arg(job.lastFrame);
  if (!job.quality.empty()) a << QStringLiteral("--quality") << QString::fromStdString(job.quality);
  a << QStringLiteral("--threads") << QString::number(tools.threads);
  if (!job.tears) a << QStringLiteral("--no-tears");
  if (job.mesh)
    a << QStringLiteral("--mesh") << QString::fromStdString(job.mesh->resolved)
      << QStringLiteral("--fdp") << QString::fromStdString(job.fdp->resolved);
  return a;
}

std::vector<Step> stepsOf(const BatchJob& job, const JobTools& tools, const QDir& work) {
  std::vector<Step> steps;
  QString input;
  if (!job.mood.empty()) {
    input = work.filePath(QStringLiteral("animation.fap"));
    steps.push_back(
        {QStringLiteral("lacrima-fap generate"),
         tools.fap,
         {QStringLiteral("generate"), QStringLiteral("--mood"), QString::fromStdString(job.mood),
          QStringLiteral("--seed"), QString::number(job.seed), QStringLiteral("--seconds"),
          QString::number(job.seconds, 'g', 17), QStringLiteral("-o"), input},
         false});
  } else {
    input = QString::fromStdString(job.animation->resolved);
  }
  const QStringList shared = playerOptions(job, tools);
  const QString stats = work.filePath(QStringLiteral("statistics.json"));
  bool statsTaken = false;
  // The first player run reports what it simulated; the others simulate the same.
  const auto player = [&](const QString& what, QStringList arguments, bool draws) {
    arguments << shared;
    if (!statsTaken) arguments << QStringLiteral("--stats") << stats;
    statsTaken = true;
    arguments << input;
    steps.push_back({what, tools.player, arguments, draws});
  };
  if (job.wants(Output::Frames) || job.wants(Output::Masks) || job.wants(Output::Alpha)) {
    QStringList a{QStringLiteral("--render"), work.filePath(QStringLiteral("frames")),
                  QStringLiteral("--size"),   sizeText(job),
                  QStringLiteral("--view"),   QString::fromStdString(job.view)};
    if (job.wants(Output::Masks)) a << QStringLiteral("--masks");
    if (job.wants(Output::Alpha)) a << QStringLiteral("--alpha");
    player(QStringLiteral("lacrima-player --render"), a, true);
  }
  if (job.wants(Output::Video))
    player(QStringLiteral("lacrima-player --video"),
           {QStringLiteral("--video"), work.filePath(QStringLiteral("video.mp4")),
            QStringLiteral("--size"), sizeText(job), QStringLiteral("--view"),
            QString::fromStdString(job.view)},
           true);
  if (job.wants(Output::Gltf))
    player(QStringLiteral("lacrima-player --export-gltf"),
           {QStringLiteral("--export-gltf"), work.filePath(QStringLiteral("animation.glb"))},
           false);
  if (job.wants(Output::TearMeshes))
    player(QStringLiteral("lacrima-player --export-tears"),
           {QStringLiteral("--export-tears"), work.filePath(QStringLiteral("tears"))}, false);
  return steps;
}

// A killed batch (SIGKILL from a user or from Slurm at its time limit) must not leave renders or
// an X server running on the node: the children die with the thread that started them.
void dieWithParent(QProcess& process) {
  process.setChildProcessModifier([] { ::prctl(PR_SET_PDEATHSIG, SIGKILL); });
}

std::string tail(const QByteArray& text) {
  // The programs' own lines ("lacrima-player: file:line: ..."), without Qt's chatter.
  QByteArray own;
  for (const QByteArray& line : text.split('\n'))
    if (line.startsWith("lacrima-") || (line.startsWith("  ") && !own.isEmpty()))
      own += line + '\n';
  QByteArray t = (own.isEmpty() ? text : own).trimmed();
  if (t.size() > kErrorTail) t = "..." + t.right(kErrorTail);
  return t.toStdString();
}

}  // namespace

struct VirtualDisplay::Server {
  QProcess process;
};

VirtualDisplay::VirtualDisplay(const QString& xvfb, int width, int height)
    : server_(std::make_unique<Server>()) {
  QProcess& p = server_->process;
  dieWithParent(p);
  // -displayfd: the server picks a free display itself and writes its number once it accepts
  // clients, so concurrent batches on one node never race for ":99".
  p.start(xvfb, {QStringLiteral("-displayfd"), QStringLiteral("1"), QStringLiteral("-screen"),
                 QStringLiteral("0"), QStringLiteral("%1x%2x24").arg(width).arg(height),
                 QStringLiteral("-nolisten"), QStringLiteral("tcp")});
  QByteArray number;
  while (!number.contains('\n') && p.waitForReadyRead(20000)) number += p.readAllStandardOutput();
  number = number.trimmed();
  bool ok = false;
  number.toInt(&ok);
  if (!ok) {
    p.kill();
    p.waitForFinished(5000);
    throw std::runtime_error("could not start a virtual display (" + xvfb.toStdString() +
                             "): " + tail(p.readAllStandardError()));
  }
  name_ = QStringLiteral(":") + QString::fromLatin1(number);
}

VirtualDisplay::~VirtualDisplay() {
  server_->process.terminate();
  if (!server_->process.waitForFinished(5000)) {
    server_->process.kill();
    server_->process.waitForFinished(5000);
  }
}

JobTools findJobTools(const QString& selfFolder) {
  JobTools tools;
  tools.player = findProgram(QStringLiteral("lacrima-player"), selfFolder);
  tools.fap = findProgram(QStringLiteral("lacrima-fap"), selfFolder);
  if (tools.player.isEmpty())
    throw std::runtime_error("cannot find lacrima-player beside lacrima-batch or on PATH");
  if (tools.fap.isEmpty())
    throw std::runtime_error("cannot find lacrima-fap beside lacrima-batch or on PATH");
  tools.xvfb = QStandardPaths::findExecutable(QStringLiteral("Xvfb"));
  tools.environment = pinnedEnvironment(QProcessEnvironment::systemEnvironment());
  return tools;
}

QProcessEnvironment pinnedEnvironment(QProcessEnvironment e) {
  // glibc picks FMA/AVX2 variants of exp, sin, cos, pow and log, whose last bits differ from the
  // SSE2 ones; hiding the features makes every machine take the SSE2 variants. Both spellings:
  // glibc renamed the features in 2.33.
  QString tunables = e.value(QStringLiteral("GLIBC_TUNABLES"));
  if (!tunables.isEmpty()) tunables += ':';
  tunables += QStringLiteral(
      "glibc.cpu.hwcaps=-AVX,-AVX2,-FMA,-FMA4,-AVX512F,-AVX_Usable,-AVX2_Usable,-FMA_Usable,"
      "-FMA4_Usable,-AVX512F_Usable");
  e.insert(QStringLiteral("GLIBC_TUNABLES"), tunables);
  // llvmpipe compiles its shaders for the CPU it finds; SSE4.1 (x86-64-v2) is on every x86-64
  // CPU made since 2008.
  e.insert(QStringLiteral("GALLIUM_OVERRIDE_CPU_CAPS"), QStringLiteral("sse4.1"));
  e.insert(QStringLiteral("LP_NATIVE_VECTOR_WIDTH"), QStringLiteral("128"));
  // Qt's image conversions and scaling have AVX2 paths.
  e.insert(QStringLiteral("QT_NO_CPU_FEATURE"),
           QStringLiteral("avx f16c fma avx2 bmi bmi2 avx512f avx512dq avx512cd avx512bw "
                          "avx512vl avx512ifma avx512vbmi avx512vbmi2"));
  return e;
}

JobRunner::~JobRunner() = default;

void JobRunner::prepare(const std::vector<const BatchJob*>& jobs) {
  const bool draws =
      std::any_of(jobs.begin(), jobs.end(), [](const BatchJob* j) { return j->needsDisplay(); });
  if (draws && !tools_.environment.contains(QStringLiteral("DISPLAY"))) startDisplay();
}

void JobRunner::startDisplay() {
  std::lock_guard lock(displayMutex_);
  if (!display_) {
    if (tools_.xvfb.isEmpty())
      throw std::runtime_error(
          "no X display (DISPLAY is not set) and no Xvfb to start one: "
          "install xvfb, or run lacrima-batch under xvfb-run -a");
    display_ =
        std::make_unique<VirtualDisplay>(tools_.xvfb, tools_.screenWidth, tools_.screenHeight);
  }
}

QString JobRunner::displayFor(const BatchJob& job) {
  if (!job.needsDisplay() || tools_.environment.contains(QStringLiteral("DISPLAY"))) return {};
  startDisplay();
  return display_->name();
}

JobOutcome JobRunner::run(const BatchJob& job, const QString& workFolder) {
  JobOutcome outcome;
  const QDir work(workFolder);
  QProcessEnvironment environment = tools_.environment;
  try {
    const QString display = displayFor(job);
    if (!display.isEmpty()) environment.insert(QStringLiteral("DISPLAY"), display);
  } catch (const std::runtime_error& e) {
    outcome.error = e.what();
    return outcome;
  }
  for (const Step& step : stepsOf(job, tools_, work)) {
    QProcess child;
    dieWithParent(child);
    child.setProcessEnvironment(environment);
    child.setProgram(step.program);
    child.setArguments(step.arguments);
    child.setStandardOutputFile(QProcess::nullDevice());
    child.start();
    if (!child.waitForStarted(30000)) {
      outcome.error =
          step.what.toStdString() + " did not start: " + child.errorString().toStdString();
      return outcome;
    }
    if (!child.waitForFinished(tools_.timeoutSeconds * 1000)) {
      child.kill();
      child.waitForFinished(10000);
      outcome.error = step.what.toStdString() + " took longer than " +
                      std::to_string(tools_.timeoutSeconds) + " s (--timeout) and was stopped";
      return outcome;
    }
    if (child.exitStatus() != QProcess::NormalExit) {
      outcome.error = step.what.toStdString() + " crashed: " + tail(child.readAllStandardError());
      return outcome;
    }
    if (child.exitCode() != 0) {
      outcome.usageError = child.exitCode() == kExitUsage;
      outcome.error = step.what.toStdString() + " failed (exit " +
                      std::to_string(child.exitCode()) + "): " + tail(child.readAllStandardError());
      return outcome;
    }
  }
  const QString stats = work.filePath(QStringLiteral("statistics.json"));
  try {
    if (QFileInfo::exists(stats)) outcome.statistics = readRunFigures(stats.toStdString());
  } catch (const std::exception& e) {
    outcome.error = std::string("the player's statistics: ") + e.what();
    return outcome;
  }
  outcome.done = true;
  return outcome;
}

}  // namespace lacrima::batch
