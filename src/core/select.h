#pragma once
// Branch-free selects for the tracer's hot paths. Whether a ray meets a box, or which of two
// slab distances is the nearer, is a coin toss that a branch predictor loses about half the
// time, at the cost of a pipeline flush each; compilers often keep such a ternary as a branch.
// These compile to one SSE2 instruction (minsd, maxsd) or to flag arithmetic, and give
// exactly the result of the ternary they are named after, NaN cases included.

#include <cstdint>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace prt {

#if defined(__SSE2__)
namespace select_detail {
// `a` in a register the compiler knows nothing about. GCC folds minsd and maxsd of two
// constants by rules other than the processor's (min(NaN, 1) to NaN, where minsd gives 1);
// with one operand opaque the instruction is always executed. Costs no instruction.
inline __m128d opaque(double a) {
  __m128d x = _mm_set_sd(a);
  asm("" : "+x"(x));
  return x;
}
}  // namespace select_detail
#endif

// a < b ? a : b (b when either is NaN), as minsd computes it.
inline double lessOr(double a, double b) {
#if defined(__SSE2__)
  return _mm_cvtsd_f64(_mm_min_sd(select_detail::opaque(a), _mm_set_sd(b)));
#else
  return a < b ? a : b;
#endif
}

// a > b ? a : b (b when either is NaN), as maxsd computes it.
inline double greaterOr(double a, double b) {
#if defined(__SSE2__)
  return _mm_cvtsd_f64(_mm_max_sd(select_detail::opaque(a), _mm_set_sd(b)));
#else
  return a > b ? a : b;
#endif
}

// condition ? a : b for integers, without a branch.
inline uint32_t selectBits(bool condition, uint32_t a, uint32_t b) {
  const uint32_t mask = 0u - static_cast<uint32_t>(condition);
  return b ^ ((a ^ b) & mask);
}

}  // namespace prt
