#pragma once
// Where a JSON value sits in its text, so that errors about valid JSON can name a line and
// column.
//
// QJsonDocument keeps no positions. Readers therefore know the JsonPath of each value they
// read, and on an error this scanner walks the (already valid) text along the same path:
// members are matched by their unescaped key, array elements by index. The location of an
// object member is its key's opening quote; of an array element, the element's first character.
// Duplicate keys resolve to the last one, as in QJsonDocument.
#include <lacrima/common/Diagnostics.h>
#include <lacrima/common/JsonPath.h>

#include <string>
#include <string_view>

namespace lacrima::inline common {

// Line and column (1-based, columns in characters) of `path` in `json`, with `file` as the
// location's file. When the path cannot be followed the location names the file only.
SourceLocation locateJsonPath(std::string_view json, const JsonPath& path, const std::string& file);

}  // namespace lacrima::inline common
