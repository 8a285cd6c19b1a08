#pragma once
// Where a JSON syntax error is, for messages a user can act on.
#include <lacrima/common/Diagnostics.h>

#include <QJsonParseError>

#include <string>
#include <string_view>

namespace lacrima::inline common {

// 1-based line and column (in characters, not bytes) of the character `error` is about in
// `text`. QJsonDocument reports the offset just past that character, having consumed it, except
// for trailing garbage, where it points at the garbage itself; this corrects for both.
SourceLocation jsonSyntaxErrorLocation(std::string_view text, const QJsonParseError& error,
                                       const std::string& file);

}  // namespace lacrima::inline common
