#pragma once
// TriangleBlock: four triangles tested against one ray at once, each lane computing exactly
// the operations of the scalar test in triangle.h in the same order (no sum reordered, no
// fused operation: the project builds with -ffp-contract=off), so every lane's distance is bit
// for bit triangleDistance's. Written with GCC/Clang vector extensions on four doubles: two
// SSE2 registers in the baseline build, one AVX register in the x86-64-v3 build, the same IEEE
// operations in both. An unused lane holds NaN corners: its distance is NaN, which fails
// every comparison, as a miss does.

#include <bit>
#include <cstdint>
#include <limits>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "trace/triangle.h"

namespace prt {

using Double4 = double __attribute__((vector_size(32)));
using Mask4 = int64_t __attribute__((vector_size(32)));  // a comparison's lanes: all bits or none

// Bit i set when lane i of the comparison result is true.
inline int laneBits(const Mask4& m) {
#if defined(__SSE2__)
  using Mask2 = int64_t __attribute__((vector_size(16)));
  const Mask2 lo = __builtin_shufflevector(m, m, 0, 1), hi = __builtin_shufflevector(m, m, 2, 3);
  return _mm_movemask_pd(std::bit_cast<__m128d>(lo)) |
         (_mm_movemask_pd(std::bit_cast<__m128d>(hi)) << 2);
#else
  return static_cast<int>((m[0] & 1) | (m[1] & 2) | (m[2] & 4) | (m[3] & 8));
#endif
}

// (No function here takes or returns a Double4 by value: that would change the calling
// convention between the builds with and without AVX, which GCC warns about.)
#define PRT_BROADCAST4(x) Double4{(x), (x), (x), (x)}

struct alignas(32) TriangleBlock {
  Double4 corner[3][3];  // [a, b, c][x, y, z], one triangle per lane

  // Every lane unused.
  TriangleBlock() {
    for (auto& c : corner) {
      for (auto& axis : c) axis = PRT_BROADCAST4(std::numeric_limits<double>::quiet_NaN());
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

// A ShearedRay broadcast to four lanes.
struct ShearedRay4 {
  Double4 ox, oy, oz;  // the origin along the permuted axes kx, ky, kz
  Double4 sx, sy, sz;
  int kx, ky, kz;

  explicit ShearedRay4(const ShearedRay& r)
      : ox(PRT_BROADCAST4(r.origin[r.kx])),
        oy(PRT_BROADCAST4(r.origin[r.ky])),
        oz(PRT_BROADCAST4(r.origin[r.kz])),
        sx(PRT_BROADCAST4(r.sx)),
        sy(PRT_BROADCAST4(r.sy)),
        sz(PRT_BROADCAST4(r.sz)),
        kx(r.kx),
        ky(r.ky),
        kz(r.kz) {}
};

// triangleDistance for each lane: the distance, bit for bit, or NaN where the lane misses.
inline void blockDistances(const ShearedRay4& r, const TriangleBlock& t, Double4& distance) {
  const Double4 az = t.corner[0][r.kz] - r.oz, bz = t.corner[1][r.kz] - r.oz,
                cz = t.corner[2][r.kz] - r.oz;
  const Double4 ax = (t.corner[0][r.kx] - r.ox) - r.sx * az;
  const Double4 ay = (t.corner[0][r.ky] - r.oy) - r.sy * az;
  const Double4 bx = (t.corner[1][r.kx] - r.ox) - r.sx * bz;
  const Double4 by = (t.corner[1][r.ky] - r.oy) - r.sy * bz;
  const Double4 cx = (t.corner[2][r.kx] - r.ox) - r.sx * cz;
  const Double4 cy = (t.corner[2][r.ky] - r.oy) - r.sy * cz;
  const Double4 u = cx * by - cy * bx;  // edge b-c, weight of a
  const Double4 v = ax * cy - ay * cx;  // edge c-a, weight of b
  const Double4 w = bx * ay - by * ax;  // edge a-b, weight of c
  const Double4 zero = {0, 0, 0, 0};
  const Mask4 negative = (u < zero) | (v < zero) | (w < zero);
  const Mask4 positive = (u > zero) | (v > zero) | (w > zero);
  const Double4 det = u + v + w;
  const Mask4 miss = (negative & positive) | (det == zero);  // signs differ, or edge-on
  const Double4 t0 = (u * (r.sz * az) + v * (r.sz * bz) + w * (r.sz * cz)) / det;
  distance = miss ? PRT_BROADCAST4(std::numeric_limits<double>::quiet_NaN()) : t0;
}

}  // namespace prt
