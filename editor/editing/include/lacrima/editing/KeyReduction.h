#pragma once
// Key reduction for imported FAP files: keep as few frames as keys as the tolerance allows.
//
// Frames f_0..f_{n-1} at t_i = i / fps, each with values v_c(i) on the animated channels C.
// Keys kept at frames a < b reproduce a frame i between them as the editor will play it back
// with linear keys:
//   r_c(i) = v_c(a) + (t_i - t_a) / (t_b - t_a) (v_c(b) - v_c(a))   ordinary channels
//   r_c(i) = max(0, round(r_c(i)))                                  tear channels 69, 70
//   r_c(i) = v_c(a)                                                 FAP 1, 2 (codes hold)
// and the error of frame i is e(i) = max over c in C of |r_c(i) - v_c(i)|, in the channels'
// own units (FAPU steps, AU, particles): one tolerance for every channel. Below 0.5 an integer
// file is written back unchanged; at 1 the keys follow the motion rather than the rounding
// staircase of integer files (the editor's default).
//
// Ramer-Douglas-Peucker over all channels at once: keep the first and last frame; on a span
// (a, b) find the frame m with the largest e; if e(m) > tolerance, keep m and split into
// (a, m) and (m, b); otherwise drop every frame inside. Spans only split at kept frames, so
// the last span a dropped frame was tested in is bounded by its neighbouring keys: every
// dropped frame is reproduced within the tolerance on every channel. Typical cost is
// O(n log n |C|); a span is never rescanned once accepted. Tolerance 0 drops exactly the
// frames that lie on the straight line between their neighbouring keys.
#include <lacrima/common/FapAnimation.h>

#include <vector>

namespace lacrima::editing {

// Indices of the frames to keep, ascending; always includes the first and last frame.
std::vector<int> reduceKeyFrames(const FapAnimation& animation, double tolerance);

// The largest error e(i) over all frames when only `kept` frames are keys (for reports).
double reductionError(const FapAnimation& animation, const std::vector<int>& kept);

}  // namespace lacrima::editing
