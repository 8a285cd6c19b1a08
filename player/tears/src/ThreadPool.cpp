#include "ThreadPool.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#endif

namespace lacrima::tears {

namespace {

// Polls ready() for up to ThreadPool::kSpin; whether it became true. The pause tells the core
// (and a hypervisor) that this is a spin loop. Every 64 polls the clock is read and the core
// offered to any other runnable thread: with two two-thread simulations on two cores a pure
// spin took the cores from the threads with work (114-126 ms a frame at 10,000 particles
// against 69-75 with a sleeping pool); yielding gives 69-77, and costs nothing on idle cores.
template <class Ready>
bool spinUntil(Ready ready) {
  const auto until = std::chrono::steady_clock::now() + ThreadPool::kSpin;
  for (unsigned k = 1;; ++k) {
    if (ready()) return true;
#if defined(__x86_64__) || defined(__i386__)
    _mm_pause();
#endif
    if (k % 64 == 0) {
      if (std::chrono::steady_clock::now() > until) return false;
      std::this_thread::yield();
    }
  }
}

}  // namespace

ThreadPool::ThreadPool(int threads) : threads_(std::max(1, threads)) {}

ThreadPool::~ThreadPool() {
  // Joined here, not by the jthreads' own destructors: those would run after mutex_ and the
  // condition variables (declared later) are gone, while a worker may still be leaving wait().
  for (auto& w : workers_) w.request_stop();
  wake_.notify_all();
  for (auto& w : workers_) w.join();
}

void ThreadPool::start() {
  workers_.reserve(static_cast<std::size_t>(threads_ - 1));
  for (int t = 1; t < threads_; ++t)
    workers_.emplace_back([this, t](const std::stop_token& stop) { work(stop, t); });
}

int ThreadPool::take(int thread) {
  const auto own = static_cast<std::size_t>(thread);
  if (front_[own] < back_[own]) return front_[own]++;
  // Own block done: the last chunk of the block with the most left (its owner keeps the
  // chunks next to the ones it has just run).
  std::size_t victim = own;
  int most = 0;
  for (std::size_t u = 0; u < front_.size(); ++u)
    if (back_[u] - front_[u] > most) {
      most = back_[u] - front_[u];
      victim = u;
    }
  return most > 0 ? --back_[victim] : -1;
}

void ThreadPool::drain(int thread) {
  std::unique_lock lock(mutex_);
  for (int c = take(thread); c >= 0; c = take(thread)) {
    const std::function<void(int)>& job = *job_;
    lock.unlock();
    job(c);
    lock.lock();
    if (++done_ == chunks_) {
      completed_.store(generation_.load(std::memory_order_relaxed), std::memory_order_release);
      finished_.notify_one();
    }
  }
}

void ThreadPool::work(const std::stop_token& stop, int thread) {
  std::uint64_t seen = 0;
  const auto started = [&] { return generation_.load(std::memory_order_acquire) != seen; };
  for (;;) {
    if (!spinUntil(started)) {
      std::unique_lock lock(mutex_);
      if (!wake_.wait(lock, stop, started)) return;
    }
    seen = generation_.load(std::memory_order_acquire);
    drain(thread);
  }
}

void ThreadPool::run(int chunks, const std::function<void(int)>& job) {
  if (chunks <= 0) return;
  if (threads_ == 1 || chunks == 1) {
    for (int c = 0; c < chunks; ++c) job(c);
    return;
  }
  if (workers_.empty()) start();
  std::uint64_t generation = 0;
  {
    std::lock_guard lock(mutex_);
    job_ = &job;
    chunks_ = chunks;
    done_ = 0;
    const auto t = static_cast<std::size_t>(threads_);
    front_.resize(t);
    back_.resize(t);
    for (std::size_t k = 0; k < t; ++k) {
      front_[k] = static_cast<int>(k * static_cast<std::size_t>(chunks) / t);
      back_[k] = static_cast<int>((k + 1) * static_cast<std::size_t>(chunks) / t);
    }
    generation = generation_.load(std::memory_order_relaxed) + 1;
    generation_.store(generation, std::memory_order_release);
  }
  wake_.notify_all();
  drain(0);
  const auto finished = [&] { return completed_.load(std::memory_order_acquire) == generation; };
  if (spinUntil(finished)) return;
  std::unique_lock lock(mutex_);
  finished_.wait(lock, finished);
  // Every chunk is handed out before done_ reaches chunks_, so a worker that wakes late finds
  // no chunk left and goes back to sleep without touching job_.
}

int resolveThreadCount(int requested) {
  if (requested > 0) return requested;
  if (const char* text = std::getenv("LACRIMA_THREADS"); text && *text) {
    char* end = nullptr;
    const long value = std::strtol(text, &end, 10);
    if (*end == '\0' && value >= 1 && value <= 256) return static_cast<int>(value);
    static std::once_flag reported;
    std::call_once(reported, [&] {
      std::fprintf(stderr,
                   "LACRIMA_THREADS: expected a whole number from 1 to 256, not '%s'; using every "
                   "hardware thread\n",
                   text);
    });
  }
  return std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
}

}  // namespace lacrima::tears
