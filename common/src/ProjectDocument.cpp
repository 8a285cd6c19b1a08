#include <lacrima/common/AtomicSave.h>
#include <lacrima/common/FapTable.h>
#include <lacrima/common/JsonSyntaxError.h>
#include <lacrima/common/JsonWriter.h>
#include <lacrima/common/ProjectDocument.h>

#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QJsonParseError>
#include <QString>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <initializer_list>
#include <numeric>
#include <stdexcept>

namespace lacrima::inline common {
namespace {

constexpr std::string_view kFormat = "lacrima-project";
constexpr double kMaxFps = 1000.0;
constexpr double kMaxChannelMagnitude = 1e7;  // far beyond any face; catches unit mix-ups
constexpr qint64 kMaxFileBytes = qint64{64} << 20;
constexpr double kSameKeyTime = 1e-9;  // as KeyframeSequence: closer keys would merge


// The double to write for a float value: the shortest decimal that reads back as the float
// ("0.1", not "0.10000000149011612"), provided text -> double -> float returns exactly the
// float; otherwise (a double rounding near a tie) the float's exact double value.
double doubleForFloat(float value) {
  std::array<char, 32> buffer{};
  const auto written = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
  double shortest = 0.0;
  const auto read = std::from_chars(buffer.data(), written.ptr, shortest);
  if (read.ec == std::errc{} && static_cast<float>(shortest) == value) return shortest;
  return static_cast<double>(value);
}

void writeKey(JsonWriter& out, const Keyframe& key) {
  out.beginObject();
  out.key("time");
  out.number(key.time);
  out.key("interpolation");
  out.string(toString(key.interpolation));
  out.key("values");
  out.beginObject();
  for (int fap = 1; fap <= kChannelCount; ++fap) {
    if (!key.has(fap)) continue;
    out.key(fapInfo(fap).name);
    out.number(doubleForFloat(key.value(fap)));
  }
  out.endObject();
  out.endObject();
}

void writeSource(JsonWriter& out, std::string_view side,
                 const std::optional<Eigen::Vector3d>& source) {
  out.key(side);
  if (!source) {
    out.null();
    return;
  }
  const std::array<double, 3> xyz{source->x(), source->y(), source->z()};
  out.numberRow(xyz);
}

void writeSimulation(JsonWriter& out, const TearParameterValues& simulation) {
  out.beginObject();
  // Table order groups related parameters; names outside the table (which load would
  // reject) are still written, so the problem surfaces on load rather than vanishing.
  for (const TearParameterInfo& info : tearParameterTable()) {
    const auto found = simulation.find(info.name);
    if (found == simulation.end()) continue;
    out.key(info.name);
    out.number(found->second);
  }
  for (const auto& [name, value] : simulation) {
    if (findTearParameter(name)) continue;
    out.key(name);
    out.number(value);
  }
  out.endObject();
}

std::string_view toString(SceneSettings::Redness redness) {
  return redness == SceneSettings::Redness::Tears ? "tears" : "animation";
}

void writeScene(JsonWriter& out, const SceneSettings& scene) {
  out.beginObject();
  out.key("particles");
  out.boolean(scene.particles);
  out.key("surface");
  out.boolean(scene.surface);
  out.key("trails");
  out.boolean(scene.trails);
  out.key("textureBlending");
  out.boolean(scene.textureBlending);
  out.key("redness");
  out.string(toString(scene.redness));
  out.key("blush");
  out.boolean(scene.blush);
  out.key("simulation");
  writeSimulation(out, scene.simulation);
  out.endObject();
}

// ---------------------------------------------------------------------------------------
// Reading. Every problem is reported with its JSON path ("keys[2].values.open_jaw") so a
// user editing the file by hand can find it; line and column exist only for syntax errors,
// because QJsonDocument keeps no positions for values.

std::string join(std::initializer_list<std::string_view> names) {
  std::string text;
  for (std::string_view name : names) {
    if (!text.empty()) text += ", ";
    text += name;
  }
  return text;
}

std::string describe(const QJsonValue& value) {
  switch (value.type()) {
    case QJsonValue::Null: return "null";
    case QJsonValue::Bool: return value.toBool() ? "true" : "false";
    case QJsonValue::Double: return formatJsonNumber(value.toDouble());
    case QJsonValue::String: return "the string \"" + value.toString().toStdString() + "\"";
    case QJsonValue::Array:
      return "an array of " + std::to_string(value.toArray().size()) + " values";
    case QJsonValue::Object: return "an object";
    case QJsonValue::Undefined: break;
  }
  return "nothing";
}

std::string child(const std::string& path, std::string_view field) {
  return path.empty() ? std::string(field) : path + "." + std::string(field);
}

std::string element(const std::string& path, qsizetype index) {
  return path + "[" + std::to_string(index) + "]";
}

// Edit distance, to suggest the FAP name a typo was probably meant to be.
std::size_t editDistance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  std::iota(row.begin(), row.end(), std::size_t{0});
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t substitute = diagonal + (a[i - 1] == b[j - 1] ? 0 : 1);
      diagonal = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, substitute});
    }
  }
  return row[b.size()];
}

