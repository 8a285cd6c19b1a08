#pragma once
// Errors and warnings that point at a place in a file: "file:line:column: message".
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace lacrima::inline common {

struct SourceLocation {
  std::string file;  // as the user named it
  int line = 0;      // 1-based; 0 when the message concerns the whole file
  int column = 0;    // 1-based; 0 when it concerns the whole line

  // "file:line:column", "file:line" or "file", whichever parts are known.
  std::string toString() const;
};

struct Diagnostic {
  SourceLocation where;
  std::string message;

  std::string toString() const;  // "file:line:col: message"
};

// Thrown for input that cannot be used: malformed files, invalid documents, failed saves.
// what() is the full "file:line:col: message" text, ready to show to a user.
class FileError : public std::runtime_error {
 public:
  FileError(SourceLocation where, const std::string& message);
  explicit FileError(const Diagnostic& problem) : FileError(problem.where, problem.message) {}

  const SourceLocation& where() const { return where_; }
  const std::string& message() const { return message_; }

 private:
  SourceLocation where_;
  std::string message_;
};

using Warnings = std::vector<Diagnostic>;

// Where byte `offset` of `text` is, named `file`: 1-based line and column, the column counted in
// characters, as editors count it (UTF-8 continuation bytes belong to the character before them).
SourceLocation locationInText(std::string_view text, std::size_t offset, const std::string& file);

}  // namespace lacrima::inline common
