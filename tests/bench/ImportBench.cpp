// lacrima-bench import: what reading a user's head in the importer process costs against reading
// it in the program itself (ImportProcess.h against MeshImport.h). Rounds are interleaved, each
// reading the file both ways in alternating order, so that a disturbance of the machine falls on
// both; the added cost is the median of each round's difference. Heads: the ICT head (OBJ), the
// default head written out as OBJ, and a generated head of about 10 MB (the target: under
// 50 ms added).
#include "BenchCommandLine.h"
#include "BenchSupport.h"
#include "RealHeads.h"

#include <lacrima/rigging/ImportProcess.h>
#include <lacrima/rigging/MeshImport.h>

#include <QTemporaryDir>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <vector>

namespace lacrima::bench {
namespace {

struct Options {
  int rounds = 9;
  bool json = false;
};

struct Spread {
  double median = 0, min = 0, max = 0;
};

Spread spreadOf(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  const double median = n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
  return {median, values.front(), values.back()};
}

struct Row {
  std::string head;
  double megabytes = 0;
  int vertices = 0;
  Spread inProcess, isolated, added;
};

double millisecondsOf(const std::function<void()>& body) {
  const auto start = std::chrono::steady_clock::now();
  body();
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

Row measure(const std::string& name, const std::string& path, int rounds) {
  Row row;
  row.head = name;
  row.megabytes = static_cast<double>(std::filesystem::file_size(path)) / 1e6;
  row.vertices = rigging::importHeadMeshIsolated(path).vertexCount();  // warm-up, both ways
  (void)rigging::importHeadMesh(path);
  std::vector<double> in, out, added;
  for (int r = 0; r < rounds; ++r) {
    double a = 0, b = 0;
    const auto inside = [&] { a = millisecondsOf([&] { (void)rigging::importHeadMesh(path); }); };
    const auto outside = [&] {
      b = millisecondsOf([&] { (void)rigging::importHeadMeshIsolated(path); });
    };
    if (r % 2) {
      outside();
      inside();
    } else {
      inside();
      outside();
    }
    in.push_back(a);
    out.push_back(b);
    added.push_back(b - a);
  }
  row.inProcess = spreadOf(in);
  row.isolated = spreadOf(out);
  row.added = spreadOf(added);
  return row;
}

// `head` as an OBJ file: its vertices, uvs and one group per part.
void writeObj(const HeadMesh& head, const std::string& path) {
  std::ofstream out(path);
  for (int v = 0; v < head.vertexCount(); ++v)
    out << "v " << head.positions(0, v) << ' ' << head.positions(1, v) << ' '
        << head.positions(2, v) << '\n';
  const bool uvs = head.uvs.cols() > 0;
  for (int v = 0; uvs && v < head.vertexCount(); ++v)
    out << "vt " << head.uvs(0, v) << ' ' << 1.0f - head.uvs(1, v) << '\n';
  for (const HeadSubmesh& s : head.submeshes) {
    out << "g " << s.name << '\n';
    for (const Eigen::Vector3i& t : s.triangles) {
      out << 'f';
      for (int c = 0; c < 3; ++c) {
        out << ' ' << t[c] + 1;
        if (uvs) out << '/' << t[c] + 1;
      }
      out << '\n';
    }
  }
}

// A closed latitude-longitude ellipsoid of `rings` x `segments` vertices, as OBJ text.
void writeGeneratedHead(int rings, int segments, const std::string& path) {
  std::ofstream out(path);
  out.precision(7);
  for (int r = 0; r < rings; ++r) {
    const double polar = std::numbers::pi * (r + 0.5) / rings;
    for (int s = 0; s < segments; ++s) {
      const double around = 2 * std::numbers::pi * s / segments;
      out << "v " << 75 * std::sin(polar) * std::sin(around) << ' ' << 110 * std::cos(polar) << ' '
          << 95 * std::sin(polar) * std::cos(around) << '\n';
    }
  }
  for (int r = 0; r + 1 < rings; ++r)
    for (int s = 0; s < segments; ++s) {
      const int a = r * segments + s + 1, b = r * segments + (s + 1) % segments + 1;
      const int c = a + segments, d = b + segments;
      out << "f " << a << ' ' << c << ' ' << b << "\nf " << b << ' ' << c << ' ' << d << '\n';
    }
}

}  // namespace

int runImport(int argc, char** argv) {
  Options options;
  BenchCommandLine line(
      "import",
      "A head read in the importer process against in the program itself: interleaved rounds, "
      "medians\nwith their ranges, on the ICT head, the default head (as OBJ) and a generated "
      "10 MB head.");
  line.wholeNumber("rounds", "N", "Interleaved rounds per head, after one warm-up (default 9).", 1,
                   1000, options.rounds);
  line.flag("json", "Print one JSON object instead of the table.", options.json);
  if (const std::optional<int> status = line.parse(argc, argv)) return *status;
  if (rigging::importerProgram().empty()) {
    std::fprintf(stderr, "lacrima-bench import: lacrima-import is not beside lacrima-bench\n");
    return 1;
  }

  QTemporaryDir dir;
  std::vector<Row> rows;
  std::vector<std::string> notes;
  try {
    const RealHeadSpec ict = ictHeadSpec();
    if (std::filesystem::exists(ict.meshPath))
      rows.push_back(measure("ICT-FaceKit head (OBJ)", ict.meshPath, options.rounds));
    else
      notes.push_back(ict.name + ": " + ict.meshPath + " is absent; skipped");
    std::string why;
    if (const std::optional<HeadMesh> head = loadRealMesh(defaultHeadSpec(), why)) {
      const std::string path = dir.filePath("default-head.obj").toStdString();
      writeObj(*head, path);
      rows.push_back(measure("default head (as OBJ)", path, options.rounds));
    } else {
      notes.push_back("default head: " + why + "; skipped");
    }
    const std::string generated = dir.filePath("generated-10mb.obj").toStdString();
    writeGeneratedHead(360, 400, generated);
    rows.push_back(measure("generated head (OBJ)", generated, options.rounds));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "lacrima-bench import: %s\n", e.what());
    return 1;
  }

