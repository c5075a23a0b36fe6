#include "scene/mesh_pack.h"

#include <cstring>
#include <stdexcept>
#include <string>

namespace prt {
namespace {

bool isShipped(const Object& object) {
  const auto* m = std::get_if<MeshShape>(&object.shape);
  return m != nullptr && !m->source.file.empty();
}

class Reader {
 public:
  explicit Reader(const std::vector<uint8_t>& bytes) : bytes_(bytes) {}
  void read(void* to, uint64_t n) {
    if (n > bytes_.size() - at_) throw std::runtime_error("malformed meshes: truncated");
    std::memcpy(to, bytes_.data() + at_, n);
    at_ += n;
  }
  uint64_t count() {
    uint64_t n = 0;
    read(&n, sizeof n);
    // Each counted thing takes at least 12 bytes: a count beyond the rest is a lie.
    if (n > (bytes_.size() - at_) / 4) throw std::runtime_error("malformed meshes: bad count");
    return n;
  }
  bool done() const { return at_ == bytes_.size(); }

 private:
  const std::vector<uint8_t>& bytes_;
  size_t at_ = 0;
};

}  // namespace

std::vector<uint8_t> packMeshes(const Scene& scene) {
  std::vector<uint8_t> out;
  auto put = [&](const void* data, size_t n) {
    if (n == 0) return;
    const size_t at = out.size();
    out.resize(at + n);
    std::memcpy(out.data() + at, data, n);
  };
  auto putCount = [&](uint64_t n) { put(&n, sizeof n); };
  uint64_t meshes = 0;
  for (const Object& o : scene.objects) meshes += isShipped(o) ? 1 : 0;
  putCount(meshes);
  for (const Object& o : scene.objects) {
    if (!isShipped(o)) continue;
    const TriangleMesh& m = *std::get<MeshShape>(o.shape).mesh;
    putCount(m.vertices.size());
    putCount(m.triangles.size());
    putCount(m.normals.size());
    put(m.vertices.data(), m.vertices.size() * sizeof(Vec3));
    put(m.triangles.data(), m.triangles.size() * sizeof(m.triangles[0]));
    put(m.normals.data(), m.normals.size() * sizeof(Vec3));
  }
  return out;
}

ShippedMeshes unpackMeshes(const std::vector<uint8_t>& bytes) {
  static_assert(sizeof(Vec3) == 24 && sizeof(std::array<uint32_t, 3>) == 12);
  Reader in(bytes);
  ShippedMeshes meshes;
  const uint64_t count = in.count();
  for (uint64_t i = 0; i < count; ++i) {
    auto m = std::make_shared<TriangleMesh>();
    const uint64_t vertices = in.count(), triangles = in.count(), normals = in.count();
    if (normals != 0 && normals != vertices) throw std::runtime_error("malformed meshes: normals");
    m->vertices.resize(vertices);
    in.read(m->vertices.data(), vertices * sizeof(Vec3));
    m->triangles.resize(triangles);
    in.read(m->triangles.data(), triangles * sizeof(m->triangles[0]));
    m->normals.resize(normals);
    in.read(m->normals.data(), normals * sizeof(Vec3));
    for (const auto& t : m->triangles) {
      if (t[0] >= vertices || t[1] >= vertices || t[2] >= vertices) {
        throw std::runtime_error("malformed meshes: index out of range");
      }
    }
    if (m->triangles.empty()) throw std::runtime_error("malformed meshes: no triangles");
    meshes.push_back(std::move(m));
  }
  if (!in.done()) throw std::runtime_error("malformed meshes: trailing bytes");
  return meshes;
}

}  // namespace prt
