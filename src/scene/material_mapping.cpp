#include "scene/material_mapping.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "scene/value_reader.h"
#include "trace/bsdf.h"

namespace prt {
namespace {

// A mirror term weaker than this costs a ray per hit for a change the eye does not see.
constexpr double kLeastReflection = 0.02;

double clamp01(double v) { return std::isfinite(v) ? std::clamp(v, 0.0, 1.0) : 0.0; }
Color clamp01(const Color& c) { return {clamp01(c.x), clamp01(c.y), clamp01(c.z)}; }
Color nonNegative(const Color& c) {
  auto f = [](double v) { return std::isfinite(v) && v > 0 ? v : 0.0; };
  return {f(c.x), f(c.y), f(c.z)};
}
// Emission as the scene format bounds colours, [0, 1e6] per component: larger values are
// surely mistakes, and with them no image can hold an infinity (a component beyond a float's
// range would, and a worker sending one would be taken for a liar).
Color emissionOf(const Color& c) {
  const Color n = nonNegative(c);
  auto f = [](double v) { return std::min(v, kMaxColorComponent); };
  return {f(n.x), f(n.y), f(n.z)};
}

// The values mapPbrMaterial takes for those given, each range written once (pbrValuesOutOfRange
// names what these change).
double iorOf(double ior) { return std::isfinite(ior) ? std::clamp(ior, 1.0, 10.0) : 1.5; }
double emissiveStrengthOf(double s) { return std::isfinite(s) ? std::max(0.0, s) : 1.0; }
double normalScaleOf(double s) { return std::isfinite(s) ? std::clamp(s, -1e6, 1e6) : 1.0; }
// glTF asks for a thickness of at least 0 and a distance above 0 (infinite by default); a
// distance that is not (or is not a number) is taken as the default, clear.
double thicknessOf(double t) { return t > 0 ? t : 0.0; }
double attenuationDistanceOf(double d) {
  return d > 0 ? d : std::numeric_limits<double>::infinity();
}
// A specular colour multiplies F0, which stays at most 1: no bound below the colours'.
Color specularColorOf(const Color& c) { return emissionOf(c); }

// The Phong exponent whose lobe is about as wide as a GGX lobe of this roughness: Blinn-Phong's
// 2 / alpha^2 - 2 with alpha = roughness^2 (Walter et al. 2007), a quarter of it for Phong's
// reflection-vector form, between 1 and 10000.
double phongExponentFor(double roughness) {
  const double r = std::max(roughness, 0.03);
  return std::clamp((2 / (r * r * r * r) - 2) / 4, 1.0, 10000.0);
}

// The half-angle of the cone of glossy rays for a roughness, in degrees.
double glossFor(double roughness) { return std::min(45.0, 60 * roughness * roughness); }

}  // namespace

Material mapPbrMaterial(const PbrMaterialInputs& in) {
  Material m;
  const double metallic = clamp01(in.metallic), roughness = clamp01(in.roughness);
  m.color = clamp01(in.baseColor);
  m.colorTexture = in.baseColorTexture;
  m.emission = emissionOf(in.emissive * emissiveStrengthOf(in.emissiveStrength));
  m.emissionTexture = in.emissiveTexture;
  if (in.unlit) {  // shown as its colour, whatever the lights
    m.diffuse = m.ambient = m.specular = 0;
    m.emission = m.color;
    m.emissionTexture = in.baseColorTexture;
    m.color = Color();
    m.colorTexture = {};
    return m;
  }
  // A dielectric reflects ((n - 1) / (n + 1))^2 at normal incidence: 4 % at glTF's default
  // index of 1.5 (KHR_materials_ior changes both); a metal reflects its colour.
  const double ior = iorOf(in.ior);
  const double f0 = (ior - 1) / (ior + 1);
  double dielectric = f0 * f0;
  if (in.specular) {  // KHR_materials_specular: its colour's luminance and its factor
    dielectric = std::min(dielectric * luminance(specularColorOf(in.specularColorFactor)), 1.0) *
                 clamp01(in.specularFactor);
  }
  const double reflectance = dielectric * (1 - metallic) + metallic;
  m.metallic = metallic;
  m.phongExponent = phongExponentFor(roughness);
  // The Phong lobe normalised as a BRDF peaks at (n + 2) / (2 pi) times the reflectance; with
  // lights scaled by 1 / pi (model lights: see the import notes) that is (n + 2) / 2.
  m.specular = std::min(1.0, reflectance * (m.phongExponent + 2) / 2);
  const double smooth = (1 - roughness) * (1 - roughness);
  const double reflect = reflectance * smooth;
  m.reflectivity = reflect >= kLeastReflection ? reflect : 0.0;
  m.glossDegrees = m.reflectivity > 0 ? glossFor(roughness) : 0.0;
  const double transmission = clamp01(in.transmission) * (1 - metallic);
  double cover = 1;  // how much of the surface is there: alpha
  const double alpha = clamp01(in.alpha);
  if (in.alphaMode == PbrMaterialInputs::AlphaMode::mask && alpha < in.alphaCutoff) cover = 0;
  if (in.alphaMode == PbrMaterialInputs::AlphaMode::blend) cover = alpha;
  if (transmission > 0) {  // glass: refracts by its index
    m.transmissivity = std::min(transmission, 1 - m.reflectivity);
    m.ior = ior;
    m.translucencyDegrees = ior > 1 ? glossFor(roughness) : 0.0;
  } else if (cover < 1) {  // light passes straight through the missing part
    m.transmissivity = std::min(1 - cover, 1 - m.reflectivity);
    m.ior = 1;
  }
  // The path tracer takes the model as it is (trace/bsdf.h).
  m.pbr.given = true;
  m.pbr.roughness = roughness;
  m.pbr.transmission = clamp01(in.transmission);
  m.pbr.ior = ior;
  m.pbr.coverage = cover;
  m.pbr.metallicRoughnessTexture = in.metallicRoughnessTexture;
  m.pbr.normalTexture = in.normalTexture;
  m.pbr.normalScale = normalScaleOf(in.normalScale);
  m.pbr.transmissionTexture = in.transmissionTexture;
  if (in.specular) {  // F0 from the index, as glTF's specification has it
    m.pbr.specularLevel = std::min(f0 * f0 / 0.08, kMaxSpecularLevel);
    m.pbr.specularWeight = clamp01(in.specularFactor);
    m.pbr.specularColor = specularColorOf(in.specularColorFactor);
  }
  m.pbr.clearcoat = clamp01(in.clearcoat);
  m.pbr.clearcoatRoughness = clamp01(in.clearcoatRoughness);
  m.pbr.thinWalled = in.volume && thicknessOf(in.thickness) == 0;
  if (in.volume && !m.pbr.thinWalled) {
    m.pbr.attenuationColor = clamp01(in.attenuationColor);
    m.pbr.attenuationDistance = attenuationDistanceOf(in.attenuationDistance);
  }
  if (m.pbr.thinWalled && m.transmissivity > 0) {  // the paper's renderer: through it unbent
    m.ior = 1;
    m.translucencyDegrees = 0;
  }
  m.diffuse = (1 - metallic) * (1 - transmission) * cover;
  m.ambient = m.diffuse;
  m.specular *= cover;
  if (cover == 0) m.reflectivity = m.specular = 0, m.glossDegrees = 0, m.transmissivity = 1;
  return m;
}

std::vector<std::string> pbrValuesOutOfRange(const PbrMaterialInputs& in) {
  std::vector<std::string> out;
  // Said when the value taken is not the one given (a NaN never equals what replaces it).
  const auto check = [&](const char* what, double given, double taken) {
    if (given == taken) return;
    char text[96];
    std::snprintf(text, sizeof text, "%s %g (taken as %g)", what, given, taken);
    out.emplace_back(text);
  };
  const auto unit = [&](const char* what, double given) { check(what, given, clamp01(given)); };
  unit("base colour red", in.baseColor.x);
  unit("base colour green", in.baseColor.y);
  unit("base colour blue", in.baseColor.z);
  unit("alpha", in.alpha);
  unit("metallic", in.metallic);
  unit("roughness", in.roughness);
  unit("transmission", in.transmission);
  check("ior", in.ior, iorOf(in.ior));
  check("emissive strength", in.emissiveStrength, emissiveStrengthOf(in.emissiveStrength));
  const Color asked = in.emissive * emissiveStrengthOf(in.emissiveStrength);
  const Color taken = emissionOf(asked);
  check("emission red", asked.x, taken.x);
  check("emission green", asked.y, taken.y);
  check("emission blue", asked.z, taken.z);
  check("normal scale", in.normalScale, normalScaleOf(in.normalScale));
  if (in.specular) {
    unit("specular factor", in.specularFactor);
    const Color colour = specularColorOf(in.specularColorFactor);
    check("specular colour red", in.specularColorFactor.x, colour.x);
    check("specular colour green", in.specularColorFactor.y, colour.y);
    check("specular colour blue", in.specularColorFactor.z, colour.z);
  }
  unit("clearcoat", in.clearcoat);
  unit("clearcoat roughness", in.clearcoatRoughness);
  if (in.volume) {
    check("thickness", in.thickness, thicknessOf(in.thickness));
    unit("attenuation colour red", in.attenuationColor.x);
    unit("attenuation colour green", in.attenuationColor.y);
    unit("attenuation colour blue", in.attenuationColor.z);
    check("attenuation distance", in.attenuationDistance, attenuationDistanceOf(in.attenuationDistance));
  }
  return out;
}

Material mapCommonMaterial(const CommonMaterialInputs& in) {
  Material m;
  m.color = clamp01(in.diffuse);
  m.colorTexture = in.diffuseTexture;
  m.diffuse = 1;
  m.ambient = 1;
  m.emission = emissionOf(in.emissive);
  m.emissionTexture = in.emissiveTexture;
  const int illum = in.illum;
  if (illum == 0) {  // "colour on, ambient off": the colour, unlit
    m.emission = m.color;
    m.emissionTexture = m.colorTexture;
    m.diffuse = m.ambient = 0;
    return m;
  }
  const double specular = clamp01(maxComponent(in.specular));
  if (illum != 1 && specular > 0) {
    m.specular = specular;
    m.phongExponent = std::isfinite(in.shininess) ? std::clamp(in.shininess, 1.0, 10000.0) : 40;
  }
  // Illumination models 3 and up trace reflections, weighted by Ks; other formats say how
  // much they reflect with a reflectivity of their own.
  double reflect = 0;
  if (illum >= 3 && illum != 4 && illum != 6 && illum != 9) reflect = specular;
  if (illum == 4 || illum == 6 || illum == 7) reflect = std::max(reflect, specular * 0.1);
  reflect = std::max(reflect, clamp01(in.reflectivity));
  m.reflectivity = reflect >= kLeastReflection ? reflect : 0.0;
  const double opacity = clamp01(in.opacity);
  if (opacity < 1) {
    m.transmissivity = std::min(1 - opacity, 1 - m.reflectivity);
    // Only the glass models refract: most files write Ni whatever the material.
    const bool glass = illum == 4 || illum == 6 || illum == 7 || illum == 9 || illum < 0;
    m.ior = glass && std::isfinite(in.ior) ? std::clamp(in.ior, 1.0, 10.0) : 1.0;
    m.diffuse = m.ambient = opacity;
  }
  return m;
}

}  // namespace prt
