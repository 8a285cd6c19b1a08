#pragma once
// Writing a set of files that belong together (a .mesh, its .material and its textures) so that
// a failure leaves the targets as they were.
#include <string>
#include <string_view>
#include <vector>

namespace lacrima::exporters {

// Each file is first written completely to a temporary beside its target (same directory, so
// the final rename cannot cross file systems); only when every file is written are they renamed
// over their targets, in the order they were added. Temporaries of a batch that is abandoned,
// by an exception or by never calling commit(), are deleted by the destructor.
class StagedFiles {
 public:
  StagedFiles() = default;
  ~StagedFiles();
  StagedFiles(const StagedFiles&) = delete;
  StagedFiles& operator=(const StagedFiles&) = delete;

  // Writes `bytes` to a new temporary for `path`. Throws FileError naming `path` and the
  // system's reason (e.g. a missing directory, a full disk).
  void add(const std::string& path, std::string_view bytes);

  // Renames every temporary over its target. Throws FileError naming the target whose rename
  // failed; targets renamed before it keep their new content.
  void commit();

 private:
  struct Staged {
    std::string target;
    std::string temporary;
  };
  std::vector<Staged> staged_;
};

// The whole content of the file at `path`. Throws FileError naming `path`, with `what` (e.g.
// "texture") and the system's reason.
std::string readFileBytes(const std::string& path, const std::string& what);

}  // namespace lacrima::exporters
