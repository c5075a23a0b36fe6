#include "trace/camera.h"

#include <cmath>
#include <numbers>

#include "core/portable_math.h"

namespace prt {

PinholeCamera::PinholeCamera(const Camera& camera, int width, int height)
    : eye_(camera.eye), invWidth_(1.0 / width), invHeight_(1.0 / height) {
  forward_ = normalize(camera.lookAt - camera.eye);
  const Vec3 right = normalize(cross(camera.up, forward_));
  const Vec3 up = cross(forward_, right);
  orthographic_ = camera.orthoHeight > 0;
  const double halfHeight = orthographic_
                                ? 0.5 * camera.orthoHeight
                                : tanRadians(camera.fovDegrees * std::numbers::pi / 360.0);
  const double halfWidth = halfHeight * static_cast<double>(width) / height;
  right_ = right * halfWidth;
  up_ = up * halfHeight;
}

bool PinholeCamera::project(const Vec3& p, double& px, double& py) const {
  // generateRay's direction is forward + sx right + sy up, the three orthogonal.
  const Vec3 v = p - eye_;
  const double depth = dot(v, forward_);
  if (!(depth > 0)) return false;
  const double perspective = orthographic_ ? 1.0 : depth;  // parallel rays: no foreshortening
  const double sx = dot(v, right_) / (dot(right_, right_) * perspective);
  const double sy = dot(v, up_) / (dot(up_, up_) * perspective);
  px = (sx + 1.0) / (2.0 * invWidth_);
  py = (1.0 - sy) / (2.0 * invHeight_);
  return true;
}

Ray PinholeCamera::generateRay(double px, double py) const {
  const double sx = 2.0 * px * invWidth_ - 1.0;
  const double sy = 1.0 - 2.0 * py * invHeight_;
  if (orthographic_) return Ray{eye_ + sx * right_ + sy * up_, forward_};
  return Ray{eye_, normalize(forward_ + sx * right_ + sy * up_)};
}

}  // namespace prt
