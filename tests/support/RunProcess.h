#pragma once
// One of the project's programs run as a process by a test: its exit code (-2 when it crashed,
// -1 when it outlived `timeoutMs` and was killed) and what it printed.
#include <QProcess>
#include <QProcessEnvironment>
#include <QString>
#include <QStringList>

namespace lacrima::testsupport {

struct ProcessRun {
  int exitCode = -1;
  QString out, err;
};

inline ProcessRun runProcess(
    const QString& program, const QStringList& arguments, int timeoutMs,
    const QProcessEnvironment& environment = QProcessEnvironment::systemEnvironment()) {
  QProcess process;
  process.setProcessEnvironment(environment);
  process.start(program, arguments);
  ProcessRun r;
  if (!process.waitForFinished(timeoutMs)) {
    process.kill();
    process.waitForFinished();
    return r;
  }
  r.exitCode = process.exitStatus() == QProcess::NormalExit ? process.exitCode() : -2;
  r.out = QString::fromLocal8Bit(process.readAllStandardOutput());
  r.err = QString::fromLocal8Bit(process.readAllStandardError());
  return r;
}

}  // namespace lacrima::testsupport
