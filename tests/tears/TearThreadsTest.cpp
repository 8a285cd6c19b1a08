// The tear simulation gives the same bits whatever the number of threads (ParallelChunks.h,
// docs/decisions/0015): particles, surface and trails after every frame, for 1, 2, 3 and 8
// threads, on the cheek sheet (spawning, removal, recycling, strays, a swaying sheet, a
// checkpoint restored mid-run) and on the default head (skipped when not fetched). Runs have
// more particles than the sharing threshold and several particle chunks, so the shared loops
// and their spill lists really run on several threads, and the mesher splats in several slabs.
#include "../support/MissingData.h"
#include "ParallelChunks.h"  // internal to lacrima_tears
#include "TearTestSupport.h"
#include "ThreadPool.h"

#include <lacrima/rigging/DefaultHead.h>
#include <lacrima/tears/SurfaceMesher.h>

#include <QtTest>

#include <malloc.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstdlib>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

using namespace lacrima;
using namespace lacrima::tears;
using namespace lacrima::tears::testing;

namespace {

constexpr int kThreadCounts[] = {1, 2, 3, 8};
// Particles a run must exceed: past the sharing threshold, and three particle chunks or more.
constexpr int kSharedRun = std::max(2 * static_cast<int>(kParticleChunk), kParallelParticles);

// Particles plus trails (FrameState) and the surface mesh of one frame.
struct Snapshot {
  FrameState state;
  Eigen::MatrixXd surface;     // vertex positions, then normals
  Eigen::MatrixXi triangles;   // one column per triangle
  std::size_t surfaceSlabs{};  // how many slabs the mesher shared its splat in (not compared)
};

Snapshot snapshotOf(const TearSimulation& sim, const TrailBuilder& trails,
                    const SurfaceMesher& mesher) {
  const TearSurface& surface = mesher.surface();
  Eigen::MatrixXd vertices(6, surface.vertexCount());
  vertices << surface.positions(), surface.normals();
  return {stateOf(sim, trails), vertices, surface.triangles(), mesher.stats().slabs};
}

bool sameBits(const Snapshot& a, const Snapshot& b) {
  return testing::sameBits(a.state, b.state) && testing::sameBits(a.surface, b.surface) &&
         a.triangles == b.triangles;
}

// Whether some frame's splat was shared in several slabs.
bool surfaceShared(const std::vector<Snapshot>& frames) {
  return std::any_of(frames.begin(), frames.end(),
                     [](const Snapshot& s) { return s.surfaceSlabs > 1; });
}

// The sheet run: short sheet (drops run off its bottom and are recycled, re-emitted in place
// as strays), swaying, with counts that rise and then fall (spawning and removal).
class SheetRun {
 public:
  explicit SheetRun(int threads, int maxSubsteps = SimulationOptions{}.maxSubsteps)
      : sheet_(makeSheet()), trails_(sheet_.triangles) {
    SimulationOptions options;
    options.threads = threads;
    options.maxSubsteps = maxSubsteps;
    sim_ = makeSheetSimulation(sheet_, {}, options);
  }
  static SyntheticSkin makeSheet() {
    CheekSheetOptions o;
    o.height = 1.2;
    return makeCheekSheet(o);
  }
  Eigen::Matrix3Xf skinAt(int f, double amplitude) const {
    return movedSheet(
        sheet_, Eigen::Vector3d(amplitude * std::sin(0.3 * f), 0, 0),
        Eigen::AngleAxisd(0.5 * amplitude * std::sin(0.2 * f), Eigen::Vector3d::UnitY()));
  }
  static std::pair<int, int> countsAt(int f) {
    return f < 30 ? std::pair{1500, 1300} : std::pair{1200, 1400};
  }
  void step(int f) {
    const Eigen::Matrix3Xf x = skinAt(f, 0.02);
    const auto [left, right] = countsAt(f);
    sim_->step(x, left, right, kFrameDt);
    trails_.update(*sim_, x, kFrameDt);
    mesher_.update(*sim_);
  }
  Snapshot snapshot() const { return snapshotOf(*sim_, trails_, mesher_); }
  TearSimulation& simulation() { return *sim_; }
  TrailBuilder& trails() { return trails_; }
  SurfaceMesher& mesher() { return mesher_; }

 private:
  SyntheticSkin sheet_;
  std::unique_ptr<TearSimulation> sim_;
  TrailBuilder trails_;
  SurfaceMesher mesher_;
};

constexpr int kSheetFrames = 44;

std::vector<Snapshot> sheetFrames(int threads) {
  SheetRun run(threads);
  std::vector<Snapshot> frames;
  for (int f = 0; f < kSheetFrames; ++f) {
    run.step(f);
    frames.push_back(run.snapshot());
  }
  return frames;
}

}  // namespace

