// lacrima-bench geodesics: what geodesic accuracy costs in time. For Dijkstra and the heat
// method (several time factors m) on refinements of a unit icosphere and a flat equilateral
// lattice, the error against the exact distance (great circle, Euclidean) beside the set-up
// and per-source milliseconds; then milliseconds per feature point on the real heads.
#include "../rigging/GeodesicTestSurfaces.h"
#include "BenchCommandLine.h"
#include "BenchSupport.h"

#include <lacrima/common/JsonWriter.h>
#include <lacrima/rigging/DefaultHead.h>
#include <lacrima/rigging/DijkstraGeodesics.h>
#include <lacrima/rigging/HeatGeodesics.h>
#include <lacrima/rigging/InfluenceFalloff.h>
#include <lacrima/rigging/InfluenceWeights.h>
#include <lacrima/rigging/MeshImport.h>
#include <lacrima/rigging/SurfaceGraph.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <fstream>
#include <limits>
#include <memory>
#include <optional>
#include <random>
#include <string>
#include <vector>

#ifndef LACRIMA_SHARED_DIR
#define LACRIMA_SHARED_DIR ""
#endif

namespace lacrima::bench {

namespace {

namespace ts = lacrima::testsurfaces;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// Errors are measured where the exact distance is at least kBand (about 3% of the sphere's
// half circumference, 5% of the lattice's width): relative error means nothing at the source.
constexpr double kBand = 0.1;
// Weight error for a feature point of this radius: about the size of a lip or lid point on a
// head (radius / head size), and what the rig finally sees.
constexpr double kWeightRadius = 0.3;
const double kTimeFactors[] = {0.25, 1.0, 4.0};
constexpr int kHeadPoints = 70;
constexpr double kHeadRadiusFraction = 0.06;  // of the head's height

struct Options {
  int runs = 3;
  int sources = 8;
  bool quick = false;
  bool json = false;
  std::string csv;
  std::string ictPath =
      std::string(LACRIMA_SHARED_DIR) + "/heads/ict-facekit/generic_neutral_mesh.obj";
};

// One measured configuration.
struct Row {
  std::string surface;
  int vertices = 0;
  std::string method;  // "dijkstra", "dijkstra cut-off", "heat"
  double m = kNaN;     // heat time factor
  double graphMs = kNaN, factorMs = kNaN, msPerSource = kNaN;
  double meanRelError = kNaN, maxRelError = kNaN, maxWeightError = kNaN;
  double edgeLength = kNaN;
  // Heads only.
  double radius = kNaN, listedPerPoint = kNaN, maxWeightDiffToHeat = kNaN;
};

std::optional<int> parseOptions(int argc, char** argv, Options& options) {
  BenchCommandLine line("geodesics", QString("Geodesic distance: error against exact distances "
                                             "beside time, for Dijkstra and the heat\n"
                                             "method (m = 0.25, 1, 4; and m = 1 with the "
                                             "straight-line bound InfluenceWeights uses) on\n"
                                             "an icosphere and a flat lattice at four refinements, "
                                             "then milliseconds per feature point\n"
                                             "(%1 points) on the default head and the ICT head.")
                                         .arg(kHeadPoints));
  line.wholeNumber("runs", "N", "Timed runs of each measurement, after one warm-up (default 3).", 1,
                   1000, options.runs);
  line.wholeNumber("sources", "N",
                   "Sources per synthetic surface, errors averaged over them (default 8).", 1, 64,
                   options.sources);
  line.flag("quick", "Skip the finest refinement.", options.quick);
  line.text("ict", "FILE", "The ICT-FaceKit head (default: the shared folder's copy).",
            options.ictPath);
  line.flag("json", "Print one JSON object instead of the tables.", options.json);
  line.text("csv", "FILE", "Also write every row as CSV.", options.csv);
  return line.parse(argc, argv);
}

struct Case {
  std::string name;
  ts::Surface surface;
  bool sphere = false;  // exact distance: great circle, else Euclidean (the lattice is convex)
  std::vector<int> sources;

