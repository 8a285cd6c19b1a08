// lacrima-bench worst-cases: how long the far ends of everyday work take, with the targets
// beside the figures. The unit tests check what these produce; how fast depends on the
// machine's load, so it is measured here: baking ten minutes of keys (< 500 ms), refusing an
// 8 MiB FAP line from text and from a file (< 2 s), and the editor's event loop while a real
// head rigs in the background (longest stall < 150 ms, a 1 ms timer firing at least once per
// 20 ms on average).
#include "../support/WorstCaseInputs.h"
#include "BenchCommandLine.h"
#include "BenchSupport.h"
#include "RealHeads.h"

#include <lacrima/common/FapReader.h>
#include <lacrima/common/JsonWriter.h>
#include <lacrima/editor/HeadRigWork.h>
#include <lacrima/editor/RigJob.h>
#include <lacrima/playback/HeadRig.h>
#include <lacrima/rigging/DefaultHead.h>

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QTemporaryDir>
#include <QTimer>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>

namespace lacrima::bench {

namespace {

constexpr double kBakeTargetMs = 500;
constexpr double kLongLineTargetMs = 2000;
constexpr double kStallTargetMs = 150;
constexpr double kTickTargetMs = 20;  // the timer's mean interval through the rig, at most

struct Options {
  int runs = 5;
  bool json = false;
};

// How the event loop fared while a head rigged on RigJob's worker.
struct RigStall {
  std::string head;  // empty: no head to rig (`note` says why)
  std::string note;
  double rigMs = 0;
  double longestStallMs = 0;
  int ticks = 0;
  bool stallPass() const { return longestStallMs < kStallTargetMs; }
  bool ticksPass() const { return ticks >= rigMs / kTickTargetMs; }
};

// The ICT head when ../shared is there (about a second to rig, in stages), else the default head.
RigStall measureRigStall() {
  RigStall result;
  editor::RigJob::Work work;
  const RealHeadSpec ict = ictHeadSpec();
  if (std::filesystem::exists(ict.meshPath)) {
    result.head = ict.name;
    work = editor::headFilesWork(ict.meshPath, ict.fdpPath);
  } else if (rigging::defaultHeadAvailable()) {
    result.head = defaultHeadSpec().name;
    work = editor::defaultHeadWork();
  } else {
    result.note = "no head: neither " + ict.meshPath +
                  " nor the default head (packaging/fetch-default-head.sh)";
    return result;
  }
  editor::RigJob job;
  bool done = false;
  QObject::connect(&job, &editor::RigJob::finished, [&] { done = true; });
  QObject::connect(&job, &editor::RigJob::failed, [&](const QString& message) {
    result.note = message.toStdString();
    done = true;
  });
  QTimer tick;
  tick.setInterval(1);
  tick.setTimerType(Qt::PreciseTimer);
  QElapsedTimer sinceTick;
  qint64 longest = 0;
  QObject::connect(&tick, &QTimer::timeout, [&] {
    longest = std::max(longest, sinceTick.restart());
    ++result.ticks;
  });
  QElapsedTimer rigTime;
  rigTime.start();
  sinceTick.start();
  tick.start();
  job.start(std::move(work));
  while (!done) QCoreApplication::processEvents(QEventLoop::WaitForMoreEvents);
  tick.stop();
  result.rigMs = static_cast<double>(rigTime.nsecsElapsed()) / 1e6;
  result.longestStallMs = static_cast<double>(longest);
  if (!result.note.empty()) result.head.clear();  // the rig failed: no figures
  return result;
}

const char* mark(bool pass) { return pass ? "PASS" : "MISS"; }

void printTiming(const char* what, const Timing& t, double targetMs) {
  std::printf("  %-34s median %8.2f ms  (min %.2f, max %.2f)   target < %g ms  %s\n", what,
              t.medianMs, t.minMs, t.maxMs, targetMs, mark(t.medianMs < targetMs));
}

}  // namespace

int runWorstCases(int argc, char** argv) {
  Options options;
  BenchCommandLine line(
      "worst-cases",
      "Times the far ends of everyday work whose results the unit tests check: baking ten\n"
      "minutes of keys, refusing an 8 MiB FAP line (text and file), and the event loop while a\n"
      "real head rigs on RigJob's worker thread (the ICT head from ../shared, else the default\n"
      "head).");
  line.wholeNumber("runs", "N",
                   "Timed runs of the bake and the refusals, after one warm-up "
                   "(default 5).",
                   1, 1000, options.runs);
  line.flag("json", "Print one JSON object instead of the table.", options.json);
  if (const std::optional<int> status = line.parse(argc, argv)) return *status;

  QTemporaryDir folder;
  if (!folder.isValid()) {
    std::fprintf(stderr, "lacrima-bench worst-cases: cannot create a temporary folder\n");
    return 1;
  }
  const KeyframeSequence keys = test::tenMinutesOfKeys();
  const Timing bake = timeRuns(options.runs, [&] { keys.bake(22.0); });

  const std::string text = test::eightMebibyteLineFap();
  const std::string path = folder.filePath("long-line.fap").toStdString();
  std::ofstream(path, std::ios::binary) << text;
  // Each run must end in the refusal: a reader that took the line would be timed doing
  // something else.
  bool refused = true;
  const auto refuse = [&](const auto& read) {
    try {
      read();
      refused = false;
    } catch (const FileError&) {
    }
  };
  const Timing parse =
      timeRuns(options.runs, [&] { refuse([&] { FapReader::parse(text, "long-line.fap"); }); });
  const Timing readFile =
      timeRuns(options.runs, [&] { refuse([&] { FapReader::readFile(path); }); });
  if (!refused) {
    std::fprintf(stderr, "lacrima-bench worst-cases: the reader took an 8 MiB line\n");
    return 1;
  }

  int appArgc = 1;
  char appName[] = "lacrima-bench";
  char* appArgv[] = {appName, nullptr};
  QCoreApplication app(appArgc, appArgv);
  const RigStall stall = measureRigStall();
  const bool rigged = !stall.head.empty();

  const bool pass = bake.medianMs < kBakeTargetMs && parse.medianMs < kLongLineTargetMs &&
                    readFile.medianMs < kLongLineTargetMs &&
                    (!rigged || (stall.stallPass() && stall.ticksPass()));
  if (options.json) {
    JsonWriter json(JsonWriter::Layout::Compact);
    json.beginObject();
    json.field("benchmark", "worst-cases");
    writeTiming(json, "bake_ten_minutes_ms", bake, kBakeTargetMs);
    writeTiming(json, "long_line_parse_ms", parse, kLongLineTargetMs);
    writeTiming(json, "long_line_read_file_ms", readFile, kLongLineTargetMs);
    json.key("rig_stall");
    json.beginObject();
    if (rigged) {
      json.field("head", stall.head);
      json.field("rig_ms", stall.rigMs);
      json.field("longest_stall_ms", stall.longestStallMs);
      json.field("stall_target_below", kStallTargetMs);
      json.field("ticks", stall.ticks);
      json.field("ticks_target_at_least", stall.rigMs / kTickTargetMs);
      json.field("pass", stall.stallPass() && stall.ticksPass());
    } else {
      json.field("skipped", stall.note);
    }
    json.endObject();
    json.field("pass", pass);
    json.endObject();
    std::fputs(std::move(json).finish().c_str(), stdout);
    return 0;
  }

  std::printf("worst-cases: %d runs each after one warm-up\n", options.runs);
  printTiming("bake 13,200 keys at 22 fps", bake, kBakeTargetMs);
  printTiming("refuse an 8 MiB line (parse)", parse, kLongLineTargetMs);
  printTiming("refuse an 8 MiB line (readFile)", readFile, kLongLineTargetMs);
  if (!rigged) {
    std::printf("  event loop while a head rigs: skipped (%s)\n", stall.note.c_str());
    return 0;
  }
  std::printf("  event loop while the %s rigs (%.0f ms):\n", stall.head.c_str(), stall.rigMs);
  std::printf("    longest stall %6.0f ms                            target < %g ms  %s\n",
              stall.longestStallMs, kStallTargetMs, mark(stall.stallPass()));
  std::printf("    1 ms timer ticks %6d                            target >= %.0f    %s\n",
              stall.ticks, stall.rigMs / kTickTargetMs, mark(stall.ticksPass()));
  return 0;
}

}  // namespace lacrima::bench
