// lacrima-bench bezier: what the accuracy of the graph editor's Bézier curves costs. A Bézier
// segment is a function of time only through a solve of x(u) = t for u (CurveHandles.h:
// solveBezierTime, bisection-safeguarded Newton). This measures, for several stopping
// tolerances and step limits, the worst time error |x(u) - t|, the worst value error against a
// reference u (200 bisection halvings on de Casteljau's x, independent of the solver), the mean
// steps and the nanoseconds per solve-and-evaluate, over random segments of every kind: auto
// handles (x linear in u, Newton exact at once), dragged handles, and handles reaching across
// the whole segment (x'(u) = 0 at an end, where Newton is slowest).
#include "BenchCommandLine.h"
#include "BenchSupport.h"

#include <lacrima/common/CurveHandles.h>
#include <lacrima/common/JsonWriter.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

namespace lacrima::bench {
namespace {

struct Options {
  int segments = 3000;
  int samples = 64;  // times per segment
  bool json = false;
};

std::optional<int> parseOptions(int argc, char** argv, Options& options) {
  BenchCommandLine line("bezier",
                        "Bézier segments as functions of time: error of the u-for-t solve beside "
                        "its cost, per stopping tolerance and step limit.");
  line.wholeNumber("segments", "N", "Random segments (default 3000).", 1, 1000000,
                   options.segments);
  line.wholeNumber("samples", "N", "Times per segment (default 64).", 1, 100000, options.samples);
  line.flag("json", "One JSON object instead of the table.", options.json);
  return line.parse(argc, argv);
}

struct Segment {
  std::array<double, 4> x, y;
};

double cubic(const std::array<double, 4>& p, double u) {
  const double r = 1.0 - u;
  return r * r * r * p[0] + 3.0 * u * r * r * p[1] + 3.0 * u * u * r * p[2] + u * u * u * p[3];
}

// De Casteljau for x, then bisection: the reference u, shared with nothing in the library.
double referenceU(const std::array<double, 4>& x, double t) {
  const auto xAt = [&](double u) {
    const auto lerp = [u](double a, double b) { return a + u * (b - a); };
    const double a = lerp(x[0], x[1]), b = lerp(x[1], x[2]), c = lerp(x[2], x[3]);
    return lerp(lerp(a, b), lerp(b, c));
  };
  double lo = 0.0, hi = 1.0;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    if (mid == lo || mid == hi) break;
    (xAt(mid) < t ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

// Segments as KeyframeSequence makes them: handles inside the segment, together no longer
// than it. A third each are auto-like, dragged, and reaching across the whole segment.
std::vector<Segment> randomSegments(int count) {
  std::mt19937 random(2026);
  std::uniform_real_distribution<double> unit(0.0, 1.0), value(-1000.0, 1000.0);
  std::vector<Segment> segments;
  for (int i = 0; i < count; ++i) {
    const double t0 = 100.0 * unit(random);
    const double h = 0.04 + 2.0 * unit(random);
    double a = 1.0 / 3.0, b = 1.0 / 3.0;  // handle reaches as fractions of h
    if (i % 3 == 1) {
      a = unit(random);
      b = unit(random) * (1.0 - a);
    } else if (i % 3 == 2) {
      a = 1.0 - 1e-3 * unit(random);
      b = 1.0 - a;
    }
    const double y0 = value(random), y3 = value(random);
    segments.push_back({{t0, t0 + a * h, t0 + h - b * h, t0 + h},
                        {y0, y0 + value(random), y3 + value(random), y3}});
  }
  return segments;
}

struct Row {
  BezierSolverSettings settings;
  double maxTimeError = 0, maxValueError = 0, meanSteps = 0, nsPerSolve = 0;
};

}  // namespace

int runBezier(int argc, char** argv) {
  Options options;
  if (const std::optional<int> status = parseOptions(argc, argv, options)) return *status;
  const std::vector<Segment> segments = randomSegments(options.segments);
  std::vector<std::pair<std::size_t, double>> queries;  // (segment, t)
  std::vector<double> reference;                        // y at the reference u
  std::mt19937 random(14);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (std::size_t s = 0; s < segments.size(); ++s) {
    for (int i = 0; i < options.samples; ++i) {
      const auto& x = segments[s].x;
      const double t = x[0] + unit(random) * (x[3] - x[0]);
      queries.emplace_back(s, t);
      reference.push_back(cubic(segments[s].y, referenceU(x, t)));
    }
  }

  const std::vector<BezierSolverSettings> settings = {{1e-3, 60},  {1e-6, 60},  {1e-9, 60},
                                                      {1e-12, 60}, {1e-15, 60}, {1e-12, 2},
                                                      {1e-12, 4},  {1e-12, 8}};
  std::vector<Row> rows;
  for (const BezierSolverSettings& setting : settings) {
    Row row;
    row.settings = setting;
    long long steps = 0;
    for (std::size_t q = 0; q < queries.size(); ++q) {
      const auto& [s, t] = queries[q];
      const BezierTimeSolve solve = solveBezierTime(segments[s].x, t, setting);
      steps += solve.steps;
      row.maxTimeError = std::max(row.maxTimeError, std::abs(cubic(segments[s].x, solve.u) - t));
      row.maxValueError =
          std::max(row.maxValueError, std::abs(cubic(segments[s].y, solve.u) - reference[q]));
    }
    row.meanSteps = static_cast<double>(steps) / static_cast<double>(queries.size());
    volatile double sink = 0;
    const Timing timing = timeRuns(5, [&] {
      double sum = 0;
      for (const auto& [s, t] : queries)
        sum += cubic(segments[s].y, solveBezierTime(segments[s].x, t, setting).u);
      sink = sink + sum;
    });
    row.nsPerSolve = timing.medianMs * 1e6 / static_cast<double>(queries.size());
    rows.push_back(row);
  }

  if (options.json) {
    JsonWriter json;
    json.beginObject();
    json.field("segments", options.segments);
    json.field("samples_per_segment", options.samples);
    json.key("settings");
    json.beginArray();
    for (const Row& row : rows) {
      json.beginObject();
      json.field("tolerance", row.settings.tolerance);
      json.field("max_steps", row.settings.maxSteps);
      json.field("max_time_error_s", row.maxTimeError);
      json.field("max_value_error", row.maxValueError);
      json.field("mean_steps", row.meanSteps);
      json.field("ns_per_solve", row.nsPerSolve);
      json.endObject();
    }
    json.endArray();
    json.endObject();
    std::printf("%s\n", std::move(json).finish().c_str());
    return 0;
  }
  std::printf("%zu solves on %d segments (values in -2000..2000, 40 ms to 2 s long)\n",
              queries.size(), options.segments);
  std::printf("%10s %6s %16s %16s %11s %10s\n", "tolerance", "steps", "max |x(u)-t| s",
              "max value error", "mean steps", "ns/solve");
  for (const Row& row : rows) {
    std::printf("%10.0e %6d %16.3e %16.3e %11.2f %10.1f%s\n", row.settings.tolerance,
                row.settings.maxSteps, row.maxTimeError, row.maxValueError, row.meanSteps,
                row.nsPerSolve,
                row.settings.tolerance == 1e-12 && row.settings.maxSteps == 60 ? "  (used)" : "");
  }
  return 0;
}

}  // namespace lacrima::bench
