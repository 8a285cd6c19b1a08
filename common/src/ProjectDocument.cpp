#include <lacrima/common/AtomicSave.h>
#include <lacrima/common/FapTable.h>
#include <lacrima/common/JsonInput.h>
#include <lacrima/common/JsonWriter.h>
#include <lacrima/common/ProjectDocument.h>

#include "ProjectKeysJson.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <limits>
#include <numeric>
#include <system_error>

namespace lacrima::inline common {
namespace {

constexpr std::string_view kFormat = "lacrima-project";
constexpr double kMaxFps = 1000.0;

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
  // Only what differs from the defaults, so projects that never chose keep their text.
  const TearQualitySettings& quality = scene.quality;
  if (quality.level != TearQuality::Balanced) {
    out.key("quality");
    out.string(toString(quality.level));
  }
  if (quality.solver) {
    out.key("solver");
    out.string(*quality.solver);
  }
  if (quality.tension) {
    out.key("tension");
    out.string(*quality.tension);
  }
  if (quality.neighbours) {
    out.key("neighbours");
    out.string(*quality.neighbours);
  }
  out.endObject();
}

void writeHead(JsonWriter& out, const HeadFiles& head) {
  out.beginObject();
  out.key("mesh");
  out.string(head.mesh);
  out.key("fdp");
  out.string(head.fdp);
  out.endObject();
}

// ---------------------------------------------------------------------------------------
// Head paths. Lexical only (no symlinks resolved): the paths stay the ones the user chose.

namespace fs = std::filesystem;

std::string absoluteIn(const std::string& path, const std::string& folder) {
  const fs::path p(path);
  if (p.is_absolute()) return p.lexically_normal().string();
  fs::path base(folder.empty() ? std::string(".") : folder);  // "" is the current folder
  if (base.is_relative()) {
    std::error_code ignored;
    base = fs::absolute(base, ignored);
  }
  return (base / p).lexically_normal().string();
}

// `path` relative to `folder` when they share a folder below the root ("../x" within one
// tree), otherwise `path` unchanged: "../../../opt/heads" from a home folder would break as
// soon as the project moves, while "/opt/heads" keeps working.
std::string relativeTo(const std::string& path, const std::string& folder) {
  const fs::path target = fs::path(absoluteIn(path, folder));
  const fs::path base = fs::path(absoluteIn(".", folder));
  if (target.root_path() != base.root_path()) return path;
  const fs::path targetBelowRoot = target.relative_path();
  const fs::path baseBelowRoot = base.relative_path();
  if (targetBelowRoot.empty() || baseBelowRoot.empty() ||
      *targetBelowRoot.begin() != *baseBelowRoot.begin())
    return path;
  const fs::path relative = target.lexically_relative(base);
  return relative.empty() ? path : relative.generic_string();
}

// ---------------------------------------------------------------------------------------
// Reading. Every problem names its JSON path ("keys[2].values.open_jaw") so that a user
// editing the file by hand can find it.

// Checked before anything else: another program's JSON or a newer schema should be reported
// as such, not as a list of fields this build happens not to know. Returns the version.
int checkFormatAndVersion(const JsonValue& root) {
  const JsonValue format = root["format"];
  if (format.missing()) format.fail("missing; this is not a Lacrima project");
  if (!format.isString() || format.string() != kFormat) {
    format.fail("expected \"" + std::string(kFormat) + "\", got " +
                (format.isString() ? "the string " : "") + format.describe());
  }
  const JsonValue version = root["version"];
  if (version.missing()) version.fail("missing");
  const double number = version.isNumber() ? version.number() : 0.0;
  if (number != std::floor(number) || number < 1.0)
    version.fail("expected a whole number >= 1, got " + version.describe());
  if (number > ProjectDocument::kSchemaVersion) {
    version.fail("written by a newer Lacrima (schema " + formatJsonNumber(number) +
                 "); this build reads up to " + std::to_string(ProjectDocument::kSchemaVersion));
  }
  return static_cast<int>(number);
}

double readFps(const JsonValue& value) {
  const double fps = value.isNumber() ? value.number() : std::nan("");
  if (!(fps > 0.0 && fps <= kMaxFps))
    value.fail("expected a number in (0, " + formatJsonNumber(kMaxFps) + "], got " +
               value.describe());
  return fps;
}

std::optional<Eigen::Vector3d> readSource(const JsonValue& value) {
  if (value.isNull()) return std::nullopt;
  if (!value.isArray() || value.size() != 3) {
    value.fail("expected null or an array of 3 finite numbers [x, y, z], got " + value.describe());
  }
  const std::vector<double> xyz = value.numbers(3);
  return Eigen::Vector3d(xyz[0], xyz[1], xyz[2]);
}

TearSources readTearSources(const JsonValue& value) {
  value.rejectUnknownMembers({"left", "right"});
  TearSources sources;
  if (value.has("left")) sources.left = readSource(value["left"]);
  if (value.has("right")) sources.right = readSource(value["right"]);
  return sources;
}

bool isWellFormedMethodKey(const std::string& key) {
  constexpr std::size_t kMaxKeyLength = 64;
  if (key.empty() || key.size() > kMaxKeyLength) return false;
  return std::all_of(key.begin(), key.end(), [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-' || c == '_';
  });
}

// A method's registry key: one of `known` when the reader was given the registry's keys, else
// any well-formed key.
std::string readMethodKey(const JsonValue& value, const std::vector<std::string>* known) {
  if (known) {
    const std::vector<std::string_view> keys(known->begin(), known->end());
    return (*known)[value.oneOf(keys)];
  }
  if (!value.isString() || !isWellFormedMethodKey(value.string()))
    value.fail("expected a method's key (lower-case letters, digits, - and _), got " +
               value.describe());
  return value.string();
}

// The quality level and the advanced choices (version 2).
TearQualitySettings readQuality(const JsonValue& scene, int version,
                                const TearMethodKeys* methods) {
  TearQualitySettings quality;
  for (const char* name : {"quality", "solver", "tension", "neighbours"})
    if (scene.has(name) && version < 2)
      scene[name].fail(std::string(name) + " needs a project of version 2 or later");
  if (scene.has("quality"))
    quality.level = static_cast<TearQuality>(scene["quality"].oneOf(kTearQualityNames));
  if (scene.has("solver"))
    quality.solver = readMethodKey(scene["solver"], methods ? &methods->solvers : nullptr);
  if (scene.has("tension"))
    quality.tension = readMethodKey(scene["tension"], methods ? &methods->tensions : nullptr);
  if (scene.has("neighbours"))
    quality.neighbours =
        readMethodKey(scene["neighbours"], methods ? &methods->neighbours : nullptr);
  return quality;
}

SceneSettings readScene(const JsonValue& value, int version, const TearMethodKeys* methods) {
  value.rejectUnknownMembers({"particles", "surface", "trails", "textureBlending", "redness",
                              "blush", "simulation", "quality", "solver", "tension", "neighbours"});
  SceneSettings scene;
  const auto flag = [&](const char* name, bool& target) {
    if (value.has(name)) target = value[name].boolean();
  };
  flag("particles", scene.particles);
  flag("surface", scene.surface);
  flag("trails", scene.trails);
  flag("textureBlending", scene.textureBlending);
  flag("blush", scene.blush);
  if (value.has("redness")) {
    scene.redness = value["redness"].oneOf({"animation", "tears"}) == 0
                        ? SceneSettings::Redness::Animation
                        : SceneSettings::Redness::Tears;
  }
  if (value.has("simulation")) scene.simulation = readTearParameters(value["simulation"]);
  scene.quality = readQuality(value, version, methods);
  return scene;
}

FaceColourCurves readColours(const JsonValue& value, int version) {
  if (version < 2) value.fail("colours need a project of version 2 or later");
  if (!value.isObject())
    value.fail("expected an object {\"redness\": [keys], \"blush\": [keys]}, got " +
               value.describe());
  value.rejectUnknownMembers({"redness", "blush"});
  FaceColourCurves colours;
  if (value.has("redness"))
    colours.redness = IntensityCurve(detail::readIntensityKeys(value["redness"], version, 0, 1));
  if (value.has("blush"))
    colours.blush = IntensityCurve(detail::readIntensityKeys(value["blush"], version, 0, 1));
  return colours;
}

MoodCurves readMoods(const JsonValue& value, int version) {
  if (version < 2) value.fail("moods need a project of version 2 or later");
  if (!value.isObject())
    value.fail("expected an object {\"sadness\": [keys], \"anger\": [keys], ...}, got " +
               value.describe());
  value.rejectUnknownMembers({"sadness", "anger", "joy", "shame"});
  MoodCurves moods;
  for (Mood mood : kMoods) {
    const std::string name(moodName(mood));
    if (value.has(name))
      moods[mood] = IntensityCurve(detail::readIntensityKeys(value[name], version, 0, 1));
  }
  return moods;
}

std::string readHeadPath(const JsonValue& value) {
  const std::string path = value.isString() ? value.string() : std::string();
  if (path.empty() || path.find('\0') != std::string::npos)
    value.fail("expected a file path (relative to the project's folder), got " + value.describe());
  return path;
}

HeadFiles readHead(const JsonValue& value) {
  if (!value.isObject())
    value.fail("expected an object {\"mesh\": path, \"fdp\": path}, got " + value.describe());
  value.rejectUnknownMembers({"mesh", "fdp"});
  HeadFiles head;
  head.mesh = readHeadPath(value.required("mesh"));
  head.fdp = readHeadPath(value.required("fdp"));
  return head;
}

}  // namespace

