#include <lacrima/rigging/FeaturePointFile.h>

#include "FeaturePointFileSnap.h"

#include <lacrima/common/FapTable.h>
#include <lacrima/common/JsonInput.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <limits>
#include <set>

namespace lacrima::rigging {
namespace {

// {group, index} of a well-formed id, or nullopt.
std::optional<std::pair<int, int>> parseId(std::string_view id) {
  const auto dot = id.find('.');
  if (dot == std::string_view::npos || dot == 0 || dot + 1 == id.size()) return std::nullopt;
  int group = 0, index = 0;
  const char* begin = id.data();
  auto [g, ge] = std::from_chars(begin, begin + dot, group);
  auto [i, ie] = std::from_chars(begin + dot + 1, begin + id.size(), index);
  if (ge != std::errc() || g != begin + dot || ie != std::errc() || i != begin + id.size())
    return std::nullopt;
  return std::pair{group, index};
}

// A feature-point file names a few hundred points; anything this large is not one.
constexpr qint64 kMaxFileBytes = qint64{16} << 20;
constexpr std::size_t kMaxNames = 1000;  // sub-meshes in one role
constexpr int kMaxIndex = std::numeric_limits<int>::max();

// One FileError for all the problems of a document, so that a user sees all of them at once:
// the first is the error's own, the others follow on lines of their own.
[[noreturn]] void throwAll(const std::vector<Diagnostic>& problems) {
  std::string message = problems.front().message;
  for (std::size_t k = 1; k < problems.size(); ++k) message += "\n  " + problems[k].toString();
  throw FileError(problems.front().where, message);
}

// Collects the problems of one document instead of stopping at the first.
class Reader {
 public:
  explicit Reader(Warnings* warnings) : warnings_(warnings) {}

  void error(const JsonValue& at, const std::string& what) { errors_.push_back(at.problem(what)); }
  void warn(const JsonValue& at, const std::string& what) {
    if (warnings_) warnings_->push_back(at.problem(what));
  }
  void throwIfErrors() const {
    if (!errors_.empty()) throwAll(errors_);
  }

  // What `read` returns, or nullopt with its error kept.
  template <class Read>
  auto attempt(Read read) -> std::optional<decltype(read())> {
    try {
      return read();
    } catch (const FileError& e) {
      errors_.push_back({e.where(), e.message()});
      return std::nullopt;
    }
  }

  // Warns about the members of `object` not in `known`; a non-object has none.
  void allowKeys(const JsonValue& object, const std::vector<std::string_view>& known) {
    if (!object.isObject()) return;
    for (const JsonValue& member : object.members())
      if (std::find(known.begin(), known.end(), member.name()) == known.end())
        warn(member, "unknown key, ignored");
  }

  std::optional<int> index(const JsonValue& value) {
    return attempt([&] { return value.integer(0, kMaxIndex); });
  }

  std::optional<Eigen::Vector3d> vector3(const JsonValue& value) {
    if (!value.isArray() || value.size() != 3) {
      error(value, "expected an array of three numbers [x, y, z], got " + value.describe());
      return std::nullopt;
    }
    const auto xyz = attempt([&] { return value.numbers(3); });
    if (!xyz) return std::nullopt;
    return Eigen::Vector3d((*xyz)[0], (*xyz)[1], (*xyz)[2]);
  }

  std::vector<std::string> names(const JsonValue& value) {
    std::vector<std::string> out;
    if (!value.isArray()) {
      error(value, "expected an array of sub-mesh names, got " + value.describe());
      return out;
    }
    const auto elements = attempt([&] { return value.array(kMaxNames); });
    if (!elements) return out;
    for (const JsonValue& name : *elements) {
      if (!name.isString() || name.string().empty())
        error(name, "expected a non-empty sub-mesh name (a string), got " + name.describe());
      else
        out.push_back(name.string());
    }
    return out;
  }

