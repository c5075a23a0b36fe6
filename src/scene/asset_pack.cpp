#include "scene/asset_pack.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>

#include "core/byte_codec.h"
#include "image/image.h"
#include "scene/rig_pack.h"
#include "trace/bsdf.h"

namespace prt {
namespace {

constexpr uint32_t kTag = 0x41545250;  // "PRTA"
// 2: the rig; 3: the path tracer's surface; 4: the map; 5: data textures and tangents;
// 6: volumes, KHR_materials_specular and _clearcoat
constexpr uint32_t kVersion = 6;

bool isShippedMeshBlock(const Object& object) {
  const auto* m = std::get_if<MeshShape>(&object.shape);
  return m != nullptr && !m->source.file.empty();
}

template <typename T>
void putArray(ByteWriter& w, const std::vector<T>& v) {
  w.pod(static_cast<uint64_t>(v.size()));
  if (!v.empty()) w.raw(v.data(), v.size() * sizeof(T));
}

void putTextureRef(ByteWriter& w, const TextureRef& ref, int32_t offset) {
  w.pod(ref.texture < 0 ? int32_t{-1} : ref.texture - offset);
  for (const double v : ref.uv.m) w.pod(v);
}

void putMaterial(ByteWriter& w, const Material& m, int32_t textureOffset) {
  for (const double v : {m.color.x, m.color.y, m.color.z, m.ambient, m.diffuse, m.specular,
                         m.phongExponent, m.reflectivity, m.transmissivity, m.ior, m.glossDegrees,
                         m.translucencyDegrees, m.metallic, m.emission.x, m.emission.y,
                         m.emission.z}) {
    w.pod(v);
  }
  putTextureRef(w, m.colorTexture, textureOffset);
  putTextureRef(w, m.emissionTexture, textureOffset);
  w.pod(static_cast<uint8_t>(m.pbr.given));
  for (const double v : {m.pbr.roughness, m.pbr.transmission, m.pbr.ior, m.pbr.specularLevel,
                         m.pbr.coverage}) {
    w.pod(v);
  }
  putTextureRef(w, m.pbr.metallicRoughnessTexture, textureOffset);
  putTextureRef(w, m.pbr.normalTexture, textureOffset);
  w.pod(m.pbr.normalScale);
  putTextureRef(w, m.pbr.transmissionTexture, textureOffset);
  for (const double v : {m.pbr.attenuationColor.x, m.pbr.attenuationColor.y,
                         m.pbr.attenuationColor.z, m.pbr.attenuationDistance}) {
    w.pod(v);  // the distance may be infinite: clear
  }
  w.pod(static_cast<uint8_t>(m.pbr.thinWalled));
  for (const double v : {m.pbr.specularWeight, m.pbr.specularColor.x, m.pbr.specularColor.y,
                         m.pbr.specularColor.z, m.pbr.clearcoat, m.pbr.clearcoatRoughness}) {
    w.pod(v);
  }
}

class Reader {
 public:
  explicit Reader(const std::vector<uint8_t>& bytes) : in_(bytes.data(), bytes.size(), "assets") {}

  template <typename T>
  std::vector<T> array() {
    const auto n = in_.pod<uint64_t>();
    in_.needItems(n, sizeof(T));
    std::vector<T> v(static_cast<size_t>(n));
    in_.raw(v.data(), v.size() * sizeof(T));
    return v;
  }
  uint64_t count(uint64_t leastBytesEach) {
    const auto n = in_.pod<uint64_t>();
    in_.needItems(n, leastBytesEach);
    return n;
  }
  double finite() {
    const double v = in_.pod<double>();
    if (!std::isfinite(v)) in_.fail("a value that is not finite");
    return v;
  }
  ByteReader& raw() { return in_; }

  TextureRef textureRef(size_t textures) {
    TextureRef ref;
    ref.texture = in_.pod<int32_t>();
    if (ref.texture < -1 || (ref.texture >= 0 && static_cast<size_t>(ref.texture) >= textures)) {
      in_.fail("a texture index out of range");
    }
    for (double& v : ref.uv.m) v = finite();
    return ref;
  }