bool ProjectDocument::operator==(const ProjectDocument& other) const {
  return name == other.name && fps == other.fps &&
         defaultInterpolation == other.defaultInterpolation && keys.keys() == other.keys.keys() &&
         layers == other.layers && tearSources == other.tearSources && scene == other.scene &&
         head == other.head && colours == other.colours && moods == other.moods &&
         moodLayer == other.moodLayer;
}

namespace {

bool mixed(const PoseLayer& layer) { return !layer.muted && layer.hasIntensity(); }

}  // namespace

std::pair<double, double> ProjectDocument::bakeRange() const {
  double start = keys.empty() ? std::numeric_limits<double>::infinity() : keys.startTime();
  double end = keys.empty() ? -std::numeric_limits<double>::infinity() : keys.endTime();
  for (const PoseLayer& layer : layers) {
    if (!mixed(layer)) continue;
    start = std::min(start, layer.startTime());
    end = std::max(end, layer.endTime());
  }
  if (moodLayer && !moodLayer->muted) {
    start = std::min(start, moodLayer->start);
    end = std::max(end, moodLayer->end);
  }
  return {start, end};
}

FapAnimation ProjectDocument::bake(double rate) const {
  MoodLayerCache cache;
  return bake(rate, cache);
}

FapAnimation ProjectDocument::bake(double rate, MoodLayerCache& cache) const {
  const MoodLayerTake* mood = moodTake(cache);
  if (!mood && std::none_of(layers.begin(), layers.end(), mixed)) {
    FapAnimation animation = keys.bake(rate);
    animation.name = name;
    return animation;
  }
  const auto [start, end] = bakeRange();
  FapAnimation animation = keys.bake(rate, start, end);
  for (const PoseLayer& layer : layers) {
    if (mixed(layer)) animation.animated |= layer.channels();
  }
  if (mood) animation.animated |= mood->channels();
  for (std::size_t f = 0; f < animation.frames.size(); ++f) {
    const double t = start + static_cast<double>(f) / rate;
    animation.frames[f] = mixMoodLayer(mixLayers(animation.frames[f], layers, t), mood, t);
  }
  animation.name = name;
  return animation;
}

