#include <lacrima/editing/PresetLibrary.h>

#include <lacrima/common/FapTable.h>
#include <lacrima/common/JsonSyntaxError.h>
#include <lacrima/common/JsonWriter.h>
#include <lacrima/editing/ChannelLimits.h>
#include <lacrima/editing/JsonPathLocator.h>

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <algorithm>
#include <cmath>
#include <set>

namespace lacrima::editing {
namespace {

// A presets file is a few kilobytes; anything this large is not one.
constexpr qint64 kMaxFileBytes = 16 * 1024 * 1024;

std::string describe(const QJsonValue& value) {
  switch (value.type()) {
    case QJsonValue::Null: return "null";
    case QJsonValue::Bool: return value.toBool() ? "true" : "false";
    case QJsonValue::Double: return formatJsonNumber(value.toDouble());
    case QJsonValue::String: return '"' + value.toString().toStdString() + '"';
    case QJsonValue::Array: return "an array";
    case QJsonValue::Object: return "an object";
    case QJsonValue::Undefined: break;
  }
  return "nothing";
}

bool isValidId(const std::string& id) {
  return !id.empty() && std::all_of(id.begin(), id.end(), [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-';
  });
}

class Reader {
public:
  Reader(std::string_view json, std::string file) : json_(json), file_(std::move(file)) {}

  [[noreturn]] void fail(const JsonPath& path, const std::string& message) const {
    const std::string where = path.empty() ? message : path.toString() + ": " + message;
    throw FileError(locateJsonPath(json_, path, file_), where);
  }

  std::vector<Preset> read(const QJsonObject& root) const;

private:
  void rejectUnknown(const QJsonObject& object, const JsonPath& path,
                     std::initializer_list<std::string_view> known) const {
    for (auto it = object.begin(); it != object.end(); ++it) {
      const std::string name = it.key().toStdString();
      if (std::find(known.begin(), known.end(), name) != known.end()) continue;
      std::string list;
      for (std::string_view k : known) list += (list.empty() ? "" : ", ") + std::string(k);
      fail(path / name, "unknown field; expected one of " + list);
    }
  }

  QJsonObject object(const QJsonValue& value, const JsonPath& path) const {
    if (!value.isObject()) fail(path, "expected an object, got " + describe(value));
    return value.toObject();
  }

  std::string text(const QJsonObject& parent, std::string_view name, const JsonPath& path,
                   bool required) const {
    const QString key = QString::fromUtf8(name.data(), static_cast<qsizetype>(name.size()));
    if (!parent.contains(key)) {
      if (required) fail(path, "missing field \"" + std::string(name) + "\"");
      return {};
    }
    const QJsonValue value = parent[key];
    if (!value.isString() || value.toString().trimmed().isEmpty())
      fail(path / name, "expected non-empty text, got " + describe(value));
    return value.toString().toStdString();
  }

  double number(const QJsonValue& value, const JsonPath& path) const {
    if (!value.isDouble() || !std::isfinite(value.toDouble()))
      fail(path, "expected a finite number, got " + describe(value));
    return value.toDouble();
  }

  Keyframe pose(const QJsonValue& value, const JsonPath& path) const {
    const QJsonObject values = object(value, path);
    if (values.isEmpty()) fail(path, "expected at least one FAP value, got an empty object");
    Keyframe key;
    for (auto it = values.begin(); it != values.end(); ++it) {
      const std::string name = it.key().toStdString();
      const JsonPath at = path / name;
      const std::optional<int> fap = fapByName(name);
      if (!fap) fail(at, "unknown FAP name; expected a name from the FAP table such as open_jaw, raise_l_i_eyebrow or tears_l_eye");
      const ChannelLimits limits = editLimits(*fap);
      const double v = number(it.value(), at);
      const bool whole = isTearChannel(*fap) || isHighLevelFap(*fap);
      if (v < limits.min || v > limits.max || (whole && v != std::floor(v))) {
        fail(at, std::string("expected ") + (whole ? "a whole number" : "a number") + " in [" +
                     std::to_string(limits.min) + ", " + std::to_string(limits.max) +
                     "] (the editing range of " + name + "), got " + formatJsonNumber(v));
      }
      key.set(*fap, static_cast<float>(v));
    }
    return key;
  }

  std::vector<Keyframe> sequence(const QJsonValue& value, const JsonPath& path) const {
    if (!value.isArray()) fail(path, "expected an array of keys, got " + describe(value));
    const QJsonArray array = value.toArray();
    if (array.size() < 2) fail(path, "expected at least two keys (use \"values\" for a single pose)");
    std::vector<Keyframe> keys;
    for (qsizetype i = 0; i < array.size(); ++i) {
      const JsonPath at = path / static_cast<int>(i);
      const QJsonObject entry = object(array[i], at);
      rejectUnknown(entry, at, {"time", "interpolation", "values"});
      if (!entry.contains("time")) fail(at, "missing field \"time\"");
      if (!entry.contains("values")) fail(at, "missing field \"values\"");
      const double time = number(entry["time"], at / "time");
      if (i == 0 && time != 0.0) fail(at / "time", "expected 0 for the first key, got " + formatJsonNumber(time));
      if (i > 0 && time <= keys.back().time) {
        fail(at / "time", "expected a time after the previous key's " +
                              formatJsonNumber(keys.back().time) + " s, got " + formatJsonNumber(time));
      }
      if (time > 600.0) fail(at / "time", "expected at most 600 s, got " + formatJsonNumber(time));
      Keyframe key = pose(entry["values"], at / "values");
      key.time = time;
      key.interpolation = Interpolation::Smooth;
      if (entry.contains("interpolation")) {
        const QJsonValue mode = entry["interpolation"];
        const auto parsed = mode.isString() ? interpolationFromString(mode.toString().toStdString())
                                            : std::nullopt;
        if (!parsed) fail(at / "interpolation", "expected \"linear\" or \"smooth\", got " + describe(mode));
        key.interpolation = *parsed;
      }
      keys.push_back(key);
    }
    return keys;
  }

