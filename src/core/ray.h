#pragma once
// Ray: origin + t * direction. Directions are unit length unless stated otherwise.

#include "core/vec3.h"

namespace prt {

struct Ray {
  Vec3 origin;
  Vec3 direction;
  Vec3 at(double t) const { return origin + t * direction; }
};

}  // namespace prt
