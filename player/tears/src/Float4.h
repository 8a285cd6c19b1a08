#pragma once
// Four floats as one SSE register, through GCC's vector extension (also understood by Clang):
// element-wise arithmetic compiles to single baseline SSE2 instructions, with the rounding of
// scalar float arithmetic, so results stay bitwise identical on every x86-64 machine (no FMA:
// nothing here is compiled with -march). The pair loops keep 3-vectors in lanes 0..2.
#include <cstring>

namespace lacrima::tears {

using Float4 = float __attribute__((vector_size(16)));
// Lane-wise comparisons of Float4 give -1 (true) or 0 per lane.
using Int4 = int __attribute__((vector_size(16)));

// Unaligned load and store of 4 consecutive floats (std::vector<float> guarantees no more than
// float alignment); GCC turns the memcpy into one movups.
inline Float4 load4(const float* p) {
  Float4 v;
  std::memcpy(&v, p, sizeof v);
  return v;
}
inline void store4(float* p, Float4 v) { std::memcpy(p, &v, sizeof v); }

// A 3-vector (anything with x(), y(), z(), e.g. Eigen::Vector3d) in lanes 0..2, 0 in lane 3.
template <class Vector3>
inline Float4 toFloat4(const Vector3& v) {
  return Float4{static_cast<float>(v.x()), static_cast<float>(v.y()), static_cast<float>(v.z()),
                0.0f};
}

// x^2 + y^2 + z^2 of lanes 0..2, summed in that order (as the scalar code would).
inline float dot3(Float4 a, Float4 b) {
  const Float4 s = a * b;
  return s[0] + s[1] + s[2];
}

}  // namespace lacrima::tears
