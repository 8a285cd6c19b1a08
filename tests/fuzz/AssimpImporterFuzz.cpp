// assimp's reader of one format family (LACRIMA_FUZZ_SUFFIX: ".ply", ".glb", ...) run on each
// input through the importer process, as every program reads a user's head
// (importHeadMeshIsolated), and its answer through the parent's reader.
//
// What assimp does wrong here is what the process exists for: a crash, a hang or an exhausted
// memory limit of the child is a finding of assimp, not of this target. With
// LACRIMA_ASSIMP_FINDINGS set, each such input is kept there (the file, and the message beside
// it as .txt) and the run goes on; packaging/lacrima.sh fuzz counts them. Anything escaping the
// parent's side (an exception other than the documented ImportError, a sanitizer report) is a
// finding of ours and stops the run as in the other targets.
#include "FuzzInput.h"

#include <lacrima/rigging/ImportProcess.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

namespace {

// FNV-1a: a name that is the same for the same input, so a finding is kept once.
std::string fingerprint(const std::uint8_t* data, std::size_t size) {
  std::uint64_t hash = 1469598103934665603ull;
  for (std::size_t i = 0; i < size; ++i) hash = (hash ^ data[i]) * 1099511628211ull;
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(hash));
  return text;
}

const char* kindOf(lacrima::rigging::ImportFailure failure) {
  using lacrima::rigging::ImportFailure;
  switch (failure) {
    case ImportFailure::Crashed:
      return "crash";
    case ImportFailure::TimedOut:
      return "hang";
    case ImportFailure::OutOfMemory:
      return "memory";
    case ImportFailure::Malformed:  // the child's memory corrupted before it answered
      return "malformed";
    default:
      return nullptr;  // an answer: the reader or assimp refused the file, as it should
  }
}

void keep(const char* kind, const std::uint8_t* data, std::size_t size, const std::string& why) {
  const char* folder = std::getenv("LACRIMA_ASSIMP_FINDINGS");
  if (!folder || !*folder) return;
  const std::string base =
      std::string(folder) + "/" + kind + "-" + fingerprint(data, size) + LACRIMA_FUZZ_SUFFIX;
  std::ofstream(base, std::ios::binary)
      .write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  std::ofstream(base + ".txt") << why << '\n';
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const lacrima::fuzz::InputFile file(data, size, LACRIMA_FUZZ_SUFFIX);
  lacrima::rigging::ImportOptions options;
  // Below libFuzzer's own -timeout, so that a hang of assimp is the child's, not ours.
  options.seconds = 3.0;
  options.memoryBytes = std::uint64_t{512} << 20;
  try {
    (void)lacrima::rigging::importHeadMeshIsolated(file.path(), options);
  } catch (const lacrima::rigging::ImportError& e) {
    if (e.failure() == lacrima::rigging::ImportFailure::NotStarted) {
      std::fprintf(stderr, "%s\n", e.what());  // nothing would be fuzzed
      std::abort();
    }
    if (const char* kind = kindOf(e.failure())) keep(kind, data, size, e.what());
  }
  return 0;
}