FapValues ProjectDocument::evaluate(double seconds, MoodLayerCache& cache) const {
  return mixMoodLayer(mixLayers(keys.evaluate(seconds), layers, seconds), moodTake(cache), seconds);
}

KeyedColours ProjectDocument::coloursAt(double seconds, MoodLayerCache& cache) const {
  return mixMoodColours(colours.at(seconds), moodTake(cache), seconds);
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
  detail::writeKeys(out, keys);
  out.key("tearSources");
  out.beginObject();
  writeSource(out, "left", tearSources.left);
  writeSource(out, "right", tearSources.right);
  out.endObject();
  out.key("scene");
  writeScene(out, scene);
  if (head) {
    out.key("head");
    writeHead(out, *head);
  }
  if (!layers.empty()) {
    out.key("layers");
    detail::writeLayers(out, layers);
  }
  if (!colours.empty()) {
    out.key("colours");
    out.beginObject();
    if (!colours.redness.empty()) {
      out.key("redness");
      detail::writeIntensityKeys(out, colours.redness.keys());
    }
    if (!colours.blush.empty()) {
      out.key("blush");
      detail::writeIntensityKeys(out, colours.blush.keys());
    }
    out.endObject();
  }
  if (!moods.empty()) {
    out.key("moods");
    out.beginObject();
    for (Mood mood : kMoods) {
      if (moods[mood].empty()) continue;
      out.key(std::string(moodName(mood)));
      detail::writeIntensityKeys(out, moods[mood].keys());
    }
    out.endObject();
  }
  if (moodLayer) {
    out.key("moodLayer");
    detail::writeMoodLayer(out, *moodLayer);
  }
  out.endObject();
  return std::move(out).finish();
}

