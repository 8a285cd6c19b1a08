#pragma once
// Physical lines of a .fap text, from memory or from a file read in fixed-size chunks.
// Private to lacrima_common (used by FapReader).
#include <cstddef>
#include <cstdio>
#include <string>
#include <string_view>
#include <vector>

namespace lacrima::inline common::detail {

class LineSource {
 public:
  // Lines of text already in memory; `text` must outlive the source.
  LineSource(std::string_view text, const std::string& displayName, std::size_t maxLineLength);
  // Lines of an open file, read in chunks so memory stays bounded whatever the file holds.
  LineSource(std::FILE* file, const std::string& displayName, std::size_t maxLineLength);

  // The next line without its '\n' (a CR before it stays: the tokenizer treats it as blank).
  // Returns false at the end of the input. Throws FileError for an over-long line or a read
  // error.
  bool next(std::string_view& line);

  // 1-based number of the line last returned by next().
  int lineNumber() const { return lineNumber_; }

  // True once next() has seen at least one byte of input.
  bool sawInput() const { return sawInput_; }

  static constexpr std::size_t kChunkSize = 64 * 1024;

 private:
  bool refill();

  const std::string& displayName_;
  std::size_t maxLineLength_;
  std::FILE* file_ = nullptr;
  std::vector<char> buffer_;  // file mode: holds window_ plus room for one chunk
  std::string_view window_;   // bytes read but not yet returned as lines
  bool atEnd_ = false;
  bool sawInput_ = false;
  int lineNumber_ = 0;
};

}  // namespace lacrima::inline common::detail
