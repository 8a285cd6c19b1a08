#include "ThreadPool.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace lacrima::tears {

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
    workers_.emplace_back([this](const std::stop_token& stop) { work(stop); });
}

void ThreadPool::drain() {
  std::unique_lock lock(mutex_);
  while (next_ < chunks_) {
    const int c = next_++;
    const std::function<void(int)>& job = *job_;
    lock.unlock();
    job(c);
    lock.lock();
    if (++done_ == chunks_) finished_.notify_one();
  }
}

void ThreadPool::work(const std::stop_token& stop) {
  std::uint64_t seen = 0;
  for (;;) {
    {
      std::unique_lock lock(mutex_);
      if (!wake_.wait(lock, stop, [&] { return generation_ != seen; })) return;
      seen = generation_;
    }
    drain();
  }
}

void ThreadPool::run(int chunks, const std::function<void(int)>& job) {
  if (chunks <= 0) return;
  if (threads_ == 1 || chunks == 1) {
    for (int c = 0; c < chunks; ++c) job(c);
    return;
  }
  if (workers_.empty()) start();
  {
    std::lock_guard lock(mutex_);
    job_ = &job;
    chunks_ = chunks;
    next_ = 0;
    done_ = 0;
    ++generation_;
  }
  wake_.notify_all();
  drain();
  std::unique_lock lock(mutex_);
  finished_.wait(lock, [&] { return done_ == chunks_; });
  // Every chunk is handed out before done_ reaches chunks_, so a worker that wakes late finds
  // next_ == chunks_ and goes back to sleep without touching job_.
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
