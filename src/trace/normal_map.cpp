#include "trace/normal_map.h"

#include <algorithm>
#include <cmath>

namespace prt {
namespace {

double component(double c) { return std::clamp((255 * c - 128) / 127, -1.0, 1.0); }

double sqrtAtLeast0(double v) { return v > 0 ? std::sqrt(v) : 0.0; }

}  // namespace

Vec3 normalMapVector(const Color& texel, double scale) {
  return {scale * component(texel.x), scale * component(texel.y), component(texel.z)};
}

Vec3 mappedNormal(const Vec3& normal, const Vec3& tangent, double handedness, const Vec3& mapVector) {
  if (mapVector.x == 0 && mapVector.y == 0) return normal;
  const Vec3 t = tangent - dot(normal, tangent) * normal;
  const double size = length(t);
  if (!(size > 1e-12 * length(tangent)) || !std::isfinite(size)) return normal;
  const Vec3 unitT = t / size;
  const Vec3 b = (handedness < 0 ? -1.0 : 1.0) * cross(normal, unitT);
  const Vec3 mapped = mapVector.x * unitT + mapVector.y * b + mapVector.z * normal;
  const double mappedSize = length(mapped);
  if (!(mappedSize > 0) || !std::isfinite(mappedSize)) return normal;
  return mapped / mappedSize;
}

Vec3 keepReflectionAbove(const Vec3& ng, const Vec3& wo, const Vec3& n) {
  const Vec3 r = 2 * dot(n, wo) * n - wo;
  const double threshold = std::min(0.9 * dot(ng, wo), 0.01);
  if (dot(ng, r) >= threshold) return n;
  // A frame with ng as z and n in the x-z plane; n' = (x, z) lifts the reflection to the
  // threshold: of the two solutions of the quadratic in z^2, the one that reflects wo above
  // the surface, the shallower reflection when both do.
  const double ndotng = dot(n, ng);
  const Vec3 xAxis0 = n - ndotng * ng;
  const double xSize = length(xAxis0);
  if (!(xSize > 0)) return ng;
  const Vec3 xAxis = xAxis0 / xSize;
  const double ix = dot(wo, xAxis), iz = dot(wo, ng);
  const double ix2 = ix * ix, iz2 = iz * iz;
  const double a = ix2 + iz2;
  const double b = sqrtAtLeast0(ix2 * (a - threshold * threshold));
  const double c = iz * threshold + a;
  const double fac = 0.5 / a;
  const double n1z2 = fac * (b + c), n2z2 = fac * (-b + c);
  bool valid1 = n1z2 > 1e-5 && n1z2 <= 1 + 1e-5;
  bool valid2 = n2z2 > 1e-5 && n2z2 <= 1 + 1e-5;
  double nx, nz;
  if (valid1 && valid2) {
    const double n1x = sqrtAtLeast0(1 - n1z2), n1z = sqrtAtLeast0(n1z2);
    const double n2x = sqrtAtLeast0(1 - n2z2), n2z = sqrtAtLeast0(n2z2);
    const double r1 = 2 * (n1x * ix + n1z * iz) * n1z - iz;
    const double r2 = 2 * (n2x * ix + n2z * iz) * n2z - iz;
    valid1 = r1 >= 1e-5;
    valid2 = r2 >= 1e-5;
    const bool first = valid1 && valid2 ? r1 < r2 : r1 > r2;
    nx = first ? n1x : n2x;
    nz = first ? n1z : n2z;
  } else if (valid1 || valid2) {
    const double z2 = valid1 ? n1z2 : n2z2;
    nx = sqrtAtLeast0(1 - z2);
    nz = sqrtAtLeast0(z2);
  } else {
    return ng;
  }
  return nx * xAxis + nz * ng;
}

}  // namespace prt
