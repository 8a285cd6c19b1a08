#pragma once
// Entry guard of the heavy per-frame calls (simulation step, surface mesher, trail builder).
//
// The library is compiled for baseline x86-64 (SSE2: bitwise-identical results everywhere, see
// Float4.h). When code elsewhere in the process (Qt, the renderer, a driver) has left the upper
// halves of the AVX registers dirty, every legacy-SSE instruction then carries a false
// dependency or a state transition, and measured on this project's machine the whole step ran
// 2.2x slower (1.70 against 0.76 ms for 100 particles on the default head, after loading it
// with Qt). VZEROUPPER on entry restores full speed. It changes no lower 128 bits, so no result
// changes; it is issued only where the CPU and OS support AVX (checked once).
namespace lacrima::tears {

#if defined(__GNUC__) && (defined(__x86_64__) || defined(__i386__))
namespace detail {
__attribute__((target("avx"))) inline void zeroUpper() { __builtin_ia32_vzeroupper(); }
inline bool avxUsable() {
  static const bool usable = __builtin_cpu_supports("avx");
  return usable;
}
}  // namespace detail

inline void clearUpperVectorState() {
  if (detail::avxUsable()) detail::zeroUpper();
}
#else
inline void clearUpperVectorState() {}
#endif

}  // namespace lacrima::tears
