#pragma once
// One value of a JSON file and the path to it, with getters that check what a reader expects.
//
// A getter that finds something else throws FileError "file:line:column: json.path: expected
// ..., got ...". The line and column are looked up only then (JsonPathLocator.h), so reading a
// valid file costs nothing for them. Readers walk a document with operator[] and array() and
// read each value with a getter, or with their own check followed by fail():
//
//   const JsonValue root = JsonInput::load(path, {"presets file", kMaxBytes}).root();
//   root.rejectUnknownMembers({"format", "version", "presets"});
//   for (const JsonValue& preset : root["presets"].array(kMaxPresets)) {
//     const std::string id = preset["id"].string();
//     if (!isValidId(id)) preset["id"].fail("expected lower-case letters, got " + ...);
//   }
//
// Object members come in the order QJsonObject keeps, sorted by name.
#include <lacrima/common/Diagnostics.h>
#include <lacrima/common/JsonPath.h>

#include <QJsonValue>

#include <cstddef>
#include <initializer_list>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace lacrima::inline common {

// The text a document was parsed from and the name its errors give it.
struct JsonSource {
  std::string text;
  std::string name;  // the file as the user named it, or what stands for one ("clipboard")

  // "path: message" at the line and column of `path` (the file alone when it is not in the
  // text), for errors found after reading, such as an index a mesh does not have.
  Diagnostic problem(const JsonPath& path, const std::string& message) const;
};

class JsonValue {
 public:
  JsonValue(QJsonValue value, JsonPath path, std::shared_ptr<const JsonSource> source);

  const JsonPath& path() const { return path_; }
  // The member name it is stored under; empty for an array element or the top level.
  std::string name() const;

  // A member the object does not have.
  bool missing() const { return value_.isUndefined(); }
  bool isNull() const { return value_.isNull(); }
  bool isBool() const { return value_.isBool(); }
  bool isNumber() const { return value_.isDouble(); }  // finite: Qt refuses 1e999
  bool isString() const { return value_.isString(); }
  bool isArray() const { return value_.isArray(); }
  bool isObject() const { return value_.isObject(); }
  // Elements of an array, members of an object, 0 for anything else.
  std::size_t size() const;

  // Objects. Each but has() fails unless this is an object.
  const JsonValue& object() const;
  bool has(std::string_view member) const;              // false for a non-object
  JsonValue operator[](std::string_view member) const;  // missing() when absent
  JsonValue required(std::string_view member) const;    // fails `missing field "member"`
  std::vector<JsonValue> members() const;
  // Fails at the first member not in `known`: "unknown field; expected one of a, b".
  void rejectUnknownMembers(std::initializer_list<std::string_view> known) const;

  // Arrays. Each fails unless this is an array of at most `maxSize` values, so that no file
  // makes a reader allocate more than it means to.
  std::vector<JsonValue> array(std::size_t maxSize) const;
  std::vector<double> numbers(std::size_t maxSize) const;                  // each as number()
  std::vector<int> integers(int min, int max, std::size_t maxSize) const;  // each as integer()
  // Precondition: an array of more than `index` values.
  JsonValue element(std::size_t index) const;

  // Scalars. A missing member fails `missing field "name"` at the object that lacks it.
  double number() const;
  double number(double min, double max) const;  // in [min, max]
  int integer(int min, int max) const;          // a whole number in [min, max]
  std::string string() const;
  bool boolean() const;
  // The index in `choices` of this string: fails `expected "a", "b" or "c", got ...`.
  std::size_t oneOf(std::initializer_list<std::string_view> choices) const {
    return oneOf(std::span<const std::string_view>(choices.begin(), choices.size()));
  }
  std::size_t oneOf(std::span<const std::string_view> choices) const;

  // For messages: null, true, 2.5, "text", an array of 3 values, an object, nothing.
  std::string describe() const;

  // "path: message" at this value's line and column; for a missing member, at the object
  // that lacks it. fail() throws it as a FileError.
  Diagnostic problem(const std::string& message) const;
  [[noreturn]] void fail(const std::string& message) const;

 private:
  JsonValue child(QJsonValue value, JsonPath path) const;
  // Fails `expected <what>, got <describe()>`, or `missing field` for a missing member.
  [[noreturn]] void expected(const std::string& what) const;
  void requireArray(std::size_t maxSize) const;

  QJsonValue value_;
  JsonPath path_;
  std::shared_ptr<const JsonSource> source_;
};

}  // namespace lacrima::inline common
