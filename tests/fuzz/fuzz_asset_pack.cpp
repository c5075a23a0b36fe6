// libFuzzer target: the asset pack a worker receives (scene/asset_pack.h), on arbitrary bytes.
// Bytes that are not a packing must end in a std::runtime_error (never a crash, an
// out-of-bounds read, a huge allocation or a leak); bytes that unpack must give meshes and
// images as the pack promises (indices in range, texels matching the size, usable
// transforms, texture references within their import, a rig whose curves are well formed and
// whose indices are in range), and must pack again, from a scene
// holding what they gave, into bytes that unpack and pack to the very same bytes.

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <stdexcept>
#include <variant>
#include <vector>

#include "scene/asset_pack.h"

namespace {

void check(bool ok) {
  if (!ok) std::abort();
}

void checkMesh(const std::shared_ptr<const prt::TriangleMesh>& m) {
  check(m != nullptr && !m->triangles.empty());
  check(m->tangents.empty() || (m->tangents.size() == m->vertices.size() && !m->uvs.empty()));
  for (const auto& t : m->triangles) {
    for (const uint32_t v : t) check(v < m->vertices.size());
  }
}

// A scene holding the assets as the parser would have placed them: each mesh block an object,
// each import a range of objects and textures.
prt::Scene sceneOf(const prt::ShippedAssets& assets) {
  prt::Scene scene;
  for (const auto& mesh : assets.meshBlocks) {
    prt::MeshSource source;
    source.file = "/fuzz/mesh.ply";
    scene.objects.push_back({prt::MeshShape{mesh, source}, {}});
  }
  for (const prt::ShippedImport& shipped : assets.imports) {
    prt::ImportSource import;
    import.file = "/fuzz/model.glb";
    import.firstObject = scene.objects.size();
    import.objectCount = shipped.objects.size();
    import.firstTexture = scene.textures.size();
    import.textureCount = shipped.textures.size();
    const auto offset = static_cast<int32_t>(scene.textures.size());
    for (prt::Object o : shipped.objects) {
      prt::PbrSurface& p = o.material.pbr;
      for (prt::TextureRef* ref : {&o.material.colorTexture, &o.material.emissionTexture,
                                   &p.metallicRoughnessTexture, &p.normalTexture, &p.transmissionTexture}) {
        if (ref->texture >= 0) ref->texture += offset;
      }
      scene.objects.push_back(std::move(o));
    }
    scene.textures.insert(scene.textures.end(), shipped.textures.begin(), shipped.textures.end());
    scene.imports.push_back(import);
  }
  if (!(assets.rig == prt::SceneAnimation{})) {
    scene.animation = std::make_shared<const prt::SceneAnimation>(assets.rig);
  }
  return scene;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::vector<uint8_t> bytes(data, data + size);
  prt::ShippedAssets assets;
  try {
    assets = prt::unpackAssets(bytes);
  } catch (const std::runtime_error&) {
    return 0;
  }
  for (const auto& mesh : assets.meshBlocks) checkMesh(mesh);
  for (const prt::ShippedImport& import : assets.imports) {
    for (const prt::Texture& t : import.textures) {
      check(t.image != nullptr);
      check(t.image->texels.size() == static_cast<size_t>(t.image->width) * static_cast<size_t>(t.image->height) *
                                          static_cast<size_t>(t.image->channels));
    }
    for (const prt::Object& o : import.objects) {
      const auto* instance = std::get_if<prt::InstanceShape>(&o.shape);
      check(instance != nullptr && instance->worldFromMesh.isUsable());
      checkMesh(instance->mesh);
      const prt::PbrSurface& p = o.material.pbr;
      for (const prt::TextureRef* ref : {&o.material.colorTexture, &o.material.emissionTexture,
                                         &p.metallicRoughnessTexture, &p.normalTexture,
                                         &p.transmissionTexture}) {
        check(ref->texture >= -1 && ref->texture < static_cast<int32_t>(import.textures.size()));
      }
    }
  }
  check(assets.rig.fields.empty() && prt::rigProblem(assets.rig).empty());
  for (const prt::ObjectBinding& b : assets.rig.objects) check(b.import < assets.imports.size());
  for (const prt::LightBinding& b : assets.rig.lights) check(b.import < assets.imports.size());
  for (const prt::CameraBinding& b : assets.rig.camera) check(b.import < assets.imports.size());
  // Packed again, the assets unpack, and pack to the same bytes once more.
  const std::vector<uint8_t> again = prt::packAssets(sceneOf(assets));
  const std::vector<uint8_t> twice = prt::packAssets(sceneOf(prt::unpackAssets(again)));
  check(again == twice);
  return 0;
}
