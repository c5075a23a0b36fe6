#pragma once
// Scene: the plain description of what to render, as read from a .scene file (scene/) and
// sent to workers. No acceleration structures here: trace/ builds those from it.
// Units: world units for positions and sizes, degrees for angles, linear RGB for colours.

#include <limits>
#include <memory>
#include <string>
#include <variant>
#include <vector>

#include "core/transform.h"
#include "core/vec3.h"
#include "image/image.h"
#include "trace/texture.h"
#include "trace/triangle_mesh.h"

namespace prt {

struct Camera {
  Vec3 eye{0, 0, -5};    // position of the eye
  Vec3 lookAt{0, 0, 0};  // point at the centre of the image
  Vec3 up{0, 1, 0};      // approximate up direction; need not be perpendicular to the view
  double fovDegrees = 45;  // vertical field of view, degrees, in (0, 180)
  // Orthographic when > 0: every ray runs along the view direction, and the image's height
  // spans this many world units around the eye (the field of view is then not used).
  double orthoHeight = 0;
  bool operator==(const Camera&) const = default;
};

struct ImageSpec {
  int width = 320;
  int height = 240;
  std::string output = "out.png";  // extension picks the format: .png, .ppm, .pfm
};

// How pixels are computed: the paper's Whitted ray tracing with Hall's model (trace/shader.h),
// or the physically based path tracer (trace/path_tracer.h).
enum class Integrator : uint8_t { hall, path };

// An HDR environment map (trace/environment_light.h): an equirectangular image of linear
// radiance that surrounds the scene.
struct EnvironmentMap {
  std::shared_ptr<const Image> image;  // null: none (the background colour is the world)
  std::string file;                    // where it was read from, for the scene's text
  double strength = 1;                 // multiplies the image's radiance, in [0, 1e6]
  double rotateDegrees = 0;              // about the up axis, in [-1e6, 1e6]
  bool operator==(const EnvironmentMap& o) const {
    return file == o.file && strength == o.strength && rotateDegrees == o.rotateDegrees &&
           (image == o.image || (image && o.image && *image == *o.image));
  }
};

struct Environment {
  Color background{0, 0, 0};   // colour of rays that hit nothing (the path tracer: radiance)
  Color ambient{0.1, 0.1, 0.1};  // ambient light colour (Hall's I_a)
  int maxDepth = 5;            // maximum recursion depth of reflection/transmission rays
  Integrator integrator = Integrator::hall;
  int maxBounces = 12;  // the path tracer's longest path, in bounces (Cycles' default)
  EnvironmentMap map{};  // when given, the world in place of `background`
};

// Default sampling of the scene; the command line overrides it.
struct Sampling {
  int samplesPerPixel = 1;  // SS: stratified, jittered samples per pixel
  int drtRate = 1;          // DRT: rays per glossy reflection, blurry transmission, area light
};

// What the path tracer needs of a surface beyond the fields it shares with Hall's model (the
// colour as the base colour, `metallic`, `emission` and the textures): glTF 2.0's
// metallic-roughness model (trace/bsdf.h). `given` false: derived from Hall's parameters by
// pbrFromHall (trace/bsdf_inputs.h), the rule for scenes written for the paper's renderer.
struct PbrSurface {
  bool given = false;
  double roughness = 0.5;     // in [0, 1]
  double transmission = 0;    // share that is glass, in [0, 1]
  double ior = 1.5;           // in [1, 10]
  double specularLevel = 0.5;  // Blender's "specular": F0 = 0.08 * level for dielectrics, in
                               // [0, 12.5]
  double coverage = 1;        // alpha: 0 absent (rays pass straight through) to 1, in [0, 1]
  // glTF's data textures (linear Textures), which only the path tracer reads: metallic (B)
  // and roughness (G) multiplying the material's `metallic` and `roughness`; a tangent-space
  // normal map (trace/normal_map.h) with its scale; the transmission (R) multiplying
  // `transmission`.
  TextureRef metallicRoughnessTexture;
  TextureRef normalTexture;
  double normalScale = 1;  // in [-1e6, 1e6]
  TextureRef transmissionTexture;
  // KHR_materials_volume: light inside a refracting object is absorbed by Beer and Lambert's
  // law, falling to `attenuationColor` over `attenuationDistance` (world units; infinite:
  // clear). A thin-walled glass (the extension's thickness 0) has no inside: light passes it
  // unbent and unabsorbed.
  Color attenuationColor{1, 1, 1};  // in [0, 1]
  double attenuationDistance = std::numeric_limits<double>::infinity();  // > 0
  bool thinWalled = false;
  // KHR_materials_specular: the dielectric's F0 becomes min(0.08 specularLevel specularColor,
  // 1) specularWeight and its F90 specularWeight (trace/bsdf.h).
  double specularWeight = 1;      // in [0, 1]
  Color specularColor{1, 1, 1};  // in [0, 1e6]
  // KHR_materials_clearcoat: a clear GGX layer of index 1.5 over the rest (trace/bsdf.h).
  double clearcoat = 0;           // in [0, 1]
  double clearcoatRoughness = 0;  // in [0, 1]
  bool operator==(const PbrSurface&) const = default;
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
  // A metal's share: its mirror reflection and highlight take the surface colour by this much
  // (POV-Ray's `metallic`), in [0, 1]; 0 leaves them the colour of what they reflect.
  double metallic = 0.0;
  Color emission{0, 0, 0};  // light the surface gives off itself, added to its colour (it
                            // lights nothing else: it is not a light source)
  TextureRef colorTexture;     // multiplies `color` (and a mesh's vertex colours)
  TextureRef emissionTexture;  // multiplies `emission`
  PbrSurface pbr;              // the path tracer's

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
// A mesh placed by a transform (an instance): the mesh, in its own coordinates, is stored and
// its tree built once however many objects place it (World shares them by the pointer).
struct InstanceShape {
  std::shared_ptr<const TriangleMesh> mesh;  // never null; in the mesh's own coordinates
  Transform worldFromMesh;                   // usable (Transform::isUsable)
  bool operator==(const InstanceShape& o) const {
    return worldFromMesh == o.worldFromMesh && (mesh == o.mesh || *mesh == *o.mesh);
  }
};
// A triangle mesh (trace/triangle_mesh.h): closed or not, convex or not.
using Shape = std::variant<SphereShape, BoxShape, PlaneShape, MeshShape, InstanceShape>;

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
// A point light whose light is confined to a cone: full inside `innerDegrees` of the axis,
// none beyond `outerDegrees`, a smooth step between (as Blender and POV-Ray fade a spot).
struct SpotLight {
  Vec3 position;
  Vec3 direction{0, -1, 0};  // the cone's axis, unit length: where the light shines
  double innerDegrees = 30;  // half-angles, 0 <= inner <= outer <= 90
  double outerDegrees = 30;
  bool operator==(const SpotLight&) const = default;
};
// Light from infinitely far away (the sun): parallel rays, one shadow ray per shading point.
struct DirectionalLight {
  Vec3 direction{0, -1, 0};  // unit length: the direction the light travels
  bool operator==(const DirectionalLight&) const = default;
};
using LightShape = std::variant<PointLight, SphereLight, RectLight, SpotLight, DirectionalLight>;

// How a light weakens with the distance d to it: not at all (the paper's lights), or as 1/d^2
// (the physical law, which lights read from model files follow; `color` is then the intensity
// at distance 1).
enum class Falloff : uint8_t { none, inverseSquare };

struct Light {
  LightShape shape;
  Color color{1, 1, 1};  // intensity I_l (may exceed 1)
  Falloff falloff = Falloff::none;  // never inverseSquare for a directional light
  bool operator==(const Light&) const = default;
};

// How an `import` block brought a model file in, so that the scene can be written back (and
// sent) as it was read: its objects and lights are those at the ranges given.
struct ImportSource {
  std::string file;  // absolute, as resolved against the scene file's directory
  Vec3 scale{1, 1, 1};  // applied first,
  Vec3 rotateDegrees;   // then rotations about x, then y, then z,
  Vec3 translate;       // then the translation
  bool lights = true;   // whether the file's lights were brought in
  size_t firstObject = 0, objectCount = 0;  // in Scene::objects
  size_t firstLight = 0, lightCount = 0;    // in Scene::lights
  size_t firstTexture = 0, textureCount = 0;  // in Scene::textures
  double lightScale = 1;  // what the file's light intensities were multiplied by
  bool operator==(const ImportSource&) const = default;
};

struct SceneAnimation;  // scene/animation.h

struct Scene {
  Camera camera;
  ImageSpec image;
  Environment environment;
  Sampling sampling;
  std::vector<Light> lights;
  std::vector<Object> objects;
  std::vector<Texture> textures;  // what materials' TextureRefs index
  std::vector<ImportSource> imports;  // in the order of their blocks
  // How the scene moves (scene/animation.h: sceneAt gives it at a time); null: it does not.
  std::shared_ptr<const SceneAnimation> animation;
  // What reading the scene skipped and why (triangles of a mesh file), for the user to see;
  // "file:line: what". Not part of the scene itself: never written or sent.
  std::vector<std::string> warnings;
};

}  // namespace prt
