#pragma once
// TriangleBlock: eight triangles tested against one ray at once, each lane computing exactly
// the operations of the scalar test in triangle.h in the same order (no sum reordered, no
// fused operation: the project builds with -ffp-contract=off), so every lane's distance is bit
// for bit triangleDistance's. Written with GCC/Clang vector extensions on vectors as wide as
// the build's registers: four parts of two doubles (SSE2) in the baseline build, two of four
// (AVX) in the x86-64-v3 build, one of eight (AVX-512) in the x86-64-v4 build, the same IEEE
// operations in all. (Vectors wider than the registers would have their comparisons done lane
// by lane.) An unused lane holds NaN corners: its distance is NaN, which fails every
// comparison, as a miss does; parts past a block's used lanes are not computed.

#include <cstdint>
#include <cstring>
#include <limits>

#if defined(__AVX512F__) || defined(__AVX__)
#include <immintrin.h>
#elif defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "trace/triangle.h"

namespace prt {

// Triangles per block.
inline constexpr int kBlockLanes = 8;

namespace block_detail {
#if defined(__AVX512F__) && defined(__AVX512DQ__)
inline constexpr int kWidth = 8;  // lanes per vector
#elif defined(__AVX__)
inline constexpr int kWidth = 4;
#else
inline constexpr int kWidth = 2;
#endif
using Doubles = double __attribute__((vector_size(8 * kWidth)));
using Mask = int64_t __attribute__((vector_size(8 * kWidth)));  // lanes all bits or none

// Bit i set when lane i of the comparison result is true.
inline int bits(const Mask& m) {
#if defined(__AVX512F__) && defined(__AVX512DQ__)
  return _mm512_movepi64_mask(reinterpret_cast<__m512i>(m));
#elif defined(__AVX__)
  return _mm256_movemask_pd(reinterpret_cast<__m256d>(m));
#elif defined(__SSE2__)
  return _mm_movemask_pd(reinterpret_cast<__m128d>(m));
#else
  int b = 0;
  for (int i = 0; i < kWidth; ++i) b |= static_cast<int>(m[i] & 1) << i;
  return b;
#endif
}

// (No function here takes or returns a vector by value: that would change the calling
// convention between builds, which GCC warns about.)
// x - 0 is x for every x, -0 and NaN included (0 + x would turn -0 into +0).
#define PRT_SPLAT(x) ((x) - block_detail::Doubles{})
}  // namespace block_detail

struct TriangleBlock {
  alignas(64) double corner[3][3][kBlockLanes];  // [a, b, c][x, y, z][lane], one per lane

  // Every lane unused.
  TriangleBlock() {
    for (auto& c : corner) {
      for (auto& axis : c) {
        for (double& x : axis) x = std::numeric_limits<double>::quiet_NaN();
      }
    }
  }
  void set(int lane, const double* a, const double* b, const double* c) {
    for (int axis = 0; axis < 3; ++axis) {
      corner[0][axis][lane] = a[axis];
      corner[1][axis][lane] = b[axis];
      corner[2][axis][lane] = c[axis];
    }
  }
};

// A ShearedRay broadcast to a vector's lanes.
struct ShearedRay4 {
  block_detail::Doubles ox, oy, oz;  // the origin along the permuted axes kx, ky, kz
  block_detail::Doubles sx, sy, sz;
  int kx, ky, kz;

  explicit ShearedRay4(const ShearedRay& r)
      : ox(PRT_SPLAT(r.origin[r.kx])),
        oy(PRT_SPLAT(r.origin[r.ky])),
        oz(PRT_SPLAT(r.origin[r.kz])),
        sx(PRT_SPLAT(r.sx)),
        sy(PRT_SPLAT(r.sy)),
        sz(PRT_SPLAT(r.sz)),
        kx(r.kx),
        ky(r.ky),
        kz(r.kz) {}
};

// triangleDistance for each of the first `used` lanes (the lanes in use come first): distance[i]
// is lane i's, bit for bit, or NaN where it misses. Lanes past `used` in a part still computed
// are tested too (their NaN corners miss); those in parts past it are left unset.
// Returns the lanes whose distance d is within range, lo < d < hi (lo < d <= hi with `toHi`),
// as bit i for lane i: from the vectors still in registers, for the caller's next decision.
inline int blockHits(const ShearedRay4& r, const TriangleBlock& t, int used, double lo, double hi,
                     bool toHi, double distance[kBlockLanes]) {
  using block_detail::Doubles;
  using block_detail::Mask;
  auto load = [](const double* p) {
    Doubles v;
    std::memcpy(&v, p, sizeof v);
    return v;
  };
  const Doubles low = PRT_SPLAT(lo), high = PRT_SPLAT(hi);
  int lanes = 0;
  for (int part = 0; part < used; part += block_detail::kWidth) {
    const Doubles az = load(&t.corner[0][r.kz][part]) - r.oz;
    const Doubles bz = load(&t.corner[1][r.kz][part]) - r.oz;
    const Doubles cz = load(&t.corner[2][r.kz][part]) - r.oz;
    const Doubles ax = (load(&t.corner[0][r.kx][part]) - r.ox) - r.sx * az;
    const Doubles ay = (load(&t.corner[0][r.ky][part]) - r.oy) - r.sy * az;
    const Doubles bx = (load(&t.corner[1][r.kx][part]) - r.ox) - r.sx * bz;
    const Doubles by = (load(&t.corner[1][r.ky][part]) - r.oy) - r.sy * bz;
    const Doubles cx = (load(&t.corner[2][r.kx][part]) - r.ox) - r.sx * cz;
    const Doubles cy = (load(&t.corner[2][r.ky][part]) - r.oy) - r.sy * cz;
    const Doubles u = cx * by - cy * bx;  // edge b-c, weight of a
    const Doubles v = ax * cy - ay * cx;  // edge c-a, weight of b
    const Doubles w = bx * ay - by * ax;  // edge a-b, weight of c
    const Doubles zero = {};
    const Mask negative = (u < zero) | (v < zero) | (w < zero);
    const Mask positive = (u > zero) | (v > zero) | (w > zero);
    const Doubles det = u + v + w;
    const Mask miss = (negative & positive) | (det == zero);  // signs differ, or edge-on
    const Doubles d = (u * (r.sz * az) + v * (r.sz * bz) + w * (r.sz * cz)) / det;
    const Doubles result = miss ? PRT_SPLAT(std::numeric_limits<double>::quiet_NaN()) : d;
    std::memcpy(distance + part, &result, sizeof result);
    const Mask within = (result > low) & (toHi ? result <= high : result < high);
    lanes |= block_detail::bits(within) << part;
  }
  return lanes;
}

}  // namespace prt
