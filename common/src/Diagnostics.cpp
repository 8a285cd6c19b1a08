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

}  // namespace lacrima::common
