#pragma once
// What every fuzz target shares: the input as text, or as a file on disk for readers that take a
// path, and the rule that a reader may refuse an input only with its documented error.
//
// libFuzzer calls LLVMFuzzerTestOneInput once per input; an exception escaping it aborts the run
// and is reported as a finding, so each target catches exactly the error its reader documents
// (FileError) and lets anything else through.
#include <lacrima/common/Diagnostics.h>
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>

namespace lacrima::fuzz {

// Runs read(); the reader's documented refusal (FileError) is an answer, anything else escapes
// and is a finding.
template <class Read>
void refusingOnlyWithFileError(Read&& read) {
  try {
    read();
  } catch (const FileError&) {
  }
}

inline std::string_view text(const std::uint8_t* data, std::size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

// The input written to a file of its own (removed when this goes), for readers that take a
// path. `suffix` matters to readers that choose a format by extension (assimp).
class InputFile {
 public:
  InputFile(const std::uint8_t* data, std::size_t size, std::string_view suffix) {
    const auto folder = std::filesystem::temp_directory_path();
    path_ =
        (folder / ("lacrima-fuzz-" + std::to_string(::getpid()) + std::string(suffix))).string();
    std::ofstream out(path_, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  ~InputFile() { std::remove(path_.c_str()); }
  InputFile(const InputFile&) = delete;
  InputFile& operator=(const InputFile&) = delete;

  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

}  // namespace lacrima::fuzz