  std::optional<GeodesicMethod> method(const JsonValue& value) {
    const auto choice = attempt([&] { return value.oneOf({"dijkstra", "heat"}); });
    if (!choice) return std::nullopt;
    return *choice == 0 ? GeodesicMethod::Dijkstra : GeodesicMethod::Heat;
  }

  std::optional<SurfacePoint> surfacePoint(const JsonValue& value,
                                           std::initializer_list<std::string_view> extraKeys = {}) {
    if (!value.isObject()) {
      error(value,
            "expected an object with \"submesh\" and \"vertex\" (or \"triangle\" and "
            "\"barycentric\")");
      return std::nullopt;
    }
    std::vector<std::string_view> known{"submesh", "vertex", "triangle", "barycentric", "position"};
    known.insert(known.end(), extraKeys.begin(), extraKeys.end());
    allowKeys(value, known);
    SurfacePoint p;
    bool good = true;
    const JsonValue submesh = value["submesh"];
    if (!submesh.isString() || submesh.string().empty()) {
      error(submesh, "expected a sub-mesh name (string), got " + submesh.describe());
      good = false;
    } else {
      p.submesh = submesh.string();
    }
    if (value.has("position")) {
      p.position = vector3(value["position"]);
      good = good && p.position.has_value();
    }
    const bool hasVertex = value.has("vertex"), hasTriangle = value.has("triangle");
    if (hasVertex == hasTriangle) {
      error(value, "expected exactly one of \"vertex\" or \"triangle\"");
      return std::nullopt;
    }
    if (hasVertex) {
      if (value.has("barycentric")) warn(value["barycentric"], "ignored for a vertex point");
      const auto v = index(value["vertex"]);
      if (!v) return std::nullopt;
      p.vertex = *v;
    } else {
      const auto t = index(value["triangle"]);
      const auto b = vector3(value["barycentric"]);
      if (!t || !b) return std::nullopt;
      p.triangle = *t;
      p.barycentric = *b;
      if (b->minCoeff() < 0.0 || b->maxCoeff() > 1.0 || std::abs(b->sum() - 1.0) > 1e-4) {
        error(value["barycentric"], "expected three weights in [0, 1] summing to 1");
        good = false;
      }
    }
    return good ? std::optional(p) : std::nullopt;
  }

 private:
  Warnings* warnings_;
  std::vector<Diagnostic> errors_;
};

// Checks what the file names against the mesh, collecting every problem.
class Validator {
 public:
  Validator(const FeaturePointFile& file, const HeadMesh& mesh)
      : source_{file.text, file.path}, mesh_(mesh) {}

  void error(const JsonPath& at, const std::string& what) {
    errors_.push_back(source_.problem(at, what));
  }
  void error(Diagnostic problem) { errors_.push_back(std::move(problem)); }
  Diagnostic note(const JsonPath& at, const std::string& what) const {
    return source_.problem(at, what);
  }
  const std::vector<Diagnostic>& errors() const { return errors_; }
  void throwIfErrors() const {
    if (!errors_.empty()) throwAll(errors_);
  }

  std::string unknownSubmesh(const std::string& name) const {
    std::string known;
    for (const HeadSubmesh& each : mesh_.submeshes)
      known += (known.empty() ? "" : ", ") + each.name;
    return "unknown sub-mesh \"" + name + "\" (the head has: " + known + ")";
  }

  const HeadSubmesh* submesh(const std::string& name, const JsonPath& at) {
    const HeadSubmesh* s = mesh_.findSubmesh(name);
    if (!s) error(at, unknownSubmesh(name));
    return s;
  }

