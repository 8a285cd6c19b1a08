#include <lacrima/appsupport/ThreadsOption.h>

#include <QCommandLineParser>

#include <cstdio>

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
  bool ok = false;
  const int count = parser.value(kName).toInt(&ok);
  if (ok && count >= 1 && count <= kMostThreads) return count;
  std::fprintf(stderr, "%s: --threads expects a whole number from 1 to %d, not %s\n", program,
               kMostThreads, qPrintable(parser.value(kName)));
  return std::nullopt;
}

}  // namespace lacrima::appsupport
