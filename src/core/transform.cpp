#include "core/transform.h"

#include <cmath>

namespace prt {

Transform Transform::rotation(double x, double y, double z, double w) {
  const double size = std::sqrt(x * x + y * y + z * z + w * w);
  if (size > 0) x /= size, y /= size, z /= size, w /= size;
  Transform r;
  r.m[0] = {1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w), 0};
  r.m[1] = {2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w), 0};
  r.m[2] = {2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y), 0};
  return r;
}

Transform Transform::fromColumnMajor(const double* c) {
  Transform r;
  for (int row = 0; row < 3; ++row) {
    for (int column = 0; column < 4; ++column) r.m[row][column] = c[column * 4 + row];
  }
  return r;
}

double Transform::determinant() const {
  return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
         m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
         m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

bool Transform::isUsable() const {
  for (const auto& row : m) {
    for (const double v : row) {
      if (!std::isfinite(v)) return false;
    }
  }
  // Relative to the size of the entries, so that a model scaled by 0.001 is still usable.
  double largest = 0;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) largest = std::fmax(largest, std::fabs(m[r][c]));
  }
  const double det = determinant();
  return largest > 0 && std::isfinite(det) && std::fabs(det) > 1e-12 * largest * largest * largest;
}

Transform Transform::inverse() const {
  const double inv = 1.0 / determinant();
  Transform r;
  r.m[0][0] = (m[1][1] * m[2][2] - m[1][2] * m[2][1]) * inv;
  r.m[0][1] = (m[0][2] * m[2][1] - m[0][1] * m[2][2]) * inv;
  r.m[0][2] = (m[0][1] * m[1][2] - m[0][2] * m[1][1]) * inv;
  r.m[1][0] = (m[1][2] * m[2][0] - m[1][0] * m[2][2]) * inv;
  r.m[1][1] = (m[0][0] * m[2][2] - m[0][2] * m[2][0]) * inv;
  r.m[1][2] = (m[0][2] * m[1][0] - m[0][0] * m[1][2]) * inv;
  r.m[2][0] = (m[1][0] * m[2][1] - m[1][1] * m[2][0]) * inv;
  r.m[2][1] = (m[0][1] * m[2][0] - m[0][0] * m[2][1]) * inv;
  r.m[2][2] = (m[0][0] * m[1][1] - m[0][1] * m[1][0]) * inv;
  const Vec3 t(m[0][3], m[1][3], m[2][3]);
  const Vec3 back = r.vector(t);
  r.m[0][3] = -back.x, r.m[1][3] = -back.y, r.m[2][3] = -back.z;
  return r;
}

Transform operator*(const Transform& a, const Transform& b) {
  Transform r;
  for (int row = 0; row < 3; ++row) {
    for (int column = 0; column < 4; ++column) {
      double sum = a.m[row][0] * b.m[0][column] + a.m[row][1] * b.m[1][column] +
                   a.m[row][2] * b.m[2][column];
      if (column == 3) sum += a.m[row][3];
      r.m[row][column] = sum;
    }
  }
  return r;
}

}  // namespace prt