  constexpr double kAddedTarget = 50.0;  // ms, for a 10 MB head
  if (options.json) {
    JsonWriter json;
    json.beginObject();
    json.key("heads");
    json.beginArray();
    for (const Row& row : rows) {
      json.beginObject();
      json.key("head");
      json.string(row.head);
      json.field("megabytes", row.megabytes);
      json.field("vertices", row.vertices);
      for (const auto& [name, s] :
           {std::pair{"in_process_ms", row.inProcess}, std::pair{"isolated_ms", row.isolated},
            std::pair{"added_ms", row.added}}) {
        json.key(name);
        json.beginObject();
        json.field("median", s.median);
        json.field("min", s.min);
        json.field("max", s.max);
        json.endObject();
      }
      json.endObject();
    }
    json.endArray();
    json.field("rounds", options.rounds);
    json.field("added_target_ms_for_10_mb", kAddedTarget);
    json.key("notes");
    json.beginArray();
    for (const std::string& note : notes) json.string(note);
    json.endArray();
    json.endObject();
    std::printf("%s\n", std::move(json).finish().c_str());
    return 0;
  }
  std::printf("%-26s %6s %8s  %-22s %-22s %-22s\n", "head", "MB", "vertices", "in process ms",
              "importer process ms", "added ms");
  const auto cell = [](const Spread& s) {
    char text[64];
    std::snprintf(text, sizeof text, "%7.1f (%.1f-%.1f)", s.median, s.min, s.max);
    return std::string(text);
  };
  for (const Row& row : rows)
    std::printf("%-26s %6.1f %8d  %-22s %-22s %-22s\n", row.head.c_str(), row.megabytes,
                row.vertices, cell(row.inProcess).c_str(), cell(row.isolated).c_str(),
                cell(row.added).c_str());
  std::printf(
      "medians (min-max) of %d interleaved rounds; target: under %.0f ms added for a 10 MB "
      "head\n",
      options.rounds, kAddedTarget);
  for (const std::string& note : notes) std::printf("note: %s\n", note.c_str());
  return 0;
}

}  // namespace lacrima::bench
