#pragma once
// EnvironmentLight: the light that arrives from every direction no surface is met in — the
// world colour, or an HDR environment map (an equirectangular image of linear radiance) times
// a strength and turned about the up axis.
//
// The map's layout is Blender's, in the glTF frame (y up) that model files are read into: the
// image's centre column looks along +x, columns to its right turn towards +z, the top row is
// straight up (+y) and the bottom row straight down; column u in [0, 1) and row v in [0, 1)
// (from the top) look along
//   (sin theta cos phi, cos theta, sin theta sin phi),  theta = pi v,  phi = 2 pi (u - 1/2),
// and a turn of D degrees moves what the map shows from azimuth phi to phi + D. Radiance is
// filtered bilinearly between texel centres (wrapping around in u, clamped at the poles).
//
// Sampling (a map only; the uniform world colour is found by paths alone): a direction is
// chosen in proportion to the radiance's luminance times sin theta, which is the solid angle
// of a texel — a 2-D piecewise-constant distribution, a row from the rows' sums, then a column
// from the row's texels (pbrt-v4's PiecewiseConstant2D; Pharr, Jakob and Humphreys, Physically
// Based Rendering, 4th ed., 2023). A texel's weight is the most luminance the bilinear filter
// can give over it (its own and its eight neighbours'), so wherever the map gives light it can
// be chosen. Its density per solid angle is p(u, v) / (2 pi^2 sin theta).
//
// All arithmetic is portable (core/portable_math.h), so directions, densities and radiance are
// the same bits everywhere. Immutable after construction; safe to share between threads.

#include <memory>
#include <vector>

#include "core/vec3.h"
#include "trace/scene.h"

namespace prt {

class EnvironmentLight {
 public:
  explicit EnvironmentLight(const Environment& environment);

  // Whether a map is given (else the world colour is the environment).
  bool hasMap() const { return map_ != nullptr; }
  // Whether next-event estimation can aim at it: a map with some light in it.
  bool sampled() const { return !marginal_.empty(); }

  // Radiance arriving from direction `d` (unit; it travels along -d).
  Color radiance(const Vec3& d) const;
  // A direction chosen by (u1, u2) in [0, 1)^2, its radiance and its density per solid angle;
  // false when nothing can be chosen.
  bool sample(double u1, double u2, Vec3& direction, Color& radiance, double& pdf) const;
  // The density per solid angle with which sample() chooses direction `d`.
  double pdf(const Vec3& d) const;

  // Whether this light was built from the same map, strength and turn (so a frame of an
  // animation may take the one built for the frame before).
  bool sameAs(const Environment& environment) const;

 private:
  // Map coordinates (u, v) in [0, 1)^2 of a unit direction, and sin theta.
  void coordinates(const Vec3& d, double& u, double& v, double& sinTheta) const;
  Color texel(int x, int y) const;

  Color background_;
  std::shared_ptr<const Image> map_;
  double strength_ = 1, rotateDegrees_ = 0;
  double turn_ = 0;  // the turn in turns (a fraction of the circle)
  int width_ = 0, height_ = 0;
  std::vector<double> marginal_;  // height_ + 1 running sums of the rows' weights, from 0
  std::vector<float> rows_;       // per row, width_ + 1 running sums of its texels' weights
};

}  // namespace prt
