#pragma once
// Reading a head from a user's file in a separate, limited process. assimp is a large collection
// of C++ parsers; a damaged or hostile file can make it loop forever, abort on one of its own
// assertions or crash (Debian's build keeps the assertions), and inside the editor that would
// take the user's unsaved work with it. So every file a user names is read by the importer
// program (lacrima-import, installed beside the programs in libexec/lacrima), which runs
// importHeadMesh (MeshImport.h) and sends the head back on a pipe (ImportedMeshWire.h); the
// default head keeps its own in-process reader.
//
// The child runs under limits: address space and processor time (setrlimit), a wall-clock
// deadline kept by this side, no descriptor but its pipes, no core dumps, no files written, no
// network where an unprivileged network namespace is available. A crash, an abort, a hang, a
// limit reached or a cancel becomes an ImportError naming the file and what happened, e.g.
// "head.ply: assimp crashed reading it (SIGSEGV, a segmentation fault); the file may be
// damaged". The child never outlives the call.
#include <lacrima/common/Diagnostics.h>
#include <lacrima/common/HeadMesh.h>

#include <cstdint>
#include <functional>
#include <optional>
#include <string>

namespace lacrima::rigging {

enum class ImportFailure {
  Refused,      // importHeadMesh refused the file (its own message: no faces, too large, ...)
  Crashed,      // the importer died of a signal (SIGSEGV, SIGABRT, ...)
  TimedOut,     // past the wall-clock or processor-time limit
  OutOfMemory,  // past the address-space limit
  Cancelled,    // options.cancelled said so
  Malformed,    // the importer's answer failed the reader's checks
  NotStarted,   // the importer program is missing or cannot run
};

class ImportError : public FileError {
 public:
  ImportError(ImportFailure failure, const std::string& file, const std::string& message)
      : FileError(SourceLocation{file}, message), failure_(failure) {}
  ImportFailure failure() const { return failure_; }

 private:
  ImportFailure failure_;
};

// What the child may use. The defaults grow with the file: a large head takes longer and needs
// more memory, a small damaged one is stopped soon.
struct ImportLimits {
  double seconds = 0;             // wall clock, and processor time
  std::uint64_t memoryBytes = 0;  // address space
  // 10 s plus 3 s per MiB; 1 GiB plus 32 times the file's size.
  static ImportLimits forFileSize(std::uintmax_t bytes);
};

struct ImportOptions {
  std::optional<double> seconds;             // instead of the default time limit
  std::optional<std::uint64_t> memoryBytes;  // instead of the default memory limit
  // Polled about 50 times a second while the child runs; true kills it at once and throws
  // ImportError(Cancelled). It may also throw, which kills the child the same way.
  std::function<bool()> cancelled;
  std::string importer;  // the importer program; empty: importerProgram()
};

// Reads `path` as importHeadMesh does, in the importer process. Throws ImportError (a FileError)
// naming `path`.
HeadMesh importHeadMeshIsolated(const std::string& path, const ImportOptions& options = {});

// Where lacrima-import is: beside the running program (the build's bin/), else in
// <program's folder>/../libexec/lacrima (an installed copy under any prefix). Empty when neither
// has it.
std::string importerProgram();

}  // namespace lacrima::rigging
