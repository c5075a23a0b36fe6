#pragma once
// BoxPair: two axis-aligned boxes laid out for one SIMD slab test against a ray (the two lanes
// of an SSE2 register, through GCC/Clang vector extensions: baseline x86-64, no wider ISA, so
// every machine computes the same bits). It culls for the BVH: each lane is true whenever
// `hitsBounds` would be true for that box, so culling with it never loses a hit.
//
// Per lane the arithmetic is hitsBounds' own, (plane - origin) * invDirection and the same
// compare-and-select that ignores NaN; only the choice of entry and exit face differs: it is
// made once per ray from the sign of the inverse direction instead of by a compare per box.
// The two agree except when a ray runs in a slab's plane (0 * inf = NaN), where this test may
// accept a box hitsBounds rejects — conservative, as culling must be.

#include <cstdint>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "trace/bounds.h"

namespace prt {

using Double2 = double __attribute__((vector_size(16)));

// A ray prepared for BoxPair tests: each component broadcast to both lanes.
struct SlabRay {
  Double2 origin[3];
  Double2 invDirection[3];
  // Per axis, the byte offset in BoxPair::planes of the planes through which the ray enters
  // the slab and leaves it: the min plane when travelling +, the max plane when travelling -.
  size_t entryOffset[3];
  size_t exitOffset[3];

  explicit SlabRay(const RayQuery& q) {
    for (int a = 0; a < 3; ++a) {
      origin[a] = Double2{q.ray.origin[a], q.ray.origin[a]};
      invDirection[a] = Double2{q.invDirection[a], q.invDirection[a]};
      const size_t entrySide = q.invDirection[a] < 0 ? 1 : 0;  // -0 has inv = -inf: max side
      entryOffset[a] = (2 * static_cast<size_t>(a) + entrySide) * sizeof(Double2);
      exitOffset[a] = (2 * static_cast<size_t>(a) + 1 - entrySide) * sizeof(Double2);
    }
  }
};

struct BoxPair {
  Double2 planes[3][2];  // [axis][0: min plane, 1: max plane], one box per lane

  // An empty box in both lanes: no ray meets it.
  BoxPair() {
    constexpr double inf = std::numeric_limits<double>::infinity();
    for (auto& axis : planes) {
      axis[0] = Double2{inf, inf};
      axis[1] = Double2{-inf, -inf};
    }
  }

  void set(int lane, const Bounds& b) {
    for (int a = 0; a < 3; ++a) {
      planes[a][0][lane] = b.lo[a];
      planes[a][1][lane] = b.hi[a];
    }
  }
  Bounds get(int lane) const {
    Bounds b;
    b.lo = Vec3(planes[0][0][lane], planes[1][0][lane], planes[2][0][lane]);
    b.hi = Vec3(planes[0][1][lane], planes[1][1][lane], planes[2][1][lane]);
    return b;
  }

  // Bit i (of 1 << 0, 1 << 1) set when box i may meet the ray within (tMin, tMax), with the
  // entry distance (clamped to tMin) in `entry[i]`: the box cannot be hit before it.
  int hits(const SlabRay& r, double tMin, double tMax, Double2& entry) const {
    Double2 lo = {tMin, tMin};
    Double2 hi = {tMax, tMax};
    const char* base = reinterpret_cast<const char*>(planes);
    for (int a = 0; a < 3; ++a) {
      const Double2 tIn =
          (*reinterpret_cast<const Double2*>(base + r.entryOffset[a]) - r.origin[a]) *
          r.invDirection[a];
      const Double2 tOut =
          (*reinterpret_cast<const Double2*>(base + r.exitOffset[a]) - r.origin[a]) *
          r.invDirection[a];
      // As in hitsBounds: a NaN compares false and leaves the interval alone.
      lo = tIn > lo ? tIn : lo;
      hi = tOut < hi ? tOut : hi;
    }
    entry = lo;
    const auto inside = lo <= hi;  // per lane: all bits set or clear
#if defined(__SSE2__)
    return _mm_movemask_pd(reinterpret_cast<__m128d>(inside));
#else
    return static_cast<int>((inside[0] & 1) | (inside[1] & 2));
#endif
  }
};

}  // namespace prt
