// lacrima-import: reads one head file with assimp (importHeadMesh) and writes the head, or why it
// cannot be read, to a descriptor in the format of ImportedMeshWire.h. Run by the other programs
// through importHeadMeshIsolated (ImportProcess.h), never by a user: a damaged file may crash or
// hang assimp, and here that costs only this process.
//
//   lacrima-import [--answer-fd N] [--memory-mib N] [--cpu-seconds N] [--] FILE
//
// Exit codes: 0 an answer was written (a head or a refusal), 2 wrong usage or the limits could
// not be set, 3 out of memory, 4 the answer could not be written. A crash is a signal.
#include "Confinement.h"

#include <lacrima/common/Diagnostics.h>
#include <lacrima/rigging/ImportedMeshWire.h>
#include <lacrima/rigging/MeshImport.h>

#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <new>
#include <string>
#include <string_view>

namespace {

constexpr int kExitUsage = 2;
constexpr int kExitOutOfMemory = 3;
constexpr int kExitWriteFailed = 4;

bool parseNumber(const char* text, long long& out) {
  const std::string_view s(text);
  const auto [end, error] = std::from_chars(s.data(), s.data() + s.size(), out);
  return error == std::errc() && end == s.data() + s.size() && out >= 0;
}

bool writeAll(int fd, const std::string& bytes) {
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    done += static_cast<std::size_t>(n);
  }
  return true;
}

int usage(const char* why) {
  std::fprintf(stderr,
               "lacrima-import: %s\nusage: lacrima-import [--answer-fd N] [--memory-mib N] "
               "[--cpu-seconds N] [--] FILE\n",
               why);
  return kExitUsage;
}

}  // namespace

int main(int argc, char** argv) {
  long long answerFd = 1, memoryMiB = 0, cpuSeconds = 0;
  const char* file = nullptr;
  for (int i = 1; i < argc; ++i) {
    const std::string_view arg(argv[i]);
    long long* number = arg == "--answer-fd"     ? &answerFd
                        : arg == "--memory-mib"  ? &memoryMiB
                        : arg == "--cpu-seconds" ? &cpuSeconds
                                                 : nullptr;
    if (number) {
      if (++i == argc || !parseNumber(argv[i], *number)) return usage("expected a number");
    } else if (arg == "--" && i + 2 == argc) {
      file = argv[++i];
    } else if (!arg.starts_with("-") && i + 1 == argc) {
      file = argv[i];
    } else {
      return usage("unexpected arguments");
    }
  }
  if (!file) return usage("no file given");
  if (answerFd > 1 << 20) return usage("--answer-fd out of range");

  lacrima::importer::ConfinementLimits limits;
  limits.memoryBytes = static_cast<std::uint64_t>(memoryMiB) << 20;
  limits.cpuSeconds = cpuSeconds;
  const std::string problem = lacrima::importer::confine(static_cast<int>(answerFd), limits);
  if (!problem.empty()) return usage(problem.c_str());
  std::signal(SIGPIPE, SIG_IGN);  // a parent that went away is a failed write, not a signal

  std::string answer;
  try {
    answer = lacrima::rigging::wire::writeImportedMesh(lacrima::rigging::importHeadMesh(file));
  } catch (const std::bad_alloc&) {
    return kExitOutOfMemory;
  } catch (const lacrima::FileError& e) {
    // assimp catches its own allocation failures and reports them as a message.
    if (e.message().find("std::bad_alloc") != std::string::npos) return kExitOutOfMemory;
    answer = lacrima::rigging::wire::writeImportRefusal(e.message());
  } catch (const std::exception& e) {
    answer = lacrima::rigging::wire::writeImportRefusal(std::string("cannot read it: ") + e.what());
  }
  return writeAll(static_cast<int>(answerFd), answer) ? 0 : kExitWriteFailed;
}