  // Whether a point's indices lead anywhere on the mesh, and if not, what is wrong (at `where`).
  struct Binding {
    const HeadSubmesh* submesh = nullptr;  // nullptr: no such sub-mesh
    std::optional<Diagnostic> problem;     // unknown sub-mesh, index out of range, no area
  };
  Binding bind(const SurfacePoint& p, const JsonPath& at) const {
    Binding b;
    b.submesh = mesh_.findSubmesh(p.submesh);
    if (!b.submesh) {
      b.problem = note(at / "submesh", unknownSubmesh(p.submesh));
      return b;
    }
    const HeadSubmesh& s = *b.submesh;
    if (p.vertex >= 0) {
      if (p.vertex >= s.vertexCount)
        b.problem = note(at / "vertex",
                         "index " + std::to_string(p.vertex) + " out of range; sub-mesh \"" +
                             p.submesh + "\" has vertices 0.." + std::to_string(s.vertexCount - 1));
      return b;
    }
    if (p.triangle >= static_cast<int>(s.triangles.size())) {
      b.problem = note(at / "triangle",
                       "index " + std::to_string(p.triangle) + " out of range; sub-mesh \"" +
                           p.submesh + "\" has triangles 0.." +
                           std::to_string(static_cast<int>(s.triangles.size()) - 1));
      return b;
    }
    const Eigen::Vector3i t = s.triangles[static_cast<std::size_t>(p.triangle)];
    const Eigen::Vector3d a = mesh_.positions.col(t[0]).cast<double>();
    const Eigen::Vector3d b2 = mesh_.positions.col(t[1]).cast<double>();
    const Eigen::Vector3d c = mesh_.positions.col(t[2]).cast<double>();
    const double area2 = (b2 - a).cross(c - a).norm();
    const double scale = (b2 - a).squaredNorm() + (c - a).squaredNorm() + (c - b2).squaredNorm();
    if (!(area2 > 1e-8 * scale))
      b.problem =
          note(at / "triangle", "triangle " + std::to_string(p.triangle) + " of \"" + p.submesh +
                                    "\" is degenerate (no area); bind the point to a "
                                    "vertex or another triangle");
    return b;
  }

 private:
  JsonSource source_;
  const HeadMesh& mesh_;
  std::vector<Diagnostic> errors_;
};

std::string number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", value);
  return text;
}

std::string vectorText(const Eigen::Vector3d& v) {
  std::string text = "[";  // appended piece by piece: GCC 12 warns (-Wrestrict) about "[" + ...
  text += number(v.x());
  text += ", ";
  text += number(v.y());
  text += ", ";
  text += number(v.z());
  text += "]";
  return text;
}

// "vertex 812 of \"skin\"" or "triangle 97 of \"skin\"".
std::string bindingText(const SurfacePoint& p) {
  return (p.vertex >= 0 ? "vertex " + std::to_string(p.vertex)
                        : "triangle " + std::to_string(p.triangle)) +
         " of \"" + p.submesh + "\"";
}

// "head.glb (12345 vertices; sub-meshes skin 9000, eye_l 300, ...)", "this mesh (...)" unnamed.
std::string meshText(const HeadMesh& mesh, std::string_view name) {
  std::string text = name.empty() ? "this mesh" : std::string(name);
  text += " (" + std::to_string(mesh.vertexCount()) + " vertices; sub-meshes";
  constexpr std::size_t kListed = 6;
  for (std::size_t k = 0; k < mesh.submeshes.size() && k < kListed; ++k)
    text += (k ? ", " : " ") + mesh.submeshes[k].name + " " +
            std::to_string(mesh.submeshes[k].vertexCount);
  if (mesh.submeshes.size() > kListed)
    text += " and " + std::to_string(mesh.submeshes.size() - kListed) + " more";
  if (mesh.submeshes.empty()) text += ": none";
  return text + ")";
}

// A problem of the whole file, with no line (built member by member: GCC 12 warns about an
// aggregate initialiser here).
Diagnostic fileProblem(const std::string& file, std::string message) {
  Diagnostic d;
  d.where.file = file;
  d.message = std::move(message);
  return d;
}

// One surface point of the file (a feature point or a tear source) as validation sees it.
struct SurfaceEntry {
  JsonPath at;
  std::string name;  // "feature point 2.1", "tear source left"
  SurfacePoint* point;
};

}  // namespace