std::string fapNameHint(std::string_view name) {
  std::string_view best;
  std::size_t bestDistance = 3;  // suggest only near misses
  for (const FapInfo& info : fapTable()) {
    const std::size_t distance = editDistance(name, info.name);
    if (distance < bestDistance) {
      bestDistance = distance;
      best = info.name;
    }
  }
  return best.empty() ? std::string() : "; did you mean " + std::string(best) + "?";
}

class DocumentReader {
public:
  explicit DocumentReader(const std::string& displayName) : file_(displayName) {}

  ProjectDocument read(const QJsonObject& root) const {
    checkFormatAndVersion(root);
    rejectUnknown(root, "",
                  {"format", "version", "name", "fps", "interpolation", "keys", "tearSources",
                   "scene"});
    ProjectDocument document;
    if (root.contains("name")) document.name = string(root["name"], "name");
    if (root.contains("fps")) document.fps = fps(root["fps"]);
    if (root.contains("interpolation")) {
      document.defaultInterpolation = interpolation(root["interpolation"], "interpolation");
    }
    if (!root.contains("keys")) fail("keys", "missing; every project lists its keys");
    document.keys = keys(root["keys"], document.defaultInterpolation);
    if (root.contains("tearSources")) document.tearSources = tearSources(root["tearSources"]);
    if (root.contains("scene")) document.scene = scene(root["scene"]);
    return document;
  }

  [[noreturn]] void fail(const std::string& path, const std::string& message) const {
    throw FileError({file_, 0, 0}, path.empty() ? message : path + ": " + message);
  }

private:
  // Checked before anything else: another program's JSON or a newer schema should be
  // reported as such, not as a list of fields this build happens not to know.
  void checkFormatAndVersion(const QJsonObject& root) const {
    if (!root.contains("format")) {
      fail("format", "missing; this is not a Lacrima project");
    }
    const QJsonValue format = root["format"];
    if (!format.isString() || format.toString().toStdString() != kFormat) {
      fail("format", "expected \"" + std::string(kFormat) + "\", got " + describe(format));
    }
    if (!root.contains("version")) fail("version", "missing");
    const QJsonValue version = root["version"];
    const double number = version.toDouble(-1.0);
    if (!version.isDouble() || number != std::floor(number) || number < 1.0) {
      fail("version", "expected a whole number >= 1, got " + describe(version));
    }
    if (number > ProjectDocument::kSchemaVersion) {
      fail("version", "written by a newer Lacrima (schema " + formatJsonNumber(number) +
                          "); this build reads up to " +
                          std::to_string(ProjectDocument::kSchemaVersion));
    }
  }

  void rejectUnknown(const QJsonObject& object, const std::string& path,
                     std::initializer_list<std::string_view> known) const {
    for (auto it = object.begin(); it != object.end(); ++it) {
      const std::string name = it.key().toStdString();
      if (std::find(known.begin(), known.end(), name) == known.end()) {
        fail(child(path, name), "unknown field; expected one of " + join(known));
      }
    }
  }

  QJsonObject object(const QJsonValue& value, const std::string& path) const {
    if (!value.isObject()) fail(path, "expected an object, got " + describe(value));
    return value.toObject();
  }

  QJsonArray array(const QJsonValue& value, const std::string& path) const {
    if (!value.isArray()) fail(path, "expected an array, got " + describe(value));
    return value.toArray();
  }

  std::string string(const QJsonValue& value, const std::string& path) const {
    if (!value.isString()) fail(path, "expected a string, got " + describe(value));
    return value.toString().toStdString();
  }

  bool boolean(const QJsonValue& value, const std::string& path) const {
    if (!value.isBool()) fail(path, "expected true or false, got " + describe(value));
    return value.toBool();
  }

  double finiteNumber(const QJsonValue& value, const std::string& path) const {
    // QJsonDocument turns numbers too large for a double into infinities.
    if (!value.isDouble() || !std::isfinite(value.toDouble())) {
      fail(path, "expected a finite number, got " + describe(value));
    }
    return value.toDouble();
  }

  double fps(const QJsonValue& value) const {
    const double fps = value.isDouble() ? value.toDouble() : std::nan("");
    if (!(fps > 0.0 && fps <= kMaxFps)) {
      fail("fps", "expected a number in (0, " + formatJsonNumber(kMaxFps) + "], got " +
                      describe(value));
    }
    return fps;
  }

