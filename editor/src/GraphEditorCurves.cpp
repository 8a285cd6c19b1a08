#include "GraphEditorCurves.h"

#include <algorithm>
#include <cmath>

namespace lacrima::editor {
namespace {

// Enough that a Bézier overshoot between two keys a frame apart still shows its shape at the
// widest useful zoom; the cap keeps an hour-long channel at 240 KB.
constexpr double kSampleRate = 120.0;
constexpr double kMaxSamples = 60000.0;

}  // namespace

double GraphCurve::sampleAt(double seconds) const {
  if (samples.empty()) return 0.0;
  const double f =
      std::clamp((seconds - start) * rate, 0.0, static_cast<double>(samples.size() - 1));
  const std::size_t i = static_cast<std::size_t>(f);
  const std::size_t j = std::min(i + 1, samples.size() - 1);
  return samples[i] + (f - static_cast<double>(i)) * (samples[j] - samples[i]);
}

GraphCurve sampleChannel(const KeyframeSequence& keys, int fap, double fps) {
  GraphCurve curve;
  curve.fap = fap;
  // The channel alone, with its values and shapes: its curve is the one the document bakes,
  // since a channel's curve depends only on the keys that set it.
  std::vector<Keyframe> own;
  for (std::size_t k = 0; k < keys.keys().size(); ++k) {
    const Keyframe& key = keys.keys()[k];
    if (!key.has(fap)) continue;
    curve.keys.push_back(static_cast<int>(k));
    Keyframe only;
    only.time = key.time;
    only.interpolation = key.interpolation;
    only.set(fap, key.value(fap));
    only.setShape(fap, key.shape(fap));
    own.push_back(std::move(only));
  }
  if (own.empty()) return curve;
  const KeyframeSequence channel(std::move(own));
  const double duration = channel.endTime() - channel.startTime();
  double rate = std::max(kSampleRate, fps);
  if (duration * rate > kMaxSamples) rate = kMaxSamples / duration;
  const FapAnimation baked = channel.bake(rate);
  curve.start = channel.startTime();
  curve.rate = rate;
  curve.samples.reserve(baked.frames.size());
  const std::size_t index = static_cast<std::size_t>(channelIndex(fap));
  for (const FapValues& frame : baked.frames) curve.samples.push_back(frame[index]);
  const auto [low, high] = std::minmax_element(curve.samples.begin(), curve.samples.end());
  curve.low = *low;
  curve.high = *high;
  for (const Keyframe& key : channel.keys()) {
    curve.low = std::min<double>(curve.low, key.value(fap));
    curve.high = std::max<double>(curve.high, key.value(fap));
  }
  return curve;
}

QPolygonF curvePolyline(const GraphCurve& curve, double t0, double t1,
                        const std::function<double(double)>& xOf,
                        const std::function<double(double)>& yOf, double pixelsPerSecond) {
  QPolygonF line;
  if (curve.empty()) return line;
  const double from = std::max(t0, curve.start);
  const double to = std::min(t1, curve.end());
  if (from > to) return line;
  if (curve.rate >= pixelsPerSecond) {
    // More samples than pixels: one point per pixel column.
    const double x0 = xOf(from), x1 = xOf(to);
    line.reserve(static_cast<qsizetype>(x1 - x0) + 2);
    for (double x = x0; x < x1; x += 1.0) {
      const double t = from + (x - x0) / pixelsPerSecond;
      line << QPointF(x, yOf(curve.sampleAt(t)));
    }
    line << QPointF(x1, yOf(curve.sampleAt(to)));
    return line;
  }
  const std::size_t last = curve.samples.size() - 1;
  const std::size_t i0 = static_cast<std::size_t>(std::floor((from - curve.start) * curve.rate));
  const std::size_t i1 =
      std::min(last, static_cast<std::size_t>(std::ceil((to - curve.start) * curve.rate)));
  for (std::size_t i = std::min(i0, last); i <= i1; ++i) {
    const double t = curve.start + static_cast<double>(i) / curve.rate;
    line << QPointF(xOf(t), yOf(curve.samples[i]));
  }
  return line;
}

}  // namespace lacrima::editor
