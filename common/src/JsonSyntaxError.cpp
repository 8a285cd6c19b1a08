#include <lacrima/common/JsonSyntaxError.h>

#include <algorithm>

namespace lacrima::inline common {

SourceLocation jsonSyntaxErrorLocation(std::string_view text, const QJsonParseError& error,
                                       const std::string& file) {
  const qsizetype offset =
      error.error == QJsonParseError::GarbageAtEnd ? error.offset : error.offset - 1;
  return locationInText(text, static_cast<std::size_t>(std::max<qsizetype>(offset, 0)), file);
}

}  // namespace lacrima::inline common
