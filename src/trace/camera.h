#pragma once
// PinholeCamera: turns a position on the image plane into a primary ray. Left-handed like
// POV-Ray: with the default camera (eye on -z looking at the origin, up +y), +x is right.
// An orthographic camera (Camera::orthoHeight > 0) sends parallel rays from a plane through
// the eye instead of rays from the eye.

#include "core/ray.h"
#include "trace/scene.h"

namespace prt {

class PinholeCamera {
 public:
  PinholeCamera(const Camera& camera, int width, int height);

  // (px, py) in pixels: x in [0, width) to the right, y in [0, height) downwards.
  Ray generateRay(double px, double py) const;

  // Where point p appears in the image, in the pixel units of generateRay (the inverse map, up
  // to rounding); false when p is not in front of the eye.
  bool project(const Vec3& p, double& px, double& py) const;

 private:
  Vec3 eye_, forward_, right_, up_;  // right_ and up_ are scaled to half the image plane
  double invWidth_, invHeight_;
  bool orthographic_ = false;
};

}  // namespace prt
