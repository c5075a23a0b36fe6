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

#include <array>
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

template <int kLanes>
struct LaneVectors;
template <>
struct LaneVectors<4> {
  using Floats = Float4;
  using Ints = Int4;
};
template <>
struct LaneVectors<8> {
  using Floats = Float8;
  using Ints = Int8;
};

// Bit i set when lane i of a comparison's result is true (all bits set).
inline int laneBits(const Int4& m) {
#if defined(__SSE2__)
  return _mm_movemask_ps(reinterpret_cast<__m128>(m));
#else
  return static_cast<int>((m[0] & 1) | (m[1] & 2) | (m[2] & 4) | (m[3] & 8));
#endif
}
inline int laneBits(const Int8& m) {
#if defined(__AVX__)
  return _mm256_movemask_ps(reinterpret_cast<__m256>(m));
#else
  return laneBits(Int4{m[0], m[1], m[2], m[3]}) | laneBits(Int4{m[4], m[5], m[6], m[7]}) << 4;
#endif
}

namespace detail {
// kPlanes<kLanes>[bits][a]: the byte offset in BoxLanes<kLanes>::planes of axis a's max plane
// where bit a is set, of its min plane otherwise.
template <int kLanes>
constexpr std::array<std::array<uint32_t, 3>, 8> planeOffsets() {
  std::array<std::array<uint32_t, 3>, 8> t{};
  for (int bits = 0; bits < 8; ++bits) {
    for (int a = 0; a < 3; ++a) {
      t[bits][a] = static_cast<uint32_t>((2 * a + ((bits >> a) & 1)) * kLanes * sizeof(float));
    }
  }
  return t;
}
template <int kLanes>
inline constexpr std::array<std::array<uint32_t, 3>, 8> kPlanes = planeOffsets<kLanes>();
}  // namespace detail

// A ray prepared for BoxLanes tests, given M, the largest coordinate magnitude of any box. All
// of it in float SIMD: a handful of instructions per ray.
struct QuadRay {
  // Per lane count: each component broadcast to the lanes, and per axis the byte offsets in
  // BoxLanes::planes of the planes through which the ray enters the slab and leaves it (the
  // min plane when travelling +, the max plane when travelling -).
  template <int kLanes>
  struct Lanes {
    typename LaneVectors<kLanes>::Floats invDirection[3];
    typename LaneVectors<kLanes>::Floats entryOffset[3];  // o*inv + S: p*inv minus it bounds t below
    typename LaneVectors<kLanes>::Floats exitOffset[3];   // o*inv - S: an upper bound
    const uint32_t* entryPlane;
    const uint32_t* exitPlane;
  };
  Lanes<4> four;
  Lanes<8> eight;
  template <int kLanes>
  const Lanes<kLanes>& lanes() const {
    if constexpr (kLanes == 4) {
      return four;
    } else {
      return eight;
    }
  }

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
    // Bit a set when travelling - along axis a (a -0 component has inv = -inf: max side).
    const int octant = signBits(inv) & 7;
    for (int a = 0; a < 3; ++a) {
      // x - 0 is x for every x, -0 included (0 + x would turn -0 into +0).
      const Float4 i4 = invF[a] - Float4{}, in4 = in[a] - Float4{}, out4 = out[a] - Float4{};
      four.invDirection[a] = i4;
      four.entryOffset[a] = in4;
      four.exitOffset[a] = out4;
      eight.invDirection[a] = __builtin_shufflevector(i4, i4, 0, 1, 2, 3, 0, 1, 2, 3);
      eight.entryOffset[a] = __builtin_shufflevector(in4, in4, 0, 1, 2, 3, 0, 1, 2, 3);
      eight.exitOffset[a] = __builtin_shufflevector(out4, out4, 0, 1, 2, 3, 0, 1, 2, 3);
    }
    four.entryPlane = detail::kPlanes<4>[octant].data();
    four.exitPlane = detail::kPlanes<4>[7 - octant].data();
    eight.entryPlane = detail::kPlanes<8>[octant].data();
    eight.exitPlane = detail::kPlanes<8>[7 - octant].data();
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

// kLanes boxes tested against one ray at once (4 or 8: the lanes of LaneVectors).
template <int kLanes>
struct BoxLanes {
  using Floats = typename LaneVectors<kLanes>::Floats;
  using Ints = typename LaneVectors<kLanes>::Ints;
  Floats planes[3][2];  // [axis][0: min plane, 1: max plane], one box per lane

  // Empty boxes in every lane: no ray meets them (unless no axis can be tested at all). The
  // planes are the largest floats, not infinities, so that an axis left out of the test (inv
  // 0) gives no NaN that could drop another axis.
  BoxLanes() {
    const Floats big = std::numeric_limits<float>::max() - Floats{};
    for (auto& axis : planes) {
      axis[0] = big;
      axis[1] = -big;
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
  int hits(const QuadRay& r, float tMin, float tMax, Floats& entry) const {
    const QuadRay::Lanes<kLanes>& l = r.lanes<kLanes>();
    const Floats lowest = tMin - Floats{};  // x - 0 is x, -0 included
    const Floats highest = tMax - Floats{};
    const char* base = reinterpret_cast<const char*>(planes);
    Floats tIn[3], tOut[3];
    for (int a = 0; a < 3; ++a) {
      tIn[a] = *reinterpret_cast<const Floats*>(base + l.entryPlane[a]) * l.invDirection[a] -
               l.entryOffset[a];
      tOut[a] = *reinterpret_cast<const Floats*>(base + l.exitPlane[a]) * l.invDirection[a] -
                l.exitOffset[a];
    }
    // The interval's ends in two steps instead of three (a shorter chain of dependent
    // operations). A NaN (0 * inf: a box beyond float's range on an axis that is not tested)
    // makes a pair take its second operand, so it may drop the other axis of its pair: that
    // only accepts more.
    const Floats in01 = tIn[0] > tIn[1] ? tIn[0] : tIn[1];
    const Floats in2 = tIn[2] > lowest ? tIn[2] : lowest;
    const Floats out01 = tOut[0] < tOut[1] ? tOut[0] : tOut[1];
    const Floats out2 = tOut[2] < highest ? tOut[2] : highest;
    const Floats lo = in01 > in2 ? in01 : in2;
    const Floats hi = out01 < out2 ? out01 : out2;
    entry = lo;
    const Ints inside = lo <= hi;  // per lane: all bits set or clear
    return laneBits(inside);
  }
};

// Four boxes, and eight: a tree node's children, one AVX instruction per operation where the
// x86-64-v3 build has them (two SSE ones in the baseline build), the same IEEE operations lane
// for lane, so a BoxOct gives the masks and entries of two BoxQuads holding its boxes.
using BoxQuad = BoxLanes<4>;
using BoxOct = BoxLanes<8>;

}  // namespace prt
