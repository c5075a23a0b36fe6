#pragma once
// TriangleBlock: four triangles tested against one ray at once, each lane computing exactly
// the operations of the scalar test in triangle.h in the same order (no sum reordered, no
// fused operation: the project builds with -ffp-contract=off), so every lane's distance is bit
// for bit triangleDistance's. Written with GCC/Clang vector extensions on vectors as wide as
// the build's registers: two halves of two doubles (SSE2) in the baseline build, one vector of
// four (AVX) in the x86-64-v3 build, the same IEEE operations in both. (Vectors wider than the
// registers would have their comparisons done lane by lane.) An unused lane holds NaN corners:
// its distance is NaN, which fails every comparison, as a miss does.

#include <cstdint>
#include <cstring>
#include <limits>

#if defined(__AVX__)
#include <immintrin.h>
#elif defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "trace/triangle.h"

namespace prt {

namespace block_detail {
#if defined(__AVX__)
inline constexpr int kWidth = 4;  // lanes per vector
#else
inline constexpr int kWidth = 2;
#endif
using Doubles = double __attribute__((vector_size(8 * kWidth)));
using Mask = int64_t __attribute__((vector_size(8 * kWidth)));  // lanes all bits or none

// Bit i set when lane i of the comparison result is true.
inline int bits(const Mask& m) {
#if defined(__AVX__)
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
  alignas(32) double corner[3][3][4];  // [a, b, c][x, y, z][lane], one triangle per lane

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

// triangleDistance for each lane: distance[i] is lane i's, bit for bit, or NaN where it misses.
inline void blockDistances(const ShearedRay4& r, const TriangleBlock& t, double distance[4]) {
  using block_detail::Doubles;
  using block_detail::Mask;
  for (int part = 0; part < 4; part += block_detail::kWidth) {
    Doubles p[3][3];  // the three corners along kx, ky, kz
    for (int k = 0; k < 3; ++k) {
      std::memcpy(&p[k][0], &t.corner[k][r.kx][part], sizeof(Doubles));
      std::memcpy(&p[k][1], &t.corner[k][r.ky][part], sizeof(Doubles));
      std::memcpy(&p[k][2], &t.corner[k][r.kz][part], sizeof(Doubles));
    }
    const Doubles az = p[0][2] - r.oz, bz = p[1][2] - r.oz, cz = p[2][2] - r.oz;
    const Doubles ax = (p[0][0] - r.ox) - r.sx * az, ay = (p[0][1] - r.oy) - r.sy * az;
    const Doubles bx = (p[1][0] - r.ox) - r.sx * bz, by = (p[1][1] - r.oy) - r.sy * bz;
    const Doubles cx = (p[2][0] - r.ox) - r.sx * cz, cy = (p[2][1] - r.oy) - r.sy * cz;
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
  }
}

// Bit i set when lo < distance[i] < hi, or lo < distance[i] <= hi with `toHi` (NaN: clear).
inline int lanesWithin(const double distance[4], double lo, double hi, bool toHi) {
  using block_detail::Doubles;
  const Doubles low = PRT_SPLAT(lo), high = PRT_SPLAT(hi);
  int lanes = 0;
  for (int part = 0; part < 4; part += block_detail::kWidth) {
    Doubles d;
    std::memcpy(&d, distance + part, sizeof d);
    const block_detail::Mask in = (d > low) & (toHi ? d <= high : d < high);
    lanes |= block_detail::bits(in) << part;
  }
  return lanes;
}

}  // namespace prt