  Interpolation interpolation(const QJsonValue& value, const std::string& path) const {
    const auto mode = interpolationFromString(value.isString() ? string(value, path) : "");
    if (!mode) fail(path, "expected \"linear\" or \"smooth\", got " + describe(value));
    return *mode;
  }

  KeyframeSequence keys(const QJsonValue& value, Interpolation defaultMode) const {
    const QJsonArray list = array(value, "keys");
    std::vector<Keyframe> result;
    result.reserve(static_cast<std::size_t>(list.size()));
    for (qsizetype i = 0; i < list.size(); ++i) {
      result.push_back(key(list[i], element("keys", i), defaultMode));
    }
    rejectDuplicateTimes(result);
    return KeyframeSequence(std::move(result));
  }

  Keyframe key(const QJsonValue& value, const std::string& path,
               Interpolation defaultMode) const {
    const QJsonObject object = this->object(value, path);
    rejectUnknown(object, path, {"time", "interpolation", "values"});
    Keyframe key;
    if (!object.contains("time")) fail(child(path, "time"), "missing");
    key.time = finiteNumber(object["time"], child(path, "time"));
    if (key.time < 0.0) {
      fail(child(path, "time"), "expected a time >= 0 s, got " + formatJsonNumber(key.time));
    }
    key.interpolation = object.contains("interpolation")
                            ? interpolation(object["interpolation"], child(path, "interpolation"))
                            : defaultMode;
    if (!object.contains("values")) fail(child(path, "values"), "missing");
    const std::string valuesPath = child(path, "values");
    const QJsonObject values = this->object(object["values"], valuesPath);
    for (auto it = values.begin(); it != values.end(); ++it) {
      const std::string name = it.key().toStdString();
      const std::optional<int> fap = fapByName(name);
      if (!fap) fail(child(valuesPath, name), "unknown FAP name" + fapNameHint(name));
      key.set(*fap, channelValue(*fap, it.value(), child(valuesPath, name)));
    }
    return key;
  }

  float channelValue(int fap, const QJsonValue& value, const std::string& path) const {
    const double v = value.isDouble() ? value.toDouble() : std::nan("");
    if (isTearChannel(fap)) {
      if (!(v >= 0.0 && v <= kMaxTearParticles && v == std::floor(v))) {
        fail(path, "expected a whole number of particles in [0, " +
                       std::to_string(kMaxTearParticles) + "], got " + describe(value));
      }
    } else if (!(std::abs(v) <= kMaxChannelMagnitude)) {
      fail(path, "expected a number in [-1e7, 1e7], got " + describe(value));
    }
    return static_cast<float>(v);
  }

  void rejectDuplicateTimes(const std::vector<Keyframe>& keys) const {
    std::vector<std::size_t> order(keys.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return keys[a].time < keys[b].time; });
    for (std::size_t i = 1; i < order.size(); ++i) {
      const std::size_t first = std::min(order[i - 1], order[i]);
      const std::size_t second = std::max(order[i - 1], order[i]);
      if (keys[second].time - keys[first].time < kSameKeyTime &&
          keys[first].time - keys[second].time < kSameKeyTime) {
        fail(element("keys", static_cast<qsizetype>(second)) + ".time",
             formatJsonNumber(keys[second].time) + " repeats the time of " +
                 element("keys", static_cast<qsizetype>(first)));
      }
    }
  }

  TearSources tearSources(const QJsonValue& value) const {
    const QJsonObject object = this->object(value, "tearSources");
    rejectUnknown(object, "tearSources", {"left", "right"});
    TearSources sources;
    if (object.contains("left")) sources.left = source(object["left"], "tearSources.left");
    if (object.contains("right")) sources.right = source(object["right"], "tearSources.right");
    return sources;
  }

  std::optional<Eigen::Vector3d> source(const QJsonValue& value, const std::string& path) const {
    if (value.isNull()) return std::nullopt;
    if (!value.isArray() || value.toArray().size() != 3) {
      fail(path, "expected null or an array of 3 finite numbers [x, y, z], got " +
                     describe(value));
    }
    const QJsonArray xyz = value.toArray();
    Eigen::Vector3d position;
    for (qsizetype i = 0; i < 3; ++i) position[i] = finiteNumber(xyz[i], element(path, i));
    return position;
  }

  SceneSettings scene(const QJsonValue& value) const {
    const QJsonObject object = this->object(value, "scene");
    rejectUnknown(object, "scene",
                  {"particles", "surface", "trails", "textureBlending", "redness", "blush",
                   "simulation"});
    SceneSettings scene;
    const auto flag = [&](const char* name, bool& target) {
      if (object.contains(name)) target = boolean(object[name], child("scene", name));
    };
    flag("particles", scene.particles);
    flag("surface", scene.surface);
    flag("trails", scene.trails);
    flag("textureBlending", scene.textureBlending);
    flag("blush", scene.blush);
    if (object.contains("redness")) scene.redness = redness(object["redness"]);
    if (object.contains("simulation")) scene.simulation = simulation(object["simulation"]);
    return scene;
  }

  SceneSettings::Redness redness(const QJsonValue& value) const {
    const std::string text = value.isString() ? value.toString().toStdString() : "";
    if (text == "animation") return SceneSettings::Redness::Animation;
    if (text == "tears") return SceneSettings::Redness::Tears;
    fail("scene.redness", "expected \"animation\" or \"tears\", got " + describe(value));
  }

  TearParameterValues simulation(const QJsonValue& value) const {
    const QJsonObject object = this->object(value, "scene.simulation");
    TearParameterValues parameters;
    for (auto it = object.begin(); it != object.end(); ++it) {
      const std::string name = it.key().toStdString();
      const std::string path = child("scene.simulation", name);
      if (!it.value().isDouble()) fail(path, "expected a number, got " + describe(it.value()));
      try {
        validateTearParameter(name, it.value().toDouble());
      } catch (const std::invalid_argument& error) {
        // The path already names the parameter; drop the "<name>: " the check starts with.
        std::string_view why = error.what();
        const std::string prefix = name + ": ";
        if (why.starts_with(prefix)) why.remove_prefix(prefix.size());
        fail(path, std::string(why));
      }
      parameters[name] = it.value().toDouble();
    }
    return parameters;
  }

  std::string file_;
};


}  // namespace

