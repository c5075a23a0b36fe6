#include "scene/rig_pack.h"

#include <cmath>
#include <string>

namespace prt {
namespace {

// The fewest bytes each item can take, so that a count is checked against the bytes left.
constexpr uint64_t kCurveBytes = 3 + 2 * 8;
constexpr uint64_t kNodeBytes = 4 + 1 + 12 * 8 + 10 * 8 + 3 * 4;
constexpr uint64_t kObjectBytes = 3 * 4 + 12 * 8;
constexpr uint64_t kLightBytes = 3 * 4 + 1 + 3 * 8 + 3 * 8 + 1;
constexpr uint64_t kCameraBytes = 2 * 4 + 11 * 8;

void putVec(ByteWriter& w, const Vec3& v) {
  w.pod(v.x), w.pod(v.y), w.pod(v.z);
}
void putTransform(ByteWriter& w, const Transform& t) {
  for (const auto& row : t.m) {
    for (const double v : row) w.pod(v);
  }
}
void putDoubles(ByteWriter& w, const std::vector<double>& v) {
  w.pod(static_cast<uint64_t>(v.size()));
  if (!v.empty()) w.raw(v.data(), v.size() * sizeof(double));
}

void putLight(ByteWriter& w, const Light& light) {
  w.pod(static_cast<uint8_t>(light.shape.index()));
  std::visit(
      [&](const auto& s) {
        using T = std::decay_t<decltype(s)>;
        if constexpr (std::is_same_v<T, PointLight>) putVec(w, s.position);
        if constexpr (std::is_same_v<T, SphereLight>) putVec(w, s.center), w.pod(s.radius);
        if constexpr (std::is_same_v<T, RectLight>) putVec(w, s.corner), putVec(w, s.edge1), putVec(w, s.edge2);
        if constexpr (std::is_same_v<T, SpotLight>) {
          putVec(w, s.position), putVec(w, s.direction), w.pod(s.innerDegrees), w.pod(s.outerDegrees);
        }
        if constexpr (std::is_same_v<T, DirectionalLight>) putVec(w, s.direction);
      },
      light.shape);
  putVec(w, light.color);
  w.pod(static_cast<uint8_t>(light.falloff));
}

class RigReader {
 public:
  RigReader(ByteReader& in, size_t imports) : in_(in), imports_(imports) {}

  double finite() {
    const double v = in_.pod<double>();
    if (!std::isfinite(v)) in_.fail("a rig value that is not finite");
    return v;
  }
  Vec3 vec() {
    const double x = finite(), y = finite(), z = finite();
    return {x, y, z};
  }
  Transform transform() {
    Transform t;
    for (auto& row : t.m) {
      for (double& v : row) v = finite();
    }
    return t;
  }
  uint64_t count(uint64_t leastBytesEach) {
    const auto n = in_.pod<uint64_t>();
    in_.needItems(n, leastBytesEach);
    return n;
  }
  std::vector<double> doubles() {
    std::vector<double> v(static_cast<size_t>(count(8)));
    in_.raw(v.data(), v.size() * sizeof(double));
    return v;
  }
  uint32_t import() {
    const auto i = in_.pod<uint32_t>();
    if (i >= imports_) in_.fail("a binding's import out of range");
    return i;
  }
  Vec3 unit() {
    const Vec3 v = vec();
    if (!(length(v) > 0)) in_.fail("a light's direction of no length");
    return v;
  }

  Light light() {
    Light light;
    const auto kind = in_.pod<uint8_t>();
    switch (kind) {
      case 0: light.shape = PointLight{vec()}; break;
      case 1: {
        SphereLight s{vec(), finite()};
        if (!(s.radius > 0)) in_.fail("a sphere light without a radius");
        light.shape = s;
        break;
      }
      case 2: {
        RectLight r;
        r.corner = vec(), r.edge1 = vec(), r.edge2 = vec();
        light.shape = r;
        break;
      }
      case 3: {
        SpotLight s;
        s.position = vec(), s.direction = unit(), s.innerDegrees = finite(), s.outerDegrees = finite();
        if (!(s.innerDegrees >= 0 && s.innerDegrees <= s.outerDegrees && s.outerDegrees <= 90)) {
          in_.fail("a spot light's cone no scene can hold");
        }
        light.shape = s;
        break;
      }
      case 4: light.shape = DirectionalLight{unit()}; break;
      default: in_.fail("an unknown kind of light");
    }
    light.color = vec();
    const auto falloff = in_.pod<uint8_t>();
    if (falloff > 1 || (falloff == 1 && kind == 4)) in_.fail("an unknown falloff");
    light.falloff = static_cast<Falloff>(falloff);
    return light;
  }

