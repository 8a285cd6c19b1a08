#include <lacrima/common/JsonPathLocator.h>
#include <lacrima/common/JsonValue.h>
#include <lacrima/common/JsonWriter.h>

#include <QJsonArray>
#include <QJsonObject>

#include <algorithm>
#include <cmath>

namespace lacrima::inline common {
namespace {

// Long enough to recognise a value, short enough to keep a message on one line.
constexpr std::size_t kMaxQuotedBytes = 60;

std::string quoted(std::string text) {
  if (text.size() > kMaxQuotedBytes) {
    std::size_t cut = kMaxQuotedBytes;
    while (cut > 0 && (static_cast<unsigned char>(text[cut]) & 0xC0) == 0x80) --cut;
    text.resize(cut);
    text += "...";
  }
  return '"' + text + '"';
}

std::string values(std::size_t count) {
  return std::to_string(count) + (count == 1 ? " value" : " values");
}

QString qString(std::string_view text) {
  return QString::fromUtf8(text.data(), static_cast<qsizetype>(text.size()));
}

bool isWhole(double value) { return value == std::floor(value); }

}  // namespace

Diagnostic JsonSource::problem(const JsonPath& path, const std::string& message) const {
  return {locateJsonPath(text, path, name),
          path.empty() ? message : path.toString() + ": " + message};
}

JsonValue::JsonValue(QJsonValue value, JsonPath path, std::shared_ptr<const JsonSource> source)
    : value_(std::move(value)), path_(std::move(path)), source_(std::move(source)) {}

JsonValue JsonValue::child(QJsonValue value, JsonPath path) const {
  return JsonValue(std::move(value), std::move(path), source_);
}

std::string JsonValue::name() const {
  if (path_.empty()) return {};
  const auto* member = std::get_if<std::string>(&path_.last());
  return member ? *member : std::string();
}

std::size_t JsonValue::size() const {
  if (value_.isArray()) return static_cast<std::size_t>(value_.toArray().size());
  if (value_.isObject()) return static_cast<std::size_t>(value_.toObject().size());
  return 0;
}

const JsonValue& JsonValue::object() const {
  if (!isObject()) expected("an object");
  return *this;
}

bool JsonValue::has(std::string_view member) const {
  return isObject() && value_.toObject().contains(qString(member));
}

JsonValue JsonValue::operator[](std::string_view member) const {
  object();
  return child(value_.toObject().value(qString(member)), path_ / member);
}

JsonValue JsonValue::required(std::string_view member) const {
  JsonValue value = (*this)[member];
  if (value.missing()) value.expected("");
  return value;
}

std::vector<JsonValue> JsonValue::members() const {
  object();
  const QJsonObject members = value_.toObject();
  std::vector<JsonValue> out;
  out.reserve(static_cast<std::size_t>(members.size()));
  for (auto it = members.begin(); it != members.end(); ++it)
    out.push_back(child(it.value(), path_ / it.key().toStdString()));
  return out;
}

void JsonValue::rejectUnknownMembers(std::initializer_list<std::string_view> known) const {
  for (const JsonValue& member : members()) {
    if (std::find(known.begin(), known.end(), member.name()) != known.end()) continue;
    std::string list;
    for (std::string_view name : known) list += (list.empty() ? "" : ", ") + std::string(name);
    member.fail("unknown field; expected one of " + list);
  }
}

void JsonValue::requireArray(std::size_t maxSize) const {
  if (!isArray()) expected("an array");
  if (size() > maxSize) expected("an array of at most " + values(maxSize));
}

std::vector<JsonValue> JsonValue::array(std::size_t maxSize) const {
  requireArray(maxSize);
  const QJsonArray elements = value_.toArray();
  std::vector<JsonValue> out;
  out.reserve(static_cast<std::size_t>(elements.size()));
  for (qsizetype i = 0; i < elements.size(); ++i)
    out.push_back(child(elements.at(i), path_ / static_cast<int>(i)));
  return out;
}

// The bulk getters read the QJsonArray directly, for arrays of a hundred thousand numbers,
// and make a JsonValue only for the element they fail at.
std::vector<double> JsonValue::numbers(std::size_t maxSize) const {
  requireArray(maxSize);
  const QJsonArray elements = value_.toArray();
  std::vector<double> out(static_cast<std::size_t>(elements.size()));
  for (qsizetype i = 0; i < elements.size(); ++i) {
    const QJsonValue value = elements.at(i);
    if (!value.isDouble()) element(static_cast<std::size_t>(i)).number();
    out[static_cast<std::size_t>(i)] = value.toDouble();
  }
  return out;
}

std::vector<int> JsonValue::integers(int min, int max, std::size_t maxSize) const {
  requireArray(maxSize);
  const QJsonArray elements = value_.toArray();
  std::vector<int> out(static_cast<std::size_t>(elements.size()));
  for (qsizetype i = 0; i < elements.size(); ++i) {
    const double value = elements.at(i).toDouble(NAN);
    if (!(isWhole(value) && value >= min && value <= max))
      element(static_cast<std::size_t>(i)).integer(min, max);
    out[static_cast<std::size_t>(i)] = static_cast<int>(value);
  }
  return out;
}

JsonValue JsonValue::element(std::size_t index) const {
  const auto i = static_cast<qsizetype>(index);
  return child(value_.toArray().at(i), path_ / static_cast<int>(i));
}

double JsonValue::number() const {
  if (!isNumber()) expected("a finite number");
  return value_.toDouble();
}

double JsonValue::number(double min, double max) const {
  const double value = isNumber() ? value_.toDouble() : NAN;
  if (!(value >= min && value <= max))
    expected("a number in [" + formatJsonNumber(min) + ", " + formatJsonNumber(max) + "]");
  return value;
}

int JsonValue::integer(int min, int max) const {
  const double value = isNumber() ? value_.toDouble() : NAN;
  if (!(isWhole(value) && value >= min && value <= max))
    expected("a whole number in [" + std::to_string(min) + ", " + std::to_string(max) + "]");
  return static_cast<int>(value);
}

std::string JsonValue::string() const {
  if (!isString()) expected("a string");
  return value_.toString().toStdString();
}

bool JsonValue::boolean() const {
  if (!isBool()) expected("true or false");
  return value_.toBool();
}

std::size_t JsonValue::oneOf(std::span<const std::string_view> choices) const {
  if (isString()) {
    const std::string text = value_.toString().toStdString();
    const auto found = std::find(choices.begin(), choices.end(), text);
    if (found != choices.end()) return static_cast<std::size_t>(found - choices.begin());
  }
  std::string list;
  for (std::size_t i = 0; i < choices.size(); ++i) {
    if (i > 0) list += i + 1 == choices.size() ? " or " : ", ";
    list += '"' + std::string(choices[i]) + '"';
  }
  expected(list);
}

std::string JsonValue::describe() const {
  switch (value_.type()) {
    case QJsonValue::Null:
      return "null";
    case QJsonValue::Bool:
      return value_.toBool() ? "true" : "false";
    case QJsonValue::Double:
      return formatJsonNumber(value_.toDouble());
    case QJsonValue::String:
      return quoted(value_.toString().toStdString());
    case QJsonValue::Array:
      return "an array of " + values(size());
    case QJsonValue::Object:
      return "an object";
    case QJsonValue::Undefined:
      break;
  }
  return "nothing";
}

Diagnostic JsonValue::problem(const std::string& message) const {
  Diagnostic problem = source_->problem(path_, message);
  // A missing member has no place of its own; the object that lacks it has.
  if (missing()) problem.where = locateJsonPath(source_->text, path_.parent(), source_->name);
  return problem;
}

void JsonValue::fail(const std::string& message) const { throw FileError(problem(message)); }

void JsonValue::expected(const std::string& what) const {
  if (missing())
    throw FileError(source_->problem(path_.parent(), "missing field \"" + name() + "\""));
  fail("expected " + what + ", got " + describe());
}

}  // namespace lacrima::inline common
