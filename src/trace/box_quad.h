#pragma once
// BoxQuad: four axis-aligned boxes tested against a ray at once, in single precision (the four
// lanes of an SSE2 register, through GCC/Clang vector extensions: baseline x86-64, no wider ISA,
// so every machine computes the same bits). It only culls, for the BVH: a lane is true whenever
// `hitsBounds` (double precision) would be true for that box, never lose a hit.
//
// Why that holds, per axis: the float test computes tIn = p*inv - (o*inv + S) and
// tOut = p*inv - (o*inv - S) for a plane p, where inv = 1/d is computed in float from the
// direction rounded to float, and the slack S = 2^-18 |inv| (M + |o|) with M bounding |p| over
// the whole tree. Rounding p, d and o to float, the division, o*inv +- S and the two float
// operations of the test err by at most about 2^-24 (7 |inv| (M + |o|) + 2 S), and
// hitsBounds' own double (p - o) * inv by 2^-52 |inv| (|p| + |o|): together well under S
// (by a factor of five), so tIn never exceeds the double entry and tOut never falls short of
// the double exit. The search interval is rounded outwards to float. Where the bound would
// leave float's range (huge coordinates, a direction component near zero), the axis is left
// out of the test, which only accepts more. A NaN (0 * inf) widens the interval, as in
// hitsBounds: also accepting.

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

#if defined(__AVX__)
#include <immintrin.h>
#elif defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "core/ray.h"
#include "core/select.h"
#include "trace/bounds.h"

namespace prt {

using Float4 = float __attribute__((vector_size(16)));
using Int4 = int32_t __attribute__((vector_size(16)));
// Eight lanes: one AVX register in the x86-64-v3 build, two SSE registers in the baseline
// build (GCC splits each operation in two), the same IEEE operations lane by lane in both.
using Float8 = float __attribute__((vector_size(32)));
using Int8 = int32_t __attribute__((vector_size(32)));

namespace detail {
// kQuadPlanes[bits][a]: the byte offset in BoxQuad::planes of axis a's max plane where bit a
// is set, of its min plane otherwise.
constexpr uint32_t quadPlane(int bits, int a) {
  return static_cast<uint32_t>((2 * a + ((bits >> a) & 1)) * sizeof(Float4));
}
inline constexpr uint32_t kQuadPlanes[8][3] = {
    {quadPlane(0, 0), quadPlane(0, 1), quadPlane(0, 2)},
    {quadPlane(1, 0), quadPlane(1, 1), quadPlane(1, 2)},
    {quadPlane(2, 0), quadPlane(2, 1), quadPlane(2, 2)},
    {quadPlane(3, 0), quadPlane(3, 1), quadPlane(3, 2)},
    {quadPlane(4, 0), quadPlane(4, 1), quadPlane(4, 2)},
    {quadPlane(5, 0), quadPlane(5, 1), quadPlane(5, 2)},
    {quadPlane(6, 0), quadPlane(6, 1), quadPlane(6, 2)},
    {quadPlane(7, 0), quadPlane(7, 1), quadPlane(7, 2)}};
// The same for BoxOct::planes, whose lanes are twice as wide.
constexpr uint32_t octPlane(int bits, int a) { return 2 * quadPlane(bits, a); }
inline constexpr uint32_t kOctPlanes[8][3] = {
    {octPlane(0, 0), octPlane(0, 1), octPlane(0, 2)},
    {octPlane(1, 0), octPlane(1, 1), octPlane(1, 2)},
    {octPlane(2, 0), octPlane(2, 1), octPlane(2, 2)},
    {octPlane(3, 0), octPlane(3, 1), octPlane(3, 2)},
    {octPlane(4, 0), octPlane(4, 1), octPlane(4, 2)},
    {octPlane(5, 0), octPlane(5, 1), octPlane(5, 2)},
    {octPlane(6, 0), octPlane(6, 1), octPlane(6, 2)},
    {octPlane(7, 0), octPlane(7, 1), octPlane(7, 2)}};
}  // namespace detail

// A ray prepared for BoxQuad tests, given M, the largest coordinate magnitude of any box. All
// of it in float SIMD: a handful of instructions per ray.
struct QuadRay {
  Float4 invDirection[3];  // each component broadcast to the four lanes
  Float4 entryOffset[3];   // o*inv + S: subtracted from p*inv gives a lower bound of t
  Float4 exitOffset[3];    // o*inv - S: an upper bound
  // Per axis, the byte offsets in BoxQuad::planes of the planes through which the ray enters
  // the slab and leaves it: the min plane when travelling +, the max plane when travelling -.
  const uint32_t* entryPlane;
  const uint32_t* exitPlane;
  // The same broadcast to eight lanes, and the offsets in BoxOct::planes, for BoxOct.
  Float8 invDirection8[3];
  Float8 entryOffset8[3];
  Float8 exitOffset8[3];
  const uint32_t* entryPlane8;
  const uint32_t* exitPlane8;