  Material material(size_t textures) {
    Material m;
    double* fields[] = {&m.color.x, &m.color.y, &m.color.z, &m.ambient, &m.diffuse, &m.specular,
                        &m.phongExponent, &m.reflectivity, &m.transmissivity, &m.ior,
                        &m.glossDegrees, &m.translucencyDegrees, &m.metallic, &m.emission.x,
                        &m.emission.y, &m.emission.z};
    for (double* f : fields) *f = finite();
    if (m.phongExponent < 1 || m.ior < 1 || m.reflectivity < 0 || m.transmissivity < 0 ||
        m.reflectivity + m.transmissivity > 1 || m.glossDegrees < 0 || m.glossDegrees >= 90 ||
        m.translucencyDegrees < 0 || m.translucencyDegrees >= 90) {
      in_.fail("a material no scene can hold");
    }
    m.colorTexture = textureRef(textures);
    m.emissionTexture = textureRef(textures);
    const auto given = in_.pod<uint8_t>();
    if (given > 1) in_.fail("a material no scene can hold");
    m.pbr.given = given == 1;
    PbrSurface& p = m.pbr;
    for (double* f : {&p.roughness, &p.transmission, &p.ior, &p.specularLevel, &p.coverage}) {
      *f = finite();
    }
    auto unit = [](double v) { return v >= 0 && v <= 1; };
    if (!unit(p.roughness) || !unit(p.transmission) || !(p.ior >= 1 && p.ior <= 10) ||
        !(p.specularLevel >= 0 && p.specularLevel <= kMaxSpecularLevel) || !unit(p.coverage)) {
      in_.fail("a material no scene can hold");
    }
    p.metallicRoughnessTexture = textureRef(textures);
    p.normalTexture = textureRef(textures);
    p.normalScale = finite();
    if (!(p.normalScale >= -1e6 && p.normalScale <= 1e6)) in_.fail("a material no scene can hold");
    p.transmissionTexture = textureRef(textures);
    for (double* f : {&p.attenuationColor.x, &p.attenuationColor.y, &p.attenuationColor.z}) {
      *f = finite();
      if (!unit(*f)) in_.fail("a material no scene can hold");
    }
    p.attenuationDistance = in_.pod<double>();
    if (!(p.attenuationDistance > 0)) in_.fail("a material no scene can hold");
    const auto thin = in_.pod<uint8_t>();
    if (thin > 1) in_.fail("a material no scene can hold");
    p.thinWalled = thin == 1;
    p.specularWeight = finite();
    if (!unit(p.specularWeight)) in_.fail("a material no scene can hold");
    for (double* f : {&p.specularColor.x, &p.specularColor.y, &p.specularColor.z}) {
      *f = finite();
      if (!(*f >= 0 && *f <= 1e6)) in_.fail("a material no scene can hold");
    }
    p.clearcoat = finite();
    p.clearcoatRoughness = finite();
    if (!unit(p.clearcoat) || !unit(p.clearcoatRoughness)) in_.fail("a material no scene can hold");
    return m;
  }

