#include <lacrima/rigging/FeaturePointFile.h>
#include <lacrima/common/JsonSyntaxError.h>

#include <lacrima/common/FapTable.h>

#include <QFile>
#include <Eigen/Geometry>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <charconv>
#include <cmath>
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

// Built field by field: GCC 12 warns (falsely) about brace-initialised SourceLocation strings.
Diagnostic fileNote(const std::string& file, std::string message) {
  Diagnostic d;
  d.where.file = file;
  d.message = std::move(message);
  return d;
}

std::string quotedId(std::string_view id) {
  std::string out;
  out.reserve(id.size() + 2);
  out.append(1, '"').append(id).append(1, '"');
  return out;
}

// Collects the problems of one document so a user sees all of them at once.
class Reader {
public:
  Reader(std::string path, Warnings* warnings) : path_(std::move(path)), warnings_(warnings) {}

  void error(const std::string& where, const std::string& what) { errors_.push_back(where + ": " + what); }
  void warn(const std::string& where, const std::string& what) {
    if (warnings_) warnings_->push_back(fileNote(path_, where + ": " + what));
  }
  void throwIfErrors() const {
    if (errors_.empty()) return;
    std::string message = errors_.front();
    for (std::size_t k = 1; k < errors_.size(); ++k) message += "\n  " + errors_[k];
    throw FileError({path_, 0, 0}, message);
  }

  void allowKeys(const QJsonObject& object, const std::string& where,
                 std::initializer_list<const char*> known) {
    for (const QString& key : object.keys()) {
      bool ok = false;
      for (const char* k : known) ok = ok || key == QLatin1String(k);
      if (!ok) warn(where + "." + key.toStdString(), "unknown key, ignored");
    }
  }

  std::optional<int> index(const QJsonValue& value, const std::string& where) {
    const double d = value.toDouble(-1.0);
    if (!value.isDouble() || d < 0 || d != std::floor(d) || d > 2147483647.0) {
      error(where, "expected a non-negative whole number");
      return std::nullopt;
    }
    return static_cast<int>(d);
  }

  std::optional<Eigen::Vector3d> vector3(const QJsonValue& value, const std::string& where) {
    const QJsonArray a = value.toArray();
    if (!value.isArray() || a.size() != 3 || !a[0].isDouble() || !a[1].isDouble() || !a[2].isDouble()) {
      error(where, "expected an array of three numbers [x, y, z]");
      return std::nullopt;
    }
    return Eigen::Vector3d(a[0].toDouble(), a[1].toDouble(), a[2].toDouble());
  }

  std::vector<std::string> names(const QJsonValue& value, const std::string& where) {
    std::vector<std::string> out;
    if (!value.isArray()) {
      error(where, "expected an array of sub-mesh names");
      return out;
    }
    for (const QJsonValue& v : value.toArray()) {
      if (!v.isString() || v.toString().isEmpty()) error(where, "expected non-empty sub-mesh names (strings)");
      else out.push_back(v.toString().toStdString());
    }
    return out;
  }

  std::optional<GeodesicMethod> method(const QJsonValue& value, const std::string& where) {
    if (value == QJsonValue("dijkstra")) return GeodesicMethod::Dijkstra;
    if (value == QJsonValue("heat")) return GeodesicMethod::Heat;
    error(where, "expected \"dijkstra\" or \"heat\"");
    return std::nullopt;
  }

