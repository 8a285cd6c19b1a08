// lacrima-bench fapio: write and read a long 70-channel FAP animation, with the project's
// targets beside the figures (< 50 ms to write, < 50 ms to read, read peak < 3x the file).
#include "BenchCommandLine.h"
#include "BenchSupport.h"

#include <lacrima/common/JsonWriter.h>

#include <lacrima/common/FapReader.h>
#include <lacrima/common/FapWriter.h>

#include <QTemporaryDir>

#include <malloc.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>
#include <string>

namespace lacrima::bench {

namespace {

constexpr double kWriteTargetMs = 50;
constexpr double kReadTargetMs = 50;
constexpr double kPeakTargetRatio = 3;
constexpr double kFps = 22;

struct Options {
  int frames = 13200;  // 10 minutes at 22 fps
  int runs = 15;
  bool json = false;
};

std::optional<int> parseOptions(int argc, char** argv, Options& options) {
  BenchCommandLine line(
      "fapio",
      "Writes a deterministic pseudo-random 70-channel FAP animation to a temporary file,\n"
      "then times FapWriter::save and FapReader::readFile and measures the read's peak memory.");
  line.wholeNumber("frames", "N",
                   QString("Frames at %1 fps (default 13200: 10 minutes).").arg(kFps), 1, 1'000'000,
                   options.frames);
  line.wholeNumber("runs", "N", "Timed runs of each operation, after one warm-up (default 15).", 1,
                   1000, options.runs);
  line.flag("json", "Print one JSON object instead of the table.", options.json);
  return line.parse(argc, argv);
}

// Typical amplitude per channel, in FAPU counts: small for lips and brows, large for the
// AU-based eyeball and head rotations, particle counts for the tear channels.
int channelRange(int fap) {
  if (isTearChannel(fap)) return 200;
  if ((fap >= 23 && fap <= 26) || (fap >= 48 && fap <= 50)) return 20000;
  if (fap >= 19 && fap <= 22) return 1080;
  return 400;
}

// Real FAP tracks move smoothly: a bounded random walk per channel, integers only. Uses the
// engine's raw output (not a distribution) so every platform builds the same file.
FapAnimation buildAnimation(int frameCount) {
  FapAnimation animation;
  animation.name = "bench";
  animation.fps = kFps;
  animation.frames.resize(static_cast<std::size_t>(frameCount));
  std::mt19937 random(20240521);
  FapValues current{};
  for (FapValues& frame : animation.frames) {
    for (int fap = 3; fap <= kChannelCount; ++fap) {
      const int range = channelRange(fap);
      const int step = static_cast<int>(random() % 41) - 20;
      const int low = isTearChannel(fap) ? 0 : -range;
      float& v = current[channelIndex(fap)];
      v = static_cast<float>(
          std::clamp(static_cast<int>(v) + step * std::max(1, range / 200), low, range));
    }
    frame = current;
  }
  for (int fap = 3; fap <= kChannelCount; ++fap) animation.animated.set(channelIndex(fap));
  return animation;
}

long long fileSize(const std::string& path) {
  FILE* file = std::fopen(path.c_str(), "rb");
  if (!file) return -1;
  std::fseek(file, 0, SEEK_END);
  const long long size = std::ftell(file);
  std::fclose(file);
  return size;
}

const char* mark(bool pass) { return pass ? "PASS" : "MISS"; }

// Unlike writeTiming (BenchSupport.h) without runs: fapio states them once, at the top level.
void writeTimingAgainst(JsonWriter& json, std::string_view name, const Timing& t, double targetMs) {
  json.key(name);
  json.beginObject();
  json.field("median", t.medianMs);
  json.field("min", t.minMs);
  json.field("max", t.maxMs);
  json.field("target_below", targetMs);
  json.field("pass", t.medianMs < targetMs);
  json.endObject();
}

}  // namespace

int runFapIo(int argc, char** argv) {
  Options options;
  if (const std::optional<int> status = parseOptions(argc, argv, options)) return *status;

  QTemporaryDir folder;
  if (!folder.isValid()) {
    std::fprintf(stderr, "lacrima-bench fapio: cannot create a temporary folder\n");
    return 1;
  }
  const std::string path = folder.filePath("bench.fap").toStdString();

  try {
    const FapAnimation animation = buildAnimation(options.frames);
    FapWriter::save(animation, path);
    const long long bytes = fileSize(path);

    // Memory first, in a quiet process. malloc_trim hands memory freed by the build and the
    // save back to the system; otherwise the read could reuse it unseen and look cheaper.
    malloc_trim(0);
    const bool peakReset = resetPeakMemory();
    const long long before = residentBytes();
    long long peakBytes = 0;
    {
      const FapReadResult check = FapReader::readFile(path);
      peakBytes = peakResidentBytes() - before;
      if (check.animation.frames != animation.frames) {
        std::fprintf(stderr,
                     "lacrima-bench fapio: the file read back differs from what was written\n");
        return 1;
      }
    }
    const double peakRatio =
        bytes > 0 ? static_cast<double>(peakBytes) / static_cast<double>(bytes) : 0;

    const Timing write = timeRuns(options.runs, [&] { FapWriter::save(animation, path); });
    const Timing read = timeRuns(options.runs, [&] { FapReader::readFile(path); });

    const bool writePass = write.medianMs < kWriteTargetMs;
    const bool readPass = read.medianMs < kReadTargetMs;
    const bool peakPass = peakRatio < kPeakTargetRatio;

    if (options.json) {
      JsonWriter json(JsonWriter::Layout::Compact);
      json.beginObject();
      json.field("benchmark", "fapio");
      json.field("frames", options.frames);
      json.field("channels", kChannelCount);
      json.field("fps", kFps);
      json.field("runs", options.runs);
      json.field("file_bytes", bytes);
      writeTimingAgainst(json, "write_ms", write, kWriteTargetMs);
      writeTimingAgainst(json, "read_ms", read, kReadTargetMs);
      json.field("read_peak_bytes", peakBytes);
      json.field("read_peak_ratio", peakRatio);
      json.field("read_peak_target_below", kPeakTargetRatio);
      json.field("read_peak_pass", peakPass);
      json.field("peak_reset_supported", peakReset);
      json.field("pass", writePass && readPass && peakPass);
      json.endObject();
      std::fputs(std::move(json).finish().c_str(), stdout);
      return 0;
    }

    std::printf(
        "fapio: %d frames x %d channels at %g fps, file %.2f MB (%lld bytes), %d runs each\n",
        options.frames, kChannelCount, kFps, static_cast<double>(bytes) / 1e6, bytes, options.runs);
    std::printf(
        "  write (toText + atomic save)  median %7.2f ms  (min %.2f, max %.2f)   target < %g ms  "
        "%s\n",
        write.medianMs, write.minMs, write.maxMs, kWriteTargetMs, mark(writePass));
    std::printf(
        "  read  (FapReader::readFile)   median %7.2f ms  (min %.2f, max %.2f)   target < %g ms  "
        "%s\n",
        read.medianMs, read.minMs, read.maxMs, kReadTargetMs, mark(readPass));
    std::printf(
        "  peak memory of one read       %7.2f MB = %.2fx the file size             target < %gx   "
        "  %s\n",
        static_cast<double>(peakBytes) / 1e6, peakRatio, kPeakTargetRatio, mark(peakPass));
    if (!peakReset) {
      std::printf(
          "  (the kernel refused to reset the peak: it covers the whole process, an "
          "overestimate)\n");
    }
    return 0;
  } catch (const FileError& e) {
    std::fprintf(stderr, "lacrima-bench fapio: %s\n", e.what());
    return 1;
  }
}

}  // namespace lacrima::bench
