#include "trace/environment_light.h"

#include <algorithm>
#include <cmath>

#include "core/portable_math.h"

namespace prt {
namespace {

constexpr double kEnvironmentPi = 3.141592653589793;

// The entry i of running sums `cdf` (cdf[0] = 0, n + 1 entries, increasing) with
// cdf[i] <= x < cdf[i + 1], skipping entries of zero weight.
template <typename T>
size_t intervalOf(const T* cdf, size_t n, double x) {
  const T* end = cdf + n + 1;
  const T* above = std::upper_bound(cdf, end, static_cast<T>(x));
  size_t i = above == cdf ? 0 : static_cast<size_t>(above - cdf) - 1;
  return std::min(i, n - 1);
}

}  // namespace

EnvironmentLight::EnvironmentLight(const Environment& environment)
    : background_(environment.background), map_(environment.map.image) {
  if (!map_ || map_->width() <= 0 || map_->height() <= 0) {
    map_.reset();
    return;
  }
  strength_ = environment.map.strength;
  rotateDegrees_ = environment.map.rotateDegrees;
  turn_ = rotateDegrees_ / 360;
  width_ = map_->width();
  height_ = map_->height();
  if (!(strength_ > 0)) return;
  // Weights: the largest luminance the bilinear filter can give over each texel — the most of
  // the texel and its eight neighbours, whose light it spreads into it — times the sine of its
  // row's polar angle (the texel's solid angle, but for constants). A weight of the texel's own
  // luminance alone would leave the half-texel rim around a small sun with the density of the
  // sky beside it, and the BSDF's rays that find the rim would be fireflies. Sums in a fixed
  // order: the same bits everywhere.
  const auto w = static_cast<size_t>(width_), h = static_cast<size_t>(height_);
  std::vector<double> own(w * h);
  for (size_t y = 0; y < h; ++y) {
    for (size_t x = 0; x < w; ++x) {
      const double l = luminance(texel(static_cast<int>(x), static_cast<int>(y)));
      own[y * w + x] = l > 0 ? l : 0.0;
    }
  }
  rows_.assign(h * (w + 1), 0.0F);
  std::vector<double> marginal(h + 1, 0.0);
  for (size_t y = 0; y < h; ++y) {
    double s, c;
    sinCosTurns(0.5 * (static_cast<double>(y) + 0.5) / static_cast<double>(h), s, c);
    float* row = &rows_[y * (w + 1)];
    double sum = 0;
    for (size_t x = 0; x < w; ++x) {
      double most = 0;
      for (size_t j = y == 0 ? 0 : y - 1; j <= std::min(y + 1, h - 1); ++j) {
        for (size_t i : {(x + w - 1) % w, x, (x + 1) % w}) most = std::max(most, own[j * w + i]);
      }
      sum += most * s;
      row[x + 1] = static_cast<float>(sum);
    }
    marginal[y + 1] = marginal[y] + static_cast<double>(row[w]);
  }
  if (marginal[h] > 0 && std::isfinite(marginal[h])) marginal_ = std::move(marginal);
  else rows_.clear();
}

bool EnvironmentLight::sameAs(const Environment& environment) const {
  const EnvironmentMap& m = environment.map;
  if (!map_) return !m.image && background_ == environment.background;
  return m.image == map_ && m.strength == strength_ && m.rotateDegrees == rotateDegrees_ &&
         background_ == environment.background;
}

void EnvironmentLight::coordinates(const Vec3& d, double& u, double& v, double& sinTheta) const {
  sinTheta = std::sqrt(d.x * d.x + d.z * d.z);
  const double phi = atan2Of(d.z, d.x);          // azimuth from +x towards +z
  const double theta = atan2Of(sinTheta, d.y);   // polar angle from +y, in [0, pi]
  u = phi / (2 * kEnvironmentPi) + 0.5 - turn_;
  u -= std::floor(u);
  if (!(u < 1)) u = 0;
  v = std::min(std::max(theta / kEnvironmentPi, 0.0), 1.0);
}

Color EnvironmentLight::texel(int x, int y) const {
  x %= width_;
  if (x < 0) x += width_;
  y = std::min(std::max(y, 0), height_ - 1);
  const Color c = map_->at(x, y);
  return isFinite(c) ? c : Color();
}

Color EnvironmentLight::radiance(const Vec3& d) const {
  if (!map_) return background_;
  double u, v, sinTheta;
  coordinates(d, u, v, sinTheta);
  // Bilinear between the texel centres around (u, v).
  const double fx = u * width_ - 0.5, fy = v * height_ - 0.5;
  const double x0 = std::floor(fx), y0 = std::floor(fy);
  const double tx = fx - x0, ty = fy - y0;
  const int x = static_cast<int>(x0), y = static_cast<int>(y0);
  const Color top = (1 - tx) * texel(x, y) + tx * texel(x + 1, y);
  const Color bottom = (1 - tx) * texel(x, y + 1) + tx * texel(x + 1, y + 1);
  return strength_ * ((1 - ty) * top + ty * bottom);
}

bool EnvironmentLight::sample(double u1, double u2, Vec3& direction, Color& radiance,
                              double& pdf) const {
  if (!sampled()) return false;
  const auto w = static_cast<size_t>(width_), h = static_cast<size_t>(height_);
  const double total = marginal_[h];
  const size_t y = intervalOf(marginal_.data(), h, u1 * total);
  const double rowWeight = marginal_[y + 1] - marginal_[y];
  if (!(rowWeight > 0)) return false;
  const float* row = &rows_[y * (w + 1)];
  const double rowTotal = static_cast<double>(row[w]);
  const size_t x = intervalOf(row, w, u2 * rowTotal);
  const double lo = static_cast<double>(row[x]), weight = static_cast<double>(row[x + 1]) - lo;
  if (!(weight > 0)) return false;
  // Where in the texel: the remainder of each number, spread over it.
  const double dy = std::min(std::max((u1 * total - marginal_[y]) / rowWeight, 0.0), 1.0);
  const double dx = std::min(std::max((u2 * rowTotal - lo) / weight, 0.0), 1.0);
  const double u = (static_cast<double>(x) + dx) / static_cast<double>(w);
  const double v = (static_cast<double>(y) + dy) / static_cast<double>(h);
  double sinTheta, cosTheta, sinPhi, cosPhi;
  sinCosTurns(0.5 * v, sinTheta, cosTheta);
  double turns = u - 0.5 + turn_;
  turns -= std::floor(turns);
  if (!(turns < 1)) turns = 0;
  sinCosTurns(turns, sinPhi, cosPhi);
  if (!(sinTheta > 0)) return false;
  direction = Vec3(sinTheta * cosPhi, cosTheta, sinTheta * sinPhi);
  // p(u, v) = (row's share) (texel's share of the row) w h.
  const double density = (rowWeight / total) * (weight / rowTotal) * static_cast<double>(w * h);
  pdf = density / (2 * kEnvironmentPi * kEnvironmentPi * sinTheta);
  radiance = this->radiance(direction);
  return pdf > 0 && std::isfinite(pdf);
}

double EnvironmentLight::pdf(const Vec3& d) const {
  if (!sampled()) return 0;
  double u, v, sinTheta;
  coordinates(d, u, v, sinTheta);
  if (!(sinTheta > 0)) return 0;
  const auto w = static_cast<size_t>(width_), h = static_cast<size_t>(height_);
  const size_t x = std::min(static_cast<size_t>(u * static_cast<double>(w)), w - 1);
  const size_t y = std::min(static_cast<size_t>(v * static_cast<double>(h)), h - 1);
  const double total = marginal_[h];
  const double rowWeight = marginal_[y + 1] - marginal_[y];
  if (!(rowWeight > 0)) return 0;
  const float* row = &rows_[y * (w + 1)];
  const double weight = static_cast<double>(row[x + 1]) - static_cast<double>(row[x]);
  const double density =
      (rowWeight / total) * (weight / static_cast<double>(row[w])) * static_cast<double>(w * h);
  return density / (2 * kEnvironmentPi * kEnvironmentPi * sinTheta);
}

}  // namespace prt