namespace {

// Refuses, before anything is baked, a project whose animation would exceed kMaxBakedFrames
// at its own rate (a key at 16,000 s at 1,000 fps: 16 million frames, 4.5 GB), naming the
// latest key's time, which sets the length.
void requireBakeable(const JsonValue& root, const ProjectDocument& document) {
  const std::pair<double, double> range = document.bakeRange();
  const std::string problem = bakeLengthProblem(document.fps, range.first, range.second);
  if (problem.empty()) return;
  JsonValue latest = root["fps"];
  const auto consider = [&](const JsonValue& key) {
    const JsonValue time = key["time"];
    if (time.isNumber() && time.number() == range.second) latest = time;
  };
  constexpr std::size_t kRead = std::numeric_limits<std::size_t>::max();  // bounded when read
  for (const JsonValue& key : root["keys"].array(kRead)) consider(key);
  if (root.has("layers"))
    for (const JsonValue& layer : root["layers"].array(kRead))
      for (const JsonValue& key : layer["intensity"].array(kRead)) consider(key);
  if (root.has("moodLayer")) {
    const JsonValue end = root["moodLayer"]["end"];
    if (end.isNumber() && end.number() == range.second) latest = end;
  }
  latest.fail(problem);
}

}  // namespace

ProjectDocument ProjectDocument::read(const JsonValue& root, Use use,
                                      const TearMethodKeys* methods) {
  const int version = checkFormatAndVersion(root);
  root.rejectUnknownMembers({"format", "version", "name", "fps", "interpolation", "keys",
                             "tearSources", "scene", "head", "layers", "colours", "moods",
                             "moodLayer"});
  ProjectDocument document;
  if (root.has("name")) document.name = root["name"].string();
  if (root.has("fps")) document.fps = readFps(root["fps"]);
  if (root.has("interpolation"))
    document.defaultInterpolation = detail::readInterpolation(root["interpolation"], version);
  const JsonValue keys = root["keys"];
  if (keys.missing()) keys.fail("missing; every project lists its keys");
  document.keys = detail::readKeys(keys, document.defaultInterpolation, version);
  if (root.has("tearSources")) document.tearSources = readTearSources(root["tearSources"]);
  if (root.has("scene")) document.scene = readScene(root["scene"], version, methods);
  if (root.has("head")) document.head = readHead(root["head"]);
  if (root.has("layers")) {
    if (version < 2) root["layers"].fail("layers need a project of version 2 or later");
    document.layers = detail::readLayers(root["layers"], version);
  }
  if (root.has("colours")) document.colours = readColours(root["colours"], version);
  if (root.has("moods")) document.moods = readMoods(root["moods"], version);
  if (root.has("moodLayer")) document.moodLayer = detail::readMoodLayer(root["moodLayer"], version);
  if (use == Use::Bake) requireBakeable(root, document);
  return document;
}

ProjectDocument ProjectDocument::fromJson(std::string_view json, const std::string& displayName,
                                          Use use, const TearMethodKeys* methods) {
  return read(JsonInput::parse(json, displayName).root(), use, methods);
}

ProjectDocument ProjectDocument::load(const std::string& path, Use use,
                                      const TearMethodKeys* methods) {
  ProjectDocument document = read(
      JsonInput::load(path, {"project file", ProjectDocument::kMaxFileBytes}).root(), use, methods);
  document.resolveHeadPaths(fs::path(path).parent_path().string());
  return document;
}

void ProjectDocument::save(const std::string& path) const {
  if (!head) {
    saveAtomically(path, toJson());
    return;
  }
  ProjectDocument written = *this;
  written.relativizeHeadPaths(fs::path(path).parent_path().string());
  saveAtomically(path, written.toJson());
}

void ProjectDocument::resolveHeadPaths(const std::string& folder) {
  if (!head) return;
  head->mesh = absoluteIn(head->mesh, folder);
  head->fdp = absoluteIn(head->fdp, folder);
}

void ProjectDocument::relativizeHeadPaths(const std::string& folder) {
  if (!head) return;
  head->mesh = relativeTo(head->mesh, folder);
  head->fdp = relativeTo(head->fdp, folder);
}

std::optional<Diagnostic> ProjectDocument::missingHeadFile(const std::string& projectPath) const {
  if (!head) return std::nullopt;
  const std::pair<const char*, const std::string*> files[] = {{"head.mesh", &head->mesh},
                                                              {"head.fdp", &head->fdp}};
  for (const auto& [field, file] : files) {
    std::error_code error;
    if (fs::is_regular_file(*file, error)) continue;
    const bool elsewhere = fs::exists(*file, error);
    Diagnostic problem;
    problem.where.file = projectPath;
    problem.message = std::string(field) + ": " + (elsewhere ? "not a file: " : "no file at ") +
                      *file +
                      "; restore it there, or point the project at the head's files again "
                      "(editor: File > Choose head...)";
    return problem;
  }
  return std::nullopt;
}

ProjectDocument ProjectDocument::fromAnimation(const FapAnimation& animation) {
  ProjectDocument document;
  document.name = animation.name;
  document.fps = animation.fps;
  document.keys = KeyframeSequence::fromAnimation(animation, Interpolation::Linear);
  return document;
}

}  // namespace lacrima::inline common
