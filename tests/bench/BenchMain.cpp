// lacrima-bench SUBCOMMAND [options]: the project's benchmarks. Each prints its figures with
// the target beside them; `--json` gives one JSON object for scripts.
#include <cstdio>
#include <cstring>
#include <string>

namespace lacrima::bench {
int runFapIo(int argc, char** argv);
int runTears(int argc, char** argv);
int runGeodesics(int argc, char** argv);
int runPoses(int argc, char** argv);
int runTearsSweep(int argc, char** argv);
int runTearsSlide(int argc, char** argv);
int runEditor(int argc, char** argv);
int runPlayer(int argc, char** argv);
int runExport(int argc, char** argv);
int runHead(int argc, char** argv);
int runProposal(int argc, char** argv);
int runPick(int argc, char** argv);
int runBezier(int argc, char** argv);
int runMoodLayer(int argc, char** argv);
int runPreview(int argc, char** argv);
int runWorstCases(int argc, char** argv);
int runImport(int argc, char** argv);
int runLive(int argc, char** argv);
int runBatch(int argc, char** argv);
}  // namespace lacrima::bench

namespace {

struct Subcommand {
  const char* name;
  const char* summary;
  int (*run)(int argc, char** argv);
};

const Subcommand kSubcommands[] = {
    {"fapio", "read and write a 10-minute, 70-channel FAP animation (13,200 frames at 22 fps)",
     lacrima::bench::runFapIo},
    {"tears",
     "tear pipeline (SPH, skin collision, surface, trails) on a cheek sheet or the default head",
     lacrima::bench::runTears},
    {"tears-sweep",
     "tears: error against fine WCSPH and own-solver references beside ms per frame (sub-step "
     "per solver, kernel, cube, neighbours), and a thread axis with the error unchanged",
     lacrima::bench::runTearsSweep},
    {"tears-slide",
     "tears: a drop sliding down a plate at several angles against the law of sliding drops, "
     "per solver and sub-step factor",
     lacrima::bench::runTearsSlide},
    {"geodesics", "geodesic distance: accuracy against time (sphere, plane), ms per feature point",
     lacrima::bench::runGeodesics},
    {"editor",
     "the editor: live preview with 500 tear particles (>= 30 fps), slider and timeline costs",
     lacrima::bench::runEditor},
    {"preview",
     "the editor's live preview with 10,000 and 100,000 tear particles: longest event-loop "
     "stall (<= 50 ms) beside the simulation step",
     lacrima::bench::runPreview},
    {"poses", "rig, bake and blend every FAP pose on synthetic and real (default, ICT) heads",
     lacrima::bench::runPoses},
    {"head", "a head file to a rigged, checked head, ms per stage (ICT <= 1 s on one core)",
     lacrima::bench::runHead},
    {"import",
     "a head read in the importer process against in the program: ICT, default and a 10 MB "
     "head, interleaved (<= 50 ms added for 10 MB)",
     lacrima::bench::runImport},
    {"live",
     "the live player: latency from a frame's arrival to the end of its render (median, p99) "
     "at 22, 60, 120 fps of input with 100 and 2,000 tear particles, frames dropped",
     lacrima::bench::runLive},
    {"batch",
     "datasets: jobs per hour of lacrima-batch (5 s takes at 640x360 with masks, 1 and 2 at a "
     "time), the pinned environment's cost, Slurm's overhead per task (--slurm)",
     lacrima::bench::runBatch},
    {"export",
     "each export (video, glTF, PLY, masks) on the demo at 1280x720 in ms per frame, beside the "
     "plain render",
     lacrima::bench::runExport},
    {"player",
     "the whole player (playback + OGRE render) on the demo at 1280x720: fps, stage shares",
     lacrima::bench::runPlayer},
    {"proposal",
     "feature-point proposal on the ICT head from 8 anchors: error per FDP group beside ms per "
     "stage, two orientations",
     lacrima::bench::runProposal},
    {"pick", "picking a head under the mouse (Head workspace): hierarchy build, refit, one ray",
     lacrima::bench::runPick},
    {"bezier",
     "graph editor curves: error of the Bézier u-for-t solve beside ns per solve, per tolerance",
     lacrima::bench::runBezier},
    {"mood-layer",
     "a project's crying layer: generating 10 minutes, memory held, cache hit, evaluate, bake",
     lacrima::bench::runMoodLayer},
    {"worst-cases",
     "baking 10 minutes of keys, refusing an 8 MiB FAP line, the editor's event loop while a "
     "real head rigs in the background",
     lacrima::bench::runWorstCases},
};

void printUsage(FILE* out) {
  std::fprintf(out,
               "usage: lacrima-bench SUBCOMMAND [options]   (SUBCOMMAND --help for options)\n\n");
  for (const auto& s : kSubcommands) std::fprintf(out, "  %-12s %s\n", s.name, s.summary);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2 || !std::strcmp(argv[1], "--help") || !std::strcmp(argv[1], "-h")) {
    printUsage(argc < 2 ? stderr : stdout);
    return argc < 2 ? 2 : 0;
  }
  for (const auto& s : kSubcommands)
    if (std::string(argv[1]) == s.name) return s.run(argc - 1, argv + 1);
  std::fprintf(stderr, "lacrima-bench: unknown subcommand '%s'\n\n", argv[1]);
  printUsage(stderr);
  return 2;
}