  std::optional<SurfacePoint> surfacePoint(const QJsonValue& value, const std::string& where,
                                           std::initializer_list<const char*> extraKeys = {}) {
    if (!value.isObject()) {
      error(where, "expected an object with \"submesh\" and \"vertex\" (or \"triangle\" and \"barycentric\")");
      return std::nullopt;
    }
    const QJsonObject o = value.toObject();
    std::vector<const char*> known{"submesh", "vertex", "triangle", "barycentric"};
    known.insert(known.end(), extraKeys.begin(), extraKeys.end());
    for (const QString& key : o.keys()) {
      bool ok = false;
      for (const char* k : known) ok = ok || key == QLatin1String(k);
      if (!ok) warn(where + "." + key.toStdString(), "unknown key, ignored");
    }
    SurfacePoint p;
    bool good = true;
    if (!o.value("submesh").isString() || o.value("submesh").toString().isEmpty()) {
      error(where + ".submesh", "expected a sub-mesh name (string)");
      good = false;
    } else {
      p.submesh = o.value("submesh").toString().toStdString();
    }
    const bool hasVertex = o.contains("vertex"), hasTriangle = o.contains("triangle");
    if (hasVertex == hasTriangle) {
      error(where, "expected exactly one of \"vertex\" or \"triangle\"");
      return std::nullopt;
    }
    if (hasVertex) {
      if (o.contains("barycentric")) warn(where + ".barycentric", "ignored for a vertex point");
      const auto v = index(o.value("vertex"), where + ".vertex");
      if (!v) return std::nullopt;
      p.vertex = *v;
    } else {
      const auto t = index(o.value("triangle"), where + ".triangle");
      const auto b = vector3(o.value("barycentric"), where + ".barycentric");
      if (!t || !b) return std::nullopt;
      p.triangle = *t;
      p.barycentric = *b;
      if (!b->allFinite() || b->minCoeff() < 0.0 || b->maxCoeff() > 1.0 || std::abs(b->sum() - 1.0) > 1e-4) {
        error(where + ".barycentric", "expected three weights in [0, 1] summing to 1");
        good = false;
      }
    }
    return good ? std::optional(p) : std::nullopt;
  }

private:
  std::string path_;
  Warnings* warnings_;
  std::vector<std::string> errors_;
};

const HeadSubmesh* findAndCheck(const HeadMesh& mesh, const std::string& name, const std::string& where,
                                std::vector<std::string>& errors) {
  const HeadSubmesh* s = mesh.findSubmesh(name);
  if (!s) {
    std::string known;
    for (const HeadSubmesh& each : mesh.submeshes) known += (known.empty() ? "" : ", ") + each.name;
    errors.push_back(where + ": unknown sub-mesh \"" + name + "\" (the head has: " + known + ")");
  }
  return s;
}