  QuadRay(const Ray& ray, float maxCoordinate) {
    constexpr float inf = std::numeric_limits<float>::infinity();
    constexpr Float4 kOne = {1, 1, 1, 1}, kZero = {0, 0, 0, 0};
    constexpr Float4 kInf = {inf, inf, inf, inf}, kMinusInf = -kInf;
    constexpr Float4 kSlack = {0x1p-18f, 0x1p-18f, 0x1p-18f, 0x1p-18f};
    constexpr Float4 kTiny = {0x1p-100f, 0x1p-100f, 0x1p-100f, 0x1p-100f};
    constexpr Float4 kLargest = {0x1p100f, 0x1p100f, 0x1p100f, 0x1p100f};
    const Float4 d = toFloat4(ray.direction);  // the fourth lane is 0: padding
    const Float4 o = toFloat4(ray.origin);
    const Float4 inv = kOne / d;  // a zero (or tiny) component gives +-inf: no test on it
    const Float4 absInv = std::bit_cast<Float4>(std::bit_cast<Int4>(inv) & 0x7fffffff);
    const Float4 absO = std::bit_cast<Float4>(std::bit_cast<Int4>(o) & 0x7fffffff);
    const Float4 scale = absInv * (maxCoordinate + absO);
    const Float4 slack = kSlack * scale + kTiny;
    const Float4 oi = o * inv;
    // Where the bound would leave float's range (or is NaN), leave the axis out of the test:
    // inv 0, entry offset +inf, exit offset -inf make tIn = -inf and tOut = +inf.
    const Int4 usable = scale <= kLargest;
    const Float4 invF = usable ? inv : kZero;
    const Float4 in = usable ? oi + slack : kInf;
    const Float4 out = usable ? oi - slack : kMinusInf;
    invDirection[0] = __builtin_shufflevector(invF, invF, 0, 0, 0, 0);
    invDirection[1] = __builtin_shufflevector(invF, invF, 1, 1, 1, 1);
    invDirection[2] = __builtin_shufflevector(invF, invF, 2, 2, 2, 2);
    entryOffset[0] = __builtin_shufflevector(in, in, 0, 0, 0, 0);
    entryOffset[1] = __builtin_shufflevector(in, in, 1, 1, 1, 1);
    entryOffset[2] = __builtin_shufflevector(in, in, 2, 2, 2, 2);
    exitOffset[0] = __builtin_shufflevector(out, out, 0, 0, 0, 0);
    exitOffset[1] = __builtin_shufflevector(out, out, 1, 1, 1, 1);
    exitOffset[2] = __builtin_shufflevector(out, out, 2, 2, 2, 2);
    // Bit a set when travelling - along axis a (a -0 component has inv = -inf: max side).
    const int octant = signBits(inv) & 7;
    entryPlane = detail::kQuadPlanes[octant];
    exitPlane = detail::kQuadPlanes[7 - octant];
    for (int a = 0; a < 3; ++a) {
      invDirection8[a] = __builtin_shufflevector(invDirection[a], invDirection[a], 0, 1, 2, 3,
                                                 0, 1, 2, 3);
      entryOffset8[a] = __builtin_shufflevector(entryOffset[a], entryOffset[a], 0, 1, 2, 3, 0,
                                                1, 2, 3);
      exitOffset8[a] = __builtin_shufflevector(exitOffset[a], exitOffset[a], 0, 1, 2, 3, 0, 1,
                                               2, 3);
    }
    entryPlane8 = detail::kOctPlanes[octant];
    exitPlane8 = detail::kOctPlanes[7 - octant];
  }

