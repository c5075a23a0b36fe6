#pragma once
// Bsdf: how a surface of the path tracer scatters light — glTF 2.0's metallic-roughness
// model (the specification's appendix B) in the form Blender's Principled BSDF gives it, the
// shader Cycles renders glTF files with:
//   f = (1 - metallic)(1 - transmission) diffuse            Burley's diffuse (Disney 2012):
//       + specular                                          Lambert brightened at grazing
//       + (1 - metallic) transmission glass                 angles as roughness grows
// specular: the GGX (Trowbridge-Reitz) microfacet reflection with the height-correlated Smith
//   masking-shadowing and Schlick's Fresnel from F0 = lerp(0.08 specularLevel, base, metallic)
//   (0.04 at glTF's default, the reflectance of an index of 1.5) up to 1 at grazing angles;
//   KHR_materials_specular scales the dielectric's: F0 = min(0.08 specularLevel
//   specularColor, 1) specularWeight, F90 = specularWeight;
// glass: the rough dielectric of Walter et al. 2007 (GGX, exact Fresnel for the index,
//   refraction tinted by the base colour), both sides of the surface.
// KHR_materials_clearcoat lays a second GGX reflection over all of it, as the extension
// defines it: f = (1 - clearcoat Fc) f_base + clearcoat Fc f_coat, Fc = 0.04 + 0.96 (1 -
//   |n_c . wo|)^5 (Schlick's for an index of 1.5 on the coat's normal n_c), f_coat the
//   microfacet reflection of roughness clearcoatRoughness without a Fresnel factor.
// Directions are sampled from the visible normals (Heitz 2018) for the microfacet lobes and
// cosine-weighted for the diffuse one; a lobe is chosen by its estimated weight and the pdf is
// the mixture's, so that next-event estimation and BSDF sampling can be weighed by multiple
// importance sampling. Below a roughness of kSmoothRoughness the reflection and the glass are
// perfectly smooth (a mirror, a clear glass): delta lobes, sampled only.
//
// Every quantity is plain double arithmetic with sqrt and the portable sine and cosine: the
// same bits on every machine and build. Vectors are in world space; `n` is the shading normal
// on the side the light leaves towards (wo), `outward` tells whether that is the surface's
// outside (for the glass's index).

#include "core/vec3.h"

namespace prt {

// Below this roughness a lobe is a perfect mirror or a clear glass (GGX's alpha = 0.001).
inline constexpr double kSmoothRoughness = 0.0316;

struct BsdfInputs {
  Color base{0.8, 0.8, 0.8};
  double metallic = 0, roughness = 0.5, transmission = 0, ior = 1.5, specularLevel = 0.5;
  // KHR_materials_volume's thickness 0: the glass is a thin wall (a soap bubble, a window
  // pane), air on both sides: light passes it unbent, reflected by the index's Fresnel.
  bool thinWalled = false;
  // KHR_materials_specular: the dielectric reflection's strength (specularFactor, in [0, 1])
  // and colour (specularColorFactor, multiplying its F0, which stays at most 1).
  double specularWeight = 1;
  Color specularColor{1, 1, 1};
  // KHR_materials_clearcoat: the coat's strength (in [0, 1]), its roughness and its normal
  // (world space, unit; zero: the BSDF's normal).
  double clearcoat = 0, clearcoatRoughness = 0;
  Vec3 clearcoatNormal{0, 0, 0};
};

// The largest specularLevel: an F0 of 1.
inline constexpr double kMaxSpecularLevel = 12.5;

struct BsdfSample {
  Vec3 wi;
  Color weight;  // f |cos| / pdf: what the path's throughput is multiplied by
  double pdf = 0;  // of the mixture over the non-delta lobes; 0 for a delta lobe
  bool delta = false;
  bool transmitted = false;  // wi went through the surface
};

class Bsdf {
 public:
  // `n` unit, facing wo; `outward`: n is the surface's outward normal (wo outside).
  Bsdf(const BsdfInputs& in, const Vec3& n, const Vec3& wo, bool outward);

  // f(wo, wi) |cos(n, wi)| of the non-delta lobes.
  Color evaluate(const Vec3& wi) const;
  // The density sample() draws wi with, over the non-delta lobes (solid angle).
  double pdf(const Vec3& wi) const;
  // A direction from three uniform numbers in [0, 1); false: none (absorbed).
  bool sample(double u0, double u1, double u2, BsdfSample& out) const;
  // Whether next-event estimation can find anything: a lobe that is not delta.
  bool hasSmoothLobe() const {
    return diffuseP_ + (specularDelta_ ? 0 : specularP_) + (glassDelta_ ? 0 : glassP_) +
               (coatDelta_ ? 0 : coatP_) >
           0;
  }

 private:
  Color diffuseEval(const Vec3& wi) const;
  Color specularEval(const Vec3& wi) const;
  double specularPdf(const Vec3& wi) const;
  Color glassEval(const Vec3& wi) const;
  double glassPdf(const Vec3& wi) const;
  // Sets the coat up and scales the lobe weights below it (diffuse, specular, glass) by what
  // it leaves them.
  void setUpCoat(const Vec3& wo, double& d, double& s, double& g);
  // The coat's, for a world-space direction.
  Color coatEval(const Vec3& w) const;
  double coatPdf(const Vec3& w) const;

  BsdfInputs in_;
  Vec3 n_, t_, b_;  // shading frame
  Vec3 wo_;
  double cosO_;
  double alpha_;      // GGX's, roughness squared
  double eta_;        // index on the far side over the index on wo's side
  Color f0_, f90_;    // the specular lobe's reflectance at normal and grazing incidence
  double diffuseW_, glassW_;
  double diffuseP_ = 0, specularP_ = 0, glassP_ = 0;  // lobe choice, summing to 1
  bool specularDelta_, glassDelta_;
  // The clearcoat: its frame, wo in it, its alpha, its weight clearcoat Fc (0: none), the
  // share left to the layers below (1 - coatW_) and its lobe's choice.
  Vec3 coatN_, coatT_, coatB_, coatWo_;
  double coatAlpha_ = 1, coatW_ = 0, baseScale_ = 1, coatP_ = 0;
  bool coatDelta_ = false;
};

// Dielectric Fresnel reflectance for a cosine of incidence on wo's side and the relative
// index eta (far side over near side); 1 on total internal reflection.
double fresnelDielectric(double cosI, double eta);

}  // namespace prt