  Preset preset(const QJsonValue& value, const JsonPath& path) const {
    const QJsonObject entry = object(value, path);
    rejectUnknown(entry, path, {"id", "name", "category", "description", "expression", "values", "keys"});
    Preset preset;
    preset.id = text(entry, "id", path, true);
    if (!isValidId(preset.id))
      fail(path / "id", "expected lower-case letters, digits and '-', got \"" + preset.id + "\"");
    preset.name = text(entry, "name", path, true);
    preset.category = text(entry, "category", path, true);
    preset.description = text(entry, "description", path, false);
    if (entry.contains("expression")) {
      const double code = number(entry["expression"], path / "expression");
      if (code < 1 || code > 6 || code != std::floor(code))
        fail(path / "expression", "expected an expression code 1..6 (joy, sadness, anger, fear, disgust, surprise), got " +
                                      formatJsonNumber(code));
      preset.expression = static_cast<int>(code);
    }
    const bool hasValues = entry.contains("values");
    const bool hasKeys = entry.contains("keys");
    if (hasValues == hasKeys)
      fail(path, "expected exactly one of \"values\" (a pose) and \"keys\" (a sequence)");
    if (hasValues) {
      Keyframe key = pose(entry["values"], path / "values");
      key.interpolation = Interpolation::Smooth;
      preset.keys.push_back(key);
    } else {
      preset.keys = sequence(entry["keys"], path / "keys");
    }
    return preset;
  }

  std::string_view json_;
  std::string file_;
};

std::vector<Preset> Reader::read(const QJsonObject& root) const {
  const JsonPath top;
  if (!root.contains("format")) fail(top, "missing field \"format\"; this is not a Lacrima presets file");
  if (root["format"].toString().toStdString() != PresetLibrary::kFormat)
    fail(top / "format", "expected \"" + std::string(PresetLibrary::kFormat) + "\", got " + describe(root["format"]));
  if (!root.contains("version")) fail(top, "missing field \"version\"");
  const double version = number(root["version"], top / "version");
  if (version != PresetLibrary::kVersion)
    fail(top / "version", "expected " + std::to_string(PresetLibrary::kVersion) + ", got " + formatJsonNumber(version));
  rejectUnknown(root, top, {"format", "version", "presets"});
  if (!root.contains("presets")) fail(top, "missing field \"presets\"");
  if (!root["presets"].isArray()) fail(top / "presets", "expected an array of presets, got " + describe(root["presets"]));
  const QJsonArray array = root["presets"].toArray();
  std::vector<Preset> presets;
  std::set<std::string> ids;
  std::set<int> expressions;
  for (qsizetype i = 0; i < array.size(); ++i) {
    const JsonPath at = top / "presets" / static_cast<int>(i);
    Preset preset = this->preset(array[i], at);
    if (!ids.insert(preset.id).second)
      fail(at / "id", "expected a unique id; \"" + preset.id + "\" is used by an earlier preset");
    if (preset.expression && !expressions.insert(*preset.expression).second)
      fail(at / "expression", "expected each expression code once; " + std::to_string(*preset.expression) +
                                  " is used by an earlier preset");
    if (preset.expression && preset.isSequence())
      fail(at / "expression", "expected only on a pose (\"values\"), not on a sequence");
    presets.push_back(std::move(preset));
  }
  return presets;
}

}  // namespace

PresetLibrary PresetLibrary::fromJson(std::string_view json, const std::string& displayName) {
  QJsonParseError error;
  const QJsonDocument document = QJsonDocument::fromJson(
      QByteArray::fromRawData(json.data(), static_cast<qsizetype>(json.size())), &error);
  if (error.error != QJsonParseError::NoError) {
    throw FileError(jsonSyntaxErrorLocation(json, error, displayName),
                    "invalid JSON: " + error.errorString().toStdString());
  }
  if (!document.isObject()) throw FileError({displayName, 1, 1}, "expected a JSON object at the top level");
  PresetLibrary library;
  library.presets_ = Reader(json, displayName).read(document.object());
  return library;
}

PresetLibrary PresetLibrary::load(const std::string& path) {
  QFile file(QString::fromStdString(path));
  if (!file.open(QIODevice::ReadOnly))
    throw FileError({path, 0, 0}, "cannot open: " + file.errorString().toStdString());
  if (file.size() > kMaxFileBytes)
    throw FileError({path, 0, 0}, "is " + std::to_string(file.size() >> 20) + " MiB; expected a presets file of at most 16 MiB");
  const QByteArray bytes = file.readAll();
  return fromJson(std::string_view(bytes.constData(), static_cast<std::size_t>(bytes.size())), path);
}

PresetLibrary PresetLibrary::builtIn() { return load(std::string(kBuiltInPath)); }

const Preset* PresetLibrary::find(std::string_view id) const {
  for (const Preset& p : presets_)
    if (p.id == id) return &p;
  return nullptr;
}

const Preset* PresetLibrary::forExpression(int code) const {
  for (const Preset& p : presets_)
    if (p.expression == code) return &p;
  return nullptr;
}

std::vector<std::string> PresetLibrary::categories() const {
  std::vector<std::string> out;
  for (const Preset& p : presets_)
    if (std::find(out.begin(), out.end(), p.category) == out.end()) out.push_back(p.category);
  return out;
}

}  // namespace lacrima::editing