  double exact(int a, int b) const {
    const Eigen::Matrix3Xf& p = surface.positions;
    return sphere ? ts::greatCircle(p.col(a), p.col(b))
                  : (p.col(a).cast<double>() - p.col(b).cast<double>()).norm();
  }
};

Case sphereCase(int level, int sourceCount) {
  Case c;
  c.surface = ts::makeIcosphere(level);
  c.name = "sphere L" + std::to_string(level);
  c.sphere = true;
  const Eigen::Matrix3Xf& p = c.surface.positions;
  std::mt19937 random(7 + static_cast<unsigned>(level));
  for (int k = 0; k < sourceCount; ++k)
    c.sources.push_back(static_cast<int>(random() % static_cast<unsigned>(p.cols())));
  return c;
}

Case planeCase(int columns, int sourceCount) {
  Case c;
  ts::Lattice lattice = ts::makeLattice(columns);
  c.name = "plane " + std::to_string(columns);
  // Sources anywhere in the middle half, boundary effects included beyond it.
  std::mt19937 random(11 + static_cast<unsigned>(columns));
  while (static_cast<int>(c.sources.size()) < sourceCount) {
    const int i = columns / 4 + static_cast<int>(random() % static_cast<unsigned>(columns / 2 + 1));
    const int j =
        lattice.rows / 4 + static_cast<int>(random() % static_cast<unsigned>(lattice.rows / 2 + 1));
    c.sources.push_back(lattice.index(i, j));
  }
  c.surface = std::move(lattice);
  return c;
}

// Error statistics of `distance` (per vertex) against the exact distance from `source`.
struct Errors {
  double sumRel = 0, maxRel = 0, maxWeight = 0;
  long long counted = 0;

