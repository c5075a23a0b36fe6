#include "scene/material_mapping.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "scene/value_reader.h"

namespace prt {
namespace {

void expectLawful(const Material& m) {
  for (const double w : {m.ambient, m.diffuse, m.specular, m.reflectivity, m.transmissivity, m.metallic}) {
    EXPECT_GE(w, 0);
    EXPECT_LE(w, 1);
  }
  EXPECT_LE(m.reflectivity + m.transmissivity, 1 + 1e-15);
  EXPECT_GE(m.phongExponent, 1);
  EXPECT_GE(m.ior, 1);
  EXPECT_LT(m.glossDegrees, 90);
  EXPECT_LT(m.translucencyDegrees, 90);
}

TEST(MaterialMapping, RoughPlasticIsDiffuseWithABroadFaintHighlight) {
  PbrMaterialInputs in;
  in.baseColor = {0.8, 0.2, 0.1};
  in.metallic = 0;
  in.roughness = 0.9;
  const Material m = mapPbrMaterial(in);
  expectLawful(m);
  EXPECT_EQ(m.color, in.baseColor);
  EXPECT_EQ(m.diffuse, 1);
  EXPECT_EQ(m.reflectivity, 0);  // 4 % of a rough surface: not worth a ray
  EXPECT_LT(m.specular, 0.2);
  EXPECT_LT(m.phongExponent, 5);
}

TEST(MaterialMapping, SmoothMetalReflectsTintedAndHasNoDiffuse) {
  PbrMaterialInputs in;
  in.baseColor = {1, 0.8, 0.3};
  in.metallic = 1;
  in.roughness = 0.1;
  const Material m = mapPbrMaterial(in);
  expectLawful(m);
  EXPECT_EQ(m.diffuse, 0);
  EXPECT_EQ(m.metallic, 1);
  EXPECT_GT(m.reflectivity, 0.75);
  EXPECT_GT(m.phongExponent, 1000);
  EXPECT_GT(m.glossDegrees, 0);
  EXPECT_LT(m.glossDegrees, 1);
}

TEST(MaterialMapping, TransmissionIsGlassWithItsIndexAndFresnelReflection) {
  PbrMaterialInputs in;
  in.metallic = 0;
  in.roughness = 0;
  in.transmission = 1;
  in.ior = 1.45;
  const Material m = mapPbrMaterial(in);
  expectLawful(m);
  EXPECT_EQ(m.ior, 1.45);
  EXPECT_NEAR(m.reflectivity, std::pow(0.45 / 2.45, 2), 1e-12);
  EXPECT_NEAR(m.transmissivity, 1 - m.reflectivity, 1e-12);
  EXPECT_EQ(m.diffuse, 0);
}

// KHR_materials_volume: a thick glass keeps its index and absorbs inside; one of thickness 0
// (the extension's default) is a thin wall, through which both renderers see unbent. Without
// the extension, glass is solid and clear (as Blender renders it).
TEST(MaterialMapping, VolumeIsAbsorptionInsideOrAThinWall) {
  PbrMaterialInputs in;
  in.metallic = 0;
  in.roughness = 0;
  in.transmission = 1;
  in.ior = 1.45;
  const Material clear = mapPbrMaterial(in);
  EXPECT_FALSE(clear.pbr.thinWalled);
  EXPECT_TRUE(std::isinf(clear.pbr.attenuationDistance));
  in.volume = true;
  in.thickness = 0.2;
  in.attenuationColor = Color(0.9, 0.5, 0.1);
  in.attenuationDistance = 2;
  const Material thick = mapPbrMaterial(in);
  expectLawful(thick);
  EXPECT_FALSE(thick.pbr.thinWalled);
  EXPECT_EQ(thick.pbr.attenuationColor, Color(0.9, 0.5, 0.1));
  EXPECT_EQ(thick.pbr.attenuationDistance, 2);
  EXPECT_EQ(thick.ior, 1.45);
  EXPECT_TRUE(pbrValuesOutOfRange(in).empty());
  in.thickness = 0;
  const Material thin = mapPbrMaterial(in);
  expectLawful(thin);
  EXPECT_TRUE(thin.pbr.thinWalled);
  EXPECT_TRUE(std::isinf(thin.pbr.attenuationDistance));
  EXPECT_EQ(thin.ior, 1);
  EXPECT_EQ(thin.pbr.ior, 1.45);  // its reflection's Fresnel
}

TEST(MaterialMapping, AlphaBlendsByTransmissionWithoutRefractionAndMasksCutOut) {
  PbrMaterialInputs in;
  in.metallic = 0;
  in.alpha = 0.25;
  in.alphaMode = PbrMaterialInputs::AlphaMode::blend;
  Material m = mapPbrMaterial(in);
  expectLawful(m);
  EXPECT_EQ(m.transmissivity, 0.75);
  EXPECT_EQ(m.ior, 1);
  EXPECT_EQ(m.diffuse, 0.25);
  in.alphaMode = PbrMaterialInputs::AlphaMode::mask;
  m = mapPbrMaterial(in);
  EXPECT_EQ(m.transmissivity, 1);
  EXPECT_EQ(m.diffuse, 0);
  in.alpha = 0.75;
  EXPECT_EQ(mapPbrMaterial(in).transmissivity, 0);
  in.alphaMode = PbrMaterialInputs::AlphaMode::opaque;
  in.alpha = 0;
  EXPECT_EQ(mapPbrMaterial(in).transmissivity, 0);  // opaque ignores alpha
}

TEST(MaterialMapping, EmissionAndUnlit) {
  PbrMaterialInputs in;
  in.emissive = {1, 0.8, 0.5};
  in.emissiveStrength = 5;
  EXPECT_EQ(mapPbrMaterial(in).emission, Color(5, 4, 2.5));
  in.unlit = true;
  in.baseColor = {0.2, 0.4, 0.6};
  in.baseColorTexture.texture = 3;
  const Material m = mapPbrMaterial(in);
  EXPECT_EQ(m.emission, Color(0.2, 0.4, 0.6));
  EXPECT_EQ(m.emissionTexture.texture, 3);
  EXPECT_EQ(m.diffuse + m.ambient + m.specular, 0);
}

TEST(MaterialMapping, AbsurdInputsGiveALawfulMaterial) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  PbrMaterialInputs in;
  in.baseColor = {nan, -1, inf};
  in.metallic = nan;
  in.roughness = -3;
  in.transmission = inf;
  in.ior = nan;
  in.emissive = {nan, -2, inf};
  in.emissiveStrength = nan;
  const Material m = mapPbrMaterial(in);
  expectLawful(m);
  EXPECT_TRUE(isFinite(m.color));
  EXPECT_TRUE(isFinite(m.emission));
  CommonMaterialInputs c;
  c.diffuse = {nan, 2, -1};
  c.specular = {inf, 0, 0};
  c.shininess = nan;
  c.opacity = nan;
  c.ior = inf;
  c.illum = 7;
  expectLawful(mapCommonMaterial(c));
}

TEST(MaterialMapping, MtlIlluminationModels) {
  CommonMaterialInputs in;
  in.diffuse = {0.5, 0.5, 0.5};
  in.specular = {0.5, 0.5, 0.5};
  in.shininess = 96;
  in.illum = 1;  // no highlight
  EXPECT_EQ(mapCommonMaterial(in).specular, 0);
  in.illum = 2;
  Material m = mapCommonMaterial(in);
  EXPECT_EQ(m.specular, 0.5);
  EXPECT_EQ(m.phongExponent, 96);
  EXPECT_EQ(m.reflectivity, 0);
  in.illum = 3;  // reflection on
  EXPECT_EQ(mapCommonMaterial(in).reflectivity, 0.5);
  // Dissolve makes it see-through; only the glass models refract with Ni.
  in.illum = 2;
  in.opacity = 0.4;
  in.ior = 1.5;
  m = mapCommonMaterial(in);
  EXPECT_NEAR(m.transmissivity, 0.6, 1e-15);
  EXPECT_EQ(m.ior, 1);
  in.illum = 7;
  m = mapCommonMaterial(in);
  expectLawful(m);
  EXPECT_EQ(m.ior, 1.5);
  in.illum = 0;  // the colour, unlit
  in.opacity = 1;
  m = mapCommonMaterial(in);
  EXPECT_EQ(m.emission, in.diffuse);
  EXPECT_EQ(m.diffuse, 0);
}

TEST(MaterialMapping, EmissionIsBoundedAsSceneColoursAre) {
  PbrMaterialInputs in;
  in.emissive = Color(1, 0.5, 0);
  in.emissiveStrength = 1e39;  // beyond a float: an infinity in the image
  const Material m = mapPbrMaterial(in);
  EXPECT_EQ(m.emission, Color(kMaxColorComponent, kMaxColorComponent, 0));
  CommonMaterialInputs common;
  common.emissive = Color(1e300, 2, 0);
  EXPECT_EQ(mapCommonMaterial(common).emission, Color(kMaxColorComponent, 2, 0));
}

}  // namespace
}  // namespace prt
