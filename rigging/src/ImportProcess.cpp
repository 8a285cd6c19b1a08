#include <lacrima/rigging/ImportProcess.h>
#include <lacrima/rigging/ImportedMeshWire.h>

#include "ChildProcess.h"

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <optional>
#include <string_view>
#include <system_error>
#include <vector>

namespace lacrima::rigging {
namespace {

namespace fs = std::filesystem;

// Exit codes of lacrima-import (rigging/importer/main.cpp).
constexpr int kExitOutOfMemory = 3;

constexpr std::uint64_t kMiB = std::uint64_t{1} << 20;

std::string describeBytes(std::uintmax_t bytes) {
  if (bytes < 10 * kMiB) return std::to_string(bytes) + " bytes";
  return std::to_string(bytes / kMiB) + " MiB";
}

std::string describeSeconds(double seconds) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g s", seconds);
  return text;
}

// "SIGSEGV, a segmentation fault": the signal's name, and what it means for a reader.
std::string describeSignal(int signal) {
  const char* abbreviation = ::sigabbrev_np(signal);
  std::string name =
      abbreviation ? std::string("SIG") + abbreviation : "signal " + std::to_string(signal);
  switch (signal) {
    case SIGSEGV:
      return name + ", a segmentation fault";
    case SIGABRT:
      return name + ", one of assimp's own checks failed";
    case SIGBUS:
      return name + ", a bus error";
    case SIGFPE:
      return name + ", an arithmetic fault";
    case SIGILL:
      return name + ", an illegal instruction";
    default:
      return name;
  }
}

// The last line the child printed, shortened: assimp's failed assertion names its check.
std::string lastLine(std::string_view text) {
  while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) text.remove_suffix(1);
  const std::size_t start = text.find_last_of('\n');
  if (start != std::string_view::npos) text.remove_prefix(start + 1);
  std::string line;
  for (char c : text.substr(0, 200)) line += static_cast<unsigned char>(c) < 0x20 ? ' ' : c;
  return line;
}

HeadMesh answerOf(ChildProcess& child, const std::string& path) {
  wire::ImportAnswer answer;
  try {
    answer = wire::readImportAnswer(child.answer(), path);
  } catch (const FileError& e) {
    throw ImportError(ImportFailure::Malformed, path, e.message());
  }
  if (auto* refusal = std::get_if<wire::Refusal>(&answer))
    throw ImportError(ImportFailure::Refused, path, refusal->message);
  return std::get<HeadMesh>(std::move(answer));
}

[[noreturn]] void failOnExit(ChildProcess& child, const std::string& path,
                             const ImportLimits& limits) {
  const int status = child.status();
  const std::string said =
      child.errors().empty() ? std::string() : " (it said: \"" + lastLine(child.errors()) + "\")";
  if (WIFSIGNALED(status)) {
    const int signal = WTERMSIG(status);
    if (signal == SIGXCPU || signal == SIGKILL)
      // SIGXCPU at the processor-time limit, SIGKILL a second after it (or the kernel's
      // out-of-memory killer).
      throw ImportError(ImportFailure::TimedOut, path,
                        "reading it used more than " + describeSeconds(limits.seconds) +
                            " of processor time and was stopped (" + describeSignal(signal) +
                            "); the file may be damaged");
    throw ImportError(ImportFailure::Crashed, path,
                      "assimp crashed reading it (" + describeSignal(signal) + ")" + said +
                          "; the file may be damaged");
  }
  const int code = WEXITSTATUS(status);
  if (code == kExitOutOfMemory)
    throw ImportError(ImportFailure::OutOfMemory, path,
                      "reading it needed more than " + describeBytes(limits.memoryBytes) +
                          " of memory, the limit for a file of this size; the file may be "
                          "damaged");
  throw ImportError(ImportFailure::Crashed, path,
                    "the importer stopped with exit code " + std::to_string(code) + said);
}

}  // namespace

ImportLimits ImportLimits::forFileSize(std::uintmax_t bytes) {
  ImportLimits limits;
  limits.seconds = 10.0 + 3.0 * static_cast<double>(bytes) / static_cast<double>(kMiB);
  limits.memoryBytes = (std::uint64_t{1} << 30) + 32 * static_cast<std::uint64_t>(bytes);
  return limits;
}

std::string importerProgram() {
  std::error_code error;
  const fs::path self = fs::read_symlink("/proc/self/exe", error);
  if (error) return {};
  for (const fs::path& candidate :
       {self.parent_path() / "lacrima-import",
        (self.parent_path() / LACRIMA_LIBEXEC_FROM_BIN / "lacrima-import").lexically_normal()})
    if (::access(candidate.c_str(), X_OK) == 0) return candidate.string();
  return {};
}

HeadMesh importHeadMeshIsolated(const std::string& path, const ImportOptions& options) {
  std::error_code error;
  const std::uintmax_t bytes = fs::file_size(path, error);
  ImportLimits limits = ImportLimits::forFileSize(error ? 0 : bytes);
  if (options.seconds) limits.seconds = *options.seconds;
  if (options.memoryBytes) limits.memoryBytes = *options.memoryBytes;

  const std::string program = options.importer.empty() ? importerProgram() : options.importer;
  if (program.empty())
    throw ImportError(ImportFailure::NotStarted, path,
                      "cannot read it: the importer lacrima-import is neither beside this "
                      "program nor in " LACRIMA_LIBEXEC_FROM_BIN
                      " from its folder (the installation is incomplete)");
  // The wall clock, kept here, is the limit a user meets; the processor-time limit is a second
  // behind it, for a child whose parent can no longer keep the clock.
  const auto cpuSeconds = static_cast<long long>(std::ceil(limits.seconds)) + 1;
  std::optional<ChildProcess> child;
  try {
    child.emplace(std::vector<std::string>{
        program, "--answer-fd", "3", "--memory-mib", std::to_string(limits.memoryBytes / kMiB),
        "--cpu-seconds", std::to_string(cpuSeconds), "--", path});
  } catch (const std::system_error& e) {
    throw ImportError(ImportFailure::NotStarted, path,
                      "cannot start the importer " + program + ": " + e.code().message());
  }
  const auto deadline =
      ChildProcess::Clock::now() + std::chrono::duration_cast<ChildProcess::Clock::duration>(
                                       std::chrono::duration<double>(limits.seconds));
  switch (child->wait(deadline, options.cancelled, wire::kMaxAnswerBytes)) {
    case ChildProcess::Stop::Cancelled:
      throw ImportError(ImportFailure::Cancelled, path, "import cancelled");
    case ChildProcess::Stop::Deadline:
      throw ImportError(ImportFailure::TimedOut, path,
                        "assimp did not finish reading it in " + describeSeconds(limits.seconds) +
                            " (the limit for a file of " + describeBytes(error ? 0 : bytes) +
                            ") and was stopped; the file may be damaged");
    case ChildProcess::Stop::AnswerTooLong:
      throw ImportError(ImportFailure::Malformed, path,
                        "the importer's answer is malformed: it is longer than " +
                            describeBytes(wire::kMaxAnswerBytes));
    case ChildProcess::Stop::Exited:
      break;
  }
  if (WIFEXITED(child->status()) && WEXITSTATUS(child->status()) == 0)
    return answerOf(*child, path);
  failOnExit(*child, path, limits);
}

}  // namespace lacrima::rigging
