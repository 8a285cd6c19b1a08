// lacrima-bench mood-layer: what a project's procedural crying layer (MoodLayer.h) costs. The
// layer's take is generated from its start whenever its mood curves, seed, range or the frame
// rate change (a mood key edited in the Moods view), and then read at every evaluation (the
// editor's preview at each playhead move) and bake (the player, lacrima-fap, exports). This
// measures the generation, the memory the take holds, a cache hit, one evaluation of the keys
// with the layer, and a bake of the whole range, for a layer of --minutes at --rate.
#include "BenchCommandLine.h"
#include "BenchSupport.h"

#include <lacrima/common/JsonWriter.h>
#include <lacrima/common/ProjectDocument.h>

#include <cstdio>
#include <string>

namespace lacrima::bench {
namespace {

struct Options {
  int minutes = 10;
  double rate = 22;
  bool json = false;
};

std::optional<int> parseOptions(int argc, char** argv, Options& options) {
  BenchCommandLine line("mood-layer",
                        "A project's crying layer: generating its take, the memory it holds, a "
                        "cache hit, an evaluation and a bake.");
  line.wholeNumber("minutes", "N", "The layer's length (default 10).", 1, 600, options.minutes);
  line.number("rate", "FPS", "The project's frame rate (default 22).", 0, 1000, options.rate,
              BenchCommandLine::Low::Excluded);
  line.flag("json", "One JSON object instead of the table.", options.json);
  return line.parse(argc, argv);
}

// Sadness rising and falling, anger and shame coming and going, with a few keys on the jaw:
// every part of the generator at work.
ProjectDocument cryingProject(const Options& options) {
  const double seconds = 60.0 * options.minutes;
  ProjectDocument document;
  document.fps = options.rate;
  Keyframe first, last;
  first.set(3, 40);
  last.time = seconds;
  last.set(3, 120);
  document.keys = KeyframeSequence({first, last});
  document.moods[Mood::Sadness] = IntensityCurve({{0, 0.1, Interpolation::Smooth},
                                                  {0.3 * seconds, 0.9, Interpolation::Smooth},
                                                  {0.8 * seconds, 0.4, Interpolation::Smooth}});
  document.moods[Mood::Anger] = IntensityCurve(
      {{0.2 * seconds, 0, Interpolation::Smooth}, {0.6 * seconds, 0.7, Interpolation::Linear}});
  document.moods[Mood::Shame] = IntensityCurve({{0.5 * seconds, 0.4, Interpolation::Smooth}});
  document.moodLayer = MoodLayer{4, 0, seconds, false};
  return document;
}

}  // namespace

int runMoodLayer(int argc, char** argv) {
  Options options;
  if (const std::optional<int> status = parseOptions(argc, argv, options)) return *status;
  ProjectDocument document = cryingProject(options);
  const double seconds = document.moodLayer->end;

  resetPeakMemory();
  const long long residentBefore = residentBytes();
  const Timing generate = timeRuns(5, [&] {
    MoodLayerCache fresh;
    document.moodTake(fresh);
  });
  MoodLayerCache cache;
  const MoodLayerTake* take = document.moodTake(cache);
  const long long peak = peakResidentBytes() - residentBefore;

  constexpr int kHits = 100000;
  const Timing hit = timeRuns(5, [&] {
    for (int i = 0; i < kHits; ++i) document.moodTake(cache);
  });
  constexpr int kEvaluations = 100000;
  volatile float sink = 0;
  const Timing evaluate = timeRuns(5, [&] {
    float sum = 0;
    for (int i = 0; i < kEvaluations; ++i)
      sum += document.evaluate(seconds * (i + 0.5) / kEvaluations, cache)[30];
    sink = sink + sum;
  });
  const Timing bake = timeRuns(5, [&] { sink = sink + document.bake(options.rate, cache).fps; });

  const double hitNs = hit.medianMs * 1e6 / kHits;
  const double evaluateNs = evaluate.medianMs * 1e6 / kEvaluations;
  if (options.json) {
    JsonWriter json;
    json.beginObject();
    json.field("minutes", options.minutes);
    json.field("rate", options.rate);
    json.field("frames", take->frameCount());
    json.field("take_bytes", static_cast<double>(take->bytes()));
    json.field("peak_resident_growth_bytes", static_cast<double>(peak));
    writeTiming(json, "generate_ms", generate);
    json.field("cache_hit_ns", hitNs);
    json.field("evaluate_ns", evaluateNs);
    writeTiming(json, "bake_ms", bake);
    json.endObject();
    std::printf("%s\n", std::move(json).finish().c_str());
    return 0;
  }
  std::printf("crying layer of %d min at %g fps: %d frames\n", options.minutes, options.rate,
              take->frameCount());
  std::printf("  take held          %10.2f MB (peak resident growth %.2f MB)\n",
              static_cast<double>(take->bytes()) / 1e6, static_cast<double>(peak) / 1e6);
  std::printf("  generate           %10.1f ms (median of %d; min %.1f, max %.1f)\n",
              generate.medianMs, generate.runs, generate.minMs, generate.maxMs);
  std::printf("  cache hit          %10.1f ns\n", hitNs);
  std::printf("  evaluate           %10.1f ns (keys, layers, crying layer)\n", evaluateNs);
  std::printf("  bake (cached take) %10.1f ms\n", bake.medianMs);
  return 0;
}

}  // namespace lacrima::bench