bool FdpIdLess::operator()(std::string_view a, std::string_view b) const {
  const auto pa = parseId(a), pb = parseId(b);
  if (pa && pb) return *pa < *pb;
  if (pa != pb) return pa.has_value();  // well-formed ids first
  return a < b;
}

std::string_view toString(GeodesicMethod method) {
  return method == GeodesicMethod::Heat ? "heat" : "dijkstra";
}

const std::vector<std::string>& fapuFeaturePoints() {
  static const std::vector<std::string> ids{"2.2", "3.1", "3.2", "3.3", "3.4",
                                            "3.5", "3.6", "8.3", "8.4", "9.15"};
  return ids;
}

const std::vector<std::string>& animatedFeaturePoints() {
  static const std::vector<std::string> ids = [] {
    std::set<std::string, FdpIdLess> set;
    for (int fap = 3; fap <= 68; ++fap) {
      std::string_view fp = fapInfo(fap).featurePoint;
      while (!fp.empty()) {  // "6.3;6.4" names two
        const auto semi = fp.find(';');
        set.emplace(fp.substr(0, semi));
        fp = semi == std::string_view::npos ? std::string_view{} : fp.substr(semi + 1);
      }
    }
    set.erase("7.1");  // the neck pivot is a position of its own, not a surface point
    return std::vector<std::string>(set.begin(), set.end());
  }();
  return ids;
}

FeaturePointFile readFeaturePointFile(const std::string& path, Warnings* warnings) {
  const JsonInput input = JsonInput::load(path, {"feature-point file", kMaxFileBytes});
  const JsonValue root = input.root();
  Reader r(warnings);
  r.allowKeys(root, {"format", "version", "mesh", "submeshes", "defaults", "points", "eyes",
                     "neck_pivot", "tear_sources"});
  const JsonValue format = root["format"];
  if (!format.isString() || format.string() != "lacrima-fdp")
    format.fail("expected \"lacrima-fdp\" (is this a Lacrima feature-point file?), got " +
                format.describe());
  FeaturePointFile out;
  out.path = path;
  out.text = input.source().text;
  const auto version = r.index(root["version"]);
  r.throwIfErrors();
  if (*version < 1 || *version > kFeaturePointFileVersion)
    root["version"].fail("expected 1 to " + std::to_string(kFeaturePointFileVersion) + ", got " +
                         std::to_string(*version) + " (a newer Lacrima wrote it?)");
  out.version = *version;
  if (root.has("mesh")) {
    if (!root["mesh"].isString())
      r.error(root["mesh"], "expected a string, got " + root["mesh"].describe());
    else
      out.meshNote = root["mesh"].string();
  }

  const JsonValue roles = root["submeshes"];
  if (!roles.isObject()) {
    r.error(roles,
            "expected an object with at least \"skin\": [sub-mesh names], got " + roles.describe());
  } else {
    r.allowKeys(roles, {"skin", "eye_left", "eye_right", "jaw", "tongue", "attached", "ignored"});
    out.skin = r.names(roles["skin"]);
    if (roles["skin"].isArray() && out.skin.empty())
      r.error(roles["skin"], "expected at least one sub-mesh");
    for (auto [role, names] :
         {std::pair{"eye_left", &out.eyeLeft.submeshes},
          std::pair{"eye_right", &out.eyeRight.submeshes}, std::pair{"jaw", &out.jaw},
          std::pair{"tongue", &out.tongue}, std::pair{"attached", &out.attached},
          std::pair{"ignored", &out.ignored}})
      if (roles.has(role)) *names = r.names(roles[role]);
  }

  if (root.has("defaults")) {
    const JsonValue defaults = root["defaults"];
    r.allowKeys(defaults, {"geodesics"});
    if (defaults.has("geodesics"))
      if (auto m = r.method(defaults["geodesics"])) out.geodesics = *m;
  }

  const JsonValue points = root["points"];
  if (!points.isObject()) {
    r.error(points, "expected an object of feature points by FDP id, e.g. \"2.1\": {...}, got " +
                        points.describe());
  } else {
    for (const JsonValue& point : points.members()) {
      const std::string id = point.name();
      const auto parsed = parseId(id);
      if (!parsed || parsed->first < 2 || parsed->first > 11) {
        r.error(point, "expected an FDP id \"group.index\" with group 2 to 11");
        continue;
      }
      auto at = r.surfacePoint(point, {"radius", "geodesics", "placed"});
      if (!at) continue;
      FeaturePointSpec spec{*at, std::nullopt, std::nullopt, true};  // "placed" defaults to hand
      if (point.has("radius")) {
        const JsonValue radius = point["radius"];
        if (!radius.isNumber() || !(radius.number() > 0.0))
          r.error(radius, "expected a positive number (model units), got " + radius.describe());
        else
          spec.radius = radius.number();
      }
      if (point.has("geodesics")) spec.geodesics = r.method(point["geodesics"]);
      if (point.has("placed")) {
        const JsonValue placed = point["placed"];
        if (placed.isString() && (placed.string() == "hand" || placed.string() == "proposed"))
          spec.placedByHand = placed.string() == "hand";
        else
          r.error(placed, "expected \"hand\" or \"proposed\", got " + placed.describe());
      }
      out.points.emplace(id, spec);
    }
  }

  if (root.has("eyes")) {
    const JsonValue eyes = root["eyes"];
    r.allowKeys(eyes, {"left", "right"});
    for (auto [side, spec] : {std::pair{"left", &out.eyeLeft}, std::pair{"right", &out.eyeRight}}) {
      if (!eyes.has(side)) continue;
      const JsonValue eye = eyes[side];
      r.allowKeys(eye, {"centre"});
      if (eye.has("centre")) spec->centre = r.vector3(eye["centre"]);
    }
  }
  if (root.has("neck_pivot")) out.neckPivot = r.vector3(root["neck_pivot"]);
  if (root.has("tear_sources")) {
    const JsonValue tears = root["tear_sources"];
    r.allowKeys(tears, {"left", "right"});
    if (tears.has("left")) out.tearLeft = r.surfacePoint(tears["left"]);
    if (tears.has("right")) out.tearRight = r.surfacePoint(tears["right"]);
  }
  r.throwIfErrors();
  return out;
}

