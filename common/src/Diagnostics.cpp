#include <lacrima/common/Diagnostics.h>

namespace lacrima::inline common {

std::string SourceLocation::toString() const {
  std::string text = file;
  if (line > 0) {
    text += ':' + std::to_string(line);
    if (column > 0) text += ':' + std::to_string(column);
  }
  return text;
}

std::string Diagnostic::toString() const { return where.toString() + ": " + message; }

FileError::FileError(SourceLocation where, const std::string& message)
    : std::runtime_error(Diagnostic{where, message}.toString()),
      where_(std::move(where)),
      message_(message) {}

SourceLocation locationInText(std::string_view text, std::size_t offset, const std::string& file) {
  int line = 1;
  int column = 1;
  for (std::size_t i = 0; i < offset && i < text.size(); ++i) {
    if (text[i] == '\n') {
      ++line;
      column = 1;
    } else if ((static_cast<unsigned char>(text[i]) & 0xC0) != 0x80) {
      ++column;
    }
  }
  return {file, line, column};
}

}  // namespace lacrima::inline common
