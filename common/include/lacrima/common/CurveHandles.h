#pragma once
// The Bézier handles a channel's curve actually uses at one of its keys, for views that draw
// them (the graph editor) and edits that start from them (dragging an auto handle).
//
// Stored handles (Aligned, Free) are returned as stored. Auto handles store nothing; they are
// computed as KeyframeSequence::evaluate computes them: a third of the adjacent segment along
// the Smooth (Steffen) slope m at the key,
//   in  = (-h_in / 3, -m h_in / 3),   out = (h_out / 3, m h_out / 3),
// h_in, h_out = the durations of the channel's segments arriving at and leaving the key.
// Both functions use the very slope code of Keyframes.cpp, so a drawn auto handle is where the
// curve's tangent is.
#include <lacrima/common/Keyframes.h>

#include <array>

namespace lacrima::inline common {

struct EffectiveHandles {
  Handle in, out;
  bool hasIn = false;   // the channel has a key before this one (a segment arrives)
  bool hasOut = false;  // ... and after it (a segment leaves)
};

// Handles of channel `fap` at keys()[keyIndex]. Throws std::out_of_range when there is no such
// key or it does not set `fap`. Looks at no more than two of the channel's keys to either side.
EffectiveHandles effectiveHandles(const KeyframeSequence& keys, int fap, int keyIndex);

// The Smooth (Steffen) slope of channel `fap` at keys()[keyIndex], in channel units per second
// (0 for a channel with one key). Same preconditions as effectiveHandles.
double smoothSlope(const KeyframeSequence& keys, int fap, int keyIndex);

// --- the Bézier segment as a function of time ---------------------------------------------
// A segment P(u) = (x(u), y(u)), u in [0, 1], with x(u) = (1-u)^3 x0 + 3u(1-u)^2 x1 +
// 3u^2(1-u) x2 + u^3 x3 non-decreasing (KeyframeSequence limits the handles so that it is), is
// evaluated at time t by solving x(u) = t for u. The solve is bisection safeguarding Newton
// steps, starting at u = (t - x0) / (x3 - x0): each step keeps a bracket [lo, hi] around the
// root and takes the Newton step when it stays inside, else halves the bracket. It stops once
// |x(u) - t| <= tolerance * max(1, |t|), or after maxSteps (60 halvings reach a double's
// resolution for any segment). Auto handles make x linear in u, so Newton ends at once.

struct BezierSolverSettings {
  double tolerance = 1e-12;  // relative to max(1, |t|); KeyframeSequence uses the default
  int maxSteps = 60;
};

struct BezierTimeSolve {
  double u = 0.0;
  int steps = 0;  // Newton or bisection steps taken
};

BezierTimeSolve solveBezierTime(const std::array<double, 4>& x, double t,
                                BezierSolverSettings settings = {});

}  // namespace lacrima::inline common