FeaturePointFile validateFeaturePoints(const FeaturePointFile& input, const HeadMesh& mesh,
                                       Warnings* warnings, FeaturePointSet set,
                                       std::string_view meshName) {
  FeaturePointFile file = input;
  Validator v(file, mesh);
  const JsonPath roles = JsonPath() / "submeshes";
  std::map<std::string, std::string> roleOf;  // sub-mesh -> role, to catch a name in two roles
  auto checkRole = [&](const std::vector<std::string>& names, const std::string& role) {
    for (std::size_t i = 0; i < names.size(); ++i) {
      const JsonPath at = roles / role / static_cast<int>(i);
      v.submesh(names[i], at);
      const auto [it, fresh] = roleOf.emplace(names[i], role);
      if (!fresh)
        v.error(at, "sub-mesh \"" + names[i] + "\" already has role \"" + it->second + "\"");
    }
  };
  checkRole(file.skin, "skin");
  checkRole(file.eyeLeft.submeshes, "eye_left");
  checkRole(file.eyeRight.submeshes, "eye_right");
  checkRole(file.jaw, "jaw");
  checkRole(file.tongue, "tongue");
  checkRole(file.attached, "attached");
  checkRole(file.ignored, "ignored");

  const JsonPath points = JsonPath() / "points";
  std::vector<SurfaceEntry> entries;
  for (auto& [id, spec] : file.points) entries.push_back({points / id, "point " + id, &spec.at});
  for (auto [side, tear] : {std::pair{"left", &file.tearLeft}, std::pair{"right", &file.tearRight}})
    if (*tear)
      entries.push_back(
          {JsonPath() / "tear_sources" / side, std::string("tear source ") + side, &**tear});

  // Indices first; a point with a stored position that its index does not lead to (or cannot:
  // out of range, no area) is re-snapped below instead of refused.
  const detail::PositionTolerances tolerance = detail::positionTolerances(file, mesh);
  std::vector<Diagnostic> misfits;  // points that do not fit and cannot be re-snapped
  std::map<const HeadSubmesh*, std::vector<std::size_t>> toSnap;  // entries by sub-mesh
  std::map<std::size_t, std::optional<Eigen::Vector3d>> boundBefore;
  int positioned = 0;
  for (std::size_t k = 0; k < entries.size(); ++k) {
    const SurfacePoint& p = *entries[k].point;
    const Validator::Binding b = v.bind(p, entries[k].at);
    if (!b.submesh || (b.problem && !p.position)) {
      misfits.push_back(*b.problem);
      continue;
    }
    if (!p.position) continue;
    ++positioned;
    std::optional<Eigen::Vector3d> bound;
    if (!b.problem) bound = surfacePosition(p, mesh);
    if (bound && (*bound - *p.position).norm() <= tolerance.match) continue;
    toSnap[b.submesh].push_back(k);
    boundBefore[k] = bound;
  }

  std::vector<Diagnostic> lost;         // re-snapped, but nothing of the sub-mesh is near
  std::vector<Diagnostic> unsnappable;  // nothing to re-snap to at all
  Warnings snapped;
  for (const auto& [submesh, which] : toSnap) {
    std::vector<const SurfacePoint*> queries;
    for (std::size_t k : which) queries.push_back(entries[k].point);
    const std::vector<detail::Snap> snaps = detail::snapToSubmesh(mesh, *submesh, queries);
    for (std::size_t q = 0; q < which.size(); ++q) {
      const SurfaceEntry& entry = entries[which[q]];
      const detail::Snap& snap = snaps[q];
      const std::optional<Eigen::Vector3d>& before = boundBefore[which[q]];
      const std::string was = entry.name + " (" + bindingText(*entry.point) + ", stored at " +
                              vectorText(*entry.point->position) + ")" +
                              (before ? " is " + number((*before - *entry.point->position).norm()) +
                                            " from its stored position"
                                      : " has no place on this mesh");
      if (!std::isfinite(snap.residual)) {
        unsnappable.push_back(
            v.note(entry.at / "position", was + "; nothing to snap it to (\"" + submesh->name +
                                              "\" has no vertex or triangle with area, or the "
                                              "position is beyond the range of a float)"));
        continue;
      }
      const std::string far = " (more than the " + number(tolerance.lost) +
                              " a re-exported mesh allows; check this point)";
      if (snap.residual > tolerance.lost)
        lost.push_back(v.note(entry.at / "position", was + "; the nearest of \"" + submesh->name +
                                                         "\" is " + number(snap.residual) +
                                                         " away" + far));
      const std::string moved =
          before ? ", moved " + number((*snap.point.position - *before).norm()) : std::string();
      snapped.push_back(v.note(entry.at / "position",
                               was + ": re-snapped to " + bindingText(snap.point) + moved + ", " +
                                   number(snap.residual) + " from the stored position" +
                                   (snap.residual > tolerance.lost ? far : std::string())));
      *entry.point = snap.point;
    }
  }

  // Most points not fitting is another mesh, not a few misplaced points: say so first.
  const bool mostLost =
      2 * (lost.size() + unsnappable.size()) > static_cast<std::size_t>(positioned);
  const bool mostMisfit = 2 * misfits.size() > entries.size();
  if (mostLost || mostMisfit) {
    std::vector<Diagnostic> mismatches = lost;
    mismatches.insert(mismatches.end(), unsnappable.begin(), unsnappable.end());
    mismatches.insert(mismatches.end(), misfits.begin(), misfits.end());
    std::string summary =
        "this feature-point file was placed on another mesh: " + std::to_string(mismatches.size()) +
        " of " + std::to_string(entries.size()) + " points do not fit " + meshText(mesh, meshName);
    if (!file.meshNote.empty()) summary += "; the file says it is for \"" + file.meshNote + "\"";
    constexpr std::size_t kShown = 5;
    std::vector<Diagnostic> report{fileProblem(file.path, summary + ". First mismatches:")};
    for (std::size_t k = 0; k < mismatches.size() && k < kShown; ++k)
      report.push_back(mismatches[k]);
    if (mismatches.size() > kShown)
      report.push_back(
          fileProblem(file.path, "and " + std::to_string(mismatches.size() - kShown) + " more"));
    throwAll(report);
  }
  for (Diagnostic& d : misfits) v.error(std::move(d));
  for (Diagnostic& d : unsnappable) v.error(std::move(d));
  if (warnings) warnings->insert(warnings->end(), snapped.begin(), snapped.end());

  if (set == FeaturePointSet::Partial) {
    v.throwIfErrors();
    return file;
  }
  for (const std::string& id : fapuFeaturePoints())
    if (!file.points.count(id))
      v.error(points, "missing required feature point " + id + " (it defines a FAPU: expected \"" +
                          id + "\": {\"submesh\": ..., \"vertex\": ...})");
  v.throwIfErrors();
  if (!warnings) return file;
  for (const std::string& id : animatedFeaturePoints()) {
    if (file.points.count(id)) continue;
    std::string faps;
    for (int fap = 3; fap <= 68; ++fap)
      if (fapInfo(fap).featurePoint.find(id) != std::string_view::npos &&
          fapInfo(fap).featurePoint.size() >= id.size()) {
        // match whole ids only: "2.1" must not match "2.10"
        std::string_view list = fapInfo(fap).featurePoint;
        bool whole = false;
        for (std::size_t pos = 0; pos <= list.size();) {
          const auto semi = list.find(';', pos);
          whole = whole || list.substr(pos, semi - pos) == id;
          if (semi == std::string_view::npos) break;
          pos = semi + 1;
        }
        if (whole) faps += (faps.empty() ? "" : ", ") + std::to_string(fap);
      }
    warnings->push_back(
        v.note(points, "no feature point " + id + "; FAP " + faps + " will have no pose"));
  }
  if (file.eyeLeft.submeshes.empty())
    warnings->push_back(
        v.note(roles / "eye_left", "none given; FAPs 23, 25, 27 and 29 will not move an eye"));
  if (file.eyeRight.submeshes.empty())
    warnings->push_back(
        v.note(roles / "eye_right", "none given; FAPs 24, 26, 28 and 30 will not move an eye"));
  if (!file.neckPivot)
    warnings->push_back(v.note(JsonPath() / "neck_pivot",
                               "not given; using the centre of the skin's lowest open boundary"));
  return file;
}

std::vector<int> surfaceVertices(const SurfacePoint& point, const HeadMesh& mesh) {
  const HeadSubmesh& s = *mesh.findSubmesh(point.submesh);
  if (point.vertex >= 0) return {s.firstVertex + point.vertex};
  const Eigen::Vector3i t = s.triangles[static_cast<std::size_t>(point.triangle)];
  return {t[0], t[1], t[2]};
}

void dropIgnoredParts(HeadMesh& mesh, const FeaturePointFile& file) {
  for (HeadSubmesh& s : mesh.submeshes)
    if (std::find(file.ignored.begin(), file.ignored.end(), s.name) != file.ignored.end())
      s.triangles.clear();
}

Eigen::Vector3d surfacePosition(const SurfacePoint& point, const HeadMesh& mesh) {
  const std::vector<int> v = surfaceVertices(point, mesh);
  if (v.size() == 1) return mesh.positions.col(v[0]).cast<double>();
  Eigen::Vector3d p = Eigen::Vector3d::Zero();
  for (int k = 0; k < 3; ++k)
    p += point.barycentric[k] * mesh.positions.col(v[static_cast<std::size_t>(k)]).cast<double>();
  return p;
}

}  // namespace lacrima::rigging
