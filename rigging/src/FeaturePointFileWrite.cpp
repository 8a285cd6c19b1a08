// Writing a feature-point file: the format of FeaturePointFile.h, in its documented key order,
// and the positions every written file carries.
#include <lacrima/common/JsonWriter.h>
#include <lacrima/rigging/FeaturePointFile.h>

namespace lacrima::rigging {
namespace {

void writeNames(JsonWriter& w, const std::vector<std::string>& names) {
  w.beginArray();
  for (const std::string& name : names) w.string(name);
  w.endArray();
}

void writeVector(JsonWriter& w, const Eigen::Vector3d& v) {
  const double values[] = {v.x(), v.y(), v.z()};
  w.numberRow(values);
}

// The members of a surface point, inside an object the caller opened.
void writeSurfacePoint(JsonWriter& w, const SurfacePoint& p) {
  w.field("submesh", p.submesh);
  if (p.vertex >= 0) {
    w.field("vertex", p.vertex);
  } else {
    w.field("triangle", p.triangle);
    w.key("barycentric");
    writeVector(w, p.barycentric);
  }
  if (p.position) {
    w.key("position");
    writeVector(w, *p.position);
  }
}

}  // namespace

void recordPositions(FeaturePointFile& file, const HeadMesh& mesh) {
  for (auto& [id, spec] : file.points) spec.at.position = surfacePosition(spec.at, mesh);
  for (std::optional<SurfacePoint>* tear : {&file.tearLeft, &file.tearRight})
    if (*tear) (*tear)->position = surfacePosition(**tear, mesh);
}

std::string featurePointFileJson(const FeaturePointFile& file) {
  JsonWriter w;
  w.beginObject();
  w.field("format", "lacrima-fdp");
  w.field("version", kFeaturePointFileVersion);
  if (!file.meshNote.empty()) w.field("mesh", file.meshNote);
  w.key("submeshes");
  w.beginObject();
  for (auto [role, names] :
       {std::pair{"skin", &file.skin}, std::pair{"eye_left", &file.eyeLeft.submeshes},
        std::pair{"eye_right", &file.eyeRight.submeshes}, std::pair{"jaw", &file.jaw},
        std::pair{"tongue", &file.tongue}, std::pair{"attached", &file.attached},
        std::pair{"ignored", &file.ignored}})
    if (!names->empty() || std::string_view(role) == "skin") {
      w.key(role);
      writeNames(w, *names);
    }
  w.endObject();
  w.key("defaults");
  w.beginObject();
  w.field("geodesics", toString(file.geodesics));
  w.endObject();
  w.key("points");
  w.beginObject();
  for (const auto& [id, spec] : file.points) {
    w.key(id);
    w.beginObject();
    writeSurfacePoint(w, spec.at);
    if (spec.radius) w.field("radius", *spec.radius);
    if (spec.geodesics) w.field("geodesics", toString(*spec.geodesics));
    if (!spec.placedByHand) w.field("placed", "proposed");
    w.endObject();
  }
  w.endObject();
  if (file.eyeLeft.centre || file.eyeRight.centre) {
    w.key("eyes");
    w.beginObject();
    for (auto [side, eye] : {std::pair{"left", &file.eyeLeft}, std::pair{"right", &file.eyeRight}})
      if (eye->centre) {
        w.key(side);
        w.beginObject();
        w.key("centre");
        writeVector(w, *eye->centre);
        w.endObject();
      }
    w.endObject();
  }
  if (file.neckPivot) {
    w.key("neck_pivot");
    writeVector(w, *file.neckPivot);
  }
  if (file.tearLeft || file.tearRight) {
    w.key("tear_sources");
    w.beginObject();
    for (auto [side, tear] :
         {std::pair{"left", &file.tearLeft}, std::pair{"right", &file.tearRight}})
      if (*tear) {
        w.key(side);
        w.beginObject();
        writeSurfacePoint(w, **tear);
        w.endObject();
      }
    w.endObject();
  }
  w.endObject();
  return std::move(w).finish();
}

}  // namespace lacrima::rigging