  Camera camera() {
    Camera c;
    c.eye = vec(), c.lookAt = vec(), c.up = vec();
    c.fovDegrees = finite(), c.orthoHeight = finite();
    if (!(c.fovDegrees > 0 && c.fovDegrees < 180 && c.orthoHeight >= 0)) in_.fail("a camera no scene can hold");
    return c;
  }

  SceneAnimation rig() {
    SceneAnimation a;
    for (uint64_t i = count(kCurveBytes); i > 0; --i) {
      Curve c;
      const auto interpolation = in_.pod<uint8_t>();
      if (interpolation > 2) in_.fail("an unknown interpolation");
      c.interpolation = static_cast<Interpolation>(interpolation);
      c.width = in_.pod<uint8_t>();
      const auto rotation = in_.pod<uint8_t>();
      if (rotation > 1) in_.fail("a curve neither rotation nor not");
      c.rotation = rotation != 0;
      c.times = doubles();
      c.values = doubles();
      if (!c.wellFormed()) in_.fail("a curve that is not well formed");
      a.curves.push_back(std::move(c));
    }
    for (uint64_t i = count(kNodeBytes); i > 0; --i) {
      RigNode n;
      n.parent = in_.pod<int32_t>();
      const auto hasMatrix = in_.pod<uint8_t>();
      if (hasMatrix > 1) in_.fail("a node neither with a matrix nor without");
      n.hasMatrix = hasMatrix != 0;
      n.matrix = transform();
      n.translation = vec();
      for (double& q : n.rotation) q = finite();
      n.scale = vec();
      n.translationCurve = in_.pod<int32_t>();
      n.rotationCurve = in_.pod<int32_t>();
      n.scaleCurve = in_.pod<int32_t>();
      a.nodes.push_back(n);
    }
    for (uint64_t i = count(kObjectBytes); i > 0; --i) {
      ObjectBinding b;
      b.object = in_.pod<uint32_t>();
      b.import = import();
      b.node = in_.pod<int32_t>();
      b.local = transform();
      a.objects.push_back(b);
    }
    for (uint64_t i = count(kLightBytes); i > 0; --i) {
      LightBinding b;
      b.light = in_.pod<uint32_t>();
      b.import = import();
      b.node = in_.pod<int32_t>();
      b.local = light();
      a.lights.push_back(b);
    }
    for (uint64_t i = count(kCameraBytes); i > 0; --i) {
      CameraBinding b;
      b.import = import();
      b.node = in_.pod<int32_t>();
      b.local = camera();
      a.camera.push_back(b);
    }
    a.duration = finite();
    if (const std::string why = rigProblem(a); !why.empty()) in_.fail(why);
    return a;
  }

 private:
  ByteReader& in_;
  size_t imports_;
};

}  // namespace

void putRig(ByteWriter& w, const SceneAnimation& a) {
  w.pod(static_cast<uint64_t>(a.curves.size()));
  for (const Curve& c : a.curves) {
    w.pod(static_cast<uint8_t>(c.interpolation));
    w.pod(c.width);
    w.pod(static_cast<uint8_t>(c.rotation));
    putDoubles(w, c.times);
    putDoubles(w, c.values);
  }
  w.pod(static_cast<uint64_t>(a.nodes.size()));
  for (const RigNode& n : a.nodes) {
    w.pod(n.parent);
    w.pod(static_cast<uint8_t>(n.hasMatrix));
    putTransform(w, n.matrix);
    putVec(w, n.translation);
    for (const double q : n.rotation) w.pod(q);
    putVec(w, n.scale);
    w.pod(n.translationCurve), w.pod(n.rotationCurve), w.pod(n.scaleCurve);
  }
  w.pod(static_cast<uint64_t>(a.objects.size()));
  for (const ObjectBinding& b : a.objects) {
    w.pod(b.object), w.pod(b.import), w.pod(b.node);
    putTransform(w, b.local);
  }
  w.pod(static_cast<uint64_t>(a.lights.size()));
  for (const LightBinding& b : a.lights) {
    w.pod(b.light), w.pod(b.import), w.pod(b.node);
    putLight(w, b.local);
  }
  w.pod(static_cast<uint64_t>(a.camera.size()));
  for (const CameraBinding& b : a.camera) {
    w.pod(b.import), w.pod(b.node);
    putVec(w, b.local.eye), putVec(w, b.local.lookAt), putVec(w, b.local.up);
    w.pod(b.local.fovDegrees), w.pod(b.local.orthoHeight);
  }
  w.pod(a.duration);
}

SceneAnimation getRig(ByteReader& in, size_t imports) { return RigReader(in, imports).rig(); }

}  // namespace prt
