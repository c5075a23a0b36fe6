#pragma once
// The transcendental functions the renderer needs (sine and cosine, tangent, power), computed
// with nothing but IEEE additions, multiplications and divisions in a fixed order, so they give
// the same bits on every machine. The C library's are not portable in that sense: glibc picks
// among implementations at run time by CPU (with fused multiply-adds or without), and those
// may differ in the last bit; a cluster of mixed machines would then render the same pixel two
// ways. (The build forbids contracting a*b+c into an FMA: -ffp-contract=off.)
//
// Accuracy: a few units in the last place over the ranges documented below (powNonNegative:
// see there), far finer than any image can show. Each function is also cheaper than the library
// call it replaces, being inlined and free of the general argument reduction.

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>

namespace prt {
namespace portable_math_detail {

// c[0] + z (c[1] + z (c[2] + ...)), innermost first.
template <size_t N>
constexpr double horner(double z, const double (&c)[N]) {
  double p = c[N - 1];
  for (size_t i = N - 1; i-- > 0;) p = c[i] + z * p;
  return p;
}

// sin x and cos x for |x| <= pi/4 (a little beyond is fine). The polynomials are minimax fits
// on that interval (the coefficients of fdlibm's kernels, 6 per function: errors below 2^-58
// for sin, 2^-60 for cos, before rounding), each evaluated as two short chains that run side
// by side (Estrin's scheme, partly) rather than one long Horner chain: the shader calls this on
// every area-light sample and every glossy ray, where its latency would stall the rest.
inline void sinCosReduced(double x, double& s, double& c) {
  constexpr double kS1 = -1.66666666666666324348e-01, kS2 = 8.33333333332248946124e-03,
                   kS3 = -1.98412698298579493134e-04, kS4 = 2.75573137070700676789e-06,
                   kS5 = -2.50507602534068634195e-08, kS6 = 1.58969099521155010221e-10;
  constexpr double kC1 = 4.16666666666666019037e-02, kC2 = -1.38888888888741095749e-03,
                   kC3 = 2.48015872894767294178e-05, kC4 = -2.75573143513906633035e-07,
                   kC5 = 2.08757232129817482790e-09, kC6 = -1.13596475577881948265e-11;
  const double z = x * x;
  const double w = z * z;
  const double rs = (kS2 + z * (kS3 + z * kS4)) + z * w * (kS5 + z * kS6);
  s = x + (z * x) * (kS1 + z * rs);
  const double rc = z * (kC1 + z * (kC2 + z * kC3)) + (w * w) * (kC4 + z * (kC5 + z * kC6));
  // 1 - z/2 rounded first, then its rounding error put back.
  const double half = 0.5 * z;
  const double v = 1.0 - half;
  c = v + (((1.0 - v) - half) + z * rc);
}

// Rotates (sin r, cos r) by `quadrant` quarter turns: sin and cos of r + quadrant * pi/2.
inline void rotateQuadrants(int64_t quadrant, double& s, double& c) {
  const double sr = s, cr = c;
  switch (quadrant & 3) {
    case 0:
      break;
    case 1:
      s = cr;
      c = -sr;
      break;
    case 2:
      s = -sr;
      c = -cr;
      break;
    default:
      s = -cr;
      c = sr;
      break;
  }
}

}  // namespace portable_math_detail

// sin x and cos x for |x| <= pi/4 (the whole range of the concentric disc map).
inline void sinCosQuarter(double x, double& s, double& c) {
  portable_math_detail::sinCosReduced(x, s, c);
}

// sin and cos of 2 pi u, for u in [0, 1): a uniform angle from a uniform number. Reduced
// exactly: u - k/4 is exact (Sterbenz) for the nearest quarter k.
inline void sinCosTurns(double u, double& s, double& c) {
  const double k = std::floor(4.0 * u + 0.5);
  const double x = (u - 0.25 * k) * 6.283185307179586;  // 2 pi
  portable_math_detail::sinCosReduced(x, s, c);
  portable_math_detail::rotateQuadrants(static_cast<int64_t>(k), s, c);
}

// sin x and cos x for |x| <= 1e6 radians (angles from scene files: spreads, fields of view).
// Cody-Waite reduction by pi/2 split into a 33-bit head (k * head is exact) and a tail.
inline void sinCosRadians(double x, double& s, double& c) {
  constexpr double kTwoOverPi = 0x1.45f306dc9c883p-1;
  constexpr double kHalfPiHead = 0x1.921fb544p+0;
  constexpr double kHalfPiTail = 0x1.0b4611a626331p-34;
  const double k = std::floor(x * kTwoOverPi + 0.5);
  const double r = (x - k * kHalfPiHead) - k * kHalfPiTail;
  portable_math_detail::sinCosReduced(r, s, c);
  portable_math_detail::rotateQuadrants(static_cast<int64_t>(k), s, c);
}

inline double cosRadians(double x) {
  double s, c;
  sinCosRadians(x, s, c);
  return c;
}

inline double tanRadians(double x) {
  double s, c;
  sinCosRadians(x, s, c);
  return s / c;
}

// The arc tangent of any x, in (-pi/2, pi/2): the argument reduced to |t| <= 7/16 about one of
// four points (atan 1/2, atan 1, atan 3/2, pi/2) and an odd minimax polynomial of degree 23
// there (the coefficients and split constants of fdlibm's s_atan.c). NaN gives NaN.
inline double atanOf(double x) {
  constexpr double kHigh[] = {4.63647609000806093515e-01, 7.85398163397448278999e-01,
                              9.82793723247329054082e-01, 1.57079632679489655800e+00};
  constexpr double kLow[] = {2.26987774529616870924e-17, 3.06161699786838301793e-17,
                             1.39033110312309984516e-17, 6.12323399573676603587e-17};
  constexpr double kEven[] = {3.33333333333329318027e-01, 1.42857142725034663711e-01,
                              9.09088713343650656196e-02, 6.66107313738753120669e-02,
                              4.97687799461593236017e-02, 1.62858201153657823623e-02};
  constexpr double kOdd[] = {-1.99999999998764832476e-01, -1.11111104054623557880e-01,
                             -7.69187620504482999495e-02, -5.83357013379057348645e-02,
                             -3.65315727442169155270e-02};
  if (!(x == x)) return x;
  const bool negative = x < 0;
  double t = negative ? -x : x;
  int part = -1;
  if (t >= 0.4375) {
    if (t < 0.6875) {
      part = 0, t = (2.0 * t - 1.0) / (2.0 + t);
    } else if (t < 1.1875) {
      part = 1, t = (t - 1.0) / (t + 1.0);
    } else if (t < 2.4375) {
      part = 2, t = (t - 1.5) / (1.0 + 1.5 * t);
    } else {
      part = 3, t = -1.0 / t;
    }
  }
  const double z = t * t;
  const double w = z * z;
  const double s1 = z * portable_math_detail::horner(w, kEven);
  const double s2 = w * portable_math_detail::horner(w, kOdd);
  double r;
  if (part < 0) {
    r = t - t * (s1 + s2);
  } else {
    r = kHigh[part] - ((t * (s1 + s2) - kLow[part]) - t);
  }
  return negative ? -r : r;
}

// The angle of the point (x, y) from the +x axis, in [-pi, pi] (atan2's conventions for the
// axes; (0, 0) gives 0).
inline double atan2Of(double y, double x) {
  constexpr double kPi = 3.141592653589793, kHalfPi = 1.5707963267948966;
  if (x == 0) return y > 0 ? kHalfPi : (y < 0 ? -kHalfPi : 0.0);
  const double ax = std::fabs(x), ay = std::fabs(y);
  // The smaller over the larger keeps the quotient within [0, 1].
  double a = ay <= ax ? atanOf(ay / ax) : kHalfPi - atanOf(ax / ay);
  if (x < 0) a = kPi - a;
  return y < 0 ? -a : a;
}

// Natural logarithm of a positive finite x (x = m 2^e, m in [sqrt(1/2), sqrt(2)); ln m by the
// series of atanh((m - 1) / (m + 1)), to the 23rd power). Returns -inf for 0.
inline double logPositive(double x) {
  if (!(x > 0)) return x == 0 ? -HUGE_VAL : std::numeric_limits<double>::quiet_NaN();
  int e = 0;
  double m = std::frexp(x, &e);    // exact: m in [1/2, 1)
  if (m < 0x1.6a09e667f3bcdp-1) {  // sqrt(1/2)
    m *= 2;
    --e;
  }
  const double t = (m - 1.0) / (m + 1.0);
  const double z = t * t;
  constexpr double kAtanh[] = {2.0 / 3,  2.0 / 5,  2.0 / 7,  2.0 / 9,  2.0 / 11, 2.0 / 13,
                               2.0 / 15, 2.0 / 17, 2.0 / 19, 2.0 / 21, 2.0 / 23};
  const double tail = portable_math_detail::horner(z, kAtanh);
  constexpr double kLn2Head = 0x1.62e42fefp-1;  // 33 bits: e * head is exact
  constexpr double kLn2Tail = 0x1.473de6af278edp-34;
  const double lnM = 2.0 * t + t * (z * tail);
  return e * kLn2Head + (lnM + e * kLn2Tail);
}

// e^y: 0 below -746, +inf above 710. y = k ln 2 + r with |r| <= ln2 / 2, e^r by
// its Taylor series to r^14, scaled by 2^k exactly (std::ldexp rounds once, into subnormals).
inline double expOf(double y) {
  if (y != y) return y;  // NaN
  if (y < -746.0) return 0.0;
  if (y > 710.0) return HUGE_VAL;
  constexpr double kInvLn2 = 0x1.71547652b82fep+0;
  constexpr double kLn2Head = 0x1.62e42fefp-1;
  constexpr double kLn2Tail = 0x1.473de6af278edp-34;
  const double k = std::floor(y * kInvLn2 + 0.5);
  const double r = (y - k * kLn2Head) - k * kLn2Tail;
  constexpr double kExp[] = {0.5,
                             1.0 / 6,
                             1.0 / 24,
                             1.0 / 120,
                             1.0 / 720,
                             1.0 / 5040,
                             1.0 / 40320,
                             1.0 / 362880,
                             1.0 / 3628800,
                             1.0 / 39916800,
                             1.0 / 479001600,
                             1.0 / 6227020800,
                             1.0 / 87178291200};
  const double p = portable_math_detail::horner(r, kExp);
  const double er = 1.0 + (r + r * (r * p));
  return std::ldexp(er, static_cast<int>(k));
}

// x^n for x >= 0 and n > 0 (the Phong term: a highlight to a shininess exponent). A whole n up
// to 2^20 by repeated squaring (at most 40 products; each squaring doubles the relative error,
// which stays below about n units in the last place: 1e-13 for n = 1000); any other n as
// e^(n ln x), within about |n ln x| units.
inline double powNonNegative(double x, double n) {
  if (x == 0) return 0.0;
  if (n == std::floor(n) && n <= 1048576.0) {
    auto bits = static_cast<uint32_t>(n);
    double result = 1.0, square = x;
    while (bits != 0) {
      if (bits & 1u) result *= square;
      bits >>= 1;
      if (bits != 0) square *= square;
    }
    return result;
  }
  return expOf(n * logPositive(x));
}

}  // namespace prt
