#pragma once
// How the tear simulation shares a loop between threads and stays bit-identical whatever the
// thread count (docs/decisions/0005, 0015):
//   * the work is cut into FIXED chunks (kParticleChunk particles; a chunk's pairs are those of
//     its particles) whose bounds depend on the item count only, never on the number of threads;
//   * each chunk writes only its own outputs (the particles or pairs of its range) or a partial
//     result of its own (partials[c]);
//   * partial results are combined in chunk order: by the caller on one thread, or, where
//     each output belongs to one chunk (the density windows, the force pass's spills), by the
//     job of that output's chunk, taking the earlier chunks' partials in chunk order.
// Any thread may run any chunk, in any order, and the floating-point operations performed are
// the same, in the same order, for every output. With one thread, or fewer particles than
// kParallelParticles (sharing costs a wake-up per loop, more than a small loop takes), the
// chunks run one after the other on the calling thread and no worker is ever started.
// The chunk size may change the bits (the partial sums are grouped by chunk), the thread count
// never does; tests cut small scenes into small chunks shared from the first particle
// (SimulationOptions::chunkParticles, shareFromParticles) to run the shared paths.
#include "ThreadPool.h"

#include <lacrima/tears/SimulationOptions.h>

#include <algorithm>
#include <cstddef>

namespace lacrima::tears {

inline constexpr auto kParticleChunk = static_cast<std::size_t>(kDefaultChunkParticles);
// Measured with lacrima-bench tears --threads 1 and 2 on the cheek sheet of an idle 2-core
// machine (docs/performance.md, Threads): at 1,000 and 2,000 particles two threads were slower
// (the wake-ups cost more than the second thread saves), at 3,000 even, from 4,000 faster.
inline constexpr int kParallelParticles = kDefaultShareFromParticles;

class ParallelChunks {
 public:
  explicit ParallelChunks(int threads, std::size_t particleChunk = kParticleChunk,
                          int shareFrom = kParallelParticles)
      : pool_(threads),
        particleChunk_(std::max<std::size_t>(1, particleChunk)),
        shareFrom_(shareFrom) {}

  int threads() const { return pool_.threads(); }
  // The fixed chunk of the per-particle loops.
  std::size_t particleChunk() const { return particleChunk_; }
  // Shares the following loops only when the sub-step has enough particles.
  void setParticleCount(int particles) { shared_ = pool_.threads() > 1 && particles >= shareFrom_; }

  // Whether the loops are shared now (else they run on the calling thread).
  bool shared() const { return shared_; }

  static std::size_t chunkCount(std::size_t count, std::size_t chunk) {
    return (count + chunk - 1) / chunk;
  }
  // Calls body(c, begin, end) for every chunk c of [0, count) cut every `chunk` items.
  template <class Body>
  void forEachChunk(std::size_t count, std::size_t chunk, Body&& body) {
    const std::size_t chunks = chunkCount(count, chunk);
    const auto one = [&](int c) {
      const std::size_t begin = static_cast<std::size_t>(c) * chunk;
      body(c, begin, std::min(count, begin + chunk));
    };
    if (!shared_ || chunks < 2) {
      for (std::size_t c = 0; c < chunks; ++c) one(static_cast<int>(c));
      return;
    }
    pool_.run(static_cast<int>(chunks), one);
  }

 private:
  ThreadPool pool_;
  std::size_t particleChunk_;
  int shareFrom_;
  bool shared_ = false;
};

// parallel->forEachChunk, or the same chunks in order on the calling thread when there is no
// ParallelChunks (a mesher or finder used on its own, as the tests do).
template <class Body>
void forEachChunkOn(ParallelChunks* parallel, std::size_t count, std::size_t chunk, Body&& body) {
  if (parallel) {
    parallel->forEachChunk(count, chunk, body);
    return;
  }
  for (std::size_t begin = 0, c = 0; begin < count; begin += chunk, ++c)
    body(static_cast<int>(c), begin, std::min(count, begin + chunk));
}

}  // namespace lacrima::tears
