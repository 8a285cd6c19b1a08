#include <lacrima/rigging/RigDescription.h>

#include <lacrima/common/FapTable.h>
#include <lacrima/common/JsonWriter.h>

#include <array>
#include <cmath>

namespace lacrima::rigging {
namespace {

void row(JsonWriter& w, const Eigen::Vector3d& v) {
  const std::array<double, 3> values{v.x(), v.y(), v.z()};
  w.numberRow(values);
}

void fapuObject(JsonWriter& w, const FapuSet& f) {
  w.beginObject();
  w.field("IRISD0", f.irisd0);
  w.field("ES0", f.es0);
  w.field("ENS0", f.ens0);
  w.field("MNS0", f.mns0);
  w.field("MW0", f.mw0);
  w.endObject();
}

// Channels a translation FAP's pose lives on; 47 (curl) and 29/30 (dilation) are not
// translations of their point and are left out of the displacement check.
bool isTranslation(int fap) { return fapInfo(fap).motion == FapMotion::Translation; }

}  // namespace

Eigen::Vector3d featurePointDisplacement(const BuiltRig& rig, const std::string& id, int fap,
                                         double value) {
  const auto binding = rig.bindings.find(id);
  const VertexPose& pose = rig.poses.poses[static_cast<std::size_t>(channelIndex(fap))];
  Eigen::Vector3d d = Eigen::Vector3d::Zero();
  if (binding == rig.bindings.end() || pose.empty()) return d;
  for (const auto& [vertex, weight] : binding->second)
    for (std::size_t k = 0; k < pose.vertices.size();
         ++k)  // repeated entries add up, as in blending
      if (pose.vertices[k] == vertex)
        d += weight * value * pose.offsets.col(static_cast<Eigen::Index>(k)).cast<double>();
  return d;
}

std::string rigDescriptionJson(const HeadMesh& mesh, const BuiltRig& rig, const RigFiles& files,
                               const FaceFrame& frame) {
  JsonWriter w;
  w.beginObject();
  w.field("format", "lacrima-rig");
  w.field("version", 1);
  w.field("mesh", files.ogreMesh);
  w.field("glb", files.glb);
  w.key("face_frame");
  w.beginObject();
  w.field("axes", "+x the face's left, +y up, +z forward");
  w.key("rotation");  // rows: face frame = rotation x the imported mesh's coordinates
  w.beginArray();
  for (int i = 0; i < 3; ++i) row(w, frame.rotation.row(i).transpose());
  w.endArray();
  w.field("measured", frame.wasMeasured);
  w.field("tilt_degrees", frame.tiltDegrees);
  w.endObject();
  w.key("fapu");
  fapuObject(w, rig.fapu);
  w.key("feature_points");
  w.beginObject();
  for (const auto& [id, p] : rig.featurePoints) {
    w.key(id);
    w.beginObject();
    w.key("position");
    row(w, p);
    if (const auto r = rig.radii.find(id); r != rig.radii.end()) {
      w.field("radius", r->second);
      w.field("geodesics", toString(rig.methods.at(id)));
    }
    w.endObject();
  }
  w.endObject();
  w.key("eyes");
  w.beginObject();
  for (const auto& [side, centre, group] :
       {std::tuple{"left", &rig.eyeCentreLeft, &rig.input.eyeLeft},
        std::tuple{"right", &rig.eyeCentreRight, &rig.input.eyeRight}}) {
    if (!*centre) continue;
    w.key(side);
    w.beginObject();
    w.key("centre");
    row(w, **centre);
    w.field("vertices", static_cast<int>(group->vertices.size()));
    w.endObject();
  }
  w.endObject();
  w.key("neck_pivot");
  row(w, rig.neckPivot);
  w.key("tear_sources");
  w.beginObject();
  for (const auto& [side, tear] :
       {std::pair{"left", &rig.tearLeft}, std::pair{"right", &rig.tearRight}}) {
    w.key(side);
    w.beginObject();
    w.field("vertex", tear->vertex);
    w.key("position");
    row(w, tear->position);
    w.key("normal");
    row(w, tear->normal);
    w.endObject();
  }
  w.endObject();
  w.key("submeshes");
  w.beginArray();
  for (const HeadSubmesh& s : mesh.submeshes) {
    w.beginObject();
    w.field("name", s.name);
    const auto role = rig.roles.find(s.name);
    w.field("role", role == rig.roles.end() ? "rigid" : role->second);
    w.field("first_vertex", s.firstVertex);
    w.field("vertex_count", s.vertexCount);
    w.endObject();
  }
  w.endArray();
  w.key("poses");
  w.beginArray();
  const ChannelMask driven = rig.poses.drivenChannels();
  for (int fap = 1; fap <= kChannelCount; ++fap)
    if (driven.test(channelIndex(fap))) w.integer(fap);
  w.endArray();
  w.key("disabled_faps");
  w.beginArray();
  for (int fap : rig.disabledFaps) w.integer(fap);
  w.endArray();
  w.key("warnings");
  w.beginArray();
  for (const std::string& warning : rig.warnings) w.string(warning);
  w.endArray();
  w.endObject();
  return std::move(w).finish();
}

std::string rigReportJson(const HeadMesh& mesh, const BuiltRig& rig) {
  JsonWriter w;
  w.beginObject();
  w.field("vertices", mesh.vertexCount());
  w.key("fapu");
  fapuObject(w, rig.fapu);
  w.key("faps");
  w.beginArray();
  for (int fap = 3; fap <= 68; ++fap) {
    if (!isTranslation(fap)) continue;
    const FapInfo& info = fapInfo(fap);
    const std::string id(info.featurePoint);
    const double x0 = rig.fapu.unitValue(info.unit) * FapuSet::kDivisor;
    const Eigen::Vector3d d = featurePointDisplacement(rig, id, fap, FapuSet::kDivisor);
    const VertexPose& pose = rig.poses.poses[static_cast<std::size_t>(channelIndex(fap))];
    const double along = d.dot(info.positiveMotion.cast<double>());
    const double across = (d - along * info.positiveMotion.cast<double>()).norm();
    w.beginObject();
    w.field("fap", fap);
    w.field("name", info.name);
    w.field("feature_point", id);
    w.field("pose_vertices", static_cast<int>(pose.vertices.size()));
    w.field("x0", x0);
    w.field("displacement", d.norm());
    w.field("ratio", x0 > 0 ? along / x0 : 0.0);
    w.key("warnings");
    w.beginArray();
    if (pose.empty()) {
      w.string("no pose");
    } else {
      if (std::abs(along - x0) > 1e-3 * x0)
        w.string("displacement differs from X0 by more than 0.1%");
      if (across > 1e-3 * x0) w.string("moves the point off the FAP's axis");
    }
    w.endArray();
    w.endObject();
  }
  w.endArray();
  w.key("warnings");
  w.beginArray();
  for (const std::string& warning : rig.warnings) w.string(warning);
  w.endArray();
  w.endObject();
  return std::move(w).finish();
}

}  // namespace lacrima::rigging
