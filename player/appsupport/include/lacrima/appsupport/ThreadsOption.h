#pragma once
// --threads N, taken alike by lacrima-player and lacrima-editor: how many threads the tear
// simulation shares, handed to it as tears::SimulationOptions::threads. Without the option the
// count is 0, which the simulation resolves itself (LACRIMA_THREADS, else every hardware
// thread), so the environment variable stays the fallback for every program.
#include <QCommandLineOption>

#include <optional>

class QCommandLineParser;

namespace lacrima::appsupport {

// The option, its help naming `simulation` ("the tear simulation", "the preview's tears").
QCommandLineOption threadsOption(const QString& simulation);

// After parser.process(): the count given (1 to 256), 0 without the option, or nullopt after
// "<program>: --threads: expected threads from 1 to 256, not ..." on stderr, a usage error
// (exit status 2).
std::optional<int> threadsFrom(const QCommandLineParser& parser, const char* program);

}  // namespace lacrima::appsupport