  void add(const Case& c, int source, const Eigen::VectorXd& distance) {
    for (Eigen::Index v = 0; v < distance.size(); ++v) {
      const double exact = c.exact(source, static_cast<int>(v));
      const double d = distance[v];
      maxWeight = std::max(maxWeight, std::abs(rigging::influenceFalloff(d / kWeightRadius) -
                                               rigging::influenceFalloff(exact / kWeightRadius)));
      if (exact < kBand) continue;
      const double rel = std::isfinite(d) ? std::abs(d - exact) / exact : 1.0;
      sumRel += rel;
      maxRel = std::max(maxRel, rel);
      ++counted;
    }
  }
  void into(Row& row) const {
    row.meanRelError = counted ? sumRel / static_cast<double>(counted) : kNaN;
    row.maxRelError = maxRel;
    row.maxWeightError = maxWeight;
  }
};

Eigen::VectorXi one(int v) { return Eigen::VectorXi::Constant(1, v); }

void measureCase(const Case& c, const Options& options, std::vector<Row>& rows) {
  const Eigen::Matrix3Xf& p = c.surface.positions;
  std::optional<rigging::SurfaceGraph> graph;
  const Timing graphTime =
      timeRuns(options.runs, [&] { graph = rigging::buildSurfaceGraph(p, c.surface.triangles); });
  const auto perSource = [&](const Timing& t) {
    return t.medianMs / static_cast<double>(c.sources.size());
  };
  Row base;
  base.surface = c.name;
  base.vertices = static_cast<int>(p.cols());
  base.graphMs = graphTime.medianMs;
  base.edgeLength = graph->meanEdgeLength;

  {
    Row row = base;
    row.method = "dijkstra";
    Errors errors;
    for (const int s : c.sources) errors.add(c, s, rigging::dijkstraDistances(*graph, one(s)));
    errors.into(row);
    row.msPerSource = perSource(timeRuns(options.runs, [&] {
      for (const int s : c.sources) rigging::dijkstraDistances(*graph, one(s));
    }));
    rows.push_back(row);

    // Same distances inside the radius, so the same weights; only the time changes.
    Row cut = row;
    cut.method = "dijkstra cut-off";
    cut.meanRelError = cut.maxRelError = kNaN;
    cut.msPerSource = perSource(timeRuns(options.runs, [&] {
      for (const int s : c.sources)
        rigging::dijkstraDistances(*graph, one(s), Eigen::VectorXd(), kWeightRadius);
    }));
    rows.push_back(cut);
  }

  // The plain heat method at each time factor, then m = 1 with the straight-line bound (what
  // InfluenceWeights uses).
  std::vector<std::pair<double, bool>> variants;
  for (const double m : kTimeFactors) variants.emplace_back(m, false);
  variants.emplace_back(1.0, true);
  for (const auto& [m, bound] : variants) {
    Row row = base;
    row.method = bound ? "heat+bound" : "heat";
    row.m = m;
    std::unique_ptr<rigging::HeatGeodesics> heat;
    row.factorMs = timeRuns(options.runs, [&, m = m, bound = bound] {
                     heat = std::make_unique<rigging::HeatGeodesics>(*graph, m, bound);
                   }).medianMs;
    Errors errors;
    for (const int s : c.sources) errors.add(c, s, heat->distances(one(s)));
    errors.into(row);
    row.msPerSource = perSource(timeRuns(options.runs, [&] {
      for (const int s : c.sources) heat->distances(one(s));
    }));
    rows.push_back(row);
  }
}

// Per-feature-point cost on a real head: kHeadPoints vertices spread evenly over the graph's
// nodes, each with radius kHeadRadiusFraction of the head's height.
void measureHead(const std::string& name, const HeadMesh& head,
                 const std::vector<std::string>& submeshes, const Options& options,
                 std::vector<Row>& rows) {
  std::optional<rigging::SurfaceGraph> graph;
  const Timing graphTime = timeRuns(options.runs, [&] {
    graph = submeshes.empty() ? rigging::buildSurfaceGraph(head)
                              : rigging::buildSurfaceGraph(head, submeshes);
  });
  const double radius = kHeadRadiusFraction * (head.boundsMax().y() - head.boundsMin().y());
  std::vector<int> points;
  for (int k = 0; k < kHeadPoints; ++k)
    points.push_back(graph->vertexOfNode[static_cast<size_t>(
        (static_cast<long long>(k) * graph->nodeCount()) / kHeadPoints)]);

  Row base;
  base.surface = name;
  base.vertices = graph->nodeCount();
  base.graphMs = graphTime.medianMs;
  base.edgeLength = graph->meanEdgeLength;
  base.radius = radius;

  std::vector<FeaturePointInfluence> heatWeights;
  const auto runAll = [&](const rigging::InfluenceWeights& weights,
                          std::vector<FeaturePointInfluence>& out) {
    out.clear();
    for (const int v : points) out.push_back(weights.atVertex(v, radius));
  };
  const auto listed = [](const std::vector<FeaturePointInfluence>& all) {
    double sum = 0;
    for (const auto& w : all) sum += static_cast<double>(w.vertices.size());
    return all.empty() ? 0.0 : sum / static_cast<double>(all.size());
  };
  // Largest weight difference between two methods' weights for the same point.
  const auto difference = [&](const std::vector<FeaturePointInfluence>& a,
                              const std::vector<FeaturePointInfluence>& b) {
    double worst = 0;
    std::vector<float> dense(static_cast<size_t>(head.vertexCount()), 0.0f);
    for (size_t k = 0; k < a.size(); ++k) {
      for (size_t i = 0; i < a[k].vertices.size(); ++i)
        dense[static_cast<size_t>(a[k].vertices[i])] = a[k].weights[i];
      for (size_t i = 0; i < b[k].vertices.size(); ++i)
        dense[static_cast<size_t>(b[k].vertices[i])] -= b[k].weights[i];
      for (float& w : dense) {
        worst = std::max(worst, static_cast<double>(std::abs(w)));
        w = 0;
      }
    }
    return worst;
  };

  Row heat = base;
  heat.method = "heat+bound";  // as InfluenceWeights computes it
  heat.m = 1;
  std::unique_ptr<rigging::InfluenceWeights> heatSolver;
  heat.factorMs = timeRuns(options.runs, [&] {
                    heatSolver = std::make_unique<rigging::InfluenceWeights>(
                        *graph, rigging::GeodesicMethod::Heat, 1.0);
                  }).medianMs;
  heat.msPerSource =
      timeRuns(options.runs, [&] { runAll(*heatSolver, heatWeights); }).medianMs / kHeadPoints;
  heat.listedPerPoint = listed(heatWeights);

  const rigging::InfluenceWeights dijkstra(*graph, rigging::GeodesicMethod::Dijkstra);
  Row cut = base;
  cut.method = "dijkstra cut-off";
  std::vector<FeaturePointInfluence> cutWeights;
  cut.msPerSource =
      timeRuns(options.runs, [&] { runAll(dijkstra, cutWeights); }).medianMs / kHeadPoints;
  cut.listedPerPoint = listed(cutWeights);
  cut.maxWeightDiffToHeat = difference(cutWeights, heatWeights);

  // Without the cut-off: the whole head is searched for every point.
  Row full = base;
  full.method = "dijkstra";
  full.msPerSource = timeRuns(options.runs,
                              [&] {
                                for (const int v : points)
                                  rigging::InfluenceWeights::fromDistances(
                                      rigging::dijkstraDistances(*graph, one(v)), radius);
                              })
                         .medianMs /
                     kHeadPoints;
  full.listedPerPoint = cut.listedPerPoint;
  full.maxWeightDiffToHeat = cut.maxWeightDiffToHeat;

  rows.push_back(cut);
  rows.push_back(full);
  rows.push_back(heat);
}

std::string methodLabel(const Row& r) {
  if (std::isnan(r.m)) return r.method;
  char text[32];
  std::snprintf(text, sizeof text, "%s m=%g", r.method.c_str(), r.m);
  return text;
}

// A number for the table: "-" when it does not apply.
std::string cell(double value, const char* format) {
  if (std::isnan(value)) return "-";
  char text[32];
  std::snprintf(text, sizeof text, format, value);
  return text;
}

void printSynthetic(const std::vector<Row>& rows) {
  std::printf(
      "Accuracy against time. Errors where the exact distance >= %g (unit sphere; plane 2 wide);\n"
      "max |dw|: largest weight error for a feature point of radius %g. cut-off = %g.\n"
      "heat+bound: with the straight-line bound; on the flat lattice that bound IS the exact\n"
      "distance, so only the sphere tests it fairly.\n\n",
      kBand, kWeightRadius, kWeightRadius);
  std::printf("%-10s %7s %7s  %-17s %9s %9s %10s %9s %9s %8s\n", "surface", "verts", "h", "method",
              "graph ms", "factor ms", "ms/source", "mean err", "max err", "max |dw|");
  std::string last;
  for (const Row& r : rows) {
    if (!std::isnan(r.radius)) continue;
    if (r.surface != last && !last.empty()) std::printf("\n");
    last = r.surface;
    std::printf("%-10s %7d %7.4f  %-17s %9s %9s %10s %9s %9s %8s\n", r.surface.c_str(), r.vertices,
                r.edgeLength, methodLabel(r).c_str(), cell(r.graphMs, "%.2f").c_str(),
                cell(r.factorMs, "%.1f").c_str(), cell(r.msPerSource, "%.3f").c_str(),
                cell(100 * r.meanRelError, "%.2f%%").c_str(),
                cell(100 * r.maxRelError, "%.1f%%").c_str(),
                cell(r.maxWeightError, "%.3f").c_str());
  }
}

void printHeads(const std::vector<Row>& rows, const std::vector<std::string>& notes) {
  std::printf(
      "\nPer feature point on the heads: %d points spread over the surface, radius %g x the\n"
      "head's height; ms/point includes listing the weights. |dw| heat: largest difference\n"
      "between the Dijkstra and heat+bound (m=1) weights of the same point.\n\n",
      kHeadPoints, kHeadRadiusFraction);
  std::printf("%-22s %7s %7s %7s  %-17s %9s %9s %9s %8s %10s\n", "head", "nodes", "h", "radius",
              "method", "graph ms", "factor ms", "ms/point", "listed", "|dw| heat");
  for (const Row& r : rows) {
    if (std::isnan(r.radius)) continue;
    std::printf("%-22s %7d %7.4f %7.3f  %-17s %9s %9s %9s %8s %10s\n", r.surface.c_str(),
                r.vertices, r.edgeLength, r.radius, methodLabel(r).c_str(),
                cell(r.graphMs, "%.2f").c_str(), cell(r.factorMs, "%.1f").c_str(),
                cell(r.msPerSource, "%.3f").c_str(), cell(r.listedPerPoint, "%.0f").c_str(),
                cell(r.maxWeightDiffToHeat, "%.3f").c_str());
  }
  for (const std::string& note : notes) std::printf("%s\n", note.c_str());
}

void writeJson(const std::vector<Row>& rows, const std::vector<std::string>& notes,
               const Options& options) {
  JsonWriter json(JsonWriter::Layout::Indented);
  json.beginObject();
  json.field("benchmark", "geodesics");
  json.field("runs", options.runs);
  json.field("sources", options.sources);
  json.field("error_band", kBand);
  json.field("weight_radius", kWeightRadius);
  json.key("rows");
  json.beginArray();
  for (const Row& r : rows) {
    json.beginObject();
    json.field("surface", r.surface);
    json.field("vertices", r.vertices);
    json.field("mean_edge_length", r.edgeLength);
    json.field("method", r.method);
    json.field("m", r.m);  // null when not the heat method
    json.field("graph_ms", r.graphMs);
    json.field("factor_ms", r.factorMs);
    json.field(std::isnan(r.radius) ? "ms_per_source" : "ms_per_point", r.msPerSource);
    if (std::isnan(r.radius)) {
      json.field("mean_relative_error", r.meanRelError);
      json.field("max_relative_error", r.maxRelError);
      json.field("max_weight_error", r.maxWeightError);
    } else {
      json.field("radius", r.radius);
      json.field("listed_per_point", r.listedPerPoint);
      json.field("max_weight_difference_to_heat", r.maxWeightDiffToHeat);
    }
    json.endObject();
  }
  json.endArray();
  json.key("notes");
  json.beginArray();
  for (const std::string& note : notes) json.string(note);
  json.endArray();
  json.endObject();
  std::fputs(std::move(json).finish().c_str(), stdout);
}

bool writeCsv(const std::vector<Row>& rows, const std::string& path) {
  std::ofstream out(path);
  const auto value = [](double v) { return std::isnan(v) ? std::string() : cell(v, "%.6g"); };
  out << "surface,vertices,mean_edge_length,method,m,graph_ms,factor_ms,ms_per_source,"
         "mean_relative_error,max_relative_error,max_weight_error,radius,listed_per_point,"
         "max_weight_difference_to_heat\n";
  for (const Row& r : rows)
    out << r.surface << ',' << r.vertices << ',' << value(r.edgeLength) << ',' << r.method << ','
        << value(r.m) << ',' << value(r.graphMs) << ',' << value(r.factorMs) << ','
        << value(r.msPerSource) << ',' << value(r.meanRelError) << ',' << value(r.maxRelError)
        << ',' << value(r.maxWeightError) << ',' << value(r.radius) << ','
        << value(r.listedPerPoint) << ',' << value(r.maxWeightDiffToHeat) << '\n';
  out.flush();
  return static_cast<bool>(out);
}

// The skin for the default head; for an imported head the face and back of the head when
// present (ICT-FaceKit's material groups), else every sub-mesh.
std::vector<std::string> skinOf(const HeadMesh& head) {
  if (head.findSubmesh("skin")) return {"skin"};
  std::vector<std::string> parts;
  for (const char* name : {"M_Face", "M_BackHead"})
    if (head.findSubmesh(name)) parts.emplace_back(name);
  return parts;
}

}  // namespace

int runGeodesics(int argc, char** argv) {
  Options options;
  if (const std::optional<int> status = parseOptions(argc, argv, options)) return *status;

  std::vector<Row> rows;
  std::vector<std::string> notes;
  try {
    const int finest = options.quick ? 3 : 4;
    for (int k = 0; k < finest; ++k) {
      const Case sphere = sphereCase(3 + k, options.sources);
      measureCase(sphere, options, rows);
    }
    for (int k = 0; k < finest; ++k) {
      const Case plane = planeCase(32 << k, options.sources);
      measureCase(plane, options, rows);
    }

    if (rigging::defaultHeadAvailable()) {
      const HeadMesh head = rigging::loadDefaultHead();
      measureHead("default head (skin)", head, skinOf(head), options, rows);
    } else {
      notes.push_back(
          "default head: not in the cache (run packaging/fetch-default-head.sh); skipped");
    }
    if (std::ifstream(options.ictPath).good()) {
      const HeadMesh head = rigging::importHeadMesh(options.ictPath);
      const std::vector<std::string> parts = skinOf(head);
      measureHead(parts.empty() ? "ICT head (all)" : "ICT head (face+back)", head, parts, options,
                  rows);
    } else {
      notes.push_back("ICT head: " + options.ictPath + " is absent; skipped");
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "lacrima-bench geodesics: %s\n", e.what());
    return 1;
  }

  if (!options.csv.empty() && !writeCsv(rows, options.csv)) {
    std::fprintf(stderr, "lacrima-bench geodesics: cannot write %s\n", options.csv.c_str());
    return 1;
  }
  if (options.json) {
    writeJson(rows, notes, options);
  } else {
    printSynthetic(rows);
    printHeads(rows, notes);
  }
  return 0;
}

}  // namespace lacrima::bench
