#pragma once
// Scene: the plain description of what to render, as read from a .scene file (scene/) and
// sent to workers. No acceleration structures here: trace/ builds those from it.
// Units: world units for positions and sizes, degrees for angles, linear RGB for colours.

#include <string>
#include <variant>
#include <vector>

#include "core/vec3.h"
#include "trace/triangle_mesh.h"

namespace prt {

struct Camera {
  Vec3 eye{0, 0, -5};    // position of the eye
  Vec3 lookAt{0, 0, 0};  // point at the centre of the image
  Vec3 up{0, 1, 0};      // approximate up direction; need not be perpendicular to the view
  double fovDegrees = 45;  // vertical field of view, degrees, in (0, 180)
};

struct ImageSpec {
  int width = 320;
  int height = 240;
  std::string output = "out.png";  // extension picks the format: .png, .ppm, .pfm
};

struct Environment {
  Color background{0, 0, 0};   // colour of rays that hit nothing
  Color ambient{0.1, 0.1, 0.1};  // ambient light colour (Hall's I_a)
  int maxDepth = 5;            // maximum recursion depth of reflection/transmission rays
};

// Default sampling of the scene; the command line overrides it.
struct Sampling {
  int samplesPerPixel = 1;  // SS: stratified, jittered samples per pixel
  int drtRate = 1;          // DRT: rays per glossy reflection, blurry transmission, area light
};

// The paper's surface: Hall's simplified model. All weights are in [0, 1] unless stated.
struct Material {
  Color color{0.8, 0.8, 0.8};  // surface colour O_d
  double ambient = 1.0;        // k_a: weight of the environment's ambient colour
  double diffuse = 0.7;        // k_d
  double specular = 0.0;       // k_s: Phong highlight weight (highlight takes the light's colour)
  double phongExponent = 40;   // n in (R.V)^n, >= 1
  double reflectivity = 0.0;   // k_r: weight of the mirror-reflected colour
  double transmissivity = 0.0;  // k_t: weight of the transmitted colour; also how much light
                                // passes through the surface to shadowed points
  double ior = 1.0;            // index of refraction of the inside (>= 1)
  double glossDegrees = 0.0;   // half-angle of the cone of reflected rays (0: perfect mirror)
  double translucencyDegrees = 0.0;  // half-angle of the cone of transmitted rays

  bool operator==(const Material&) const = default;
};

struct SphereShape {
  Vec3 center;
  double radius = 1;
  bool operator==(const SphereShape&) const = default;
};
struct BoxShape {  // axis-aligned
  Vec3 min;
  Vec3 max;
  bool operator==(const BoxShape&) const = default;
};
struct PlaneShape {  // one-sided: visible, and opaque to shadow rays, only from the normal's side
  Vec3 point;
  Vec3 normal{0, 1, 0};  // unit length
  bool operator==(const PlaneShape&) const = default;
};
// A triangle mesh (trace/triangle_mesh.h): closed or not, convex or not.
using Shape = std::variant<SphereShape, BoxShape, PlaneShape, MeshShape>;

struct Object {
  Shape shape;
  Material material;
  bool operator==(const Object&) const = default;
};

struct PointLight {
  Vec3 position;
  bool operator==(const PointLight&) const = default;
};
struct SphereLight {  // soft shadows: samples are drawn over the sphere's visible disc
  Vec3 center;
  double radius = 0.5;
  bool operator==(const SphereLight&) const = default;
};
struct RectLight {  // soft shadows: the parallelogram corner + s*edge1 + t*edge2, s,t in [0,1]
  Vec3 corner;
  Vec3 edge1;
  Vec3 edge2;
  bool operator==(const RectLight&) const = default;
};
using LightShape = std::variant<PointLight, SphereLight, RectLight>;

struct Light {
  LightShape shape;
  Color color{1, 1, 1};  // intensity I_l (may exceed 1)
  bool operator==(const Light&) const = default;
};

struct Scene {
  Camera camera;
  ImageSpec image;
  Environment environment;
  Sampling sampling;
  std::vector<Light> lights;
  std::vector<Object> objects;
  // What reading the scene skipped and why (triangles of a mesh file), for the user to see;
  // "file:line: what". Not part of the scene itself: never written or sent.
  std::vector<std::string> warnings;
};

}  // namespace prt