 private:
  // (v.x, v.y, v.z, 0) rounded to float.
  static Float4 toFloat4(const Vec3& v) {
#if defined(__SSE2__)
    const __m128 xy = _mm_cvtpd_ps(_mm_loadu_pd(&v.x));
    const __m128 z = _mm_cvtsd_ss(_mm_setzero_ps(), _mm_load_sd(&v.z));
    return reinterpret_cast<Float4>(_mm_movelh_ps(xy, z));
#else
    return Float4{static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z), 0};
#endif
  }
  // Bit i set when lane i is negative (sign bit set and not NaN: -0 is not negative).
  static int signBits(const Float4& v) {
    const Int4 negative = v < Float4{0, 0, 0, 0};
#if defined(__SSE2__)
    return _mm_movemask_ps(reinterpret_cast<__m128>(negative));
#else
    return (negative[0] & 1) | (negative[1] & 2) | (negative[2] & 4) | (negative[3] & 8);
#endif
  }
};

// The nearest float at or below x, and at or above x (x not NaN).
inline float floatBelow(double x) {
  const auto f = static_cast<float>(x);
  // Rounding went up: step one float down (f is finite and nonzero then). Without a branch,
  // the outcome being a coin toss.
  const uint32_t bits = std::bit_cast<uint32_t>(f);
  const uint32_t down = bits + 1u - 2u * static_cast<uint32_t>(f > 0);  // -1 or +1
  return std::bit_cast<float>(selectBits(static_cast<double>(f) > x, down, bits));
}
inline float floatAbove(double x) { return -floatBelow(-x); }

struct BoxQuad {
  Float4 planes[3][2];  // [axis][0: min plane, 1: max plane], one box per lane

  // Empty boxes in every lane: no ray meets them (unless no axis can be tested at all). The
  // planes are the largest floats, not infinities, so that an axis left out of the test (inv
  // 0) gives no NaN that could drop another axis.
  BoxQuad() {
    constexpr float big = std::numeric_limits<float>::max();
    for (auto& axis : planes) {
      axis[0] = Float4{big, big, big, big};
      axis[1] = Float4{-big, -big, -big, -big};
    }
  }

  // Rounded to nearest: the slack covers it.
  void set(int lane, const Bounds& b) {
    for (int a = 0; a < 3; ++a) {
      planes[a][0][lane] = static_cast<float>(b.lo[a]);
      planes[a][1][lane] = static_cast<float>(b.hi[a]);
    }
  }

