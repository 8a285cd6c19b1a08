#pragma once
// The graph editor's picture of one channel, built once per edit and reused by every repaint:
// the curve sampled by a single-channel bake (>= 120 samples per second, at most 60,000
// samples), the indices of the keys that set the channel, and the range the curve spans (for
// framing and for the normalised view). Drawing then costs one point per pixel column whatever
// the animation's length (polyline below).
#include <lacrima/common/Keyframes.h>

#include <QPolygonF>

#include <functional>
#include <vector>

namespace lacrima::editor {

struct GraphCurve {
  int fap = 0;
  double start = 0.0, rate = 1.0;  // sample i is at start + i / rate
  std::vector<float> samples;
  std::vector<int> keys;         // indices into the sequence of the keys that set `fap`, by time
  double low = 0.0, high = 0.0;  // the values the curve takes (0, 0 when it has no key)

  bool empty() const { return samples.empty(); }
  double end() const { return start + static_cast<double>(samples.size() - 1) / rate; }
  // Linear between samples, held outside them.
  double sampleAt(double seconds) const;
  // Mid and half-height of the range, for Blender's Normalize: (v - mid) / half is in -1..1.
  double mid() const { return 0.5 * (low + high); }
  double half() const { return high - low > 1e-9 ? 0.5 * (high - low) : 1.0; }
};

GraphCurve sampleChannel(const KeyframeSequence& keys, int fap, double fps);

// The curve between times t0 and t1 (the view), clipped to its keys' span: one point per
// pixel column when samples are denser than pixels, else the samples themselves. `xOf` and
// `yOf` map time and value to pixels. The holds outside the keys are not included.
QPolygonF curvePolyline(const GraphCurve& curve, double t0, double t1,
                        const std::function<double(double)>& xOf,
                        const std::function<double(double)>& yOf, double pixelsPerSecond);

}  // namespace lacrima::editor
