#pragma once
// JSON text parsed for reading, from memory or from a file, under the name its errors give it.
//
// Every Lacrima format is a JSON object; a reader starts at root():
//
//   const JsonValue root = JsonInput::load(path, {"project file", 64 << 20}).root();
//
// Syntax errors throw FileError "name:line:column: invalid JSON: <what Qt found>"; JsonValue.h
// reports the values that are valid JSON but not what the reader expects.
#include <lacrima/common/JsonValue.h>

#include <QJsonValue>

#include <memory>
#include <string>
#include <string_view>

namespace lacrima::inline common {

class JsonInput {
 public:
  // What load() accepts: `kind` names the file in messages ("project file"), and a larger file
  // than `maxBytes` is refused before it is read.
  struct FileLimits {
    std::string_view kind;
    qint64 maxBytes;
  };

  // `name` stands for the file in messages: its path, or what the text came from.
  static JsonInput parse(std::string_view text, std::string name);
  // Reads `path` (Qt resources ":/..." too). Throws FileError "path: cannot open: ...",
  // "is a folder, not a <kind>", "is N MiB or more; <kind>s are limited to M MiB", or a
  // syntax error.
  static JsonInput load(const std::string& path, const FileLimits& limits);

  // The top-level object; fails "expected a JSON object at the top level, got ..." for
  // anything else.
  JsonValue root() const;
  const JsonSource& source() const { return *source_; }

 private:
  JsonInput(std::shared_ptr<const JsonSource> source, QJsonValue root)
      : source_(std::move(source)), root_(std::move(root)) {}

  std::shared_ptr<const JsonSource> source_;
  QJsonValue root_;
};

}  // namespace lacrima::inline common
