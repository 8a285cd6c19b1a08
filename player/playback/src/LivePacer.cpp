// LivePacer (LivePacer.h): render now or wait for the stream's next frame.
#include <lacrima/playback/LivePacer.h>

#include <algorithm>

namespace lacrima::playback {

namespace {

// A gap this long is a pause: the stream starts again, and so does its line.
constexpr double kLongestGap = 2.0;
// Frames needed before the stream counts as regular, and the rates it may have.
constexpr int kFramesToPace = 4;
constexpr double kShortestInterval = 1.0 / 1000.0;

}  // namespace

void LivePacer::frameArrived(double seconds) {
  if (frames_ > 0 &&
      seconds - reads_[static_cast<std::size_t>((frames_ - 1) % kArrivals)] > kLongestGap)
    frames_ = 0;
  reads_[static_cast<std::size_t>(frames_ % kArrivals)] = seconds;
  ++frames_;
  fitStream();
}

// Least squares of read time on frame number over the window, then the line moved down to the
// least delayed read: the reads lie on or above it.
void LivePacer::fitStream() {
  interval_.reset();
  newest_ = -1;
  const long long n = std::min<long long>(frames_, kArrivals);
  if (n < kFramesToPace) return;
  const long long first = frames_ - n;
  auto read = [&](long long k) { return reads_[static_cast<std::size_t>(k % kArrivals)]; };
  const double meanK = static_cast<double>(first) + static_cast<double>(n - 1) / 2;
  double meanT = 0;
  for (long long k = first; k < frames_; ++k) meanT += read(k);
  meanT /= static_cast<double>(n);
  double sKT = 0, sKK = 0;
  for (long long k = first; k < frames_; ++k) {
    const double dk = static_cast<double>(k) - meanK;
    sKT += dk * (read(k) - meanT);
    sKK += dk * dk;
  }
  const double slope = sKT / sKK;
  if (!(slope >= kShortestInterval && slope <= kLongestGap)) return;  // a burst, not a rate
  double phase = read(first) - slope * static_cast<double>(first);
  for (long long k = first + 1; k < frames_; ++k)
    phase = std::min(phase, read(k) - slope * static_cast<double>(k));
  interval_ = slope;
  newest_ = phase + slope * static_cast<double>(frames_ - 1);
}

void LivePacer::rendered(double seconds) {
  if (!(seconds >= 0)) return;
  renders_[static_cast<std::size_t>(nextRender_)] = seconds;
  nextRender_ = (nextRender_ + 1) % kRenders;
  renderCount_ = std::min(renderCount_ + 1, kRenders);
}

std::optional<double> LivePacer::streamInterval() const { return interval_; }
double LivePacer::newestArrival() const { return newest_; }

double LivePacer::renderSeconds() const {
  if (renderCount_ == 0) return 0;
  std::array<double, kRenders> sorted = renders_;
  const auto middle = sorted.begin() + renderCount_ / 2;
  std::nth_element(sorted.begin(), middle, sorted.begin() + renderCount_);
  return *middle;
}

double LivePacer::tolerance(double interval) { return std::max(0.003, 0.25 * interval); }

LivePacer::Decision LivePacer::decide(double now, bool frameWaiting) const {
  const double render = renderSeconds();
  if (!interval_ || render <= 0) return {};
  const double due = newest_ + *interval_;
  const double giveUp = due + tolerance(*interval_);
  if (now > giveUp) return {};  // late: the stream may have stopped
  if (frameWaiting) {
    const double age = now - newest_, wait = due - now;
    const bool fresherByWaiting = wait > 0 && wait < age && due < now + render;
    if (!fresherByWaiting) return {};
    return {false, giveUp};
  }
  if (now + render + kMargin <= due) return {};
  return {false, giveUp};
}

void LivePacer::reset() { *this = LivePacer{}; }

}  // namespace lacrima::playback
