#include "trace/shadow_shafts.h"

#include <algorithm>
#include <cmath>

namespace prt {
namespace {

struct Interval {
  double lo, hi;
};

Interval project(const Bounds& b, const Vec3& axis) {
  const double centre = dot(b.centroid(), axis);
  const Vec3 half = 0.5 * b.diagonal();
  const double radius =
      half.x * std::abs(axis.x) + half.y * std::abs(axis.y) + half.z * std::abs(axis.z);
  return {centre - radius, centre + radius};
}

}  // namespace

Shaft::Shaft(const Bounds& from, const Bounds& to) {
  box_ = from;
  box_.extend(to);
  // Its other faces are parallel to a coordinate axis a: seen along a, they are edges of the
  // 2-D hull of two rectangles, which join corresponding corners (a line supporting both
  // touches each at the corner its normal's signs pick). Their normals are the cross products
  // of a with the four corner-to-corner vectors in the other two coordinates.
  for (int a = 0; a < 3; ++a) {
    for (int s = 0; s < 8; ++s) {
      if ((s >> a) & 1) continue;  // the corner's a coordinate does not matter
      const Vec3 d = to.corner(s) - from.corner(s);
      const Vec3 axis = a == 0   ? Vec3(0, -d.z, d.y)
                        : a == 1 ? Vec3(d.z, 0, -d.x)
                                 : Vec3(-d.y, d.x, 0);
      if (axis == Vec3()) continue;
      const Interval f = project(from, axis), t = project(to, axis);
      const Vec3 absAxis(std::abs(axis.x), std::abs(axis.y), std::abs(axis.z));
      sides_[count_++] = {axis, absAxis, std::min(f.lo, t.lo), std::max(f.hi, t.hi)};
    }
  }
}

bool Shaft::meets(const Bounds& b) const {
  if (!box_.overlaps(b)) return false;
  const Vec3 centre = b.centroid(), half = 0.5 * b.diagonal();
  for (int i = 0; i < count_; ++i) {
    const Side& side = sides_[i];
    const double c = dot(centre, side.axis), r = dot(half, side.absAxis);
    if (c + r < side.lo || c - r > side.hi) return false;
  }
  return true;
}

ShadowShafts::ShadowShafts(const std::vector<Bounds>& items, const std::vector<Bounds>& lights,
                           uint32_t longest)
    : longest_(longest) {
  Bounds grid;
  for (const Bounds& b : items) grid.extend(b);
  if (items.empty() || lights.empty() || !isFinite(grid.lo) || !isFinite(grid.hi)) return;
  // A light without a finite box (a directional one) gets no lists: its rays go to the BVH.
  auto bounded = [](const Bounds& l) { return isFinite(l.lo) && isFinite(l.hi); };
  if (std::none_of(lights.begin(), lights.end(), bounded)) return;
  double magnitude = grid.largestMagnitude();
  for (const Bounds& l : lights) {
    if (bounded(l)) magnitude = std::max(magnitude, l.largestMagnitude());
  }
  // Far above the rounding of any coordinate, of a cell lookup or of a shadow ray's end.
  margin_ = 1e-7 * std::max(1.0, magnitude);
  // From the objects up to the lights: the floor around the objects, under the lights, is in.
  for (const Bounds& l : lights) {
    if (bounded(l)) grid.extend(l);
  }
  grid = grid.widened(margin_);

  // About cellsFor(lights) cells, as near cubes as the grid's shape allows; an axis shorter
  // than a cell (a flat scene) gets one, and the others share the cells.
  const double cells = cellsFor(lights.size());
  const Vec3 size = grid.diagonal();
  bool active[3] = {true, true, true};
  double edge = 0;
  for (int round = 0; round < 3; ++round) {
    double product = 1;
    int count = 0;
    for (int a = 0; a < 3; ++a) {
      if (active[a]) product *= size[a], ++count;
    }
    if (count == 0) break;
    edge = std::pow(product / cells, 1.0 / count);
    bool changed = false;
    for (int a = 0; a < 3; ++a) {
      if (active[a] && size[a] < edge) active[a] = false, changed = true;
    }
    if (!changed) break;
  }
  for (int a = 0; a < 3; ++a) {
    dims_[a] = active[a] ? static_cast<int>(std::clamp(std::ceil(size[a] / edge), 1.0, cells)) : 1;
  }
  lo_ = grid.lo;
  cell_ = Vec3(size.x / dims_[0], size.y / dims_[1], size.z / dims_[2]);
  scale_ = Vec3(1.0 / cell_.x, 1.0 / cell_.y, 1.0 / cell_.z);
  lights_ = lights.size();
  lists_.assign(cellCount() * lights_, List{0, 0});

  std::vector<uint32_t> all(items.size());
  for (uint32_t i = 0; i < all.size(); ++i) all[i] = i;
  for (size_t l = 0; l < lights_; ++l) {
    if (!bounded(lights[l])) {
      for (size_t cell = 0; cell < cellCount(); ++cell) lists_[cell * lights_ + l] = {0, kLong};
      continue;
    }
    refine(items, lights[l].widened(margin_), l, {{0, 0, 0}, {dims_[0], dims_[1], dims_[2]}}, all);
  }
}

void ShadowShafts::refine(const std::vector<Bounds>& items, const Bounds& light, size_t l,
                          const Region& region, const std::vector<uint32_t>& candidates) {
  Bounds from;
  from.lo = lo_ + Vec3(region.lo[0], region.lo[1], region.lo[2]) * cell_;
  from.hi = lo_ + Vec3(region.hi[0], region.hi[1], region.hi[2]) * cell_;
  const Shaft shaft(from.widened(margin_), light);
  std::vector<uint32_t> kept;
  for (const uint32_t i : candidates) {
    if (shaft.meets(items[i])) kept.push_back(i);
    if (kept.size() > kCrowded) break;  // crowded: how crowded does not matter
  }
  const bool single = region.hi[0] - region.lo[0] == 1 && region.hi[1] - region.lo[1] == 1 &&
                      region.hi[2] - region.lo[2] == 1;
  // Every cell of the region gets `list` (the region's list: empty, or for one cell).
  auto assign = [&](List list) {
    for (int z = region.lo[2]; z < region.hi[2]; ++z) {
      for (int y = region.lo[1]; y < region.hi[1]; ++y) {
        for (int x = region.lo[0]; x < region.hi[0]; ++x) {
          lists_[cellIndex(x, y, z) * lights_ + l] = list;
        }
      }
    }
  };
  if (kept.empty()) return assign({0, 0});
  if (single || kept.size() > kCrowded) {
    if (kept.size() > longest_) return assign({0, kLong});
    const List list{static_cast<uint32_t>(items_.size()), static_cast<uint32_t>(kept.size())};
    items_.insert(items_.end(), kept.begin(), kept.end());
    return assign(list);
  }
  // Halve every axis still more than a cell wide: the children's shafts lie inside this one,
  // so they need only test what it kept.
  int mid[3];
  for (int a = 0; a < 3; ++a) mid[a] = (region.lo[a] + region.hi[a]) / 2;
  for (int octant = 0; octant < 8; ++octant) {
    Region child = region;
    bool empty = false;
    for (int a = 0; a < 3; ++a) {
      if ((octant >> a) & 1) {
        child.lo[a] = mid[a];
      } else {
        child.hi[a] = mid[a];
      }
      empty = empty || child.lo[a] >= child.hi[a];
    }
    if (!empty) refine(items, light, l, child, kept);
  }
}

}  // namespace prt