  // Bit i set when box i may meet the ray within the interval [tMin, tMax] (floats rounded
  // outwards from the doubles), with a lower bound of the entry distance in `entry[i]`.
  int hits(const QuadRay& r, float tMin, float tMax, Float4& entry) const {
    const Float4 lowest = {tMin, tMin, tMin, tMin};
    const Float4 highest = {tMax, tMax, tMax, tMax};
    const char* base = reinterpret_cast<const char*>(planes);
    Float4 tIn[3], tOut[3];
    for (int a = 0; a < 3; ++a) {
      tIn[a] = *reinterpret_cast<const Float4*>(base + r.entryPlane[a]) * r.invDirection[a] -
               r.entryOffset[a];
      tOut[a] = *reinterpret_cast<const Float4*>(base + r.exitPlane[a]) * r.invDirection[a] -
                r.exitOffset[a];
    }
    // The interval's ends in two steps instead of three (a shorter chain of dependent
    // operations). A NaN (0 * inf: a box beyond float's range on an axis that is not tested)
    // makes a pair take its second operand, so it may drop the other axis of its pair: that
    // only accepts more.
    const Float4 in01 = tIn[0] > tIn[1] ? tIn[0] : tIn[1];
    const Float4 in2 = tIn[2] > lowest ? tIn[2] : lowest;
    const Float4 out01 = tOut[0] < tOut[1] ? tOut[0] : tOut[1];
    const Float4 out2 = tOut[2] < highest ? tOut[2] : highest;
    const Float4 lo = in01 > in2 ? in01 : in2;
    const Float4 hi = out01 < out2 ? out01 : out2;
    entry = lo;
    const auto inside = lo <= hi;  // per lane: all bits set or clear
#if defined(__SSE2__)
    return _mm_movemask_ps(reinterpret_cast<__m128>(inside));
#else
    return static_cast<int>((inside[0] & 1) | (inside[1] & 2) | (inside[2] & 4) | (inside[3] & 8));
#endif
  }
};

// Eight boxes tested at once: BoxQuad's test, lane for lane the same operations in the same
// order (so the same masks and entries as two BoxQuads holding the same boxes), in half the
// instructions where the build has AVX.
struct BoxOct {
  Float8 planes[3][2];  // [axis][0: min plane, 1: max plane], one box per lane

  BoxOct() {
    constexpr float big = std::numeric_limits<float>::max();
    for (auto& axis : planes) {
      axis[0] = Float8{big, big, big, big, big, big, big, big};
      axis[1] = -axis[0];
    }
  }

  void set(int lane, const Bounds& b) {
    for (int a = 0; a < 3; ++a) {
      planes[a][0][lane] = static_cast<float>(b.lo[a]);
      planes[a][1][lane] = static_cast<float>(b.hi[a]);
    }
  }

  // As BoxQuad::hits, for eight boxes: bit i for box i.
  int hits(const QuadRay& r, float tMin, float tMax, Float8& entry) const {
    const Float8 lowest = {tMin, tMin, tMin, tMin, tMin, tMin, tMin, tMin};
    const Float8 highest = {tMax, tMax, tMax, tMax, tMax, tMax, tMax, tMax};
    const char* base = reinterpret_cast<const char*>(planes);
    Float8 tIn[3], tOut[3];
    for (int a = 0; a < 3; ++a) {
      tIn[a] = *reinterpret_cast<const Float8*>(base + r.entryPlane8[a]) * r.invDirection8[a] -
               r.entryOffset8[a];
      tOut[a] = *reinterpret_cast<const Float8*>(base + r.exitPlane8[a]) * r.invDirection8[a] -
                r.exitOffset8[a];
    }
    const Float8 in01 = tIn[0] > tIn[1] ? tIn[0] : tIn[1];
    const Float8 in2 = tIn[2] > lowest ? tIn[2] : lowest;
    const Float8 out01 = tOut[0] < tOut[1] ? tOut[0] : tOut[1];
    const Float8 out2 = tOut[2] < highest ? tOut[2] : highest;
    const Float8 lo = in01 > in2 ? in01 : in2;
    const Float8 hi = out01 < out2 ? out01 : out2;
    entry = lo;
    const Int8 inside = lo <= hi;  // per lane: all bits set or clear
#if defined(__AVX__)
    return _mm256_movemask_ps(reinterpret_cast<__m256>(inside));
#elif defined(__SSE2__)
    const Int4 low = __builtin_shufflevector(inside, inside, 0, 1, 2, 3);
    const Int4 high = __builtin_shufflevector(inside, inside, 4, 5, 6, 7);
    return _mm_movemask_ps(reinterpret_cast<__m128>(low)) |
           _mm_movemask_ps(reinterpret_cast<__m128>(high)) << 4;
#else
    int bits = 0;
    for (int i = 0; i < 8; ++i) bits |= (inside[i] & 1) << i;
    return bits;
#endif
  }
};

}  // namespace prt
