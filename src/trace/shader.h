#pragma once
// Shader: the paper's simplified Hall model, recursively.
//   colour = k_a I_a O_d + E
//          + sum over lights of  S_l I_l (k_d O_d (N.L) + k_s (R.V)^n)
//          + k_r * reflected colour + k_t * transmitted colour
// O_d is the surface colour, times the mesh's vertex colour and the colour texture where there
// are; E the material's emission (times its texture). A spot light's I_l is weighed by its cone,
// and a light with inverse-square falloff's by 1 / d^2. S_l is the light's visibility: 0 behind an opaque object, the product of the
// transmissivities of the transmissive surfaces crossed, averaged over the light's samples
// for lights with extent. Reflection and transmission recurse up to the environment's
// maximum depth; with gloss or translucency each spawns drtRate perturbed rays.
//
// Every ray carries its path weight: the share of the pixel sample its colour makes up, the
// product of the k_r and k_t it was reflected and transmitted by, divided by drtRate at each
// spread into a cone of rays. A ray whose weight would fall below kMinPathWeight is not traced
// (POV-Ray's adc_bailout), and a cone whose rays would each fall below it is sampled by one
// ray of the whole weight instead. As scene files keep k_r + k_t <= 1, the weights of one
// level of a sample's ray tree sum to at most 1, so no level holds more than
// 1 / kMinPathWeight rays: whatever the scene, a sample's cost is bounded.
//
// Reads only immutable data; one Shader may be used by many threads at once.

#include <cstdint>
#include <span>
#include <vector>

#include "core/rng.h"
#include "trace/light_sampling.h"
#include "trace/render_settings.h"
#include "trace/world.h"

namespace prt {

// Whether every point of `reach` lies so far behind the plane through `origin` with normal `n`
// that each shadow ray aimed at one would have a computed cosine dot(n, direction) below 0,
// and be skipped: the margins cover the rounding of sampling the point, of normalising the
// direction and of the dot product. `n` is a unit normal up to rounding; `nn` is dot(n, n),
// which covers one a little longer than unit.
bool surelyBehind(const LightReach& reach, const Vec3& origin, const Vec3& n, double nn);

// Rays of a smaller path weight are not traced: 2^-16, the last step of a 16-bit pixel. The
// example scenes' images do not change by it (of the benchmark scene's 921,600 8-bit channels
// one moves by 1, a value that lay on a rounding boundary), and it stops a tree of glass in
// glass (reflect 0.5 transmit 0.5) after 16 levels.
inline constexpr double kMinPathWeight = 1.0 / 65536;

class Shader {
 public:
  Shader(const World& world, const RenderSettings& settings);

  // Colour seen along `ray` arriving at recursion depth `depth` (0 for primary rays).
  // `rays` counts every ray traced, shadow rays included.
  Color trace(const Ray& ray, int depth, Rng rng, uint64_t& rays) const;
  // The same for a primary ray that can meet only the planes and the items in `candidates`
  // (World::intersectAmong): a camera ray through a tile of ViewLists.
  Color traceAmong(std::span<const uint32_t> candidates, const Ray& ray, Rng rng,
                   uint64_t& rays) const;

  // Local illumination at a hit: ambient plus every light's diffuse and Phong terms with
  // shadows. Exposed for tests of the shading terms.
  Color direct(const Hit& hit, const Vec3& shadingNormal, const Vec3& toEye, Rng& rng,
               uint64_t& rays) const;

 private:
  // The cone a glossy or blurry surface spreads its rays over: none when radians is 0.
  struct Spread {
    double radians = 0;
    double cosine = 1;  // of the half-angle
  };
  // What shading needs of an object's material beyond the material itself, computed once.
  struct Surface {
    Spread reflection, transmission;
    double inverseIor = 1;  // 1 / ior: the relative index entering the object
    const Texture* colorTexture = nullptr;     // the material's, in the scene's list
    const Texture* emissionTexture = nullptr;
    bool vertexColors = false;  // the object's mesh has them
    bool attributes = false;    // a hit's texture coordinates or colour are needed
    bool emits = false;         // the material's emission is not black
  };
  // What shading needs of a light beyond its shape, computed once.
  struct LightTerms {
    bool directional = false;
    Vec3 sunward;  // a directional light's: against its direction
    bool spot = false;
    Vec3 axis;     // a spot's
    double cosOuter = 0, cosInner = 1;
    bool inverseSquare = false;
    // Whether the light is weighed by scale(): the paper's lights are not.
    bool shaped() const { return spot || inverseSquare; }
    // The share of the light's intensity that arrives along unit direction toLight (towards
    // the light) from `distance` away: the spot's cone and the inverse-square law.
    double scale(const Vec3& toLight, double distance) const;
  };

  // The surface colour at a hit (the material's, times vertex colours and texture) and, when
  // `emission` is given and the material emits, its emission there.
  Color albedoAt(const Ray& ray, const Hit& hit, const Surface& surface, const Material& m,
                 Color* emission) const;
  Color direct(const Hit& hit, const Color& albedo, const Vec3& n, const Vec3& toEye, double eps,
               Rng& rng, uint64_t& rays) const;
  // Where a ray is: its recursion depth (0 for primary rays) and its path weight.
  struct PathState {
    int depth = 0;
    double weight = 1;
  };
  // The colour of `hit`, met by `ray`.
  Color shade(const Ray& ray, const Hit& hit, PathState path, Rng rng, uint64_t& rays) const;
  // `inside`: the scene object the spawned rays start inside, or kOutside.
  static constexpr uint32_t kOutside = ~0u;
  Color traceFrom(uint32_t inside, const Ray& ray, PathState path, Rng rng, uint64_t& rays) const;
  template <typename Intersect>
  Color traceWith(Intersect&& intersect, const Ray& ray, PathState path, Rng rng,
                  uint64_t& rays) const;
  Color traceAt(const Ray& ray, PathState path, Rng rng, uint64_t& rays) const;
  // The rays leaving a surface in `direction` (spread into a cone of drtRate rays, or one):
  // their mean colour. `path` is that of the spawned rays, before any division by drtRate.
  Color spawn(uint32_t inside, const Vec3& origin, const Vec3& direction, const Spread& spread,
              const Vec3& normal, bool above, PathState path, Rng rng, uint64_t& rays) const;

  const World& world_;
  RenderSettings settings_;
  std::vector<Surface> surfaces_;    // per object
  std::vector<LightReach> reaches_;  // per light
  std::vector<LightTerms> lightTerms_;  // per light
};

// Whether the Phong term specular * highlight^exponent is surely below a quarter of the last
// place of every component of `diffuse`: added to them it would change no bit, so the power
// need not be computed. Holds often, Phong exponents being large.
bool specularIsNegligible(double highlight, double exponent, double specular, const Color& diffuse);

// Refraction of unit direction d through unit normal n (facing against d) with relative index
// eta = n_incident / n_transmitted. Returns false on total internal reflection.
bool refract(const Vec3& d, const Vec3& n, double eta, Vec3& transmitted);

}  // namespace prt
