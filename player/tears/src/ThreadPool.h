#pragma once
// A small pool of worker threads (std::jthread) for the tear simulation's chunked loops
// (ParallelChunks.h says how work is cut so that results do not depend on the thread count).
//
// run(chunks, job) calls job(c) once for every chunk c in [0, chunks), on the workers and on
// the calling thread, and returns when all have finished. Thread t (the caller is 0) owns the
// t-th of `threads` equal blocks of chunks and runs them in order; a thread done with its block
// takes the last chunk of the block with the most left. So a loop over the particles gives each
// thread the same particles in every pass of a sub-step, whose data then stays in that core's
// cache (on this project's VM two threads ran the 10,000-particle sheet 7 % faster than with
// chunks handed out in order), and a thread that wakes late or is descheduled holds up no one.
// Chunks are taken under the pool's mutex (a chunk is tens of microseconds of work, the lock
// tens of nanoseconds); which thread runs which chunk still varies from run to run, so a job
// must write only outputs that belong to its chunk. The workers are started on the first run that
// has more than one chunk, so a simulation that never has enough particles to share never starts
// one.
//
// Between runs a worker spins for kSpin before it sleeps, and the caller spins as long for the
// last chunk of its run: a sub-step shares about ten loops with a little serial work between
// them, and on this project's VM a sleeping thread takes tens of microseconds to wake, where a
// spinning one sees the next run at once. The spin yields the core every few microseconds, so
// on busy cores it does not hold up threads that have work (docs/performance.md, Threads).
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace lacrima::tears {

class ThreadPool {
 public:
  // Measured with lacrima-bench tears at 10,000 particles on two threads: 50 µs won about half
  // of what 1 ms won, 200 and 500 µs a little less than 1 ms, 3 ms no more.
  static constexpr std::chrono::microseconds kSpin{1000};

  // `threads` counts the calling thread: 1 runs everything on the caller, no worker ever.
  explicit ThreadPool(int threads);
  ~ThreadPool();  // stops and joins the workers (a run must not be in progress)
  ThreadPool(const ThreadPool&) = delete;
  ThreadPool& operator=(const ThreadPool&) = delete;

  int threads() const { return threads_; }
  // Runs job(c) for c in [0, chunks); not re-entrant (a job must not call run). Jobs must not
  // throw (the simulation's loops do not).
  void run(int chunks, const std::function<void(int)>& job);

 private:
  void start();
  void work(const std::stop_token& stop, int thread);
  void drain(int thread);  // runs chunks of the current run until none is left
  int take(int thread);    // the next chunk for `thread`, or -1; mutex_ held

  int threads_;
  std::vector<std::jthread> workers_;
  std::mutex mutex_;
  std::condition_variable_any wake_;  // a new run, or stop
  std::condition_variable finished_;  // the last chunk of a run is done
  // Runs started, and the last run whose chunks are all done. Written under mutex_, read
  // without it by spinning threads.
  std::atomic<std::uint64_t> generation_ = 0, completed_ = 0;
  // The current run, all guarded by mutex_.
  const std::function<void(int)>* job_ = nullptr;
  int chunks_ = 0;
  int done_ = 0;  // chunks finished
  // Thread t's block of chunks still to run, [front_[t], back_[t]).
  std::vector<int> front_, back_;
};

// The thread count a simulation uses: `requested` when positive, else LACRIMA_THREADS when it
// holds a whole number from 1 to 256, else every hardware thread (at least 1). A malformed
// LACRIMA_THREADS is reported once on stderr and ignored.
int resolveThreadCount(int requested);

}  // namespace lacrima::tears