void checkPoint(const SurfacePoint& p, const HeadMesh& mesh, const std::string& where,
                std::vector<std::string>& errors) {
  const HeadSubmesh* s = findAndCheck(mesh, p.submesh, where + ".submesh", errors);
  if (!s) return;
  if (p.vertex >= 0) {
    if (p.vertex >= s->vertexCount)
      errors.push_back(where + ".vertex: index " + std::to_string(p.vertex) + " out of range; sub-mesh \"" +
                       p.submesh + "\" has vertices 0.." + std::to_string(s->vertexCount - 1));
    return;
  }
  if (p.triangle >= static_cast<int>(s->triangles.size())) {
    errors.push_back(where + ".triangle: index " + std::to_string(p.triangle) + " out of range; sub-mesh \"" +
                     p.submesh + "\" has triangles 0.." + std::to_string(static_cast<int>(s->triangles.size()) - 1));
    return;
  }
  const Eigen::Vector3i t = s->triangles[static_cast<std::size_t>(p.triangle)];
  const Eigen::Vector3d a = mesh.positions.col(t[0]).cast<double>();
  const Eigen::Vector3d b = mesh.positions.col(t[1]).cast<double>();
  const Eigen::Vector3d c = mesh.positions.col(t[2]).cast<double>();
  const double area2 = (b - a).cross(c - a).norm();
  const double scale = (b - a).squaredNorm() + (c - a).squaredNorm() + (c - b).squaredNorm();
  if (!(area2 > 1e-8 * scale))
    errors.push_back(where + ".triangle: triangle " + std::to_string(p.triangle) + " of \"" + p.submesh +
                     "\" is degenerate (no area); bind the point to a vertex or another triangle");
}

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
  static const std::vector<std::string> ids{"2.2", "3.1", "3.2", "3.3", "3.4", "3.5", "3.6", "8.3", "8.4", "9.15"};
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
  QFile file(QString::fromStdString(path));
  if (!file.open(QIODevice::ReadOnly))
    throw FileError({path, 0, 0}, "cannot open feature-point file: " + file.errorString().toStdString());
  const QByteArray bytes = file.readAll();
  QJsonParseError parseError;
  const QJsonDocument doc = QJsonDocument::fromJson(bytes, &parseError);
  if (parseError.error != QJsonParseError::NoError)
    throw FileError(jsonSyntaxErrorLocation(std::string_view(bytes.constData(), static_cast<std::size_t>(bytes.size())), parseError, path),
                    "not valid JSON: " + parseError.errorString().toStdString());
  if (!doc.isObject()) throw FileError({path, 0, 0}, "expected a JSON object at the top level");

  Reader r(path, warnings);
  const QJsonObject root = doc.object();
  r.allowKeys(root, "(top level)",
              {"format", "version", "mesh", "submeshes", "defaults", "points", "eyes", "neck_pivot", "tear_sources"});
  if (root.value("format") != QJsonValue("lacrima-fdp"))
    throw FileError({path, 0, 0}, "format: expected \"lacrima-fdp\" (is this a Lacrima feature-point file?)");
  FeaturePointFile out;
  out.path = path;
  const auto version = r.index(root.value("version"), "version");
  r.throwIfErrors();
  if (*version < 1 || *version > kFeaturePointFileVersion)
    throw FileError({path, 0, 0}, "version: expected 1 to " + std::to_string(kFeaturePointFileVersion) +
                                      ", got " + std::to_string(*version) + " (a newer Lacrima wrote it?)");
  out.version = *version;
  if (root.contains("mesh")) {
    if (!root.value("mesh").isString()) r.error("mesh", "expected a string");
    out.meshNote = root.value("mesh").toString().toStdString();
  }

  const QJsonObject roles = root.value("submeshes").toObject();
  if (!root.value("submeshes").isObject()) {
    r.error("submeshes", "expected an object with at least \"skin\": [sub-mesh names]");
  } else {
    r.allowKeys(roles, "submeshes", {"skin", "eye_left", "eye_right", "jaw", "tongue", "attached"});
    out.skin = r.names(roles.value("skin"), "submeshes.skin");
    if (roles.value("skin").isArray() && out.skin.empty()) r.error("submeshes.skin", "expected at least one sub-mesh");
    if (roles.contains("eye_left")) out.eyeLeft.submeshes = r.names(roles.value("eye_left"), "submeshes.eye_left");
    if (roles.contains("eye_right")) out.eyeRight.submeshes = r.names(roles.value("eye_right"), "submeshes.eye_right");
    if (roles.contains("jaw")) out.jaw = r.names(roles.value("jaw"), "submeshes.jaw");
    if (roles.contains("tongue")) out.tongue = r.names(roles.value("tongue"), "submeshes.tongue");
    if (roles.contains("attached")) out.attached = r.names(roles.value("attached"), "submeshes.attached");
  }

  if (root.contains("defaults")) {
    const QJsonObject defaults = root.value("defaults").toObject();
    r.allowKeys(defaults, "defaults", {"geodesics"});
    if (defaults.contains("geodesics"))
      if (auto m = r.method(defaults.value("geodesics"), "defaults.geodesics")) out.geodesics = *m;
  }

  if (!root.value("points").isObject()) {
    r.error("points", "expected an object of feature points by FDP id, e.g. \"2.1\": {...}");
  } else {
    const QJsonObject points = root.value("points").toObject();
    for (auto it = points.begin(); it != points.end(); ++it) {
      const std::string id = it.key().toStdString();
      const std::string where = "points." + quotedId(id);
      const auto parsed = parseId(id);
      if (!parsed || parsed->first < 2 || parsed->first > 11) {
        r.error(where, "expected an FDP id \"group.index\" with group 2 to 11");
        continue;
      }
      auto at = r.surfacePoint(it.value(), where, {"radius", "geodesics"});
      if (!at) continue;
      FeaturePointSpec spec{*at, std::nullopt, std::nullopt};
      const QJsonObject o = it.value().toObject();
      if (o.contains("radius")) {
        const double radius = o.value("radius").toDouble(-1.0);
        if (!o.value("radius").isDouble() || !(radius > 0.0) || !std::isfinite(radius))
          r.error(where + ".radius", "expected a positive number (model units)");
        else
          spec.radius = radius;
      }
      if (o.contains("geodesics")) spec.geodesics = r.method(o.value("geodesics"), where + ".geodesics");
      out.points.emplace(id, spec);
    }
  }

  if (root.contains("eyes")) {
    const QJsonObject eyes = root.value("eyes").toObject();
    r.allowKeys(eyes, "eyes", {"left", "right"});
    for (auto [side, spec] : {std::pair{"left", &out.eyeLeft}, std::pair{"right", &out.eyeRight}}) {
      if (!eyes.contains(side)) continue;
      const QJsonObject eye = eyes.value(side).toObject();
      r.allowKeys(eye, std::string("eyes.") + side, {"centre"});
      if (eye.contains("centre")) spec->centre = r.vector3(eye.value("centre"), std::string("eyes.") + side + ".centre");
    }
  }
  if (root.contains("neck_pivot")) out.neckPivot = r.vector3(root.value("neck_pivot"), "neck_pivot");
  if (root.contains("tear_sources")) {
    const QJsonObject tears = root.value("tear_sources").toObject();
    r.allowKeys(tears, "tear_sources", {"left", "right"});
    if (tears.contains("left")) out.tearLeft = r.surfacePoint(tears.value("left"), "tear_sources.left");
    if (tears.contains("right")) out.tearRight = r.surfacePoint(tears.value("right"), "tear_sources.right");
  }
  for (const auto& [what, v] : {std::pair{"neck_pivot", out.neckPivot}, std::pair{"eyes.left.centre", out.eyeLeft.centre},
                                std::pair{"eyes.right.centre", out.eyeRight.centre}})
    if (v && !v->allFinite()) r.error(what, "expected finite coordinates");
  r.throwIfErrors();
  return out;
}