class TearThreadsTest : public QObject {
  Q_OBJECT

 private slots:
  void poolRunsEveryChunkOnce() {
    // Many runs back to back (workers that wake late must not take a chunk of the next run),
    // chunk counts below, at and far above the thread count; every fifth run after a pause
    // longer than the spin, so that runs start both on spinning and on sleeping workers.
    ThreadPool pool(4);
    for (int chunks : {0, 1, 3, 4, 64, 1000}) {
      std::vector<int> hits(static_cast<std::size_t>(chunks), 0);
      for (int run = 0; run < 50; ++run) {
        if (run % 5 == 0) std::this_thread::sleep_for(3 * ThreadPool::kSpin);
        pool.run(chunks, [&hits](int c) { ++hits[static_cast<std::size_t>(c)]; });
      }
      for (int c = 0; c < chunks; ++c) QCOMPARE(hits[static_cast<std::size_t>(c)], 50);
    }
  }

  void stalledThreadsChunksAreTakenByOthers() {
    // Each thread owns a block of chunks; one that stalls (here the caller, on the first chunk
    // it takes) must not hold up the run: the worker runs its own block, then takes the rest of
    // the caller's from the back. Without taking from other blocks this waits out the deadline.
    ThreadPool pool(2);
    constexpr int kChunks = 8;
    const std::thread::id caller = std::this_thread::get_id();
    std::mutex mutex;
    std::condition_variable othersDone;
    std::vector<std::thread::id> ranOn(kChunks);
    int done = 0;
    bool stalledOnce = false, timedOut = false;
    pool.run(kChunks, [&](int c) {
      std::unique_lock lock(mutex);
      ranOn[static_cast<std::size_t>(c)] = std::this_thread::get_id();
      if (std::this_thread::get_id() == caller && !stalledOnce) {
        stalledOnce = true;
        timedOut = !othersDone.wait_for(lock, std::chrono::seconds(20),
                                        [&] { return done == kChunks - 1; });
      } else if (++done == kChunks - 1) {
        othersDone.notify_all();
      }
    });
    QVERIFY(!timedOut);
    // The caller ran only the chunk it stalled on (none, if it was descheduled for the whole run).
    QVERIFY(std::count(ranOn.begin(), ranOn.end(), caller) <= 1);
  }

  void threadCountIsResolved() {
    // An explicit count wins; 0 falls back to LACRIMA_THREADS, then to the hardware.
    SheetRun three(3);
    QCOMPARE(three.simulation().threads(), 3);
    qputenv("LACRIMA_THREADS", "5");
    QCOMPARE(SheetRun(0).simulation().threads(), 5);
    qputenv("LACRIMA_THREADS", "many");  // malformed: reported on stderr, ignored
    QVERIFY(SheetRun(0).simulation().threads() >= 1);
    qunsetenv("LACRIMA_THREADS");
    QVERIFY(SheetRun(0).simulation().threads() >= 1);
  }

  void sheetIsBitIdenticalForAnyThreadCount() {
    const std::vector<Snapshot> reference = sheetFrames(1);
    {
      // The run covers what the shared loops must get right: several chunks of particles,
      // recycled drops as strays, removal.
      SheetRun probe(1);
      for (int f = 0; f < kSheetFrames; ++f) probe.step(f);
      QVERIFY(probe.simulation().particles().size() > kSharedRun);
      QVERIFY(probe.simulation().counters().recycled > 0);
      QVERIFY(probe.simulation().counters().straySubsteps > 0);
      QVERIFY(probe.simulation().counters().removed > 0);
      QVERIFY(!probe.trails().mesh().empty());
      QVERIFY(probe.mesher().surface().positions().cols() > 0);
    }
    for (int threads : kThreadCounts) {
      if (threads == 1) continue;
      const std::vector<Snapshot> frames = sheetFrames(threads);
      QVERIFY2(surfaceShared(frames), "the surface was never shared between threads");
      for (int f = 0; f < kSheetFrames; ++f)
        QVERIFY2(
            sameBits(frames[static_cast<std::size_t>(f)], reference[static_cast<std::size_t>(f)]),
            qPrintable(QStringLiteral("%1 threads differ from 1 at frame %2").arg(threads).arg(f)));
    }
  }

  void cappedSubstepsAreBitIdenticalForAnyThreadCount() {
    // Two sub-steps a frame at most: the sub-steps are capped, and the velocity clamps that
    // make a capped step stable run chunk by chunk, fused with the move. Same bits and the same
    // number of clamps on 1 and 3 threads.
    constexpr int kFrames = 16, kFewSubsteps = 2;
    std::vector<Snapshot> ends;
    std::vector<long long> clamps;
    for (int threads : {1, 3}) {
      SheetRun run(threads, kFewSubsteps);
      for (int f = 0; f < kFrames; ++f) run.step(f);
      QVERIFY(run.simulation().particles().size() > kSharedRun);
      QVERIFY(run.simulation().counters().substepCapHits > 0);
      ends.push_back(run.snapshot());
      clamps.push_back(run.simulation().counters().clamped);
    }
    QVERIFY(clamps[0] > 0);
    QCOMPARE(clamps[1], clamps[0]);
    QVERIFY(sameBits(ends[1], ends[0]));
  }

