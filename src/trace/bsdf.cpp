#include "trace/bsdf.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/portable_math.h"

namespace prt {
namespace {

constexpr double kInvPi = 1.0 / std::numbers::pi;

double pow5(double x) {
  const double x2 = x * x;
  return x2 * x2 * x;
}

Color schlick(const Color& f0, const Color& f90, double cosine) {
  const double w = pow5(std::clamp(1 - cosine, 0.0, 1.0));
  return f0 + w * (f90 - f0);
}

// GGX in the local frame (z along the normal), alpha the width.
double ggxD(const Vec3& h, double alpha) {
  if (h.z <= 0) return 0;
  const double a2 = alpha * alpha;
  const double c2 = h.z * h.z;
  const double d = c2 * (a2 - 1) + 1;
  return a2 / (std::numbers::pi * d * d);
}
double ggxLambda(const Vec3& w, double alpha) {
  const double c2 = w.z * w.z;
  if (c2 <= 0) return 1e300;
  const double tan2 = std::max(0.0, 1 - c2) / c2;
  return 0.5 * (std::sqrt(1 + alpha * alpha * tan2) - 1);
}
double ggxG1(const Vec3& w, double alpha) { return 1 / (1 + ggxLambda(w, alpha)); }
double ggxG2(const Vec3& wo, const Vec3& wi, double alpha) {
  return 1 / (1 + ggxLambda(wo, alpha) + ggxLambda(wi, alpha));
}
// The density of visible normal h seen from wo (wo.z > 0).
double ggxVisible(const Vec3& wo, const Vec3& h, double alpha) {
  return ggxG1(wo, alpha) * std::max(0.0, dot(wo, h)) * ggxD(h, alpha) / wo.z;
}
// A visible normal from wo (Heitz 2018, "Sampling the GGX Distribution of Visible Normals").
Vec3 sampleVisibleNormal(const Vec3& wo, double alpha, double u1, double u2) {
  const Vec3 vh = normalize(Vec3(alpha * wo.x, alpha * wo.y, wo.z));
  const double lensq = vh.x * vh.x + vh.y * vh.y;
  const Vec3 t1 = lensq > 0 ? Vec3(-vh.y, vh.x, 0) / std::sqrt(lensq) : Vec3(1, 0, 0);
  const Vec3 t2 = cross(vh, t1);
  double s, c;
  sinCosTurns(u2, s, c);
  const double r = std::sqrt(u1);
  const double p1 = r * c;
  double p2 = r * s;
  const double mix = 0.5 * (1 + vh.z);
  p2 = (1 - mix) * std::sqrt(std::max(0.0, 1 - p1 * p1)) + mix * p2;
  const Vec3 nh = p1 * t1 + p2 * t2 + std::sqrt(std::max(0.0, 1 - p1 * p1 - p2 * p2)) * vh;
  return normalize(Vec3(alpha * nh.x, alpha * nh.y, std::max(1e-12, nh.z)));
}

// wo refracted through the microfacet normal m (on wo's side) with relative index eta.
bool refractThrough(const Vec3& wo, const Vec3& m, double eta, Vec3& wt) {
  const double cosI = dot(m, wo);
  const double sin2I = std::max(0.0, 1 - cosI * cosI);
  const double sin2T = sin2I / (eta * eta);
  if (sin2T >= 1) return false;
  const double cosT = std::sqrt(1 - sin2T);
  wt = -wo / eta + (cosI / eta - cosT) * m;
  return true;
}

}  // namespace

double fresnelDielectric(double cosI, double eta) {
  cosI = std::clamp(cosI, -1.0, 1.0);
  if (cosI < 0) {
    eta = 1 / eta;
    cosI = -cosI;
  }
  const double sin2T = (1 - cosI * cosI) / (eta * eta);
  if (sin2T >= 1) return 1;
  const double cosT = std::sqrt(std::max(0.0, 1 - sin2T));
  const double parallel = (eta * cosI - cosT) / (eta * cosI + cosT);
  const double perpendicular = (cosI - eta * cosT) / (cosI + eta * cosT);
  return 0.5 * (parallel * parallel + perpendicular * perpendicular);
}

Bsdf::Bsdf(const BsdfInputs& in, const Vec3& n, const Vec3& wo, bool outward) : in_(in), n_(n) {
  orthonormalBasis(n_, t_, b_);
  wo_ = Vec3(dot(wo, t_), dot(wo, b_), dot(wo, n_));
  cosO_ = std::max(wo_.z, 1e-9);
  wo_.z = cosO_;
  const double roughness = std::clamp(in_.roughness, 0.0, 1.0);
  alpha_ = std::max(roughness * roughness, 1e-3);
  const double ior = std::clamp(in_.ior, 1.0, 10.0);
  // A thin wall has air on both sides: its Fresnel is the index's whichever side wo is on.
  eta_ = outward || in_.thinWalled ? ior : 1 / ior;
  const double metallic = std::clamp(in_.metallic, 0.0, 1.0);
  const double transmission = std::clamp(in_.transmission, 0.0, 1.0);
  Color dielectric(0.08 * std::clamp(in_.specularLevel, 0.0, kMaxSpecularLevel));
  f90_ = Color(1);
  if (in_.specularWeight != 1 || in_.specularColor != Color(1)) {
    // KHR_materials_specular: F0 coloured (at most 1) and, with F90, weighted (the dielectric's
    // part; a metal's is its base colour up to 1).
    const double weight = std::clamp(in_.specularWeight, 0.0, 1.0);
    const Color tinted = dielectric * in_.specularColor;
    dielectric = weight * Color(std::min(tinted.x, 1.0), std::min(tinted.y, 1.0), std::min(tinted.z, 1.0));
    f90_ = Color((1 - metallic) * weight + metallic);
  }
  f0_ = (1 - metallic) * dielectric + metallic * in_.base;
  diffuseW_ = (1 - metallic) * (1 - transmission);
  glassW_ = (1 - metallic) * transmission;
  specularDelta_ = glassDelta_ = roughness < kSmoothRoughness;
  // The glass carries its own reflection: the specular layer covers the rest.
  double d = diffuseW_ * luminance(in_.base);
  double s = (1 - glassW_) * luminance(schlick(f0_, f90_, cosO_));
  double g = glassW_;
  if (in_.clearcoat > 0) setUpCoat(wo, d, s, g);
  const double sum = d + s + g + coatP_;
  if (sum > 0) diffuseP_ = d / sum, specularP_ = s / sum, glassP_ = g / sum, coatP_ = coatP_ / sum;
}

void Bsdf::setUpCoat(const Vec3& wo, double& d, double& s, double& g) {
  coatN_ = in_.clearcoatNormal == Vec3() ? n_ : in_.clearcoatNormal;
  if (!(dot(coatN_, wo) > 0)) coatN_ = n_;  // a coat normal facing away: the surface's
  orthonormalBasis(coatN_, coatT_, coatB_);
  coatWo_ = Vec3(dot(wo, coatT_), dot(wo, coatB_), std::max(dot(wo, coatN_), 1e-9));
  const double roughness = std::clamp(in_.clearcoatRoughness, 0.0, 1.0);
  coatAlpha_ = std::max(roughness * roughness, 1e-3);
  coatDelta_ = roughness < kSmoothRoughness;
  coatW_ = std::clamp(in_.clearcoat, 0.0, 1.0) * (0.04 + 0.96 * pow5(1 - coatWo_.z));
  baseScale_ = 1 - coatW_;
  d *= baseScale_, s *= baseScale_, g *= baseScale_;
  coatP_ = coatW_;  // made a share by the caller
}

Color Bsdf::coatEval(const Vec3& w) const {
  const Vec3 wi(dot(w, coatT_), dot(w, coatB_), dot(w, coatN_));
  if (wi.z <= 0 || coatDelta_) return {};
  const Vec3 h = normalize(wi + coatWo_);
  return Color(coatW_ * ggxD(h, coatAlpha_) * ggxG2(coatWo_, wi, coatAlpha_) / (4 * coatWo_.z));
}

double Bsdf::coatPdf(const Vec3& w) const {
  const Vec3 wi(dot(w, coatT_), dot(w, coatB_), dot(w, coatN_));
  if (wi.z <= 0 || coatDelta_) return 0;
  const Vec3 h = normalize(wi + coatWo_);
  return ggxG1(coatWo_, coatAlpha_) * ggxD(h, coatAlpha_) / (4 * coatWo_.z);
}

Color Bsdf::diffuseEval(const Vec3& wi) const {
  if (wi.z <= 0 || diffuseW_ <= 0) return {};
  // Burley's diffuse: Lambert times a retro-reflection that grows with roughness.
  const Vec3 h = normalize(wi + wo_);
  const double cosD = dot(wi, h);
  const double fd90 = 0.5 + 2 * in_.roughness * cosD * cosD;
  const double fi = 1 + (fd90 - 1) * pow5(1 - wi.z);
  const double fo = 1 + (fd90 - 1) * pow5(1 - cosO_);
  return (diffuseW_ * kInvPi * fi * fo * wi.z) * in_.base;
}

Color Bsdf::specularEval(const Vec3& wi) const {
  if (wi.z <= 0 || specularDelta_) return {};
  const Vec3 h = normalize(wi + wo_);
  const Color f = schlick(f0_, f90_, dot(wo_, h));
  const double weight = (1 - glassW_) * ggxD(h, alpha_) * ggxG2(wo_, wi, alpha_) / (4 * cosO_);
  return weight * f;
}

double Bsdf::specularPdf(const Vec3& wi) const {
  if (wi.z <= 0 || specularDelta_) return 0;
  const Vec3 h = normalize(wi + wo_);
  return ggxG1(wo_, alpha_) * ggxD(h, alpha_) / (4 * cosO_);
}

Color Bsdf::glassEval(const Vec3& wi) const {
  if (glassW_ <= 0 || glassDelta_ || wi.z == 0) return {};
  if (wi.z > 0) {  // reflected by the glass
    const Vec3 m = normalize(wi + wo_);
    const double r = fresnelDielectric(dot(wo_, m), eta_);
    return Color(glassW_ * r * ggxD(m, alpha_) * ggxG2(wo_, wi, alpha_) / (4 * cosO_));
  }
  if (in_.thinWalled) {  // the reflection's lobe mirrored through the wall, (1 - F) of it
    const Vec3 r(wi.x, wi.y, -wi.z);
    const Vec3 m = normalize(r + wo_);
    const double t = 1 - fresnelDielectric(dot(wo_, m), eta_);
    return (glassW_ * t * ggxD(m, alpha_) * ggxG2(wo_, r, alpha_) / (4 * cosO_)) * in_.base;
  }
  Vec3 m = normalize(eta_ * wi + wo_);
  if (m.z < 0) m = -m;
  const double im = dot(wi, m), om = dot(wo_, m);
  if (im >= 0 || om <= 0) return {};
  const double t = 1 - fresnelDielectric(om, eta_);
  const double denom = im + om / eta_;
  const double value = t * ggxD(m, alpha_) * ggxG2(wo_, wi, alpha_) * std::abs(im * om) /
                       (cosO_ * denom * denom * eta_ * eta_);
  return (glassW_ * value) * in_.base;
}

double Bsdf::glassPdf(const Vec3& wi) const {
  if (glassW_ <= 0 || glassDelta_ || wi.z == 0) return 0;
  if (wi.z > 0) {
    const Vec3 m = normalize(wi + wo_);
    const double om = dot(wo_, m);
    if (om <= 0) return 0;
    return ggxVisible(wo_, m, alpha_) / (4 * om) * fresnelDielectric(om, eta_);
  }
  if (in_.thinWalled) {
    const Vec3 m = normalize(Vec3(wi.x, wi.y, -wi.z) + wo_);
    const double om = dot(wo_, m);
    if (om <= 0) return 0;
    return ggxVisible(wo_, m, alpha_) / (4 * om) * (1 - fresnelDielectric(om, eta_));
  }
  Vec3 m = normalize(eta_ * wi + wo_);
  if (m.z < 0) m = -m;
  const double im = dot(wi, m), om = dot(wo_, m);
  if (im >= 0 || om <= 0) return 0;
  const double denom = im + om / eta_;
  return ggxVisible(wo_, m, alpha_) * std::abs(im) / (denom * denom) *
         (1 - fresnelDielectric(om, eta_));
}

Color Bsdf::evaluate(const Vec3& w) const {
  const Vec3 wi(dot(w, t_), dot(w, b_), dot(w, n_));
  const Color below = diffuseEval(wi) + specularEval(wi) + glassEval(wi);
  if (coatW_ > 0) return baseScale_ * below + coatEval(w);
  return below;
}

double Bsdf::pdf(const Vec3& w) const {
  const Vec3 wi(dot(w, t_), dot(w, b_), dot(w, n_));
  double p = 0;
  if (diffuseP_ > 0 && wi.z > 0) p += diffuseP_ * wi.z * kInvPi;
  if (specularP_ > 0) p += specularP_ * specularPdf(wi);
  if (glassP_ > 0) p += glassP_ * glassPdf(wi);
  if (coatP_ > 0) p += coatP_ * coatPdf(w);
  return p;
}

bool Bsdf::sample(double u0, double u1, double u2, BsdfSample& out) const {
  auto toWorld = [&](const Vec3& v) { return v.x * t_ + v.y * b_ + v.z * n_; };
  Vec3 wi;
  if (u0 < diffuseP_) {
    double s, c;
    sinCosTurns(u2, s, c);
    const double r = std::sqrt(u1);
    wi = Vec3(r * c, r * s, std::sqrt(std::max(0.0, 1 - u1)));
  } else if (u0 < diffuseP_ + specularP_) {
    if (specularDelta_) {
      out.wi = toWorld(Vec3(-wo_.x, -wo_.y, wo_.z));
      out.weight = ((1 - glassW_) / specularP_) * schlick(f0_, f90_, cosO_);
      if (coatW_ > 0) out.weight = baseScale_ * out.weight;
      out.pdf = 0;
      out.delta = true;
      out.transmitted = false;
      return true;
    }
    const Vec3 h = sampleVisibleNormal(wo_, alpha_, u1, u2);
    wi = 2 * dot(wo_, h) * h - wo_;
  } else if (glassP_ > 0 && (coatP_ == 0 || u0 < diffuseP_ + specularP_ + glassP_)) {
    // Which of reflection and refraction: the rest of u0 within the glass's share.
    const double u = std::clamp((u0 - diffuseP_ - specularP_) / glassP_, 0.0, 1.0);
    const Vec3 m = glassDelta_ ? Vec3(0, 0, 1) : sampleVisibleNormal(wo_, alpha_, u1, u2);
    const double om = dot(wo_, m);
    const double r = fresnelDielectric(om, eta_);
    Vec3 wt;
    bool reflects;
    if (in_.thinWalled) {  // through the wall unbent: the reflection mirrored to the far side
      reflects = u < r;
      const Vec3 wr = 2 * om * m - wo_;
      // Reflected into the wall (either way): lost, as for the other lobes; kept, it would be
      // taken for the other branch's direction and weighed by that branch's density alone.
      if (wr.z <= 0) return false;
      wi = reflects ? wr : Vec3(wr.x, wr.y, -wr.z);
    } else {
      reflects = u < r || !refractThrough(wo_, m, eta_, wt);
      wi = reflects ? 2 * om * m - wo_ : wt;
    }
    if (glassDelta_) {
      out.wi = toWorld(wi);
      // Radiance is compressed by 1 / eta^2 entering a denser medium; a thin wall's far side
      // is the near side's air.
      out.weight = reflects          ? Color(glassW_ / glassP_)
                   : in_.thinWalled ? (glassW_ / glassP_) * in_.base
                                    : (glassW_ / (glassP_ * eta_ * eta_)) * in_.base;
      if (coatW_ > 0) out.weight = baseScale_ * out.weight;
      out.pdf = 0;
      out.delta = true;
      out.transmitted = !reflects;
      return true;
    }
  } else if (coatP_ > 0) {
    const Vec3 h = coatDelta_ ? Vec3(0, 0, 1) : sampleVisibleNormal(coatWo_, coatAlpha_, u1, u2);
    const Vec3 c = 2 * dot(coatWo_, h) * h - coatWo_;
    const Vec3 w = c.x * coatT_ + c.y * coatB_ + c.z * coatN_;
    if (coatDelta_) {
      out.wi = w;
      out.weight = Color(coatW_ / coatP_);
      out.pdf = 0;
      out.delta = true;
      out.transmitted = dot(w, n_) < 0;
      return true;
    }
    wi = Vec3(dot(w, t_), dot(w, b_), dot(w, n_));
  } else {
    return false;
  }
  if (wi.z == 0) return false;
  out.wi = toWorld(wi);
  out.pdf = pdf(out.wi);
  if (!(out.pdf > 0)) return false;
  out.weight = evaluate(out.wi) / out.pdf;
  out.delta = false;
  out.transmitted = wi.z < 0;
  return true;
}

}  // namespace prt