void validateFeaturePoints(const FeaturePointFile& file, const HeadMesh& mesh, Warnings* warnings) {
  std::vector<std::string> errors;
  std::map<std::string, std::string> roleOf;  // sub-mesh -> role, to catch a name in two roles
  auto checkRole = [&](const std::vector<std::string>& names, const std::string& role) {
    for (const std::string& name : names) {
      findAndCheck(mesh, name, "submeshes." + role, errors);
      const auto [it, fresh] = roleOf.emplace(name, role);
      if (!fresh)
        errors.push_back("submeshes." + role + ": sub-mesh \"" + name + "\" already has role \"" + it->second + "\"");
    }
  };
  checkRole(file.skin, "skin");
  checkRole(file.eyeLeft.submeshes, "eye_left");
  checkRole(file.eyeRight.submeshes, "eye_right");
  checkRole(file.jaw, "jaw");
  checkRole(file.tongue, "tongue");
  checkRole(file.attached, "attached");

  for (const auto& [id, spec] : file.points) checkPoint(spec.at, mesh, "points." + quotedId(id), errors);
  if (file.tearLeft) checkPoint(*file.tearLeft, mesh, "tear_sources.left", errors);
  if (file.tearRight) checkPoint(*file.tearRight, mesh, "tear_sources.right", errors);

  for (const std::string& id : fapuFeaturePoints())
    if (!file.points.count(id))
      errors.push_back("points: missing required feature point " + id + " (it defines a FAPU: expected \"" + id +
                       "\": {\"submesh\": ..., \"vertex\": ...})");
  if (!errors.empty()) {
    std::string message = errors.front();
    for (std::size_t k = 1; k < errors.size(); ++k) message += "\n  " + errors[k];
    throw FileError({file.path, 0, 0}, message);
  }
  if (!warnings) return;
  auto warn = [&](const std::string& text) { warnings->push_back(fileNote(file.path, text)); };
  for (const std::string& id : animatedFeaturePoints()) {
    if (file.points.count(id)) continue;
    std::string faps;
    for (int fap = 3; fap <= 68; ++fap)
      if (fapInfo(fap).featurePoint.find(id) != std::string_view::npos && fapInfo(fap).featurePoint.size() >= id.size()) {
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
    warn("points: no feature point " + id + "; FAP " + faps + " will have no pose");
  }
  if (file.eyeLeft.submeshes.empty()) warn("submeshes.eye_left: none given; FAPs 23, 25, 27 and 29 will not move an eye");
  if (file.eyeRight.submeshes.empty()) warn("submeshes.eye_right: none given; FAPs 24, 26, 28 and 30 will not move an eye");
  if (!file.neckPivot) warn("neck_pivot: not given; using the centre of the skin's lowest open boundary");
}

std::vector<int> surfaceVertices(const SurfacePoint& point, const HeadMesh& mesh) {
  const HeadSubmesh& s = *mesh.findSubmesh(point.submesh);
  if (point.vertex >= 0) return {s.firstVertex + point.vertex};
  const Eigen::Vector3i t = s.triangles[static_cast<std::size_t>(point.triangle)];
  return {t[0], t[1], t[2]};
}

Eigen::Vector3d surfacePosition(const SurfacePoint& point, const HeadMesh& mesh) {
  const std::vector<int> v = surfaceVertices(point, mesh);
  if (v.size() == 1) return mesh.positions.col(v[0]).cast<double>();
  Eigen::Vector3d p = Eigen::Vector3d::Zero();
  for (int k = 0; k < 3; ++k) p += point.barycentric[k] * mesh.positions.col(v[static_cast<std::size_t>(k)]).cast<double>();
  return p;
}

}  // namespace lacrima::rigging