  void checkpointRestoredOnOtherThreadCountsRepeatsTheRun() {
    // 1 thread runs through; 3 and 8 threads save mid-run, wander off with other input,
    // restore and finish: all end on the same bits.
    SheetRun straight(1);
    for (int f = 0; f < kSheetFrames; ++f) straight.step(f);
    const Snapshot expected = straight.snapshot();
    for (int threads : {3, 8}) {
      SheetRun run(threads);
      const int middle = kSheetFrames / 2;
      for (int f = 0; f < middle; ++f) run.step(f);
      const TearCheckpoint saved = run.simulation().checkpoint();
      const TrailBuilder savedTrails = run.trails();
      for (int f = 0; f < 8; ++f) {
        const Eigen::Matrix3Xf x = run.skinAt(f, 0.05);
        run.simulation().step(x, 900 + 50 * f, 1500 - 40 * f, kFrameDt);
        run.trails().update(run.simulation(), x, kFrameDt);
      }
      run.simulation().restore(saved);
      run.trails() = savedTrails;
      for (int f = middle; f < kSheetFrames; ++f) run.step(f);
      QVERIFY2(sameBits(run.snapshot(), expected),
               qPrintable(QStringLiteral("restored run on %1 threads diverged").arg(threads)));
    }
  }

  void checkpointsAreNoLargerOnMoreThreads() {
    // A checkpoint copies the solver's state, not its working buffers (Scratch.h): a shared
    // pair-list build keeps a buffer per chunk, which checkpoints once carried too (twice the
    // memory on two threads at 10,000 particles).
    const auto bytesPerCheckpoint = [](int threads) {
      SheetRun run(threads);
      for (int f = 0; f < 20; ++f) run.step(f);
      [&] { QVERIFY(run.simulation().particles().size() > kSharedRun); }();
      const double before = static_cast<double>(mallinfo2().uordblks);
      std::vector<TearCheckpoint> kept;
      for (int k = 0; k < 4; ++k) kept.push_back(run.simulation().checkpoint());
      return (static_cast<double>(mallinfo2().uordblks) - before) / 4;
    };
    const double one = bytesPerCheckpoint(1), three = bytesPerCheckpoint(3);
    if (!(one > 0)) QSKIP("mallinfo2 does not see this build's allocator (a sanitizer's)");
    QVERIFY2(three < 1.05 * one, qPrintable(QStringLiteral("%1 bytes on 3 threads, %2 on 1")
                                                .arg(three, 0, 'f', 0)
                                                .arg(one, 0, 'f', 0)));
  }

  void defaultHeadIsBitIdenticalForAnyThreadCount() {
    if (!rigging::defaultHeadAvailable()) LACRIMA_SKIP_WITHOUT_DEFAULT_HEAD();
    const HeadMesh head = rigging::loadDefaultHead();
    const HeadSubmesh* skin = head.findSubmesh("skin");
    QVERIFY(skin);
    constexpr int kFrames = 22;
    const auto runHead = [&](int threads) {
      SimulationOptions options;
      options.threads = threads;
      auto sim = TearSimulation::forHead(head, {}, options);
      TrailBuilder trails(skin->triangles);
      SurfaceMesher mesher;
      std::vector<Snapshot> frames;
      for (int f = 0; f < kFrames; ++f) {
        sim->step(head.positions, 1600, 1600, kFrameDt);
        trails.update(*sim, head.positions, kFrameDt);
        mesher.update(*sim);
        frames.push_back(snapshotOf(*sim, trails, mesher));
      }
      [&] { QVERIFY(sim->particles().size() > kSharedRun); }();
      return frames;
    };
    const std::vector<Snapshot> reference = runHead(1);
    for (int threads : kThreadCounts) {
      if (threads == 1) continue;
      const std::vector<Snapshot> frames = runHead(threads);
      QVERIFY(surfaceShared(frames));
      for (int f = 0; f < kFrames; ++f)
        QVERIFY2(
            sameBits(frames[static_cast<std::size_t>(f)], reference[static_cast<std::size_t>(f)]),
            qPrintable(QStringLiteral("%1 threads differ from 1 at frame %2 on the head")
                           .arg(threads)
                           .arg(f)));
    }
  }
};

QTEST_GUILESS_MAIN(TearThreadsTest)
#include "TearThreadsTest.moc"
