#pragma once
// Foreign materials onto the paper's Hall model: the two families model files use, the
// physically based metallic-roughness model (glTF 2.0, and assimp's PBR keys) and the
// "common" Phong-style model (OBJ's MTL, COLLADA's profile_COMMON, FBX, glTF 1.0 through
// assimp). The rules and the reasons for them are in docs/scene-format.md ("How materials
// from model files are mapped"); what a material asks for that the mapping cannot express is
// listed in `unused` by its callers and reported as one warning.
// Pure functions; thread-safe.

#include <limits>
#include <string>
#include <vector>

#include "trace/scene.h"

namespace prt {

struct PbrMaterialInputs {
  Color baseColor{1, 1, 1};  // linear RGB, the factor (times the texture and vertex colours)
  double alpha = 1;
  TextureRef baseColorTexture;
  double metallic = 1, roughness = 1;  // glTF's defaults
  // Data textures (linear), the path tracer's alone: B metallic and G roughness multiplying
  // the factors; the tangent-space normal map and its scale; R transmission (KHR_materials_
  // transmission) multiplying its factor.
  TextureRef metallicRoughnessTexture;
  TextureRef normalTexture;
  double normalScale = 1;
  TextureRef transmissionTexture;
  Color emissive{0, 0, 0};
  double emissiveStrength = 1;  // KHR_materials_emissive_strength
  TextureRef emissiveTexture;
  double transmission = 0;  // KHR_materials_transmission
  double ior = 1.5;         // KHR_materials_ior
  // KHR_materials_volume: `volume` when the material has it. Thickness 0 (the extension's
  // default) makes the glass thin-walled; light inside a thick one falls to the attenuation
  // colour over the attenuation distance (world units; infinite: clear).
  bool volume = false;
  double thickness = 0;
  Color attenuationColor{1, 1, 1};
  double attenuationDistance = std::numeric_limits<double>::infinity();
  // KHR_materials_specular: `specular` when the material has it; the dielectric's F0 is then
  // min(((ior - 1) / (ior + 1))^2 specularColorFactor, 1) specularFactor.
  bool specular = false;
  double specularFactor = 1;
  Color specularColorFactor{1, 1, 1};
  // KHR_materials_clearcoat (the path tracer's alone).
  double clearcoat = 0, clearcoatRoughness = 0;
  enum class AlphaMode { opaque, mask, blend } alphaMode = AlphaMode::opaque;
  double alphaCutoff = 0.5;
  bool unlit = false;  // KHR_materials_unlit
};
Material mapPbrMaterial(const PbrMaterialInputs& in);
// The values of `in` that mapPbrMaterial does not take as given, each as "roughness 7 (taken
// as 1)": out of their ranges (colours and factors [0, 1], ior [1, 10], emission [0, 1e6] per
// component) or not finite. Empty when every value is taken as it is.
std::vector<std::string> pbrValuesOutOfRange(const PbrMaterialInputs& in);

struct CommonMaterialInputs {
  Color diffuse{0.8, 0.8, 0.8};  // Kd
  TextureRef diffuseTexture;     // map_Kd
  Color specular{0, 0, 0};       // Ks
  double shininess = 0;          // Ns: the Phong exponent
  Color emissive{0, 0, 0};       // Ke
  TextureRef emissiveTexture;    // map_Ke
  double opacity = 1;            // d (or 1 - Tr)
  double ior = 1;                // Ni
  int illum = 2;                 // the MTL illumination model; -1 unknown (not an MTL)
  double reflectivity = 0;       // COLLADA's and FBX's reflectivity, times the reflective colour
};
Material mapCommonMaterial(const CommonMaterialInputs& in);

}  // namespace prt