 private:
  ByteReader in_;
};

}  // namespace

std::vector<uint8_t> packAssets(const Scene& scene) {
  const Image* map = scene.environment.map.image.get();
  if (scene.imports.empty() && map == nullptr &&
      std::none_of(scene.objects.begin(), scene.objects.end(), isShippedMeshBlock)) {
    return {};  // nothing to ship
  }
  ByteWriter w;
  w.pod(kTag);
  w.pod(kVersion);
  // Every mesh and image once, numbered in the order first met.
  std::map<const TriangleMesh*, uint32_t> meshIndex;
  std::vector<const TriangleMesh*> meshes;
  auto meshOf = [&](const TriangleMesh* m) {
    const auto [at, added] = meshIndex.try_emplace(m, static_cast<uint32_t>(meshes.size()));
    if (added) meshes.push_back(m);
    return at->second;
  };
  std::map<const TextureImage*, uint32_t> imageIndex;
  std::vector<const TextureImage*> images;
  auto imageOf = [&](const TextureImage* i) {
    const auto [at, added] = imageIndex.try_emplace(i, static_cast<uint32_t>(images.size()));
    if (added) images.push_back(i);
    return at->second;
  };
  std::vector<uint32_t> blocks;
  for (const Object& o : scene.objects) {
    if (isShippedMeshBlock(o)) blocks.push_back(meshOf(std::get<MeshShape>(o.shape).mesh.get()));
  }
  for (const ImportSource& import : scene.imports) {
    for (size_t i = 0; i < import.objectCount; ++i) {
      const Object& o = scene.objects[import.firstObject + i];
      meshOf(std::get<InstanceShape>(o.shape).mesh.get());
    }
    for (size_t t = 0; t < import.textureCount; ++t) {
      imageOf(scene.textures[import.firstTexture + t].image.get());
    }
  }
  w.pod(static_cast<uint64_t>(meshes.size()));
  for (const TriangleMesh* m : meshes) {
    putArray(w, m->vertices);
    putArray(w, m->triangles);
    putArray(w, m->normals);
    putArray(w, m->uvs);
    putArray(w, m->colors);
    putArray(w, m->tangents);
  }
  w.pod(static_cast<uint64_t>(images.size()));
  for (const TextureImage* image : images) {
    w.pod(static_cast<int32_t>(image->width));
    w.pod(static_cast<int32_t>(image->height));
    w.pod(static_cast<int32_t>(image->channels));
    w.text(image->name.substr(0, 4096));
    putArray(w, image->texels);
  }
  putArray(w, blocks);
  w.pod(static_cast<uint64_t>(scene.imports.size()));
  for (const ImportSource& import : scene.imports) {
    const auto offset = static_cast<int32_t>(import.firstTexture);
    w.pod(static_cast<uint64_t>(import.textureCount));
    for (size_t t = 0; t < import.textureCount; ++t) {
      const Texture& texture = scene.textures[import.firstTexture + t];
      w.pod(imageIndex.at(texture.image.get()));
      w.pod(static_cast<uint8_t>(texture.wrapU));
      w.pod(static_cast<uint8_t>(texture.wrapV));
      w.pod(static_cast<uint8_t>(texture.nearest));
      w.pod(static_cast<uint8_t>(texture.linear));
    }
    w.pod(static_cast<uint64_t>(import.objectCount));
    for (size_t i = 0; i < import.objectCount; ++i) {
      const Object& o = scene.objects[import.firstObject + i];
      const auto& instance = std::get<InstanceShape>(o.shape);
      w.pod(meshIndex.at(instance.mesh.get()));
      for (const auto& row : instance.worldFromMesh.m) {
        for (const double v : row) w.pod(v);
      }
      putMaterial(w, o.material, offset);
    }
  }
  putRig(w, scene.animation ? *scene.animation : SceneAnimation{});
  // The environment map: its size (0 x 0: none), then its linear RGB floats.
  w.pod(static_cast<int32_t>(map != nullptr ? map->width() : 0));
  w.pod(static_cast<int32_t>(map != nullptr ? map->height() : 0));
  if (map != nullptr) w.raw(map->data().data(), map->data().size() * sizeof(float));
  return std::move(w.out);
}

ShippedAssets unpackAssets(const std::vector<uint8_t>& bytes) {
  static_assert(sizeof(Vec3) == 24 && sizeof(std::array<uint32_t, 3>) == 12);
  ShippedAssets out;
  if (bytes.empty()) return out;  // a scene with nothing to ship
  Reader in(bytes);
  ByteReader& raw = in.raw();
  if (raw.pod<uint32_t>() != kTag || raw.pod<uint32_t>() != kVersion) {
    raw.fail("not assets of this version of prt");
  }
  std::vector<std::shared_ptr<const TriangleMesh>> meshes;
  const uint64_t meshCount = in.count(48);
  for (uint64_t i = 0; i < meshCount; ++i) {
    auto m = std::make_shared<TriangleMesh>();
    m->vertices = in.array<Vec3>();
    m->triangles = in.array<std::array<uint32_t, 3>>();
    m->normals = in.array<Vec3>();
    m->uvs = in.array<std::array<float, 2>>();
    m->colors = in.array<std::array<float, 3>>();
    m->tangents = in.array<std::array<double, 4>>();
    const size_t n = m->vertices.size();
    if (m->triangles.empty()) raw.fail("a mesh without triangles");
    if ((!m->normals.empty() && m->normals.size() != n) || (!m->uvs.empty() && m->uvs.size() != n) ||
        (!m->colors.empty() && m->colors.size() != n) ||
        (!m->tangents.empty() && (m->tangents.size() != n || m->uvs.empty()))) {
      raw.fail("a mesh whose attributes do not match its vertices");
    }
    for (const auto& t : m->triangles) {
      if (t[0] >= n || t[1] >= n || t[2] >= n) raw.fail("a vertex index out of range");
    }
    // What the loaders never give: the tracer relies on it (trace/triangle_mesh.h).
    for (const Vec3& v : m->vertices) {
      if (!isFinite(v)) raw.fail("a vertex that is not finite");
    }
    for (const Vec3& v : m->normals) {
      if (!isFinite(v)) raw.fail("a normal that is not finite");
    }
    for (const auto& uv : m->uvs) {
      if (!std::isfinite(uv[0]) || !std::isfinite(uv[1])) raw.fail("texture coordinates that are not finite");
    }
    for (const auto& c : m->colors) {
      if (!std::isfinite(c[0]) || !std::isfinite(c[1]) || !std::isfinite(c[2])) {
        raw.fail("a vertex colour that is not finite");
      }
    }
    for (const auto& t : m->tangents) {
      if (!isFinite(Vec3{t[0], t[1], t[2]}) || (t[3] != 1 && t[3] != -1)) raw.fail("a tangent that is not finite");
    }
    for (const auto& t : m->triangles) {
      const Vec3 &a = m->vertices[t[0]], &b = m->vertices[t[1]], &c = m->vertices[t[2]];
      const double area = length(cross(b - a, c - a));
      if (!(area > 0) || !std::isfinite(area)) raw.fail("a triangle of zero area");
    }
    meshes.push_back(std::move(m));
  }
  std::vector<std::shared_ptr<const TextureImage>> images;
  const uint64_t imageCount = in.count(22);
  for (uint64_t i = 0; i < imageCount; ++i) {
    auto image = std::make_shared<TextureImage>();
    image->width = raw.pod<int32_t>();
    image->height = raw.pod<int32_t>();
    image->channels = raw.pod<int32_t>();
    image->name = raw.text();
    image->texels = in.array<uint8_t>();
    if (image->width <= 0 || image->height <= 0 || image->width > 32768 || image->height > 32768 ||
        image->channels < 1 || image->channels > 4 ||
        image->texels.size() != static_cast<size_t>(image->width) * static_cast<size_t>(image->height) *
                                    static_cast<size_t>(image->channels)) {
      raw.fail("an image whose texels do not match its size");
    }
    images.push_back(std::move(image));
  }
  for (const uint32_t index : in.array<uint32_t>()) {
    if (index >= meshes.size()) raw.fail("a mesh index out of range");
    out.meshBlocks.push_back(meshes[index]);
  }
  const uint64_t imports = in.count(16);
  for (uint64_t k = 0; k < imports; ++k) {
    ShippedImport import;
    const uint64_t textures = in.count(8);
    for (uint64_t t = 0; t < textures; ++t) {
      Texture texture;
      const auto image = raw.pod<uint32_t>();
      if (image >= images.size()) raw.fail("an image index out of range");
      texture.image = images[image];
      const auto u = raw.pod<uint8_t>(), v = raw.pod<uint8_t>(), nearest = raw.pod<uint8_t>();
      const auto linear = raw.pod<uint8_t>();
      if (u > 2 || v > 2 || nearest > 1 || linear > 1) raw.fail("an unknown way to sample a texture");
      texture.wrapU = static_cast<TextureWrap>(u);
      texture.wrapV = static_cast<TextureWrap>(v);
      texture.nearest = nearest != 0;
      texture.linear = linear != 0;
      import.textures.push_back(std::move(texture));
    }
    const uint64_t objects = in.count(4 + 12 * 8 + 16 * 8 + 2 * 52);
    for (uint64_t i = 0; i < objects; ++i) {
      InstanceShape instance;
      const auto mesh = raw.pod<uint32_t>();
      if (mesh >= meshes.size()) raw.fail("a mesh index out of range");
      instance.mesh = meshes[mesh];
      for (auto& row : instance.worldFromMesh.m) {
        for (double& v : row) v = in.finite();
      }
      if (!instance.worldFromMesh.isUsable()) raw.fail("a transform that flattens its mesh");
      const Material material = in.material(import.textures.size());
      import.objects.push_back({std::move(instance), material});
    }
    out.imports.push_back(std::move(import));
  }
  out.rig = getRig(raw, out.imports.size());
  const auto mapWidth = raw.pod<int32_t>(), mapHeight = raw.pod<int32_t>();
  if (mapWidth < 0 || mapHeight < 0 || (mapWidth == 0) != (mapHeight == 0)) {
    raw.fail("an environment map of no sensible size");
  }
  if (mapWidth > 0) {
    const uint64_t floats = 3 * static_cast<uint64_t>(mapWidth) * static_cast<uint64_t>(mapHeight);
    raw.needItems(floats, sizeof(float));
    auto map = std::make_shared<Image>(mapWidth, mapHeight);
    raw.raw(map->data().data(), map->data().size() * sizeof(float));
    for (const float v : map->data()) {
      if (!(v >= 0) || !std::isfinite(v)) raw.fail("an environment map of negative or infinite radiance");
    }
    out.environmentMap = std::move(map);
  }
  raw.finish();
  return out;
}

}  // namespace prt
