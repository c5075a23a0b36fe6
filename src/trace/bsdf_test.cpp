#include "trace/bsdf.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "core/rng.h"

namespace prt {
namespace {

struct Case {
  const char* name;
  BsdfInputs in;
};

std::vector<Case> roughCases() {
  return {{"rough white dielectric", {Color(1), 0, 1, 0, 1.5, 0.5}},
          {"half-rough red plastic", {Color(0.8, 0.1, 0.1), 0, 0.5, 0, 1.5, 0.5}},
          {"rough gold", {Color(1, 0.78, 0.34), 1, 0.3, 0, 1.5, 0.5}},
          {"rough white metal", {Color(1), 1, 0.6, 0, 1.5, 0.5}},
          {"frosted glass", {Color(1), 0, 0.4, 1, 1.5, 0.5}},
          {"half-frosted tinted glass", {Color(0.9, 1, 0.9), 0, 0.25, 0.5, 1.33, 0.5}},
          {"frosted thin wall", {Color(1), 0, 0.4, 1, 1.5, 0.5, true}},
          {"red plastic, coloured specular", {Color(0.8, 0.1, 0.1), 0, 0.5, 0, 1.5, 0.5, false, 0.6, Color(1, 0.5, 30)}},
          {"rough white, no specular", {Color(1), 0, 0.7, 0, 1.5, 0.5, false, 0, Color(1)}},
          {"clear-coated red plastic", {Color(0.8, 0.1, 0.1), 0, 0.5, 0, 1.5, 0.5, false, 1, Color(1), 1, 0.2}},
          {"gold under a smooth coat", {Color(1, 0.78, 0.34), 1, 0.3, 0, 1.5, 0.5, false, 1, Color(1), 0.5, 0}},
          {"frosted glass under a coat", {Color(1), 0, 0.4, 1, 1.5, 0.5, false, 1, Color(1), 1, 0.1}},
          {"half-frosted tinted thin wall", {Color(0.9, 1, 0.9), 0, 0.25, 0.5, 1.33, 0.5, true}}};
}

Vec3 outgoing(double cosine) { return Vec3(std::sqrt(1 - cosine * cosine), 0, cosine); }

// What sample() returns for a direction it draws (from a lobe that is not a delta) is the
// mixture's f |cos| / pdf, and evaluate and pdf agree with it: the condition for next-event
// estimation and BSDF sampling to be weighed against each other by MIS.
TEST(BsdfTest, SampleWeightsAreEvaluateOverPdf) {
  for (const Case& c : roughCases()) {
    for (const bool outward : {true, false}) {
      for (const double cosine : {0.95, 0.5, 0.1}) {
        const Bsdf bsdf(c.in, Vec3(0, 0, 1), outgoing(cosine), outward);
        Rng rng(7);
        int drawn = 0;
        for (int i = 0; i < 2000; ++i) {
          const double u0 = rng.uniform(), u1 = rng.uniform(), u2 = rng.uniform();
          BsdfSample s;
          if (!bsdf.sample(u0, u1, u2, s) || s.delta) continue;
          ++drawn;
          ASSERT_GT(s.pdf, 0) << c.name;
          EXPECT_NEAR(s.pdf, bsdf.pdf(s.wi), 1e-9 * s.pdf) << c.name;
          const Color expected = bsdf.evaluate(s.wi) / s.pdf;
          EXPECT_NEAR(s.weight.x, expected.x, 1e-9 * (1 + expected.x)) << c.name;
        }
        EXPECT_GT(drawn, 1000) << c.name << " cos " << cosine;
      }
    }
  }
}

// The pdf is a density over the sphere of directions: it integrates to at most 1 (less where
// a lobe's sampled directions are refused, below the surface), estimated by uniform sampling.
TEST(BsdfTest, PdfIntegratesToAtMostOne) {
  for (const Case& c : roughCases()) {
    const Bsdf bsdf(c.in, Vec3(0, 0, 1), outgoing(0.7), true);
    Rng rng(3);
    const int n = 200000;
    double sum = 0;
    for (int i = 0; i < n; ++i) {
      const double z = 1 - 2 * rng.uniform();
      const double r = std::sqrt(std::max(0.0, 1 - z * z));
      const double phi = 2 * std::numbers::pi * rng.uniform();
      sum += bsdf.pdf(Vec3(r * std::cos(phi), r * std::sin(phi), z)) * 4 * std::numbers::pi;
    }
    const double integral = sum / n;
    EXPECT_LT(integral, 1.03) << c.name;
    EXPECT_GT(integral, 0.8) << c.name;
  }
}

// No surface returns more light than reaches it (the directional albedo is at most 1, within
// the noise of the estimate), and the reflection lobes are reciprocal.
TEST(BsdfTest, ConservesEnergyAndIsReciprocal) {
  for (const Case& c : roughCases()) {
    for (const double cosine : {0.9, 0.5, 0.2}) {
      const Bsdf bsdf(c.in, Vec3(0, 0, 1), outgoing(cosine), true);
      Rng rng(11);
      double albedo = 0;
      const int n = 20000;
      for (int i = 0; i < n; ++i) {
        const double u0 = rng.uniform(), u1 = rng.uniform(), u2 = rng.uniform();
        BsdfSample s;
        if (bsdf.sample(u0, u1, u2, s)) albedo += maxComponent(s.weight);
      }
      // Blender's Principled BSDF, which the model follows, adds the specular layer to the
      // diffuse one without taking its share away, and Burley's diffuse brightens rough
      // surfaces at grazing angles: a white rough dielectric returns up to about 1.3. The
      // metals and glasses are within noise of at most 1 (a part glass, part diffuse one adds
      // the layer over its diffuse part: a thin wall, whose light keeps its radiance through
      // it, shows that).
      const double bound = c.in.transmission < 1 && c.in.metallic == 0 ? 1.35 : 1.03;
      EXPECT_LE(albedo / n, bound) << c.name << " cos " << cosine;
    }
    // The glass's refraction is not reciprocal (radiance is scaled by the index), nor is the
    // clearcoat's layering as glTF defines it (Fresnel of the view direction alone).
    if (c.in.transmission > 0 || c.in.clearcoat > 0) continue;
    const Vec3 a = normalize(Vec3(0.3, 0.1, 0.8)), b = normalize(Vec3(-0.5, 0.2, 0.4));
    const Color fab = Bsdf(c.in, Vec3(0, 0, 1), a, true).evaluate(b) / b.z;
    const Color fba = Bsdf(c.in, Vec3(0, 0, 1), b, true).evaluate(a) / a.z;
    EXPECT_NEAR(fab.x, fba.x, 1e-12 * (1 + fab.x)) << c.name;
  }
}

// A smooth white metal and a clear glass are deltas that lose nothing: every sample's weight
// is exactly what the Fresnel terms allow, 1 for the metal, and reflection or refraction for
// the glass in the proportion of the exact Fresnel reflectance.
TEST(BsdfTest, SmoothSurfacesAreDeltasThatLoseNothing) {
  const Bsdf mirror({Color(1), 1, 0, 0, 1.5, 0.5}, Vec3(0, 0, 1), outgoing(0.6), true);
  EXPECT_FALSE(mirror.hasSmoothLobe());
  BsdfSample s;
  ASSERT_TRUE(mirror.sample(0.3, 0.5, 0.5, s));
  EXPECT_TRUE(s.delta);
  EXPECT_DOUBLE_EQ(s.weight.x, 1.0);
  EXPECT_NEAR(s.wi.z, 0.6, 1e-15);

  const double r = fresnelDielectric(0.6, 1.5);
  EXPECT_GT(r, 0.04);
  EXPECT_LT(r, 0.2);
  const Bsdf glass({Color(1), 0, 0, 1, 1.5, 0.5}, Vec3(0, 0, 1), outgoing(0.6), true);
  ASSERT_TRUE(glass.sample(r * 0.5, 0.5, 0.5, s));  // below the reflectance: reflected
  EXPECT_FALSE(s.transmitted);
  EXPECT_NEAR(s.weight.x, 1.0, 1e-12);
  ASSERT_TRUE(glass.sample(r + (1 - r) * 0.5, 0.5, 0.5, s));  // above: refracted
  EXPECT_TRUE(s.transmitted);
  EXPECT_LT(s.wi.z, 0);
  // Radiance is compressed entering a denser medium by 1 / eta^2 (and expanded leaving it).
  EXPECT_NEAR(s.weight.x, 1 / (1.5 * 1.5), 1e-12);
  // Snell: sin t = sin i / 1.5.
  EXPECT_NEAR(std::sqrt(1 - s.wi.z * s.wi.z), 0.8 / 1.5, 1e-12);
}

// A smooth thin wall (KHR_materials_volume's thickness 0) lets light through unbent and
// uncompressed, tinted by the base colour, and reflects the index's Fresnel share, from
// either side alike: no total internal reflection, since both sides are air.
TEST(BsdfTest, ASmoothThinWallPassesLightUnbent) {
  const Color tint(0.9, 0.5, 0.2);
  for (const bool outward : {true, false}) {
    const Bsdf wall({tint, 0, 0, 1, 1.5, 0.5, true}, Vec3(0, 0, 1), outgoing(0.2), outward);
    EXPECT_FALSE(wall.hasSmoothLobe());
    const double r = fresnelDielectric(0.2, 1.5);
    BsdfSample s;
    ASSERT_TRUE(wall.sample(r + (1 - r) * 0.5, 0.5, 0.5, s));
    EXPECT_TRUE(s.delta);
    EXPECT_TRUE(s.transmitted);
    const Vec3 straight = -outgoing(0.2);
    EXPECT_NEAR(s.wi.x, straight.x, 1e-15);
    EXPECT_NEAR(s.wi.z, straight.z, 1e-15);
    EXPECT_NEAR(s.weight.x, tint.x, 1e-12);
    EXPECT_NEAR(s.weight.z, tint.z, 1e-12);
    ASSERT_TRUE(wall.sample(r * 0.5, 0.5, 0.5, s));
    EXPECT_FALSE(s.transmitted);
    EXPECT_NEAR(s.weight.x, 1.0, 1e-12);
  }
}

// KHR_materials_specular: a black dielectric's reflection seen head on is F0 =
// min(0.08 specularLevel specularColor, 1) specularWeight per channel, and at grazing angles it
// tends to F90 = specularWeight rather than 1.
TEST(BsdfTest, SpecularExtensionScalesAndColoursTheDielectricsFresnel) {
  const BsdfInputs plain{Color(0), 0, 0.5, 0, 1.5, 0.5};
  BsdfInputs tinted = plain;
  tinted.specularWeight = 0.6;
  tinted.specularColor = Color(1, 0.5, 30);
  const Vec3 up(0, 0, 1);
  const Color f = Bsdf(tinted, up, up, true).evaluate(up);
  const Color reference = Bsdf(plain, up, up, true).evaluate(up);  // F0 0.04
  EXPECT_NEAR(f.x / reference.x, 0.6 * 0.04 / 0.04, 1e-12);
  EXPECT_NEAR(f.y / reference.y, 0.6 * 0.02 / 0.04, 1e-12);
  EXPECT_NEAR(f.z / reference.z, 0.6 * 1.0 / 0.04, 1e-12);
  // Grazing: the mirror direction of a wo 89.9 degrees from the normal.
  const Vec3 wo = outgoing(std::cos(89.9 * std::numbers::pi / 180));
  const Vec3 wi(-wo.x, -wo.y, wo.z);
  const Color g = Bsdf(tinted, up, wo, true).evaluate(wi);
  const Color gReference = Bsdf(plain, up, wo, true).evaluate(wi);
  EXPECT_NEAR(g.x / gReference.x, 0.6, 0.01);
  EXPECT_NEAR(g.y / gReference.y, 0.6, 0.01);
}

// KHR_materials_clearcoat over a surface that reflects nothing itself returns the coat's
// share alone: 4 % seen head on (less what single-scattering GGX loses), far more at grazing
// angles; over a white diffuse surface, the diffuse light is what the coat leaves it.
TEST(BsdfTest, ClearcoatReflectsItsFresnelShareAndTakesItFromTheBase) {
  BsdfInputs black{Color(0), 0, 0.5, 0, 1.5, 0.5, false, 0, Color(1), 1, 0.3};
  auto albedo = [](const BsdfInputs& in, double cosine) {
    const Bsdf bsdf(in, Vec3(0, 0, 1), outgoing(cosine), true);
    Rng rng(13);
    double sum = 0;
    const int n = 40000;
    for (int i = 0; i < n; ++i) {
      BsdfSample s;
      const double u0 = rng.uniform(), u1 = rng.uniform(), u2 = rng.uniform();
      if (bsdf.sample(u0, u1, u2, s)) sum += s.weight.x;
    }
    return sum / n;
  };
  EXPECT_NEAR(albedo(black, 1.0), 0.04, 0.003);
  EXPECT_GT(albedo(black, 0.1), 0.2);
  BsdfInputs white{Color(1), 0, 1, 0, 1.5, 0.5, false, 0, Color(1)};
  const double bare = albedo(white, 1.0);
  white.clearcoat = 1;
  EXPECT_NEAR(albedo(white, 1.0), 0.96 * bare + 0.04, 0.01);
  // A smooth coat is a delta lobe that next-event estimation cannot find, but the rough base
  // below it still can.
  white.clearcoatRoughness = 0;
  EXPECT_TRUE(Bsdf(white, Vec3(0, 0, 1), outgoing(0.5), true).hasSmoothLobe());
}

TEST(BsdfTest, FresnelOfAnIndexOfOnePointFiveAtNormalIncidenceIsFourPerCent) {
  EXPECT_NEAR(fresnelDielectric(1, 1.5), 0.04, 1e-12);
  EXPECT_NEAR(fresnelDielectric(1, 1 / 1.5), 0.04, 1e-12);
  EXPECT_DOUBLE_EQ(fresnelDielectric(0.1, 1 / 1.5), 1.0);  // total internal reflection
}

}  // namespace
}  // namespace prt
