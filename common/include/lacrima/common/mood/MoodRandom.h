#pragma once
// The generator's randomness, the same bits on every machine: SplitMix64 (Steele, Lea and
// Flood 2014) for draws, an integer hash of (seed, stream, knot) for smooth noise, and shapes
// made of + - * / only. No std::*_distribution (their output differs between standard
// libraries) and no libm transcendental (glibc does not promise the same last bit everywhere);
// the build targets baseline x86-64, so there is no fused multiply-add to round differently
// (docs/decisions/0005-bit-identical-determinism.md).
#include <cstdint>

namespace lacrima::inline common {

// SplitMix64's finaliser: a 64-bit mix in which every input bit changes about half the output
// bits.
constexpr std::uint64_t mixBits(std::uint64_t x) {
  x += 0x9E3779B97F4A7C15ull;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
  return x ^ (x >> 31);
}

// The seed of one independent stream of a take: components draw from streams of their own, so
// adding a draw to one never shifts another's.
constexpr std::uint64_t streamSeed(std::uint64_t seed, std::uint64_t stream) {
  return mixBits(mixBits(seed) ^ mixBits(stream * 0x632BE59BD9B4E019ull));
}

// [0, 1) from the top 53 bits: every value a multiple of 2^-53.
constexpr double unitInterval(std::uint64_t bits) {
  return static_cast<double>(bits >> 11) * (1.0 / 9007199254740992.0);
}

class MoodRandom {
 public:
  explicit constexpr MoodRandom(std::uint64_t seed = 0) : state_(seed) {}
  constexpr std::uint64_t next() {
    state_ += 0x9E3779B97F4A7C15ull;
    return mixBits(state_ - 0x9E3779B97F4A7C15ull);
  }
  constexpr double uniform() { return unitInterval(next()); }                       // [0, 1)
  constexpr double uniform(double a, double b) { return a + (b - a) * uniform(); }  // [a, b)

 private:
  std::uint64_t state_;
};

// Hermite smoothstep of u clamped to [0, 1].
constexpr double smoothstep(double u) {
  u = u < 0 ? 0 : (u > 1 ? 1 : u);
  return u * u * (3 - 2 * u);
}

// Smooth noise in [-1, 1] with about one wiggle per unit of x: random values at the integers,
// joined by quintic fades (value noise). The same (seed, x) give the same bits at any frame rate.
double smoothNoise(std::uint64_t seed, double x);

// Moves `value` toward `target` by one implicit Euler step of a first-order lag with time
// constant `tau` seconds: stable for any step, never overshoots.
constexpr double approach(double value, double target, double dt, double tau) {
  return tau <= 0 ? target : value + (target - value) * (dt / (tau + dt));
}

}  // namespace lacrima::inline common
