#include <lacrima/appsupport/ThreadsOption.h>
#include <lacrima/common/CommandLineNumbers.h>

#include <QCommandLineParser>

#include <cstdio>
#include <string>

namespace lacrima::appsupport {

namespace {

const QString kName = QStringLiteral("threads");
// The simulation's own limit for LACRIMA_THREADS (ThreadPool.cpp), kept the same here.
constexpr int kMostThreads = 256;

}  // namespace

QCommandLineOption threadsOption(const QString& simulation) {
  return QCommandLineOption(
      kName,
      QStringLiteral("Threads %1 shares, 1 to %2 (default: LACRIMA_THREADS, else all); the tears "
                     "are the same for any count.")
          .arg(simulation)
          .arg(kMostThreads),
      QStringLiteral("N"));
}

std::optional<int> threadsFrom(const QCommandLineParser& parser, const char* program) {
  if (!parser.isSet(kName)) return 0;
  std::string error;
  const std::optional<int> count = readWholeNumberOption(
      "--threads", "threads", parser.value(kName).toStdString(), 1, kMostThreads, error);
  if (!count) std::fprintf(stderr, "%s: %s\n", program, error.c_str());
  return count;
}

}  // namespace lacrima::appsupport
