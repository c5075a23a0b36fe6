#pragma once
// Vec3: a 3-vector of doubles, used for points, directions and RGB colours alike.
// Plain value type; all operations are pure and thread-safe.

#include <algorithm>
#include <cmath>

namespace prt {

struct Vec3 {
  double x = 0, y = 0, z = 0;

  constexpr Vec3() = default;
  constexpr Vec3(double xx, double yy, double zz) : x(xx), y(yy), z(zz) {}
  constexpr explicit Vec3(double v) : x(v), y(v), z(v) {}

  constexpr double operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
  constexpr double& operator[](int i) { return i == 0 ? x : (i == 1 ? y : z); }

  constexpr Vec3 operator-() const { return {-x, -y, -z}; }
  constexpr Vec3& operator+=(const Vec3& o) { x += o.x; y += o.y; z += o.z; return *this; }
  constexpr Vec3& operator-=(const Vec3& o) { x -= o.x; y -= o.y; z -= o.z; return *this; }
  constexpr Vec3& operator*=(double s) { x *= s; y *= s; z *= s; return *this; }
  constexpr Vec3& operator*=(const Vec3& o) { x *= o.x; y *= o.y; z *= o.z; return *this; }
  constexpr Vec3& operator/=(double s) { return *this *= (1.0 / s); }

  constexpr bool operator==(const Vec3&) const = default;
};

constexpr Vec3 operator+(Vec3 a, const Vec3& b) { return a += b; }
constexpr Vec3 operator-(Vec3 a, const Vec3& b) { return a -= b; }
constexpr Vec3 operator*(Vec3 a, double s) { return a *= s; }
constexpr Vec3 operator*(double s, Vec3 a) { return a *= s; }
constexpr Vec3 operator*(Vec3 a, const Vec3& b) { return a *= b; }  // component-wise
constexpr Vec3 operator/(Vec3 a, double s) { return a /= s; }

constexpr double dot(const Vec3& a, const Vec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
constexpr Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline double length(const Vec3& v) { return std::sqrt(dot(v, v)); }
inline Vec3 normalize(const Vec3& v) { return v / length(v); }
constexpr Vec3 min(const Vec3& a, const Vec3& b) {
  return {std::min(a.x, b.x), std::min(a.y, b.y), std::min(a.z, b.z)};
}
constexpr Vec3 max(const Vec3& a, const Vec3& b) {
  return {std::max(a.x, b.x), std::max(a.y, b.y), std::max(a.z, b.z)};
}
constexpr double maxComponent(const Vec3& v) { return std::max(v.x, std::max(v.y, v.z)); }
inline bool isFinite(const Vec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// The luminance of a linear Rec. 709 colour.
constexpr double luminance(const Vec3& c) { return 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z; }
// Mirror reflection of incident direction d about unit normal n.
constexpr Vec3 reflect(const Vec3& d, const Vec3& n) { return d - 2.0 * dot(d, n) * n; }

// An orthonormal basis (u, v) perpendicular to unit vector w (Duff et al. 2017).
inline void orthonormalBasis(const Vec3& w, Vec3& u, Vec3& v) {
  const double sign = std::copysign(1.0, w.z);
  const double a = -1.0 / (sign + w.z);
  const double b = w.x * w.y * a;
  u = {1.0 + sign * w.x * w.x * a, sign * b, -sign * w.x};
  v = {b, sign + w.y * w.y * a, -w.y};
}

using Color = Vec3;  // linear RGB radiance

}  // namespace prt
