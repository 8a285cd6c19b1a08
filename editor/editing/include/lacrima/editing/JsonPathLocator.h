#pragma once
// Where a JSON value sits in its text, so that validation errors can name a line and column.
//
// QJsonDocument keeps no positions. Validators therefore build a JsonPath while they walk the
// parsed document, and on an error this scanner walks the (already valid) text along the same
// path: members are matched by their unescaped key, array elements by index. The location of
// an object member is its key's opening quote; of an array element, the element's first
// character. Duplicate keys resolve to the last one, as in QJsonDocument.
#include <lacrima/common/Diagnostics.h>

#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace lacrima::editing {

class JsonPath {
public:
  JsonPath() = default;
  JsonPath operator/(std::string_view member) const;  // path.member
  JsonPath operator/(int index) const;                // path[index]

  bool empty() const { return steps_.empty(); }
  // "presets[3].values.open_jaw"; member names that are not plain identifiers are quoted.
  std::string toString() const;
  const std::vector<std::variant<std::string, int>>& steps() const { return steps_; }

private:
  std::vector<std::variant<std::string, int>> steps_;
};

// Line and column (1-based, columns in characters) of `path` in `json`, with `file` as the
// location's file. When the path cannot be followed the location names the file only.
SourceLocation locateJsonPath(std::string_view json, const JsonPath& path, const std::string& file);

}  // namespace lacrima::editing
