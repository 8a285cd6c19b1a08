// lacrima-bench pick: what a click or a drag in the Head workspace costs. The viewport's pick()
// is a HeadPicker (RayMesh: Moller-Trumbore under a bounding-volume hierarchy) on the ray
// through the mouse: built once per head, refitted once per deformed frame, then one ray per
// mouse move. Rays come from the reset view (OrbitView::framing) through a grid over the
// picture, so about half of them hit the head and half pass it, as a drag across the face does.
#include "BenchCommandLine.h"
#include "BenchSupport.h"
#include "RealHeads.h"

#include <lacrima/scene/OrbitView.h>
#include <lacrima/viewport/HeadPicker.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

namespace lacrima::bench {
namespace {

struct Options {
  int runs = 5;
  bool json = false;
};

struct Row {
  std::string head;
  int triangles = 0;
  Timing build, refit, pick;
  double hitFraction = 0;
};

std::vector<viewport::Ray> gridRays(const HeadMesh& head, int columns, int rows) {
  const scene::OrbitView view = scene::OrbitView::framing(head);
  const Eigen::Matrix3d axes = view.orientation().toRotationMatrix();
  const double tangent = std::tan(0.5 * view.fovYDegrees * std::numbers::pi / 180);
  std::vector<viewport::Ray> rays;
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < columns; ++c) {
      const double x = (2.0 * (c + 0.5) / columns - 1) * tangent * 4.0 / 3.0;
      const double y = (1 - 2.0 * (r + 0.5) / rows) * tangent;
      rays.push_back({view.eye(), (axes * Eigen::Vector3d(x, y, -1)).normalized()});
    }
  return rays;
}

Row measure(const std::string& name, const HeadMesh& head, int runs) {
  Row row;
  row.head = name;
  row.triangles = head.triangleCount();
  row.build = timeRuns(runs, [&] { viewport::HeadPicker picker(head); });
  viewport::HeadPicker picker(head);
  Eigen::Matrix3Xf moved = head.positions;
  moved.row(1).array() += 0.01f;
  row.refit = timeRuns(runs, [&] { picker.setPositions(moved); });
  picker.setPositions(head.positions);
  const std::vector<viewport::Ray> rays = gridRays(head, 64, 48);
  int hits = 0;
  const Timing all = timeRuns(runs, [&] {
    hits = 0;
    for (const viewport::Ray& ray : rays) hits += picker.pick(ray).has_value();
  });
  const double perRay = 1.0 / static_cast<double>(rays.size());
  row.pick = {all.medianMs * perRay, all.minMs * perRay, all.maxMs * perRay, all.runs};
  row.hitFraction = hits * perRay;
  return row;
}

}  // namespace

int runPick(int argc, char** argv) {
  Options options;
  BenchCommandLine line("pick",
                        "Picking a head under the mouse (FaceViewport::pick): building the "
                        "hierarchy, refitting it\nto a deformed frame, and one ray, on the "
                        "default head and the ICT head (also in mm, +z up).");
  line.wholeNumber("runs", "N", "Timed runs of each measurement, after one warm-up (default 5).", 1,
                   1000, options.runs);
  line.flag("json", "Print one JSON object instead of the table.", options.json);
  if (const std::optional<int> status = line.parse(argc, argv)) return *status;

  std::vector<Row> rows;
  std::vector<std::string> notes;
  try {
    for (const RealHeadSpec& spec : {defaultHeadSpec(), ictHeadSpec()}) {
      std::string why;
      std::optional<HeadMesh> head = loadRealMesh(spec, why);
      if (!head) {
        notes.push_back(spec.name + ": " + why + "; skipped");
        continue;
      }
      rows.push_back(measure(spec.name, *head, options.runs));
      if (!spec.defaultHead) {
        // The same head in millimetres with +z up: the hierarchy does not care.
        head->positions =
            10.0f *
            Eigen::AngleAxisf(float(std::numbers::pi / 2), Eigen::Vector3f::UnitX()).matrix() *
            head->positions;
        rows.push_back(measure(spec.name + " (mm, +z up)", *head, options.runs));
      }
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "lacrima-bench pick: %s\n", e.what());
    return 1;
  }

  constexpr double kPickTarget = 1.0;  // ms: a drag re-picks at every mouse move
  if (options.json) {
    JsonWriter json;
    json.beginObject();
    json.key("heads");
    json.beginArray();
    for (const Row& row : rows) {
      json.beginObject();
      json.key("head");
      json.string(row.head);
      json.key("triangles");
      json.integer(row.triangles);
      writeTiming(json, "build_ms", row.build);
      writeTiming(json, "refit_ms", row.refit);
      writeTiming(json, "pick_ms", row.pick, kPickTarget);
      json.key("hit_fraction");
      json.number(row.hitFraction);
      json.endObject();
    }
    json.endArray();
    json.key("notes");
    json.beginArray();
    for (const std::string& note : notes) json.string(note);
    json.endArray();
    json.endObject();
    std::printf("%s\n", std::move(json).finish().c_str());
    return 0;
  }
  std::printf("%-28s %9s %10s %10s %12s %6s\n", "head", "triangles", "build ms", "refit ms",
              "pick ms", "hits");
  for (const Row& row : rows)
    std::printf("%-28s %9d %10.2f %10.2f %12.4f %5.0f%%\n", row.head.c_str(), row.triangles,
                row.build.medianMs, row.refit.medianMs, row.pick.medianMs, 100 * row.hitFraction);
  std::printf("target: a pick under %.1f ms (medians of %d runs; picks over a 64x48 grid)\n",
              kPickTarget, options.runs);
  for (const std::string& note : notes) std::printf("note: %s\n", note.c_str());
  return 0;
}

}  // namespace lacrima::bench