bool ProjectDocument::operator==(const ProjectDocument& other) const {
  return name == other.name && fps == other.fps &&
         defaultInterpolation == other.defaultInterpolation &&
         keys.keys() == other.keys.keys() && tearSources == other.tearSources &&
         scene == other.scene;
}

std::string ProjectDocument::toJson() const {
  JsonWriter out;
  out.beginObject();
  out.key("format");
  out.string(kFormat);
  out.key("version");
  out.number(kSchemaVersion);
  out.key("name");
  out.string(name);
  out.key("fps");
  out.number(fps);
  out.key("interpolation");
  out.string(toString(defaultInterpolation));
  out.key("keys");
  out.beginArray();
  for (const Keyframe& key : keys.keys()) writeKey(out, key);
  out.endArray();
  out.key("tearSources");
  out.beginObject();
  writeSource(out, "left", tearSources.left);
  writeSource(out, "right", tearSources.right);
  out.endObject();
  out.key("scene");
  writeScene(out, scene);
  out.endObject();
  return std::move(out).finish();
}

ProjectDocument ProjectDocument::fromJson(std::string_view json, const std::string& displayName) {
  const QByteArray bytes(json.data(), static_cast<qsizetype>(json.size()));
  QJsonParseError error{};
  const QJsonDocument parsed = QJsonDocument::fromJson(bytes, &error);
  if (error.error != QJsonParseError::NoError) {
    throw FileError(jsonSyntaxErrorLocation(json, error, displayName),
                    "invalid JSON: " + error.errorString().toStdString());
  }
  const DocumentReader reader(displayName);
  if (!parsed.isObject()) reader.fail("", "expected a JSON object at the top level");
  return reader.read(parsed.object());
}

ProjectDocument ProjectDocument::load(const std::string& path) {
  QFile file(QString::fromStdString(path));
  // QFile refuses folders with "Unknown error"; say what is actually wrong.
  if (QFileInfo(file).isDir()) throw FileError({path, 0, 0}, "is a folder, not a project file");
  if (!file.open(QIODevice::ReadOnly)) {
    throw FileError({path, 0, 0}, "cannot open: " + file.errorString().toStdString());
  }
  const auto tooLarge = [&](qint64 bytes) {
    throw FileError({path, 0, 0}, "is " + std::to_string(bytes >> 20) +
                                      " MiB or more; project files are limited to " +
                                      std::to_string(kMaxFileBytes >> 20) + " MiB");
  };
  if (file.size() > kMaxFileBytes) tooLarge(file.size());
  // Read one byte past the limit: pipes and special files report size 0.
  const QByteArray bytes = file.read(kMaxFileBytes + 1);
  if (file.error() != QFileDevice::NoError) {
    throw FileError({path, 0, 0}, "cannot read: " + file.errorString().toStdString());
  }
  if (bytes.size() > kMaxFileBytes) tooLarge(bytes.size());
  return fromJson(std::string_view(bytes.constData(), static_cast<std::size_t>(bytes.size())),
                  path);
}

void ProjectDocument::save(const std::string& path) const { saveAtomically(path, toJson()); }

ProjectDocument ProjectDocument::fromAnimation(const FapAnimation& animation) {
  ProjectDocument document;
  document.name = animation.name;
  document.fps = animation.fps;
  document.keys = KeyframeSequence::fromAnimation(animation, Interpolation::Linear);
  return document;
}

}  // namespace lacrima::common
