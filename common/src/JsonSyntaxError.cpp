#include <lacrima/common/JsonSyntaxError.h>

#include <algorithm>

namespace lacrima::inline common {

SourceLocation jsonSyntaxErrorLocation(std::string_view text, const QJsonParseError& error,
                                       const std::string& file) {
  const qsizetype offset =
      error.error == QJsonParseError::GarbageAtEnd ? error.offset : error.offset - 1;
  const auto end = static_cast<std::size_t>(
      std::clamp<qsizetype>(offset, 0, static_cast<qsizetype>(text.size())));
  int line = 1;
  int column = 1;
  for (std::size_t i = 0; i < end; ++i) {
    if (text[i] == '\n') {
      ++line;
      column = 1;
    } else if ((static_cast<unsigned char>(text[i]) & 0xC0) != 0x80) {
      ++column;  // UTF-8 continuation bytes belong to the character before them
    }
  }
  return {file, line, column};
}

}  // namespace lacrima::common
